#!/bin/sh
# Wave-maker calibration (METHOD.md 6.3, docs/validation/wave-maker.md): generated vs
# requested height of the 2D forcing region in a periodic tank, depth 0.8 m,
# T = 1 s (3 wavelengths = 4.67 m) and T = 3 s (1 wavelength = 7.90 m), over
# amplitudes 7, 9, 11 cm, kappa 6.5, 7, 7.5 and maker lengths 1.0, 1.5, 2.0 m.
#
#   run_wave_maker_calibration.sh BUILD_DIR OUTDIR DX [END] [SUBSET] [KEY=VALUE...]
#
# DX is 0.01 or 0.005 in METHOD.md 6.3 (37,000 / 150,000 particles at T = 1 s:
# hours per point on one core); SUBSET=quick runs only T = 1 s, a = 7 cm, kappa
# 6.5/7/7.5, L_w = 1.5 m. Each run writes OUTDIR/<name>.csv and prints, per gauge,
# H and H/H_requested over its last three periods (moorsph_wave_tank); gauges stand
# outside the maker, every 0.25 wavelength of the free part. KEY=VALUE pairs after
# SUBSET go to every run (e.g. density_diffusion=1, which dx = 10 mm needs).
set -e
B="$1/cases/wave_propagation/moorsph_wave_tank"
OUT="$2"
DX="$3"
END="${4:-12}"
SUBSET="${5:-all}"
if [ $# -gt 5 ]; then shift 5; else shift $#; fi
EXTRA="$*"  # key=value pairs hold no spaces
mkdir -p "$OUT"
export OMP_WAIT_POLICY=passive
run() {  # name period wavelengths amplitude kappa maker_length gauges
  echo "== $1"
  "$B" periodic dx="$DX" depth=0.8 period="$2" wavelengths="$3" amplitude="$4" kappa="$5" \
    maker_start=0 maker_length="$6" ramp_up="$2" end="$END" gauges="$7" window=3 $EXTRA --out "$OUT/$1.csv" \
    | tee "$OUT/$1.log"
}
G1=2.5,2.9,3.3,3.7,4.1   # T = 1 s: beyond a 2 m maker, a quarter wavelength apart
G3=2.5,4.5,6.5           # T = 3 s
if [ "$SUBSET" = quick ]; then
  for k in 6.5 7 7.5; do run "T1_a7_k${k}_L1.5" 1 3 0.07 "$k" 1.5 "$G1"; done
  exit 0
fi
for a in 0.07 0.09 0.11; do
  for k in 6.5 7 7.5; do
    for L in 1.0 1.5 2.0; do
      run "T1_a${a}_k${k}_L${L}" 1 3 "$a" "$k" "$L" "$G1"
      run "T3_a${a}_k${k}_L${L}" 3 1 "$a" "$k" "$L" "$G3"
    done
  done
done
