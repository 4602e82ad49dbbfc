#!/usr/bin/env bash
# Install, build and run moorsph. Without arguments it runs the built-in demo scene.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh > /dev/null
exec ./build/app/moorsph "$@"
