#!/bin/sh
# Session-16 study (docs/validation/wave-propagation.md, "Session 16"): the mirror-floor
# settings R of session 8 with a longer smoothing length (h = 2.5 dx, 3 dx), and a wave
# that starts in the water (initial_wave=1, no forcing) to tell the forcing's share of the
# loss from the propagation's. Each run also writes OUTDIR/<name>.csv.energy (kinetic,
# potential, elastic energy, horizontal momentum, fastest particle).
#
#   run_smoothing_length_study.sh BUILD_DIR OUTDIR [fine]
#
# One run after another on one thread: 3-6 wall minutes each at 5 per height; "fine" adds
# the two runs at ~10 per height over 10 wavelengths (40-100 minutes each). Then, per run:
#   python3 wave_heights.py decay OUTDIR/<name>.csv --t0 2.5    (initial-wave runs: --t0 0)
set -e
B="$1/cases/wave_propagation/moorsph_wave_tank"
OUT="$2"
mkdir -p "$OUT"
export OMP_WAIT_POLICY=passive OMP_NUM_THREADS=1
C="periodic amplitude=0.025 ramp_up=1 forcing_end=2.5"
run() { name="$1"; shift; echo "== $name: $*"; "$B" $C "$@" --out "$OUT/$name.csv" > "$OUT/$name.log"; }
R="density_diffusion=1 predictor_fraction=0.5 xsph_eps=0 dd_form=renormalised floor=mirror"
run h2 dx=0.01 $R h_factor=2 end=9
run h2_initial_wave dx=0.01 $R h_factor=2 end=9 initial_wave=1 theory=stokes2
run h2_no_viscosity dx=0.01 $R h_factor=2 end=9 no_viscosity=1
run h2_shifting dx=0.01 $R h_factor=2 end=9 shifting=1 shifting_coefficient=0.5
run h25 dx=0.01 $R h_factor=2.5 end=16     # 10 wavelengths travelled
run h3 dx=0.01 $R h_factor=3 end=9         # dx refitted to 11.1 mm (whole cells of 2h)
if [ "$3" = fine ]; then
  run h25_fine dx=0.005 $R h_factor=2.5 end=16   # 10 per height, 10,000 particles
  run h3_fine dx=0.005 $R h_factor=3 end=16      # dx refitted to 5.56 mm, 9 per height
fi
