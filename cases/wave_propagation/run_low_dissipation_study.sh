#!/bin/sh
# Session-7 wave propagation study (docs/validation/wave-propagation.md, "Session 7"):
# the periodic tank of run_decay_study.sh to t = 6 s, the reference against h = 2 dx
# with the midpoint predictor, no XSPH and Fourtakas (F) or renormalised (R) density
# diffusion, at 5 and 10 particles per wave height, plus the single-option variations.
#
#   run_low_dissipation_study.sh BUILD_DIR OUTDIR [fine]
#
# One run after another on one thread: 0.5-2 wall minutes each at dx = 10 mm; with
# "fine" also the 10-per-height runs (dx = 5 mm, 4-13 minutes each).
# Then: python3 wave_heights.py decay OUTDIR/<name>.csv --t0 2.5
set -e
B="$1/cases/wave_propagation/moorsph_wave_tank"
OUT="$2"
mkdir -p "$OUT"
export OMP_WAIT_POLICY=passive OMP_NUM_THREADS=1
C="periodic amplitude=0.025 ramp_up=1 forcing_end=2.5 end=6"
run() { name="$1"; shift; echo "== $name: $*"; "$B" $C "$@" --out "$OUT/$name.csv" > "$OUT/$name.log"; }
F="density_diffusion=1 predictor_fraction=0.5 xsph_eps=0 h_factor=2"
R="$F dd_form=renormalised"
run ref dx=0.01
run dd_fourtakas dx=0.01 density_diffusion=1
run dd_renormalised dx=0.01 density_diffusion=1 dd_form=renormalised
run h2_no_dd dx=0.01 xsph_eps=0 h_factor=2
run h2_dd dx=0.01 density_diffusion=1 h_factor=2
run h2_dd_midpoint dx=0.01 density_diffusion=1 h_factor=2 predictor_fraction=0.5
run F dx=0.01 $F
run F_half_height dx=0.01 $F amplitude=0.0125
run F_delta005 dx=0.01 $F dd_delta=0.05
run F_delta02 dx=0.01 $F dd_delta=0.2
run F_wall005 dx=0.01 $F boundary_strength=0.005
run F_wall02 dx=0.01 $F boundary_strength=0.02
run F_deep dx=0.01 $F depth=0.5 period=0.8
run R dx=0.01 $R
run R_euler dx=0.01 $R predictor_fraction=1
run R_h25 dx=0.01 $R h_factor=2.5
run R_deep dx=0.01 $R depth=0.5 period=0.8
if [ "$3" = fine ]; then
  run ref_fine dx=0.005
  run F_fine dx=0.005 $F
  run R_fine dx=0.005 $R
  run R_h25_fine dx=0.005 $R h_factor=2.5
fi
