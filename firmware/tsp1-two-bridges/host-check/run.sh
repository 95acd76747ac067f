#!/usr/bin/env bash
# Compiles the sketch's framing, command handling and detector on this PC
# (with the stand-in Arduino.h beside this script and the probe detector's
# C file) and checks them against the worked examples of docs/protocol.md
# and against the kernel run directly. Part of the test suite
# (reference-sketch); the ADC code itself needs the board.
set -euo pipefail
cd "$(dirname "$0")"
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
gcc -std=c99 -O2 -Wall -Wextra -Werror -ffp-contract=off -c ../src/probe_detector.c -o "$out/probe_detector.o"
g++ -std=c++17 -O2 -Wall -Wextra -Werror -ffp-contract=off -I. -include Arduino.h -x c++ check.cpp -x none \
  "$out/probe_detector.o" -o "$out/check" -lm
"$out/check"
