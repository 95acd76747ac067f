#!/usr/bin/env bash
# Configures (once) and builds one CMake preset: scripts/build.sh [PRESET] [TARGET...]
# The build directory is build/PRESET and is reused between runs.
set -euo pipefail
cd "$(dirname "$0")/.."
preset=${1:-dev}
shift || true
if [ ! -f "build/$preset/CMakeCache.txt" ]; then
  cmake --preset "$preset"
fi
targets=()
for target in "$@"; do targets+=(--target "$target"); done
cmake --build --preset "$preset" "${targets[@]}"
