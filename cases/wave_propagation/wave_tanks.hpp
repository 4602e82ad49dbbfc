#pragma once
// 2D wave tanks for the wave-maker tests and validations (issue 6; METHOD.md
// sections 3, 4, 6.3): a periodic tank with a forcing region, and a flume with a
// piston wave maker and a damping zone, each with wave gauges. Built from
// moorsph_fluid alone, so the tests and the case runner need nothing else.
//
// Units SI; x along the tank, y up, the floor at y = 0.
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>
#include <moorsph/fluid/fluid_simulation.hpp>
#include <moorsph/fluid/forcing_region.hpp>
#include <moorsph/fluid/piston.hpp>
#include <moorsph/fluid/wave_gauge.hpp>
#include <moorsph/fluid/wave_height_controller.hpp>

namespace moorsph::cases {

/// Active amplitude correction (fluid/wave_height_controller.hpp): off unless
/// `gauges` is not empty.
struct WaveTankControl {
  std::vector<double> gauges;  ///< x [m] of the gauges the controller watches (relative to the maker)
  double start_time = 0.0;     ///< [s]; at least the ramp-up plus the delay (wave_tanks.cpp)
  int update_periods = 2;
  double beta = 0.5;
  double stop_time = 1e300;    ///< [s], gain held afterwards
};

/// What every wave tank shares: resolution, fluid and method.
struct WaveTankFluid {
  double dx = 0.0125;          ///< target particle spacing [m] (a periodic tank adjusts it)
  double mu = 1.0e-3;          ///< dynamic viscosity [Pa s]
  double sound_speed = 0.0;    ///< [m/s]; 0: 10 sqrt(2 g d), METHOD.md's 10x the fastest flow
  fluid::MethodParameters method = fluid::MethodParameters::reference();
  std::vector<std::string> effects{"pressure", "viscosity", "xsph", "gravity", "walls"};
};

/// The low-dissipation wave settings (docs/validation/wave-propagation.md, sessions 7, 8,
/// 16 and 18): h = 2 dx, the symplectic integrator, renormalised density diffusion, no
/// XSPH. Pair with the tank's floor = "mirror"; at ~9 particles per wave height and more,
/// h = 3 dx (method.h_factor) keeps the height better.
WaveTankFluid lowDissipationWaveFluid(double dx);

/// Periodic tank of whole wavelengths with a forcing region (METHOD.md section 4a).
struct PeriodicWaveTankSpec {
  WaveTankFluid fluid;
  double period = 0.836;       ///< T [s] (adjusted slightly so the wavelength fits, see below)
  double depth = 0.25;         ///< target still depth [m] (rounded to whole rows)
  double amplitude = 0.025;    ///< requested first-harmonic amplitude a [m]
  int wavelengths = 1;         ///< the periodic length holds this many
  std::string theory = "airy"; ///< "airy" or "stokes2"
  double kappa = 7.0;
  double maker_start = 0.0;    ///< [m]
  double maker_length = 0.0;   ///< [m]; 0: the whole tank
  double bottom_gap = 0.0;     ///< [m]
  double ramp_up = 0.0;        ///< [s], half-cosine ramp of the target
  double forcing_end = std::numeric_limits<double>::infinity();  ///< [s]
  double gain = 1.0;           ///< factor on the target (amplitude calibration)
  /// Start with the wave already in the water (particles at the linear wave's orbital
  /// displacement, the velocity of `theory` and the linear wave's pressure at t = 0) and no
  /// forcing region: the scheme's own loss, with no maker.
  bool initial_wave = false;
  /// "walls": one row of boundary particles; "mirror": the mirror_floor effect (images).
  std::string floor = "walls";
  std::vector<double> gauges;  ///< gauge x [m]; empty: one every tenth of a wavelength
  WaveTankControl control;
};

/// Flume with a piston at the left end and a damping zone before the far wall
/// (METHOD.md section 4b).
struct PistonFlumeSpec {
  WaveTankFluid fluid;
  double period = 0.836;       ///< T [s]
  double depth = 0.25;         ///< still depth [m] (rounded to whole rows)
  double height = 0.05;        ///< requested wave height H [m]
  double length = 3.0;         ///< from the piston's rest face to the far wall [m]
  double ramp_up = 0.0;        ///< [s]; 0: two periods
  double gain = 1.0;           ///< factor on the stroke (amplitude calibration)
  double damping_start = 2.0;  ///< [m] from the piston's rest face
  double damping_k_max = 10.0; ///< [1/s]
  /// "walls": one row of boundary particles; "mirror": the mirror_floor effect (images).
  std::string floor = "walls";
  std::vector<double> gauges;  ///< gauge x [m] from the piston's rest face
  WaveTankControl control;
};

/// A built tank: the simulation, its gauges and the wave it is meant to carry.
struct WaveTank {
  std::unique_ptr<fluid::FluidSimulation<2>> sim;
  std::vector<fluid::WaveGauge<2>> gauges;
  double depth = 0.0;          ///< still depth [m] (whole rows x dx)
  double period = 0.0;         ///< [s]
  double wavelength = 0.0;     ///< [m]
  double amplitude = 0.0;      ///< requested amplitude [m]
  double x_origin = 0.0;       ///< x of the maker (piston rest face) [m]; gauges are relative to it
  fluid::ForcingRegion<2>* forcing = nullptr;  ///< owned by sim
  /// Active correction (null when off); the piston's signal and the forcing region
  /// read its gain.
  std::shared_ptr<fluid::WaveHeightController> controller;
  std::vector<fluid::WaveGauge<2>> control_gauges;
};

WaveTank buildPeriodicWaveTank(const PeriodicWaveTankSpec& spec);
WaveTank buildPistonFlume(const PistonFlumeSpec& spec);

/// Gauge time series: times [s] and one row of surface heights minus the still depth
/// [m] per gauge.
struct GaugeRecord {
  std::vector<double> t;
  std::vector<std::vector<double>> eta;  ///< eta[g][k]
};

/// Step the tank to `end` [s], reading every gauge every `interval` [s]; `on_sample`
/// (if set) is called after each reading (e.g. to write it out as the run goes).
GaugeRecord runAndRecord(WaveTank& tank, double end, double interval,
                         const std::function<void(const GaugeRecord&)>& on_sample = {});

/// Mean over the whole periods in [t0, t1] of the trough-to-crest height max - min
/// within each period [m] (0 if no whole period fits).
double meanWaveHeight(const std::vector<double>& t, const std::vector<double>& eta, double period, double t0,
                      double t1);

/// Mean of eta over [t0, t1] [m].
double meanLevel(const std::vector<double>& t, const std::vector<double>& eta, double t0, double t1);

/// Incident and reflected waves separated from gauges along a flume (the least-squares
/// method of Mansard & Funke 1980, with a spatial decay added): the complex amplitude
/// of the frequency omega at each gauge over the whole periods in [t0, t1],
///   Z(x) = (2/N) sum_k eta(x, t_k) exp(i omega t_k),
/// is fitted by Z(x) = A exp((i k - alpha) x) + B exp((-i k + alpha) x): an incident
/// wave decaying at alpha [1/m] on its way out and a reflected one decaying on its way
/// back. alpha is found by a scan, A and B by linear least squares for each alpha.
struct WaveSeparation {
  double incident = 0.0;    ///< |A| exp(-alpha x_ref): incident amplitude at x_ref [m]
  double reflected = 0.0;   ///< |B| exp(alpha x_ref): reflected amplitude at x_ref [m]
  double alpha = 0.0;       ///< spatial decay rate of the amplitude [1/m]
  double residual = 0.0;    ///< |fit - Z| / |Z| [-]
  /// Reflection coefficient at x_ref; equal to the standing-wave envelope ratio
  /// (H_max - H_min) / (H_max + H_min) of the fitted field there.
  double reflection() const { return reflected / incident; }
};

WaveSeparation separateIncidentReflected(const GaugeRecord& rec, const std::vector<double>& x, double omega, double k,
                                         double t0, double t1, double x_ref);

}  // namespace moorsph::cases
