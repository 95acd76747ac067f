#!/usr/bin/env bash
# Starts the real GUI under a virtual X server, lets the simulator stream for
# a few seconds and saves the window as a PNG: scripts/screenshot-gui.sh [OUT.png]
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-build/dev/screenshots/gui-xvfb.png}
scripts/install-deps.sh
scripts/build.sh dev tactiscope
mkdir -p "$(dirname "$out")"
xvfb-run -a -s "-screen 0 1280x800x24" build/dev/app/tactiscope --screenshot "$out" --screenshot-delay-ms 4000
echo "screenshot-gui: saved $out"
