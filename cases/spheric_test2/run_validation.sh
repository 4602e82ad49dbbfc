#!/usr/bin/env bash
# SPHERIC Test 2 validation: runs the scene at a coarse and a finer resolution and
# compares the water heights H1-H4 and the pressure P1 with the MARIN experiment
# (plots and tables into docs/validation/, see docs/validation/spheric-test2.md).
#
#   cases/spheric_test2/run_validation.sh            # from the repository root
#
# Environment (defaults): BUILD=build-spheric  DXS="0.04 0.025"  END=6.0  THREADS=2
#   RUNS=runs/spheric_test2  EXTRA="" (e.g. --density-diffusion)  SKIP_RUNS=1 (compare only)
# Wall time on the 2-core development machine (2 threads): about 8 min at dx = 0.04 and
# 25 min at dx = 0.025 for 6 s of simulated time.
set -euo pipefail
cd "$(dirname "$0")/../.."
BUILD=${BUILD:-build-spheric}
DXS=${DXS:-"0.04 0.025"}
END=${END:-6.0}
THREADS=${THREADS:-2}
RUNS=${RUNS:-runs/spheric_test2}
EXTRA=${EXTRA:-}
DATA=${DATA:-../shared/refdata/spheric_test2_kleefsman/test_case_2_exp_data.dat}
[ -f "$DATA" ] || DATA=/work/shared/refdata/spheric_test2_kleefsman/test_case_2_exp_data.dat

if [ ! -x "$BUILD/cases/spheric_test2/moorsph_spheric_test2" ]; then
  cmake -S . -B "$BUILD" -DCMAKE_BUILD_TYPE=Release
  cmake --build "$BUILD" --target moorsph_spheric_test2_run -j"$THREADS"
fi

dirs=()
for dx in $DXS; do
  out="$RUNS/dx$dx${EXTRA:+-dd}"
  dirs+=("$out")
  [ -n "${SKIP_RUNS:-}" ] && continue
  # The machine is shared: do not run alongside the throughput benchmark.
  while pgrep -f 'moorsph_benc[h]' >/dev/null; do echo "waiting for the benchmark to finish"; sleep 30; done
  echo "== dx = $dx m, $END s, $THREADS threads -> $out"
  OMP_WAIT_POLICY=passive "$BUILD/cases/spheric_test2/moorsph_spheric_test2" --dx "$dx" --end "$END" \
    --threads "$THREADS" --out "$out" $EXTRA
done

/usr/bin/python3 cases/spheric_test2/compare.py --data "$DATA" --plots docs/validation \
  --table docs/validation/spheric-test2-table.md "${dirs[@]}"
