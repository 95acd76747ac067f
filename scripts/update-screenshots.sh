#!/usr/bin/env bash
# Regenerates the screenshots of the documentation (docs/screenshots/): the
# UI tests that drive each mode against the live simulator save what they
# show there. Look at every one before committing them.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh dev tactiscope_ui_tests tactiscope_cli_tests
mkdir -p docs/screenshots
TACTISCOPE_SCREENSHOT_DIR="$PWD/docs/screenshots" QT_QPA_PLATFORM=offscreen \
  build/dev/tests/tactiscope_ui_tests \
  --gtest_filter='PanelScanView.Defects*:PalpationView.Presses*:CapacitiveView.Readouts*:DevicePanel.TheEmulator*:Recording.Sessions*:SensorProfileDialogTest.Lists*:DesignTool.Curves*:GaugeFactorWizardTest.Completed*:GaugeFactorWizardTest.AMislabelled*:CapacitiveWizardTest.LoadAndUnload*:CalibrationHistoryTest.Shows*:SessionBrowserTest.ListsEvery*:SessionBrowserTest.DeleteAsks*:ReviewWindowTest.Reanalysis*:ReviewWindowTest.AReviewersVerdict*:ReviewPalpation.*:ReviewCapacitive.*:ModeAndSource.AMode*'
# The first page of an inspection report (tactiscope-cli report → pdftoppm).
TACTISCOPE_SCREENSHOT_DIR="$PWD/docs/screenshots" \
  build/dev/tests/tactiscope_cli_tests --gtest_filter='ReportCli.ThePdf*:ModeReportsCli.*'
echo "update-screenshots: docs/screenshots/ regenerated"
ls docs/screenshots
