#!/bin/sh
# Session-16 study (docs/validation/wave-propagation.md, "Session 16"): the mirror-floor
# settings R of session 8 with a longer smoothing length (h = 2.5 dx, 3 dx), a wave that
# starts in the water (initial_wave=1, no forcing) to tell the maker's share of the loss,
# and the predictor study that found the midpoint predictor's instability (session 18:
# the symplectic integrator's runs). Each run also
# writes OUTDIR/<name>.csv.energy (kinetic, potential, elastic energy, horizontal
# momentum, fastest particle): an instability shows there, not in the heights.
#
#   run_smoothing_length_study.sh BUILD_DIR OUTDIR [fine]
#
# One run after another on one thread: 2-8 wall minutes each at 4-5 per height; "fine"
# adds the runs at ~10 per height over 10 wavelengths (40-60 minutes each). Then:
#   python3 wave_heights.py decay OUTDIR/<name>.csv --t0 2.5    (initial-wave runs: --t0 0)
set -e
B="$1/cases/wave_propagation/moorsph_wave_tank"
OUT="$2"
mkdir -p "$OUT"
export OMP_WAIT_POLICY=passive OMP_NUM_THREADS=1
C="periodic amplitude=0.025 ramp_up=1 forcing_end=2.5"
run() { name="$1"; shift; echo "== $name: $*"; "$B" $C "$@" --out "$OUT/$name.csv" > "$OUT/$name.log"; }
R="density_diffusion=1 xsph_eps=0 dd_form=renormalised floor=mirror"
M="$R predictor_fraction=0.5"     # session 8: the midpoint predictor
S="$R predictor_fraction=0.55"    # session 16: the recommended settings
run h2 dx=0.01 $M h_factor=2 end=9
run h25 dx=0.01 $M h_factor=2.5 end=16     # 10 wavelengths travelled
run h3 dx=0.01 $M h_factor=3 end=9         # dx refitted to 11.1 mm (whole cells of 2h)
# The wave put in the water (h = 2 dx, to 7.5 s), one option changed at a time.
I="initial_wave=1 h_factor=2 end=7.5"
run init_midpoint dx=0.01 $M $I
run init_midpoint_c125 dx=0.0125 $M $I end=9
run init_walls dx=0.01 $M $I floor=walls
run init_fourtakas dx=0.01 $M $I dd_form=fourtakas
run init_euler dx=0.01 $M $I predictor_fraction=1
run init_cfl025 dx=0.01 $M $I cfl=0.25
run init_delta02 dx=0.01 $M $I dd_delta=0.2
run init_theta055 dx=0.01 $S $I
run init_theta060 dx=0.01 $R $I predictor_fraction=0.6
run init_theta055_c125 dx=0.0125 $S $I end=9
run init_symplectic_c125 dx=0.0125 $R integrator=symplectic $I end=9   # session 18
if [ "$3" = fine ]; then
  run h25_fine_midpoint dx=0.005 $M h_factor=2.5 end=12   # 10 per height; unstable from 7.5 s
  run h3_fine_midpoint dx=0.005 $M h_factor=3 end=14      # dx 5.56 mm, 9 per height; unstable from 10.5 s
  run h25_fine dx=0.005 $S h_factor=2.5 end=16
  run h3_fine dx=0.005 $S h_factor=3 end=16
  run h3_fine_theta052 dx=0.005 $R predictor_fraction=0.52 h_factor=3 end=16
  run h3_fine_delta02 dx=0.005 $M dd_delta=0.2 h_factor=3 end=16
  run h3_fine_symplectic dx=0.005 $R integrator=symplectic h_factor=3 end=16   # session 18
fi
