#!/usr/bin/python3
"""Writes the METHOD.md section 6.5 variant scenes from ship_base.yaml (the scene loader has no
includes, so each variant is a full file; rerun this after editing the base):

    cd cases/ship && /usr/bin/python3 make_variants.py

Every variant keeps the base's comments on the ship, the frames and the economies; the lines
that differ are listed in its header. Depth changes move everything tied to the surface (the
ship, the anchors 175 m below it, the piston and wall tops, the gauges' tops, the domain).

With `--restart-variants-at DX FAR_WALL_X OUT_DIR` it also writes the restart variants
(k3e6, mass130, mass200, catenary, lumped) at spacing DX into OUT_DIR, with the files they
name (piston table, hull mesh, deck outline), to continue from a checkpoint of ship_dx6.yaml
(DX 6, FAR_WALL_X 696) or another spacing's base:

    /usr/bin/python3 make_variants.py --restart-variants-at 6 696 runs/variants_dx6
"""
import os
import shutil
import sys

def split_header(text):
    """A scene file's comment header and its body (from `dim: 3` on)."""
    i = text.index("dim: 3")
    return text[:i], text[i:]


BODY = split_header(open("ship_base.yaml").read())[1]


def replace(text, old, new, count=1):
    if text.count(old) < count:
        raise SystemExit(f"make_variants: '{old}' not found in ship_base.yaml")
    return text.replace(old, new)


def deepen(text, dd, tall=False, far_wall_x=700):
    """Water dd metres deeper: shift everything tied to the still level. tall: the order-2
    breather's headroom (domain, walls and piston 20 m, 20 m and 15 m higher)."""
    d = 132 + dd
    x = f"{far_wall_x:g}"
    text = replace(text, "upper: [720, 210, 72]", f"upper: [720, {210 + dd + (20 if tall else 0)}, 72]")
    text = replace(text, "upper: [720, 172, 72]", f"upper: [720, {172 + dd + (20 if tall else 0)}, 72]")
    text = replace(text, f"upper: [{x}, 132, 72], packed: true}}   # d = 132 m", f"upper: [{x}, {d}, 72], packed: true}}   # d = {d} m")
    text = replace(text, "top: 157                      # [m]: 25 m above the still level",
                   f"top: {157 + dd + (15 if tall else 0)}                      # [m]: {25 + (15 if tall else 0)} m above the still level")
    text = replace(text, "position: [177.9, 119.3117, 36.0]", f"position: [177.9, {119.3117 + dd:.4f}, 36.0]")
    text = replace(text, "(120 m = 132 - 12 if level at T = 12 m)", f"(d - 12 m if level at T = 12 m)")
    text = replace(text, "(y = 132 - 175 = -43 m)", f"(y = {d} - 175 = {d - 175} m)")
    for y in ("-43, 36]", "-43, 1]", "-43, 71]"):
        text = replace(text, y, y.replace("-43", str(d - 175)))
    text = text.replace("top: 200}", f"top: {200 + dd + (20 if tall else 0)}}}")
    return text


def write(name, header, body):
    body = replace(body, "name: ship_base", f"name: {name}")
    with open(f"{name}.yaml", "w") as f:
        f.write(header.strip() + "\n" + body)
    print(f"wrote {name}.yaml")


RESTART = """
#
# A restart variant: run ship_base.yaml to 265 s, then continue from its checkpoint with this
# file (same particles: geometry, resolution and piston are those of the base, and
# `moorsph run --restart` rejects a scene that differs there; a restart may change a body's
# mass and inertia and a line's stiffness and rest length, docs/scene-reference.md):
#   moorsph run cases/ship/ship_base.yaml --end 265 --out runs/ship_base_265
#   moorsph run cases/ship/{name}.yaml --restart runs/ship_base_265/checkpoint.h5 --out runs/{name}
# The fluid at 265 s is the base run's, the waves already under way; the body changes at
# once, so the first seconds after 265 s carry the ship's response to the step change.
#
# Otherwise as ship_base.yaml (the ship, frames, economies and sensors are described there)."""

# Cables 3e6 N/m, rest length for the base's equilibrium tension 17.5297 MN per cable
# (tests/io/test_ship_scene.cpp checks it): span at equilibrium 157.1 + 17.5297/1.7 =
# 167.41157 m, L0 = 167.41157 - 17.5297/3 = 161.56835 m.
body = BODY
body = body.replace("stiffness: 1.7e6                          # [N/m]", "stiffness: 3.0e6                          # [N/m]")
body = body.replace("stiffness: 1.7e6", "stiffness: 3.0e6")
body = body.replace("rest_length: 157.1                        # [m]",
                    "rest_length: 161.56835                    # [m]: the base's 17.53 MN at the same pose")
