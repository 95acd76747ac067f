#!/usr/bin/env bash
# Checks the design's layering: core includes no Qt, device library, devices
# or ui header; devices includes no Qt Widgets/Gui or ui header; the ui's
# generic code includes no mode's folder (ui/modes/<mode>/: it asks the
# mode's entry, ui/modes/ModeUi.h, whose registry alone lists them). Prints
# each offending line and fails if there is any.
set -u
root=${1:?usage: check-layering.sh SOURCE_ROOT}
status=0

check() {  # check DIR REGEX WHY
  local hits
  hits=$(grep -rnE --include='*.h' --include='*.cpp' --include='*.in' "$2" "$root/$1" 2>/dev/null)
  if [ -n "$hits" ]; then
    echo "layering: $1/ must not include $3:"
    echo "$hits"
    status=1
  fi
}

check core '^\s*#\s*include\s*[<"](Q[A-Za-z]+|Qt[A-Za-z]*/|hidapi|libserialport|qcustomplot|devices/|ui/)' \
  'Qt, hidapi, libserialport, QCustomPlot, devices/ or ui/ headers'
check devices '^\s*#\s*include\s*[<"](QtWidgets|QtGui|QWidget|QMainWindow|QApplication|QPainter|qcustomplot|ui/)' \
  'Qt Widgets/Gui, QCustomPlot or ui/ headers'

# Generic ui code: every file of ui/ but the modes' own folders and the registry.
hits=$(grep -rnE --include='*.h' --include='*.cpp' '^\s*#\s*include\s*"ui/modes/[a-z]+/' "$root/ui" 2>/dev/null |
  grep -vE "^$root/ui/modes/([a-z]+/|ModeUiRegistry\.cpp:)")
if [ -n "$hits" ]; then
  echo "layering: generic ui/ code must not include a mode's folder (ask ui/modes/ModeUi.h):"
  echo "$hits"
  status=1
fi

[ "$status" = 0 ] && echo "layering: ok"
exit $status
