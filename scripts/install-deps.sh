#!/usr/bin/env bash
# Installs the Debian 12 packages Tactiscope needs to build, test and run.
# Idempotent: installs nothing (and needs no network) when all are present.
# Runs as root directly, otherwise through sudo; never prompts.
set -euo pipefail

packages=(
  build-essential cmake pkg-config git
  qt6-base-dev qt6-svg-dev qt6-serialport-dev libqt6sql6-sqlite
  libqcustomplot-dev libhidapi-dev libserialport-dev
  libeigen3-dev libsqlite3-dev nlohmann-json3-dev
  libpq-dev postgresql
  libfftw3-dev libliquid-dev libmuparser-dev
  libgtest-dev libbenchmark-dev
  xvfb xauth file fonts-dejavu-core clang-format poppler-utils
  desktop-file-utils appstream
  clang libclang-rt-14-dev
  gcc-arm-none-eabi libnewlib-arm-none-eabi qemu-system-arm
)

missing=()
for package in "${packages[@]}"; do
  status=$(dpkg-query -W -f='${Status}' "$package" 2>/dev/null || true)
  [ "$status" = "install ok installed" ] || missing+=("$package")
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

echo "install-deps: installing ${missing[*]}"
if [ "$(id -u)" -eq 0 ]; then
  as_root=()
elif command -v sudo >/dev/null 2>&1; then
  as_root=(sudo -n)
else
  echo "install-deps: not root and no sudo; as root run: apt-get install ${missing[*]}" >&2
  exit 1
fi
export DEBIAN_FRONTEND=noninteractive
"${as_root[@]}" apt-get update -q
"${as_root[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
