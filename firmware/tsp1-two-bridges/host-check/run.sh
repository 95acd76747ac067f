#!/usr/bin/env bash
# Compiles the sketch's framing and command handling on this PC (with the
# stand-in Arduino.h beside this script) and checks them against the worked
# examples of docs/protocol.md. Not part of the test suite: the sketch is a
# reference for firmware authors, and its ADC code needs the board.
set -euo pipefail
cd "$(dirname "$0")"
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
g++ -std=c++17 -Wall -Wextra -I. -include Arduino.h -x c++ check.cpp -o "$out/check"
"$out/check"
