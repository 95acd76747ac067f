#!/usr/bin/env bash
# A bounded libFuzzer run of one target from its kept corpus; the test
# command runs the store target's after the suite (fuzz/README.md).
#   scripts/fuzz-bounded.sh [TARGET] [SECONDS]   (store, 60 by default)
# Builds only that target of the fuzz preset (clang, AddressSanitizer),
# fuzzes into a scratch folder seeded from fuzz/corpus/TARGET, and exits 1
# with the crashing input kept in build/fuzz/findings/ when libFuzzer finds
# anything. Inputs it grew are not kept: merging them into the corpus is a
# deliberate step (fuzz/README.md). It prints the edges the kept seeds
# reach before fuzzing, and fails when they reach more than 5 % fewer than
# fuzz/seed-coverage.txt records for the target (seeds that stop at a
# version check, say, or an entry point that stopped reading).
set -euo pipefail
cd "$(dirname "$0")/.."
target=${1:-store}
seconds=${2:-60}
scripts/build.sh fuzz "tactiscope_fuzz_$target"
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
mkdir -p build/fuzz/findings
# max_len: the store seeds are whole SQLite files of about 100 KiB.
log="$scratch/log"
status=0
"build/fuzz/fuzz/tactiscope_fuzz_$target" "$scratch" "fuzz/corpus/$target" \
  -max_total_time="$seconds" -max_len=131072 -timeout=30 -rss_limit_mb=2048 \
  -artifact_prefix=build/fuzz/findings/ -print_final_stats=1 2>&1 | tee "$log" || status=$?
[ "$status" -eq 0 ] || exit "$status"
reached=$(sed -n 's/.*INITED cov: \([0-9]*\).*/\1/p' "$log" | head -n 1)
floor=$(awk -v t="$target" '$1 == t { print $2 }' fuzz/seed-coverage.txt)
echo "fuzz-bounded: the $target seeds reach ${reached:-no} edges (recorded: ${floor:-none})"
if [ -n "$floor" ] && [ -z "$reached" -o "${reached:-0}" -lt $((floor * 95 / 100)) ]; then
  echo "fuzz-bounded: the $target seeds reach fewer edges than recorded in fuzz/seed-coverage.txt;" \
    "rerun fuzz/make-store-seeds.sh for the store, or see fuzz/README.md" >&2
  exit 1
fi