body = body.replace("rest_length: 157.1", "rest_length: 161.56835")
write("ship_k3e6", """# METHOD.md 6.5 variant: stiffer cables, k = 3e6 N/m instead of 1.7e6 N/m, with the rest
# length set for the same equilibrium tension (17.53 MN per cable at the base's equilibrium
# pose: L0 = 167.41157 - 17.5297e6/3e6 = 161.56835 m instead of 157.1 m).""" + RESTART.replace("{name}", "ship_k3e6"), body)

for factor, name in ((1.3, "ship_mass130"), (2.0, "ship_mass200")):
    m = 52196000 * factor
    inertia = [6.3848e9 * factor, 2.1917e11 * factor, 2.1917e11 * factor]
    body = BODY
    body = replace(body, "mass: 52196000                            # [kg]",
                   f"mass: {m:.0f}                            # [kg]: {factor:g} x 52,196 t")
    body = replace(body, "inertia: [6.3848e9, 2.1917e11, 2.1917e11] # [kg m^2] about the CoM (roll, yaw, pitch; docs/ship-hull.md)",
                   f"inertia: [{inertia[0]:.5g}, {inertia[1]:.5g}, {inertia[2]:.5g}] # [kg m^2]: {factor:g} x the base (same radii of gyration)")
    write(name, f"""# METHOD.md 6.5 variant: the ship {int(round((factor - 1) * 100))}% heavier ({m / 1e3:,.0f} t), its centre of mass
# unchanged and its inertia scaled with the mass (the added mass distributed like the
# ship's own, same radii of gyration). The hull and its start pose are those of the base
# (the restart keeps the particles); from 265 s the heavier ship sinks toward its new draught
# (about {(factor - 1) * 52196 / 1e3 * 0.137 / 1:.1f} m deeper at 0.137 m per 1000 t, less the cables' give) while the waves arrive.""" + RESTART.replace("{name}", name), body)

def at_spacing(dx, far_wall_x, body=BODY):
    """The base (or a variant of it at the base's depth) at spacing dx, its far wall (and the
    water, floor and damping zone's end) moved to far_wall_x, a multiple of dx: a fill that
    stopped short of the wall would leave a gap that lowers the still level (0.75 m for a 4 m
    gap)."""
    body = replace(body, "dx: 4.0                       # [m]", f"dx: {dx:.1f}                       # [m]")
    x = f"{far_wall_x:g}"
    body = replace(body, "upper: [700, 0, 72]", f"upper: [{x}, 0, 72]")
    body = replace(body, "lower: [700, -20, 0], upper: [720, 172, 72]", f"lower: [{x}, -20, 0], upper: [720, 172, 72]")
    body = replace(body, "upper: [700, 132, 72], packed: true}", f"upper: [{x}, 132, 72], packed: true}}")
    body = replace(body, "spacing: 6.18}", f"spacing: {1.545 * dx:.3g}}}", count=2)
    return replace(body, "{x_start: 520, x_end: 700, k_max: 1.0}", f"{{x_start: 520, x_end: {x}, k_max: 1.0}}")


# dx = 2 m: only the spacing changes (2 m divides the 700 m length).
body = replace(at_spacing(2.0, 700), "particles_interval: 5.0", "particles_interval: 10.0")
write("ship_dx2", """# METHOD.md 6.5 variant: dx = 2 m (the reference's coarse resolution; its fine one is 1 m),
# from t = 0. About 8x the particles of the 4 m base and half its time step.
#
# Otherwise as ship_base.yaml (the ship, frames, economies and sensors are described there).""", body)

# dx = 6 m and 3 m with the 4 m base: a three-spacing study (6, 4 and 3 m divide the 132 m
# depth and the 72 m period, not the 700 m length).
write("ship_dx6", """# METHOD.md 6.5 variant: dx = 6 m, from t = 0: the coarsest of a three-spacing study with
# the 4 m base and ship_dx3.yaml (the reference's "coarser dx" variant, here coarser than a
# base that is itself coarse). About 0.3x the particles of the base and 1.5x its time step;
# 2 particles over the 12.2 m draught. The far wall stands at x = 696 m instead of 700 m
# (6 m does not divide 700 m), so the damping zone is 176 m long instead of 180 m.
#
# Otherwise as ship_base.yaml (the ship, frames, economies and sensors are described there).""", at_spacing(6.0, 696))
body = at_spacing(3.0, 699)
body = replace(body, "particles_interval: 5.0", "particles_interval: 10.0")
write("ship_dx3", """# METHOD.md 6.5 variant: dx = 3 m, from t = 0: the finest of a three-spacing study with
# ship_dx6.yaml and the 4 m base. About 2.4x the particles of the base and 0.75x its time
# step (`moorsph check` on one shared thread: 10.8 h; about 7 h on 2 threads at the base's
# 9e5 particle-steps/s). The far wall stands at x = 699 m instead of
# 700 m (3 m does not divide 700 m).
#
# Otherwise as ship_base.yaml (the ship, frames, economies and sensors are described there).""", body)

