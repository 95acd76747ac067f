#!/usr/bin/env bash
# Regenerates the screenshots of the documentation (docs/screenshots/): the
# UI tests that drive each mode against the live simulator save what they
# show there, at 100 % and at 200 % scaling (docs/screenshots/200-percent/).
# Look at every one before committing them.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh dev tactiscope_ui_tests tactiscope_cli_tests
mkdir -p docs/screenshots
# The offscreen platform's own screen is 800 × 600, and windows open within
# the screen they are on: the pictures are taken on a 1920 × 1080 screen,
# and on a 3840 × 2160 one at 200 %.
screens=$(mktemp -d)
trap 'rm -rf "$screens"' EXIT
for size in 1920x1080 3840x2160; do
  cat > "$screens/$size.json" <<EOF
{"screens": [{"name": "screen", "x": 0, "y": 0, "width": ${size%x*}, "height": ${size#*x},
              "logicalDpi": 96, "logicalBaseDpi": 96, "dpr": 1}]}
EOF
done
views='PanelScanView.Defects*:PalpationView.Presses*:CapacitiveView.Readouts*:DevicePanel.TheEmulator*:Recording.Sessions*:SensorProfileDialogTest.Lists*:DesignTool.Curves*:GaugeFactorWizardTest.Completed*:GaugeFactorWizardTest.AMislabelled*:CapacitiveWizardTest.LoadAndUnload*:CapacitiveSweepWizardTest.Calibrates*:CalibrationHistoryTest.Shows*:SessionBrowserTest.ListsEvery*:SessionBrowserTest.DeleteAsks*:ReviewWindowTest.Reanalysis*:ReviewWindowTest.AReviewersVerdict*:ReviewPalpation.*:ReviewCapacitive.*:ModeAndSource.AMode*:CentralStoreUi.*:LiveListsView.*:ReviewGeneral.*:ReviewDevices.*:OtherDevices.*:ReviewProbe.*:HelpWindows.TheShortcuts*:ReviewGeometry.*:HandsFree.*:ShuntCheck.The*:SignalViews.*'
TACTISCOPE_SCREENSHOT_DIR="$PWD/docs/screenshots" QT_QPA_PLATFORM="offscreen:configfile=$screens/1920x1080.json" \
  build/dev/tests/tactiscope_ui_tests --gtest_filter="$views"
# The same views at 200 % scaling (a 4K screen, or a 2732×1536 laptop):
# nothing may be clipped or overflow there either.
mkdir -p docs/screenshots/200-percent
TACTISCOPE_SCREENSHOT_DIR="$PWD/docs/screenshots/200-percent" QT_SCALE_FACTOR=2 \
  QT_QPA_PLATFORM="offscreen:configfile=$screens/3840x2160.json" \
  build/dev/tests/tactiscope_ui_tests --gtest_filter="$views"
# The first page of an inspection report (tactiscope-cli report → pdftoppm).
TACTISCOPE_SCREENSHOT_DIR="$PWD/docs/screenshots" \
  build/dev/tests/tactiscope_cli_tests --gtest_filter='ReportCli.ThePdf*:ModeReportsCli.*:SignalSetupCli.ARecordingKeeps*'
echo "update-screenshots: docs/screenshots/ regenerated"
ls docs/screenshots
