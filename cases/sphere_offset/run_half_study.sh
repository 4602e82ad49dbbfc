#!/usr/bin/env bash
# Boundary-offset study, half-submerged sphere held at the still level (METHOD.md 6.1):
# buoyancy and eps_R against b_off for fluid spacings 20 and 10 mm, boundary spacing dx
# (and dx/2 at 20 mm), one thread per run. Writes one line per run to stdout.
# Usage: cases/sphere_offset/run_half_study.sh [build dir] | tee docs/validation/sphere-offset-half-raw.txt
# (20 mm: about 30 s a run; 10 mm: about 5 minutes a run on one thread of a shared machine)
set -uo pipefail
bin="${1:-build}/cases/sphere_offset/moorsph_sphere_offset"
export OMP_WAIT_POLICY=passive OMP_NUM_THREADS="${OMP_NUM_THREADS:-1}"
run() { "$bin" --half 1 "$@" || echo "half $* FAILED (see the diagnostic above)"; }
for boff in 0.4 0.5 0.6; do run --dx 0.02 --b-off "$boff" --end 2.0 --average-from 0.5; done
for boff in 0.4 0.5 0.6; do run --dx 0.02 --b-off "$boff" --end 1.5 --average-from 0.5; done
for boff in 0.4 0.5 0.6; do run --dx 0.02 --boundary-spacing 0.01 --b-off "$boff" --end 2.0 --average-from 0.5; done
for boff in 0.4 0.5 0.6; do run --dx 0.01 --b-off "$boff" --end 1.5 --average-from 0.5; done