# Doubled carrier wavelength: k0 = 0.0066667 1/m (942 m, period 24.6 s), a0 = 4.5 m kept
# (the 9 m background sea), so a0 k0 = 0.03; k0 d >= 1.75 needs d = 264 m.
def long_carrier(body, far_wall_x=700):
    body = deepen(body, 132, far_wall_x=far_wall_x)
    body = replace(body, "signal_order1.csv", "signal_order1_long.csv")
    body = replace(body, "(0.38 carrier wavelengths)", "(0.19 carrier wavelengths: little absorption)")
    return replace(body, "k_max: 1.0}   # [1/s], about 3 omega0", "k_max: 0.75}  # [1/s], about 3 omega0")


LONG_HEADER = """# METHOD.md 6.5 variant: doubled carrier wavelength, from t = 0. k0 = 0.0066667 1/m
# (wavelength 942 m, period 24.6 s); a0 = 4.5 m is kept (the 9 m background sea), so the
# carrier steepness halves to a0 k0 = 0.03 and the breather's envelope is 4x longer. The
# depth for k0 d >= 1.75 doubles to d = 264 m (about twice the particles, and c_s = 10
# sqrt(2 g d) = 720 m/s shortens the time step by 1.4); the anchors (y = 89 m) are now above
# the floor. The 700 m tank holds only 0.74 wavelengths and the damping zone 0.19: expect
# reflections from the far wall to reach the ship.
#   moorsph_breather_signal --order 1 --a0 4.5 --k0 0.0066667 --focus-distance 200 \\
#     --focus-time 300 --depth 264 --still 30 --ramp 75 --duration 420 --out signal_order1_long.csv
"""
OTHERWISE = """#
# Otherwise as ship_base.yaml (the ship, frames, economies and sensors are described there)."""
AT_6M = """#
# At dx = 6 m (as ship_dx6.yaml: far wall at x = 696 m, damping zone 520-696 m), the spacing
# at which this full-length variant fits in a session on 2 cores."""
write("ship_long", LONG_HEADER + OTHERWISE, long_carrier(BODY))
write("ship_long_dx6", LONG_HEADER + AT_6M + "\n" + OTHERWISE, long_carrier(at_spacing(6.0, 696), 696))


# Order-2 breather: a0 = 4.5 m, a0 k0 = 0.05 -> k0 = 0.011111 1/m (566 m, 19.0 s), d = 160 m
# (162 m at dx = 6 m, which does not divide 160 m; its piston table is made for that depth).
def order2(body, dd=28, far_wall_x=700, signal="signal_order2.csv"):
    body = deepen(body, dd, tall=True, far_wall_x=far_wall_x)
    body = replace(body, "signal_order1.csv", signal)
    return replace(body, "headroom for the 13.5 m crest and spray", "headroom for the 22.5 m crest and spray")


ORDER2_HEADER = """# METHOD.md 6.5 variant: second-order Peregrine breather (amplification 5: a 22.5 m crest,
# 42+ m from trough to crest), a0 = 4.5 m, a0 k0 = 0.05, k0 = 0.011111 1/m (wavelength
# 566 m, period 19.0 s), focused 200 m from the piston at 300 s, from t = 0. k0 d >= 1.75
# needs d = 160 m (k0 d = 1.778). The crest tops the deck (23.5 - 12.2 = 11.3 m freeboard):
# green water. The piston strokes up to 13.8 m, and its plate, the far wall and the domain
# are raised for the higher crest.
#   moorsph_breather_signal --order 2 --a0 4.5 --k0 0.011111 --focus-distance 200 \\
#     --focus-time 300 --depth 160 --still 30 --ramp 60 --duration 420 --out signal_order2.csv
"""
write("ship_order2", ORDER2_HEADER + OTHERWISE, order2(BODY))
write("ship_order2_dx6", ORDER2_HEADER + AT_6M + """
# 6 m does not divide 160 m, so the water is 162 m deep (k0 d = 1.800), everything tied to
# the still level stands 2 m higher than in ship_order2.yaml, and the piston's table is made
# for that depth:
#   moorsph_breather_signal --order 2 --a0 4.5 --k0 0.011111 --focus-distance 200 \\
#     --focus-time 300 --depth 162 --still 30 --ramp 60 --duration 420 --out signal_order2_d162.csv
""" + OTHERWISE, order2(at_spacing(6.0, 696), 30, 696, "signal_order2_d162.csv"))

