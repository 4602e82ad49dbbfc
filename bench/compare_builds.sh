#!/usr/bin/env bash
# A/B throughput of two builds of the benchmark, run in turn so that both see the same
# machine state (two vCPUs do not always deliver two cores: docs/performance.md).
# Prints one line per run: label, case, threads, particle-steps/s and the phase split.
# Usage: bench/compare_builds.sh OLD_BIN NEW_BIN [repeats] [cases...]
#   a case is DIM:PARTICLES:STEPS (default 3:50000:160 3:250000:32 2:250000:32)
# e.g. bench/compare_builds.sh /tmp/old/bench/moorsph_bench_throughput build/bench/moorsph_bench_throughput 2
set -euo pipefail
old=$1 new=$2 repeats=${3:-2}
shift $(( $# < 3 ? $# : 3 ))
cases=("$@")
[ ${#cases[@]} -eq 0 ] && cases=(3:50000:160 3:250000:32 2:250000:32)
export OMP_WAIT_POLICY=passive OMP_PROC_BIND=false
for spec in "${cases[@]}"; do
  IFS=: read -r dim n steps <<< "$spec"
  for threads in 1 2; do
    for ((k = 0; k < repeats; ++k)); do
      for label in old new; do
        bin=$old; [ "$label" = new ] && bin=$new
        out=$(OMP_NUM_THREADS=$threads "$bin" "$dim" "$n" "$steps" | tr '\n' ' ')
        rate=$(sed -E 's/.*particle_steps_per_s=([^ ]+).*/\1/' <<< "$out")
        phases=$(sed -E 's/.*phases: (.*)/\1/' <<< "$out")
        echo "$label ${dim}D n=$n threads=$threads particle_steps_per_s=$rate $phases"
      done
    done
  done
done
