#!/usr/bin/env bash
# The rewriter benchmark of docs/BENCHMARKS.md: lsys against the npm
# `lindenmayer` library on the same three systems, side by side in one hyperfine
# run per system (whole process, deriving only). Prints a Markdown table of mean
# times and ratios for docs/BENCHMARKS.md.
# Usage: tools/bench/rewriter_vs_lindenmayer.sh [RUNS]
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

lsys=$build/tools/lsys/lsys
plants=$root/data/plants
cases=(
  "bush 7 $plants/fractal_bush.lsys"
  "tree 19 $plants/decreasing_tree.lsys"
  "context 28 $plants/context_benchmark.lsys"
)
for c in "${cases[@]}"; do
  read -r name steps file <<<"$c"
  # Both must produce the same number of modules before their times mean anything.
  ours=$("$lsys" derive "$file" -n "$steps" --json | node -e 'let s="";process.stdin.on("data",d=>s+=d).on("end",()=>console.log(JSON.parse(s).modules))')
  theirs=$(node "$work/lindenmayer_bench.mjs" "$name" "$steps" | node -e 'let s="";process.stdin.on("data",d=>s+=d).on("end",()=>console.log(JSON.parse(s).modules))')
  if [ "$ours" != "$theirs" ]; then
    echo "rewriter_vs_lindenmayer: $name: lsys gives $ours modules, lindenmayer $theirs" >&2
    exit 1
  fi
  hyperfine --style none --warmup 1 --runs "$runs" --export-json "$work/$name.json" \
    -n "lsys" "$lsys derive $file -n $steps" \
    -n "lindenmayer" "node $work/lindenmayer_bench.mjs $name $steps" >&2
done
node "$work/format_hyperfine.mjs" "$work/bush.json" "$work/tree.json" "$work/context.json"
