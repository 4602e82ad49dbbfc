#!/usr/bin/env bash
# Install, build and run the default test suite (labels `fast` and `stability`).
# Other labels: `stability`, `slow`, `validation` (e.g. scripts/test.sh -L slow).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
export OMP_WAIT_POLICY=passive
cd build
if [ $# -eq 0 ]; then set -- -L "fast|stability"; fi
# Tests run side by side, one per core: each test reserves the cores its THREADS takes
# (cmake/MoorsphTesting.cmake), most one, so none is oversubscribed.
ctest --output-on-failure -j"$(nproc)" "$@"
