#!/usr/bin/env bash
# Brings the store fuzzer's corpus (fuzz/corpus/store) to this build's
# store version: run it at every store-version change (FuzzCorpusReplay's
# EveryStoreSeedIsAtTheCurrentVersion fails until then), and after merging
# a fuzz run's grown inputs into the corpus.
#   fuzz/make-store-seeds.sh
# The hand-made seeds (seed-*) are written anew by tactiscope_make_store_seeds;
# every other file (inputs a run grew) is updated in place by
# `tactiscope-cli sessions upgrade`, and removed when it is not a store this
# build reads past the version check (a mutation of the header, a
# truncated file): a seed that stops at the version check only tests the
# refusal.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh dev tactiscope_make_store_seeds tactiscope-cli
corpus=fuzz/corpus/store
build/dev/fuzz/tactiscope_make_store_seeds "$corpus"
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
kept=0 removed=0
for file in "$corpus"/*; do
  case "$(basename "$file")" in seed-*) continue ;; esac
  cp "$file" "$scratch/store"
  rm -f "$scratch/store-wal" "$scratch/store-shm"
  if build/dev/app/tactiscope-cli sessions --db "$scratch/store" upgrade >/dev/null 2>&1 &&
     [ ! -s "$scratch/store-wal" ]; then
    cp "$scratch/store" "$file"
    kept=$((kept + 1))
  else
    git rm -q --cached "$file" 2>/dev/null || true
    rm -f "$file"
    removed=$((removed + 1))
  fi
done
echo "seeds written; grown inputs: $kept updated, $removed removed (not a store read past the version check)"
