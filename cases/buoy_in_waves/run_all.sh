#!/bin/sh
# METHOD.md 6.2c: the tethered buoy in regular waves at T = 1, 2, 3 s (3D), one after the
# other, then the report of each (heave and surge in METHOD's non-dimensional form, mean
# surge offset, tether tension). Wall times measured at D/5 (docs/validation/buoy-in-waves.md,
# one thread each on a shared machine): T = 1 s 1.1 h, T = 2 s 1.8 h, T = 3 s about 3.6 h.
#   cases/buoy_in_waves/run_all.sh [BUILD_DIR] [OUT_DIR] [THREADS]
set -e
B="${1:-build}/app/moorsph"
OUT="${2:-runs/buoy_in_waves}"
THREADS="${3:-2}"
export OMP_WAIT_POLICY=passive
here="$(dirname "$0")"
for spec in "1 0.058 0.805" "2 0.04 0.808" "3 0.071 0.806"; do
  set -- $spec
  "$B" run "$here/buoy_waves_T$1.yaml" --threads "$THREADS" --out "$OUT/T$1"
  python3 "$here/buoy_waves_report.py" "$OUT/T$1" --period "$1" --amplitude "$2" --depth "$3" | tee "$OUT/T$1/report.txt"
done
