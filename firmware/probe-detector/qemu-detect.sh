#!/usr/bin/env bash
# The probe's detector on an emulated Cortex-M, over a scan:
#   qemu-detect.sh SCAN.csv OUT.csv [m4|m7|m33]     (default m4)
# Builds the kernel for that core (qemu/build.sh), runs it in QEMU with the
# scan fed through semihosting and writes the rows `tactiscope-cli detect
# --output` writes (t,out,rab,rba,lag_ab_ms,lag_ba_ms), with the paper's
# settings. The scan is read by tactiscope-cli itself (`detect
# --probe-input`, `--probe-decisions`): a scan detect refuses is refused
# here, with detect's message and exit code 2. The CLI is $TACTISCOPE_CLI,
# or tactiscope-cli on the PATH, or the dev build's. Exits 3 naming what is
# missing when the ARM toolchain, QEMU or the CLI is not there, 1 when the
# emulated probe fails (a fault, or no answer in TACTISCOPE_QEMU_TIMEOUT
# seconds, default 600).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
if (($# < 2 || $# > 3)); then
  echo "usage: qemu-detect.sh SCAN.csv OUT.csv [m4|m7|m33]" >&2
  exit 2
fi
scan="$1"
out="$2"
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
cli="${TACTISCOPE_CLI:-$(command -v tactiscope-cli || echo "$here/../../build/dev/app/tactiscope-cli")}"
[[ -x "$cli" ]] || missing+=("tactiscope-cli (scripts/build.sh dev tactiscope-cli, or set TACTISCOPE_CLI)")
if ((${#missing[@]})); then
  printf 'qemu-detect: cannot run the emulated probe: missing %s\n' "${missing[@]}" >&2
  exit 3
fi

work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
"$cli" detect "$scan" --probe-input "$work/probe-in.bin" >/dev/null || exit $?
"$here/qemu/build.sh" "$core" "$work/probe.elf"
# Semihosting opens its files relative to QEMU's working directory.
status=0
(cd "$work" && timeout "${TACTISCOPE_QEMU_TIMEOUT:-600}" qemu-system-arm -machine "$machine" -nographic \
  -monitor none -serial none -semihosting-config enable=on,target=native -kernel probe.elf) || status=$?
if ((status != 0)) || [[ ! -s "$work/probe-out.bin" ]]; then
  echo "qemu-detect: the emulated $core probe failed (status $status)" >&2
  exit 1
fi
"$cli" detect "$scan" --probe-decisions "$work/probe-out.bin" --output "$out" >/dev/null
echo "qemu-detect: the emulated $core probe decided every sample of $scan: $out"
