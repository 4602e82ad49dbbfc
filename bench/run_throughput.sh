#!/usr/bin/env bash
# Throughput sweep: 2D and 3D dam breaks at ~50k, 250k, 1M particles, 1 and 2
# threads. Prints one line per configuration plus the parallel efficiency.
# Usage: bench/run_throughput.sh [build dir]   (takes ~10 minutes on 2 cores)
set -euo pipefail
build=${1:-build}
bin="$build/bench/moorsph_bench_throughput"
export OMP_WAIT_POLICY=passive OMP_PROC_BIND=false
for dim in 3 2; do
  for n in 50000 250000 1000000; do
    steps=$(( 8000000 / n )); [ "$steps" -lt 6 ] && steps=6
    r1=$(OMP_NUM_THREADS=1 "$bin" "$dim" "$n" "$steps"); echo "$r1"
    r2=$(OMP_NUM_THREADS=2 "$bin" "$dim" "$n" "$steps"); echo "$r2"
    p1=$(sed -E 's/.*particle_steps_per_s=([^ ]+).*/\1/' <<< "$r1")
    p2=$(sed -E 's/.*particle_steps_per_s=([^ ]+).*/\1/' <<< "$r2")
    awk -v a="$p1" -v b="$p2" -v d="$dim" -v n="$n" 'BEGIN { printf "%dD ~%d particles: parallel efficiency (2 threads) = %.2f\n", d, n, b / (2 * a) }'
  done
done
