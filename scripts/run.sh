#!/usr/bin/env bash
# Install, build and run moorsph. Without arguments it runs the built-in demo scene.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh > /dev/null
# Idle OpenMP threads must sleep, not spin: on a loaded 2-core machine spinning made
# 2 threads many times slower than 1.
export OMP_WAIT_POLICY="${OMP_WAIT_POLICY:-passive}"
exec ./build/app/moorsph "$@"
