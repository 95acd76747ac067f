#!/usr/bin/env bash
# Builds the release packages: build/release/tactiscope_<version>_<arch>.deb
# (dependencies computed by dpkg-shlibdeps) and tactiscope-<version>-Linux.tar.gz.
# Installs what is missing first, like the other scripts.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
cmake --preset release >/dev/null
cmake --build --preset release -j2 --target tactiscope tactiscope-cli tactiscope_man_page
(cd build/release && cpack)
ls -l build/release/*.deb build/release/*.tar.gz
