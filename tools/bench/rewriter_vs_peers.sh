#!/usr/bin/env bash
# The rewriter benchmark of docs/BENCHMARKS.md: lsys against the npm
# `lindenmayer` library and, where CPFG_BIN names a folder holding cpfg and
# vlabcpp built from vlab's public sources, against cpfg, on the same three
# systems, side by side in one hyperfine run per system (whole process,
# deriving only: cpfg -g without -str). lindenmayer also reports its
# in-process time, iterate() alone. Before timing, the script checks that all
# derive the same string (lindenmayer: the same module count; cpfg: lsys
# derive --compare on cpfg's -str, module for module). Prints a Markdown table
# for docs/BENCHMARKS.md. hyperfine runs the commands without a shell (-N):
# lsys's runs take a few milliseconds, less than hyperfine can correct a
# shell's start-up for (it warns so), and no command needs one.
# Usage: [CPFG_BIN=/path/to/vlab/bin] tools/bench/rewriter_vs_peers.sh [RUNS]
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
build=${BUILD_DIR:-$root/build}
runs=${1:-10}
"$root/tools/deps.sh" bench
"$root/tools/build.sh" lsys >&2
work=$build/bench
mkdir -p "$work"
cp "$root/tools/bench/lindenmayer_bench.mjs" "$root/tools/bench/format_hyperfine.mjs" "$work/"
[ -d "$work/node_modules/lindenmayer" ] ||
  (cd "$work" && npm install --silent --no-audit --no-fund --no-save lindenmayer@1.5.4 >/dev/null)
cpfg=()
if [ -n "${CPFG_BIN:-}" ]; then
  if [ ! -x "$CPFG_BIN/cpfg" ] || [ ! -x "$CPFG_BIN/vlabcpp" ]; then
    echo "rewriter_vs_peers.sh: CPFG_BIN must name a folder holding cpfg and vlabcpp built from vlab's sources" >&2
    exit 2
  fi
  export PATH="$CPFG_BIN:$PATH" # cpfg runs vlabcpp through PATH
  # cpfg -g needs a view file and a colour map; all defaults will do.
  printf '/* default view */\n' >"$work/view.v"
  head -c 768 /dev/zero >"$work/colours.map"
  cpfg=("$CPFG_BIN/cpfg" -g -m "$work/colours.map")
fi

lsys=$build/tools/lsys/lsys
cases=(
  "bush 7 fractal_bush"
  "tree 19 decreasing_tree"
  "context 28 context_benchmark"
)
for c in "${cases[@]}"; do
  read -r name steps file <<<"$c"
  plant=$root/data/plants/$file.lsys
  # All must derive the same string before their times mean anything.
  ours=$("$lsys" derive "$plant" -n "$steps" --json | node -e 'let s="";process.stdin.on("data",d=>s+=d).on("end",()=>console.log(JSON.parse(s).modules))')
  theirs=$(node "$work/lindenmayer_bench.mjs" "$name" "$steps" | node -e 'let s="";process.stdin.on("data",d=>s+=d).on("end",()=>console.log(JSON.parse(s).modules))')
  if [ "$ours" != "$theirs" ]; then
    echo "rewriter_vs_peers: $name: lsys gives $ours modules, lindenmayer $theirs" >&2
    exit 1
  fi
  peers=(-n lindenmayer "node $work/lindenmayer_bench.mjs $name $steps $work/$name.inprocess")
  if [ ${#cpfg[@]} -gt 0 ]; then
    cpfg_plant=$root/tools/bench/cpfg/$file.l
    "${cpfg[@]}" -str "$work/cpfg.str" "$cpfg_plant" "$work/view.v" >/dev/null 2>&1
    "$lsys" derive "$plant" -n "$steps" --compare "$work/cpfg.str" >&2
    peers+=(-n cpfg "${cpfg[*]} $cpfg_plant $work/view.v")
  fi
  rm -f "$work/$name.inprocess"
  hyperfine -N --style none --warmup 3 --runs "$runs" --export-json "$work/$name.json" \
    -n "lsys" "$lsys derive $plant -n $steps" "${peers[@]}" >&2
done
node "$work/format_hyperfine.mjs" "$work/bush.json" "$work/tree.json" "$work/context.json"
