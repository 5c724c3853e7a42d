#!/usr/bin/env bash
# lsys against vlab's cpfg on the same cpfg files, side by side in one
# hyperfine run per system: whole process, deriving and writing the string
# file (cpfg -g -str; lsys derive --print --format cpfg). Before timing, the
# script checks that both write the same string (lsys derive --compare:
# module for module, parameters within 1e-4 relative). cpfg is not part of this
# repository: build it from vlab's public sources (cpfg and vlabcpp) and name
# the folder holding both binaries in CPFG_BIN. Prints a Markdown table for
# docs/BENCHMARKS.md.
# Usage: CPFG_BIN=/path/to/vlab/bin tools/bench/lsys_vs_cpfg.sh [RUNS]
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
build=${BUILD_DIR:-$root/build}
runs=${1:-10}
if [ ! -x "${CPFG_BIN:-}/cpfg" ] || [ ! -x "${CPFG_BIN:-}/vlabcpp" ]; then
  echo "lsys_vs_cpfg.sh: CPFG_BIN must name a folder holding cpfg and vlabcpp built from vlab's sources" >&2
  exit 2
fi
"$root/tools/deps.sh" bench
"$root/tools/build.sh" lsys >&2
work=$build/bench/cpfg
mkdir -p "$work"
cp "$root/tools/bench/format_hyperfine.mjs" "$work/"
# cpfg -g needs a view file and a colour map; all defaults will do.
printf '/* default view */\n' > "$work/view.v"
head -c 768 /dev/zero > "$work/colours.map"
export PATH="$CPFG_BIN:$PATH" # cpfg runs vlabcpp through PATH
lsys=$build/tools/lsys/lsys
cpfg=("$CPFG_BIN/cpfg" -g -m "$work/colours.map" -str "$work/cpfg.str")
for name in bush monopodial; do
  file=$root/tools/bench/cpfg/$name.l
  "${cpfg[@]}" "$file" "$work/view.v" >/dev/null 2>&1
  "$lsys" derive "$file" --compare "$work/cpfg.str" >&2
  hyperfine --style none --warmup 1 --runs "$runs" --export-json "$work/$name.json" \
    -n lsys "sh -c 'exec $lsys derive $file --print --format cpfg > $work/lsys.str'" \
    -n cpfg "${cpfg[*]} $file $work/view.v" >&2
done
node "$work/format_hyperfine.mjs" "$work/bush.json" "$work/monopodial.json"
