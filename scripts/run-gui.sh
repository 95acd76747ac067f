#!/usr/bin/env bash
# Installs what is missing, builds, and starts the Tactiscope workstation
# streaming from the built-in simulator (no hardware needed).
# Extra arguments go to the program, e.g. --help.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh dev tactiscope
if [ -z "${DISPLAY:-}" ] && [ -z "${WAYLAND_DISPLAY:-}" ] && [ -z "${QT_QPA_PLATFORM:-}" ]; then
  echo "run-gui: no display (DISPLAY and WAYLAND_DISPLAY are unset)." >&2
  echo "run-gui: on a headless machine, try: xvfb-run -a scripts/run-gui.sh" >&2
  exit 1
fi
exec build/dev/app/tactiscope "$@"