# Elastic catenary lines: the same cables with weight. EA = k L0 = 1.7e6 x 157.1 = 2.6707e8 N
# so the elastic stiffness EA / L0 is the base's k.
body = BODY
line_old = """    stiffness: 1.7e6                          # [N/m]
    rest_length: 157.1                        # [m]"""
line_new = """    length: 157.1                             # [m] unstretched
    axial_stiffness: 2.6707e8                 # EA [N] = k L0: the base's 1.7e6 N/m
    mass_per_length: 45.0                     # [kg/m] in air: a 90 mm spiral-strand wire rope
    diameter: 0.09                            # [m]: submerged weight 377 N/m
    anchor_on_seabed: true                    # the anchor is on the true seabed, 175 m down
    segments: 20                              # read by lumped_mass only"""
body = replace(body, line_old, line_new)
body = replace(body, """    stiffness: 1.7e6
    rest_length: 157.1""", """    length: 157.1
    axial_stiffness: 2.6707e8
    mass_per_length: 45.0
    diameter: 0.09
    anchor_on_seabed: true
    segments: 20""", count=2)
body = body.replace("model: tension_only_spring", "model: elastic_catenary")
write("ship_catenary", """# METHOD.md 6.5 variant: the three cables as elastic catenaries (quasi-static lines with
# weight, bodies/ elastic_catenary) instead of massless tension-only springs, from t = 0.
# The line is described once (length, EA, weight, diameter); `model: lumped_mass` on each
# line makes it the dynamic lumped-mass line with the same description (drag, added mass,
# `segments`), `tension_only_spring` would give back k = EA / length = 1.7e6 N/m with rest
# length 157.1 m. EA = 2.6707e8 N keeps the base's stiffness; the line's submerged weight
# (59 kN per line) is 0.3% of the 17.5 MN tension, so the equilibrium barely moves. The
# lines are not in the SPH fluid (their still water level is the scene's highest water top).
#
# Otherwise as ship_base.yaml (the ship, frames, economies and sensors are described there).""", body)

# Lumped-mass lines: the catenary's cables with mass, drag and added mass (the
# scene-reference defaults for a wire rope: C_dn 1.2, C_an 1.0), 20 segments of 7.9 m.
# Meant as a restart variant from the spring base's 265 s checkpoint: the lines take their
# static shape at the restored pose (MooringLine::startWithoutSavedState).
lumped = body.replace("model: elastic_catenary", "model: lumped_mass")
write("ship_lumped", """# METHOD.md 6.5 variant: the three cables as dynamic lumped-mass lines (bodies/ lumped_mass:
# 20 segments, 45 kg/m in air, EA = 2.6707e8 N = k L0, normal drag 1.2 and added mass 1.0 on
# the 90 mm diameter, in still water) instead of massless tension-only springs. Their
# inertia and drag are what the quasi-static models lack: the snap when a slack line comes
# taut. The lines are not in the SPH fluid.""" + RESTART.format(name="ship_lumped"), lumped)


RESTART_VARIANTS = ("ship_k3e6", "ship_mass130", "ship_mass200", "ship_catenary", "ship_lumped")
if len(sys.argv) == 5 and sys.argv[1] == "--restart-variants-at":
    dx, far_wall_x, out = float(sys.argv[2]), float(sys.argv[3]), sys.argv[4]
    os.makedirs(out, exist_ok=True)
    for name in RESTART_VARIANTS:
        header, body = split_header(open(f"{name}.yaml").read())
        body = replace(at_spacing(dx, far_wall_x, body), f"name: {name}", f"name: {name}_dx{dx:g}")
        with open(os.path.join(out, f"{name}_dx{dx:g}.yaml"), "w") as f:
            f.write(header + f"# Written by make_variants.py --restart-variants-at {dx:g} {far_wall_x:g}: this variant at\n"
                    f"# dx = {dx:g} m, to restart from a checkpoint of the base at that spacing.\n" + body)
    for used in ("signal_order1.csv", "hull_blunt.stl", "hull_deck.csv"):  # the files the scenes name
        shutil.copy(used, out)
    print(f"wrote {len(RESTART_VARIANTS)} restart variants at dx = {dx:g} m to {out}")
elif len(sys.argv) > 1:
    raise SystemExit(__doc__)
