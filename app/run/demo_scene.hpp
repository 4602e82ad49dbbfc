#pragma once
// The built-in demo of `moorsph` with no arguments: a coarse tethered buoy vertical
// release (METHOD.md section 6.2a in a smaller, shallower tank at D/8). The lab buoy
// (R = 0.1015 m, 1.745 kg, CoM 27 mm below the centroid) floats half submerged on a
// tension-only spring (k = 30.88 N/m, pretension 4.366 N at rest) to an anchor 9 cm
// above the floor; it starts pulled 6 cm down, is held 0.2 s while the water settles,
// then is released and heaves. The demo writes this text to <out>/demo_scene.yaml and
// runs it like any scene, then plots the series. Kept in step with
// cases/tethered_buoy_3d.yaml (the full-size scene).
namespace moorsph::app {

inline const char* const kDemoScene = R"(# moorsph built-in demo: tethered buoy vertical release (coarse; see cases/tethered_buoy_3d.yaml)
dim: 3
name: demo_buoy_release
end_time: 2.0                 # [s]: about 3 heave periods after release
resolution: {dx: 0.025}       # [m] = D/8 (coarse: a demo, not a validation)
fluid: {viscosity: 0.001}     # [Pa s]; c_s = 10 sqrt(2 g 0.4) = 28 m/s
effects: [pressure, viscosity, xsph, density_diffusion, gravity, walls, bodies]
geometry:
  - tank: {name: tank, lower: [0, 0, 0], upper: [0.6, 0.6, 0.6]}
  - water: {lower: [0, 0, 0], upper: [0.6, 0.408, 0.6]} # 8 mm above 0.4: the water kept out of the
                                                       # pulled-down buoy (and 0.45 dx around it) is
                                                       # 3.0e-3 m^3 more than it displaces at rest
bodies:
  - name: buoy
    mass: 1.745                                      # [kg]
    centre_of_mass: [0, -0.027, 0]                   # [m] body frame
    inertia: [1.735209e-3, 1.776363e-3, 1.735209e-3] # [kg m^2] about the CoM
    position: [0.3, 0.4, 0.3]                        # [m] centroid at rest (still level)
    offset: [0, -0.06, 0]                            # [m] pulled down, then released
    shape: {sphere: {radius: 0.1015}}                # [m]
moorings:
  - name: tether
    model: tension_only_spring
    fairlead: {body: buoy, point: [0, -0.1015, 0]}   # [m] the buoy's bottom point
    anchor: {point: [0.3, 0.09, 0.3]}                # [m] 9 cm above the floor
    stiffness: 30.88                                 # [N/m]
    pretension: 4.366                                # [N] at rest: half submerged
coupling: {release_time: 0.2, ramp_time: 0.0}        # [s] held while the water settles
gauges:
  - {name: G_near, x: 0.45, z: 0.3, top: 0.6}
output: {interval: 0.01, particles_interval: 0.1, checkpoint_minutes: 0}
)";

}  // namespace moorsph::app
