#!/usr/bin/env bash
# The probe's detector on an emulated Cortex-M, over a scan:
#   qemu-detect.sh SCAN.csv OUT.csv [m4|m7|m33]     (default m4)
# Builds the kernel for that core (qemu/build.sh), runs it in QEMU with the
# scan fed through semihosting and writes the rows `tactiscope-cli detect
# --output` writes (t,out,rab,rba,lag_ab_ms,lag_ba_ms), with the paper's
# settings. Exits 3 naming what is missing when the ARM toolchain, QEMU or a
# host C compiler is not installed, 2 for a scan it cannot use, 1 when the
# emulated probe fails (a fault, or no answer in TACTISCOPE_QEMU_TIMEOUT
# seconds, default 600).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
scan="${1:?usage: qemu-detect.sh SCAN.csv OUT.csv [m4|m7|m33]}"
out="${2:?usage: qemu-detect.sh SCAN.csv OUT.csv [m4|m7|m33]}"
core="${3:-m4}"
case "$core" in
  m4) machine=mps2-an386 ;;
  m7) machine=mps2-an500 ;;
  m33) machine=mps2-an505 ;;
  *) echo "qemu-detect: unknown core '$core' (m4, m7 or m33)" >&2; exit 2 ;;
esac
missing=()
command -v arm-none-eabi-gcc >/dev/null || missing+=("arm-none-eabi-gcc (Debian: gcc-arm-none-eabi libnewlib-arm-none-eabi)")
command -v qemu-system-arm >/dev/null || missing+=("qemu-system-arm (Debian: qemu-system-arm)")
command -v cc >/dev/null || missing+=("a host C compiler, cc (Debian: build-essential)")
if ((${#missing[@]})); then
  printf 'qemu-detect: cannot run the emulated probe: missing %s\n' "${missing[@]}" >&2
  exit 3
fi
[[ -r "$scan" ]] || { echo "qemu-detect: $scan cannot be read" >&2; exit 2; }

work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cc -std=c99 -O2 -o "$work/scan_io" "$here/host/scan_io.c" -lm
"$here/qemu/build.sh" "$core" "$work/probe.elf"
"$work/scan_io" pack "$scan" "$work/probe-in.bin"
# Semihosting opens its files relative to QEMU's working directory.
status=0
(cd "$work" && timeout "${TACTISCOPE_QEMU_TIMEOUT:-600}" qemu-system-arm -machine "$machine" -nographic \
  -monitor none -serial none -semihosting-config enable=on,target=native -kernel probe.elf) || status=$?
if ((status != 0)) || [[ ! -s "$work/probe-out.bin" ]]; then
  echo "qemu-detect: the emulated $core probe failed (status $status)" >&2
  exit 1
fi
"$work/scan_io" unpack "$scan" "$work/probe-out.bin" "$out"
