#!/usr/bin/env bash
# The detector under mains hum (docs/detector.md, "Under mains hum"): for
# each hum (common[,differential], in strain), five seeds of the simulated
# panel line, each detected as it is and through the causal 50 Hz notch.
# Prints per seed: events found (of the clean scan's) and the first site's
# place in mm. Usage: bench/detector-under-hum.sh [path/to/tactiscope-cli]
set -euo pipefail
cli=${1:-"$(dirname "$0")/../build/dev/app/tactiscope-cli"}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
found() {
  python3 -c 'import json, sys
d = json.load(sys.stdin); s = d["sites"]
print(len(d["events"]), "%.2f" % s[0]["position_mm"] if s else "-")'
}
for hum in 0.5e-6 1e-6 2e-6 5e-6 20e-6 0,5e-6 20e-6,5e-6; do
  for seed in 1 2 3 4 5; do
    "$cli" simulate --scenario panel-line --seconds 20 --seed "$seed" --output "$work/clean.csv"
    "$cli" simulate --scenario panel-line --seconds 20 --seed "$seed" --hum "$hum" --output "$work/hum.csv"
    clean=$("$cli" detect "$work/clean.csv" --position x --json | found)
    raw=$("$cli" detect "$work/hum.csv" --position x --json | found)
    notched=$("$cli" detect "$work/hum.csv" --position x --notch 50 --json | found)
    echo "hum $hum seed $seed: clean $clean | hum $raw | notched $notched"
  done
done
