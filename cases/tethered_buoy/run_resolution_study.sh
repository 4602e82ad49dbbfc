#!/usr/bin/env bash
# Tethered lab buoy, vertical release (METHOD.md 6.2a), at four resolutions in the reduced
# tank (0.6 x 0.6 m, 0.5 m deep; docs/validation/tethered-buoy.md says what that economy
# costs): what accuracy costs (issue 8) and how the answer moves with dx (issue 5).
#   cases/tethered_buoy/run_resolution_study.sh [OUT=runs/buoy_resolution] [BUILD=build] [END=4] ["N ..." = "8 10 12 14"]
# (dx = D/N for each N; END is the simulated time after release [s])
# One CSV and one summary per run (finished runs are kept), then
# resolution_report.py writes OUT/report.md and OUT/report.png (heave against time at each
# dx; first overshoot, first trough and period against wall time, with the Richardson
# extrapolate of the three finest).
set -euo pipefail
cd "$(dirname "$0")/../.."
out=${1:-runs/buoy_resolution}
build=${2:-build}
end=${3:-4}
read -r -a spacings <<< "${4:-8 10 12 14}"
mkdir -p "$out"
export OMP_WAIT_POLICY=passive OMP_NUM_THREADS=${OMP_NUM_THREADS:-1}
D=0.203
names=()
for n in "${spacings[@]}"; do
  name=v_d${n}
  names+=("$name")
  [ -s "$out/$name.txt" ] && grep -q "^period_s=" "$out/$name.txt" && continue
  echo "== $name: D/$n, $OMP_NUM_THREADS thread(s)" >&2
  "$build/cases/tethered_buoy/moorsph_tethered_buoy" --release vertical --dx "$(echo "$D/$n" | bc -l)" \
    --length 0.6 --width 0.6 --depth 0.5 --end "$end" --csv "$out/$name.csv" > "$out/$name.txt"
done
/usr/bin/python3 cases/tethered_buoy/resolution_report.py "$out" "${names[@]}"
