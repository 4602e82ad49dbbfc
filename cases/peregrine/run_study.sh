#!/usr/bin/env bash
# A cases/peregrine scene at several resolutions (METHOD.md 6.4, issue 6 item 3):
#   cases/peregrine/run_study.sh BUILD OUT SCENE DX_LIST [THREADS [--set key=value ...]]
#   e.g. cases/peregrine/run_study.sh build /tmp/peregrine cases/peregrine/peregrine_o1_reduced.yaml 0.0125,0.01 1
#        cases/peregrine/run_study.sh build /tmp/pfd cases/peregrine/peregrine_o2_reduced.yaml 0.01 1 \
#          --set piston.signal.finite_depth_correction=true
# writes under OUT/<scene name>/:
#   signal_theory_x<d>.csv  the breather's theoretical surface at each gauge (d m from the piston)
#   study/                  `moorsph study`: RMS error at the focus gauge G1 against theory over
#                           the event (focus_time - 6 s to the end) against wall time and particles
#                           (study.md, study.csv, study.png; the runs in study/runs/, reused when
#                           their resolved scene is unchanged)
#   report.md, report.png   every gauge: crest / a0, envelope arrival, group speed, RMS error,
#                           the carrier before the event, and the series with the theory overlaid
set -euo pipefail
build=$1 out=$2 scene=$3 dxs=$4 threads=${5:-1}
shift $(($# < 5 ? $# : 5))
sets=("$@")  # extra `moorsph study` options, e.g. --set piston.signal.finite_depth_correction=true
here=$(cd "$(dirname "$0")" && pwd)
name=$(basename "$scene" .yaml)
dir="$out/$name"
mkdir -p "$dir"
export OMP_WAIT_POLICY=passive
# The breather, its focus and the gauges' distances from the piston, from the scene itself.
read -r order a0 k0 xf tf depth ramp end dists < <(/usr/bin/python3 - "$scene" <<'PY'
import sys, yaml
s = yaml.safe_load(open(sys.argv[1]))
p, sig = s["piston"], s["piston"]["signal"]
d = ",".join("%g" % round(g["x"] - p["x"], 6) for g in s["gauges"])
print(sig.get("order", 1), sig["a0"], sig["k0"], sig["focus_distance"], sig["focus_time"], sig["depth"],
      sig.get("ramp_up", 0), s["end_time"], d)
PY
)
"$build/cases/ship/moorsph_breather_signal" --order "$order" --a0 "$a0" --k0 "$k0" --focus-distance "$xf" \
  --focus-time "$tf" --depth "$depth" --ramp "$ramp" --duration "$(/usr/bin/python3 -c "print(2 * $tf)")" --dt 0.01 \
  --out "$dir/signal.csv" --theory-at "$dists" --theory-level "$depth" > "$dir/signal.txt"
from=$(/usr/bin/python3 -c "print($tf - 6)")
if [[ "$dxs" == *,* ]]; then
  "$build/app/moorsph" study "$scene" --dx "$dxs" --metric gauge_rms --series gauges/G1 \
    --reference "$dir/signal_theory_x$(/usr/bin/python3 -c "print('%g' % $xf)").csv" --from "$from" --to "$end" \
    --threads "$threads" --out "$dir/study" --reuse "${sets[@]}"
else  # one spacing: a plain run where the study would put it (a study needs two)
  run_dir="$dir/study/runs/dx$dxs"
  [ -s "$run_dir/series.h5" ] && grep -q "^simulated " "$run_dir/log.txt" 2>/dev/null ||
    "$build/app/moorsph" run "$scene" --set "resolution.dx=$dxs" --set "resolution.boundary_spacing=$dxs" \
      "${sets[@]}" --threads "$threads" --out "$run_dir"
fi
/usr/bin/python3 "$here/peregrine_report.py" --out "$dir/report" --theory-stem "$dir/signal" "$dir/study/runs/"*/
