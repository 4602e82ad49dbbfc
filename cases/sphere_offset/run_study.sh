#!/usr/bin/env bash
# Boundary-offset study, fully submerged sphere (METHOD.md 6.1): eps_R against b_off for
# fluid spacings 20 and 10 mm and boundary spacings dx and dx/2, plus a check that the
# reduced tank does not change the answer. Writes one line per run to stdout.
# Usage: cases/sphere_offset/run_study.sh [build dir] | tee docs/validation/sphere-offset-raw.txt
# (about 40 minutes on 2 cores; the figures in docs/validation/sphere-offset.md at dx = 10 mm
# used --end 0.6 --average-from 0.3, which sloshing biases by up to 0.1 dx)
set -uo pipefail
bin="${1:-build}/cases/sphere_offset/moorsph_sphere_offset"
export OMP_WAIT_POLICY=passive
for dx in 0.02 0.01; do
  for ratio in 1 0.5; do
    bs=$(awk -v a="$dx" -v b="$ratio" 'BEGIN { print a * b }')
    for boff in 0.0 0.2 0.4 0.5 0.6; do
      "$bin" --dx "$dx" --boundary-spacing "$bs" --b-off "$boff" --end 1.5 --average-from 0.5 || echo "dx=$dx boundary_spacing=$bs b_off=$boff FAILED (see the diagnostic above)"
    done
  done
done
# Tank size: the reference tank (0.4 m wide, 0.4 m deep) against the reduced one, dx = 20 mm.
"$bin" --dx 0.02 --b-off 0.5 --tank 0.40 --depth 0.40 --end 1.5 --average-from 0.5
