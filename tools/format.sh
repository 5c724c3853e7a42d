#!/usr/bin/env bash
# Formats every tracked C++ file (.h, .cpp) with the tree's .clang-format, or
# with --check lists the files that differ from it and exits 1.
# GLSL sources (.glsl, .vert, .frag, .comp) are left as written: clang-format
# has no GLSL mode, and as C++ it reorders their order-dependent includes and
# splits interface blocks from their instance names. The layout headers they
# share with C++ (shaders/*.h) are C++ and formatted.
# Usage: tools/format.sh [--check]
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$root"
check=0
case "${1:-}" in
  --check) check=1 ;;
  "") ;;
  -h|--help) sed -n '2,8p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
  *) echo "format.sh: unknown argument '$1' (usage: tools/format.sh [--check])" >&2; exit 2 ;;
esac
command -v clang-format >/dev/null || "$root/tools/deps.sh"
mapfile -t files < <(git ls-files '*.h' '*.cpp' | grep -v '^tests/fuzz/corpus/')
if [ "$check" -eq 0 ]; then
  clang-format -i --style=file "${files[@]}"
  exit 0
fi
bad=()
for f in "${files[@]}"; do
  clang-format --style=file "$f" | cmp -s - "$f" || bad+=("$f")
done
if [ ${#bad[@]} -gt 0 ]; then
  printf 'format: %s differs from .clang-format (run tools/format.sh)\n' "${bad[@]}" >&2
  exit 1
fi
echo "format: ${#files[@]} files follow .clang-format"
