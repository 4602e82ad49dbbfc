#!/usr/bin/env bash
# The Lobovsky et al. (2014) H = 300 mm dam break at several resolutions against the
# measured pressure at sensor 2 (issue 8: accuracy against cost):
#   cases/dam_break/run_lobovsky_study.sh BUILD OUT DX_LIST [THREADS [--set key=value ...]]
#   e.g. cases/dam_break/run_lobovsky_study.sh build runs/lobovsky 0.01,0.005 1
#        cases/dam_break/run_lobovsky_study.sh build runs/lobovsky_shift 0.005,0.0025 1 \
#          --set "effects=[pressure,viscosity,xsph,density_diffusion,particle_shifting,gravity,walls]"
#   (dx = 2.5 mm needs particle_shifting: docs/stability.md 3d2)
# writes under OUT/:
#   reference/lobovsky_p2_*.csv   the measured median and 2.5 / 97.5 % curves in SI units
#   study/runs/                   the runs (`moorsph study` reuses them across the metrics)
#   study_peak.{md,csv,png}       the first impact's peak (P2, interpolated, 34 ms
#                                 trailing mean, the median given the same mean) against the
#                                 median's: error against wall time and particles
#   study_time.*, study_plateau.*, study_rms.*   time of the peak, the plateau mean
#                                 (t/T 3.5-5.5), RMS against the median
#   report.md, report.png         both probe estimates against the band, per dx
set -euo pipefail
build=$1 out=$2 dxs=$3 threads=${4:-1}
shift $(($# < 4 ? $# : 4))
sets=("$@")  # extra `moorsph study` options
here=$(cd "$(dirname "$0")" && pwd)
scene="$here/lobovsky_h300_2d.yaml"
export OMP_WAIT_POLICY=passive
mkdir -p "$out"
# The probes' moving mean (4 H / c_s, from the scene) given to the median as well.
width=$(/usr/bin/python3 -c "import yaml; print(yaml.safe_load(open('$scene'))['pressure_probes'][1]['moving_mean'])")
/usr/bin/python3 "$here/lobovsky_report.py" reference "$out/reference" "$width"
ref="$out/reference/lobovsky_p2_median_mean.csv"
T=$(/usr/bin/python3 -c "import math; print(math.sqrt(0.3 / 9.81))")
at() { /usr/bin/python3 -c "print('%.6f' % ($1 * $T))"; }
study() {  # study NAME METRIC FROM TO: one metric on probe P2 over t/T in [FROM, TO]
  "$build/app/moorsph" study "$scene" --dx "$dxs" --metric "$2" --series probes/P2_interpolated_mean \
    --reference "$ref" --from "$(at "$3")" --to "$(at "$4")" --threads "$threads" --out "$out/study" --reuse "${sets[@]}"
  for ext in md csv png; do cp "$out/study/study.$ext" "$out/$1.$ext"; done
}
study study_peak max_value 1.8 3.2
study study_time time_of_max 1.8 3.2
study study_plateau mean_value 3.5 5.5
study study_rms gauge_rms 1.8 7.0
/usr/bin/python3 "$here/lobovsky_report.py" report --out "$out/report" "$out/study/runs/"*/
