#!/usr/bin/env bash
# SPHERIC Test 2 validation: runs the scene at a coarse and a finer resolution and
# compares the water heights H1-H4 and the pressure P1 with the MARIN experiment
# (plots and tables into docs/validation/, see docs/validation/spheric-test2.md).
#
#   cases/spheric_test2/run_validation.sh            # from anywhere in the repository
#
# Environment (defaults): BUILD=build-spheric  END=6.0  THREADS=2  RUNS=runs/spheric_test2
#   CONFIGS: space-separated name:dx[:flag,flag...[:end]] (flags: density-diffusion,
#            xsph-monaghan; end [s] overrides END for that run)
#   SKIP_RUNS=1: compare the existing runs only.
# The default set (what docs/validation/spheric-test2.md reports; about 40 min of wall
# time on the 2-core development machine when it is not shared):
#   dx0.04-ref        the reference method (METHOD.md) at dx = 0.04 m (stops at 1.16 s)
#   dx0.04-dd         + density diffusion
#   dx0.04-dd-mxsph   + density diffusion + Monaghan's XSPH form, to 1.5 s (arrival times)
#   dx0.0275-dd       + density diffusion at dx = 0.0275 m (0.55 m / 20)
set -uo pipefail
cd "$(dirname "$0")/../.."
BUILD=${BUILD:-build-spheric}
END=${END:-6.0}
THREADS=${THREADS:-2}
RUNS=${RUNS:-runs/spheric_test2}
CONFIGS=${CONFIGS:-"dx0.04-ref:0.04 dx0.04-dd:0.04:density-diffusion dx0.04-dd-mxsph:0.04:density-diffusion,xsph-monaghan:1.5 dx0.0275-dd:0.0275:density-diffusion"}
DATA=${DATA:-../shared/refdata/spheric_test2_kleefsman/test_case_2_exp_data.dat}
[ -f "$DATA" ] || DATA=/work/shared/refdata/spheric_test2_kleefsman/test_case_2_exp_data.dat

if [ ! -x "$BUILD/cases/spheric_test2/moorsph_spheric_test2" ]; then
  cmake -S . -B "$BUILD" -DCMAKE_BUILD_TYPE=Release || exit 1
  cmake --build "$BUILD" --target moorsph_spheric_test2_run -j"$THREADS" || exit 1
fi

dirs=()
for config in $CONFIGS; do
  IFS=: read -r name dx flags end <<<"$config"
  end=${end:-$END}
  out="$RUNS/$name"
  dirs+=("$out")
  [ -n "${SKIP_RUNS:-}" ] && continue
  args=()
  for f in ${flags//,/ }; do args+=("--$f"); done
  # The machine is shared: do not run alongside the throughput benchmark.
  while pgrep -f 'moorsph_benc[h]' >/dev/null; do echo "waiting for the benchmark to finish"; sleep 30; done
  echo "== $name: dx = $dx m, $end s, $THREADS threads ${args[*]:-} -> $out"
  OMP_WAIT_POLICY=passive "$BUILD/cases/spheric_test2/moorsph_spheric_test2" --dx "$dx" --end "$end" \
    --threads "$THREADS" --out "$out" "${args[@]}" || echo "   ($name stopped early: see $out/run.txt)"
done

/usr/bin/python3 cases/spheric_test2/compare.py --common-window --data "$DATA" --plots docs/validation \
  --table docs/validation/spheric-test2-table.md "${dirs[@]}"
