#pragma once
// The mirror_floor and mirror_walls effects' second half (the first, the images, is
// MirrorTerm in pair_terms.hpp): a fluid particle that crossed a mirror plane during a
// step is put back by specular reflection, x_n -> 2 p - x_n, v_n -> -v_n along the
// plane's normal (free slip; the kinetic energy is kept). The images hold the water
// back by its pressure, but a particle at a plane meets its own image at zero distance,
// where the kernel gradient vanishes, so nothing there stops one pushed hard (measured: in the corner between a side
// wall and the floor, particles went under within 0.2 s and were then expelled
// downward by their own images). Ghost-particle floors are usually paired with such a
// reflection for this reason.
//
// Only the corrected state is reflected. The corrector restarts from the step's start,
// r^{n+1} = r^n + dt v*, v^{n+1} = v^n + dt a*: had the predicted state been reflected,
// v* would point up while v^n still pointed down, so a particle pressed against the
// plane (in a side wall's corner) would rise in position but keep a downward velocity
// that grew by dt a every step, crossing and being put back each time: measured, corner
// particles of still water reaching 0.9-1.3 m/s (tests/fluid/test_mirror_floor.cpp).
// A predicted state a fraction of dt v below the plane is harmless: its image lies just
// above, as for any particle near the plane.
#include <vector>
#include <moorsph/fluid/counted.hpp>
#include <moorsph/fluid/fluid_effect.hpp>
#include <moorsph/fluid/fluid_setup.hpp>

namespace moorsph::fluid {

template <int D>
class MirrorReflection final : public FluidEffect<D>, public Counted<MirrorReflection<D>> {
 public:
  explicit MirrorReflection(std::vector<MirrorPlane> planes) : planes_(std::move(planes)) {}
  const char* name() const override { return "mirror_reflection"; }
  void addRates(FluidContext<D>&) override {}
  void constrain(FluidParticles<D>& f, StepStage stage) override {
    if (stage != StepStage::Corrected) return;
    const std::size_t n = f.size();
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < n; ++i) {
      for (const MirrorPlane& p : planes_) {
        const int a = p.axis;
        if (!p.outside(f.r[i][a])) continue;
        f.r[i][a] = p.mirrored(f.r[i][a]);
        f.v[i][a] = -f.v[i][a];
      }
    }
  }

 private:
  std::vector<MirrorPlane> planes_;
};

}  // namespace moorsph::fluid
