#!/bin/sh
# Session-8 study (docs/validation/wave-propagation.md, "Session 8"): the low-dissipation
# settings R (h = 2 dx, midpoint predictor, no XSPH, renormalised density diffusion) with
# the floor as mirror images (floor=mirror) instead of a row of wall particles, in the
# periodic tank of run_low_dissipation_study.sh, plus the single-option checks.
#
#   run_mirror_floor_study.sh BUILD_DIR OUTDIR [fine]
#
# One run after another on one thread: 2-7 wall minutes each at 5 per height; "fine" adds
# the 10-per-height run (~20 minutes). Then, per run:
#   python3 wave_heights.py decay OUTDIR/<name>.csv --t0 2.5
# The flume runs are scenes: moorsph run cases/piston_flume_2d_low_dissipation.yaml
# (mirror floor, wall law on 1.2 dx) with 12 gauges to 10 s, as in the doc.
set -e
B="$1/cases/wave_propagation/moorsph_wave_tank"
OUT="$2"
mkdir -p "$OUT"
export OMP_WAIT_POLICY=passive OMP_NUM_THREADS=1
C="periodic amplitude=0.025 ramp_up=1 forcing_end=2.5 end=6"
run() { name="$1"; shift; echo "== $name: $*"; "$B" $C "$@" --out "$OUT/$name.csv" > "$OUT/$name.log"; }
R="density_diffusion=1 predictor_fraction=0.5 xsph_eps=0 h_factor=2 dd_form=renormalised"
run R_walls dx=0.01 $R
run R_mirror dx=0.01 $R floor=mirror
run R_mirror_cs2 dx=0.01 $R floor=mirror sound_speed=44.4
run R_mirror_cfl25 dx=0.01 $R floor=mirror cfl=0.25
run R_mirror_delta02 dx=0.01 $R floor=mirror dd_delta=0.2
run R_mirror_delta005 dx=0.01 $R floor=mirror dd_delta=0.05
run R_mirror_stokes2 dx=0.01 $R floor=mirror theory=stokes2
run R_mirror_long dx=0.01 $R floor=mirror end=16   # 10 wavelengths travelled
run R_mirror_half dx=0.01 $R floor=mirror amplitude=0.0125
run R_mirror_deep dx=0.01 $R floor=mirror depth=0.5 period=0.8
if [ "$3" = fine ]; then
  run R_mirror_fine dx=0.005 $R floor=mirror
fi
