#!/usr/bin/env bash
# Installs what is missing, builds, and runs the whole test suite through
# CTest: scripts/run-tests.sh [PRESET]  (dev by default; asan for sanitizers).
# Then the store files' fuzz target runs for a bounded time
# (TACTISCOPE_FUZZ_SECONDS, 60 by default; 0 leaves it out).
set -euo pipefail
cd "$(dirname "$0")/.."
preset=${1:-dev}
scripts/install-deps.sh
scripts/build.sh "$preset"
ctest --preset "$preset"
fuzz_seconds=${TACTISCOPE_FUZZ_SECONDS:-60}
if [ "$fuzz_seconds" -gt 0 ]; then
  scripts/fuzz-bounded.sh store "$fuzz_seconds"
fi
