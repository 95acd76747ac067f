#!/usr/bin/env bash
# The probe detector's cost on paper, from the compiled code: builds the
# kernel for each core (qemu/build.sh), takes pd_step's lag loop from the
# disassembly (the backward branch with the longest reach), counts its
# instructions by class and prices them with the cores' published timings.
#   cycle-budget.sh            a table for m4, m7 and m33
# Timings (cycles): Cortex-M4 and M33 (single issue, FPv4/FPv5 single
# precision): VADD VSUB VMUL VABS VMOV VCMP VMRS 1, VLDR VSTR 2, VLDM/VSTM
# of one register 2, LDR 2, other integer instructions 1, IT 1, a taken
# branch 3. Cortex-M7 (dual issue, one FP data-processing instruction per
# cycle): the FP data-processing count, the loads, stores and integer work
# issuing beside them, is its lower bound; stalls on the 3-cycle FP latency
# are not counted, so the M7 figure is optimistic by up to a third.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
printf '%-5s %6s %6s %8s %8s %9s\n' core instr fp-ops loads cycles state
for core in m4 m7 m33; do
  "$here/qemu/build.sh" "$core" "$work/$core.elf"
  arm-none-eabi-objdump -d --no-show-raw-insn "$work/$core.elf" > "$work/$core.all"
  awk '/<pd_step>:/{on=1; next} on && /^$/{on=0} on' "$work/$core.all" > "$work/$core.s"
  # The loop: the backward branch reaching farthest back. (POSIX awk: hex by hand.)
  awk -F'\t' -v core="$core" '
    function hex(text,   i, v) { v = 0; text = tolower(text)
      for (i = 1; i <= length(text); i++) v = v * 16 + index("0123456789abcdef", substr(text, i, 1)) - 1
      return v }
    NF > 1 { line++; a = $1; gsub(/[ :]/, "", a); addr[line] = hex(a); split($2, w, " "); op[line] = w[1]
      if (op[line] ~ /^b/ && split($3, t, " ") > 0 && t[1] ~ /^[0-9a-f]+$/) {
        target = hex(t[1]); if (target < addr[line] && addr[line] - target > best) { best = addr[line] - target; from = target; to = addr[line] } } }
    END {
      for (i = 1; i <= line; i++) {
        if (addr[i] < from || addr[i] > to) continue
        o = op[i]; n++
        if (o ~ /^v(add|sub|mul|abs|neg|div|sqrt|cmp)/) { arith++; c += 1 }
        else if (o ~ /^v(mov|mrs)/) { c += 1 }
        else if (o ~ /^v(ldr|str|ldm|stm)/) { mem++; c += 2 }
        else if (o ~ /^ldr/) { c += 2 }
        else if (o ~ /^b/) { c += 3 }
        else { c += 1 }
      }
      printf "%s %d %d %d %d\n", core, n, arith, mem, (core == "m7" ? arith : c)
    }' "$work/$core.s" > "$work/$core.count"
  read -r name instructions arith memory cycles < "$work/$core.count"
  # The detector's state: the one pd_detector the QEMU program holds.
  size=$(arm-none-eabi-nm -S "$work/$core.elf" | awk '$4 == "detector" { v = 0; t = tolower($2)
    for (i = 1; i <= length(t); i++) v = v * 16 + index("0123456789abcdef", substr(t, i, 1)) - 1; print v }')
  printf '%-5s %6d %6d %8d %8d %9s\n' "$name" "$instructions" "$arith" "$memory" "$cycles" "${size}B"
done
