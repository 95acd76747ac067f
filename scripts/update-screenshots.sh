#!/usr/bin/env bash
# Regenerates the screenshots of the documentation (docs/screenshots/): the
# UI tests that drive each mode against the live simulator save what they
# show there. Look at every one before committing them.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh dev tactiscope_ui_tests
mkdir -p docs/screenshots
TACTISCOPE_SCREENSHOT_DIR="$PWD/docs/screenshots" QT_QPA_PLATFORM=offscreen \
  build/dev/tests/tactiscope_ui_tests \
  --gtest_filter='PanelScanView.Defects*:PalpationView.Presses*:CapacitiveView.Readouts*:DevicePanel.TheEmulator*:Recording.Sessions*:SensorProfileDialogTest.Lists*'
echo "update-screenshots: docs/screenshots/ regenerated"
ls docs/screenshots
