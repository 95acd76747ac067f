#!/usr/bin/env bash
# Fails when a tracked C++ file differs from what .clang-format asks for.
# Fix with: clang-format -i $(git ls-files '*.h' '*.cpp')
set -u
root=${1:?usage: check-format.sh SOURCE_ROOT CLANG_FORMAT}
clang_format=${2:?usage: check-format.sh SOURCE_ROOT CLANG_FORMAT}
cd "$root" || exit 1
if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  mapfile -t files < <(git ls-files '*.h' '*.cpp')
else
  mapfile -t files < <(find app core devices ui tests bench -name '*.h' -o -name '*.cpp' 2>/dev/null)
fi
"$clang_format" --dry-run -Werror "${files[@]}" && echo "format: ${#files[@]} files ok"
