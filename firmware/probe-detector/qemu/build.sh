#!/usr/bin/env bash
# Builds the probe detector for one emulated Cortex-M core:
#   build.sh m4|m7|m33 OUT.elf
# m4: Cortex-M4F on QEMU's mps2-an386; m7: Cortex-M7 on mps2-an500; m33:
# Cortex-M33 on mps2-an505 (booting secure, code at 0x10000000). Single
# precision in hardware, no contraction (-ffp-contract=off): the same bits
# as the workstation's build of the same file.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
core="${1:?m4, m7 or m33}"
out="${2:?the ELF to write}"
case "$core" in
  m4)  cpu=(-mcpu=cortex-m4 -mfpu=fpv4-sp-d16); code=0x00000000; ram=0x20000000 ;;
  m7)  cpu=(-mcpu=cortex-m7 -mfpu=fpv5-sp-d16); code=0x00000000; ram=0x20000000 ;;
  m33) cpu=(-mcpu=cortex-m33 -mfpu=fpv5-sp-d16); code=0x10000000; ram=0x38000000 ;;
  *) echo "build.sh: unknown core '$core' (m4, m7 or m33)" >&2; exit 2 ;;
esac
command -v arm-none-eabi-gcc >/dev/null ||
  { echo "build.sh: arm-none-eabi-gcc is missing (Debian: gcc-arm-none-eabi libnewlib-arm-none-eabi)" >&2; exit 3; }
script="$(mktemp)"
trap 'rm -f "$script"' EXIT
sed -e "s/CODE_ORIGIN/$code/" -e "s/RAM_ORIGIN/$ram/" "$here/mps2.ld.in" > "$script"
arm-none-eabi-gcc "${cpu[@]}" -mthumb -mfloat-abi=hard -std=c99 -O2 -g -ffp-contract=off \
  -Wall -Wextra -Werror -ffunction-sections -fdata-sections \
  --specs=rdimon.specs -nostartfiles -Wl,--gc-sections -T "$script" \
  -o "$out" "$here/startup.c" "$here/main.c" "$here/../probe_detector.c" -lm
