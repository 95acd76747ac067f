#!/usr/bin/env bash
# Installs what is missing, builds, and runs the whole test suite through
# CTest: scripts/run-tests.sh [PRESET]  (dev by default; asan for sanitizers).
set -euo pipefail
cd "$(dirname "$0")/.."
preset=${1:-dev}
scripts/install-deps.sh
scripts/build.sh "$preset"
ctest --preset "$preset"
