#!/usr/bin/env bash
# Renders the application icon (resources/icons/tactiscope.svg) to the PNG
# sizes of the freedesktop hicolor theme, into installer/icons/. The PNGs are
# committed, so building the package needs no SVG renderer; run this after
# changing the SVG (needs librsvg2-bin).
set -euo pipefail
cd "$(dirname "$0")"
for size in 16 24 32 48 64 128 256 512; do
  rsvg-convert --width "$size" --height "$size" ../resources/icons/tactiscope.svg \
    --output "icons/tactiscope-${size}.png"
done
echo "render-icons: installer/icons/ regenerated"
