#!/usr/bin/env bash
# A bounded libFuzzer run of one target from its kept corpus; the test
# command runs the store target's after the suite (fuzz/README.md).
#   scripts/fuzz-bounded.sh [TARGET] [SECONDS]   (store, 60 by default)
# Builds only that target of the fuzz preset (clang, AddressSanitizer),
# fuzzes into a scratch folder seeded from fuzz/corpus/TARGET, and exits 1
# with the crashing input kept in build/fuzz/findings/ when libFuzzer finds
# anything. Inputs it grew are not kept: merging them into the corpus is a
# deliberate step (fuzz/README.md).
set -euo pipefail
cd "$(dirname "$0")/.."
target=${1:-store}
seconds=${2:-60}
scripts/build.sh fuzz "tactiscope_fuzz_$target"
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
mkdir -p build/fuzz/findings
# max_len: the store seeds are whole SQLite files of about 100 KiB.
"build/fuzz/fuzz/tactiscope_fuzz_$target" "$scratch" "fuzz/corpus/$target" \
  -max_total_time="$seconds" -max_len=131072 -timeout=30 -rss_limit_mb=2048 \
  -artifact_prefix=build/fuzz/findings/ -print_final_stats=1
