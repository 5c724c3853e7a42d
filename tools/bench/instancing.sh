#!/usr/bin/env bash
# The instancing benchmark of docs/BENCHMARKS.md: InstanceGraph build time and
# bytes against a flat primitive buffer for a D0L bush, parametric trees, a
# stochastic field with randomness factor k = 20 and context-sensitive systems,
# from `lsys instance --json` (b-grammar + InstanceGraph build, measured inside
# lsys without parsing). Prints a Markdown table for docs/BENCHMARKS.md.
# Usage: tools/bench/instancing.sh
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
build=${BUILD_DIR:-$root/build}
"$root/tools/deps.sh" bench
"$root/tools/build.sh" lsys >&2
lsys=$build/tools/lsys/lsys
plants=$root/data/plants
cases=(
  "D0L bush (fractal_bush, 8 steps)|$plants/fractal_bush.lsys -n 8"
  "D0L bush (fractal_bush, 10 steps)|$plants/fractal_bush.lsys -n 10"
  "parametric (decreasing_tree, 19 steps)|$plants/decreasing_tree.lsys -n 19"
  "parametric with \$ (monopodial_tree, 18 steps, exact)|$plants/monopodial_tree.lsys -n 18"
  "parametric with \$ (monopodial_tree, 18 steps, G = 16)|$plants/monopodial_tree.lsys -n 18 --granularity 16"
  "stochastic field, k = 20 (grass_field, SIZE 2048, 16 steps)|$plants/grass_field.lsys -D SIZE=2048 -n 16 --randomness 20"
  "context-sensitive (hogeweg_1_31b, 30 steps)|$plants/hogeweg_1_31b.lsys"
  "context-sensitive (hogeweg_1_31a, 30 steps)|$plants/hogeweg_1_31a.lsys"
)
echo "| system | primitives | nodes | objects | instances | compression | bytes graph | bytes flat | graph / flat | build (ms) | method |"
echo "|---|---|---|---|---|---|---|---|---|---|---|"
for c in "${cases[@]}"; do
  label=${c%%|*}
  read -r -a args <<<"${c#*|}"
  # Median build time of 5 runs; the counts are the same every run.
  for i in 1 2 3 4 5; do "$lsys" instance "${args[@]}" --json; done | LABEL="$label" node -e '
    const runs = require("fs").readFileSync(0, "utf8").trim().split("\n").map(JSON.parse);
    const r = runs[0], times = runs.map((x) => x.seconds * 1000).sort((a, b) => a - b);
    const n = (v) => v.toLocaleString("en-US").replace(/,/g, " ");
    const ratio = r.bytes_graph / r.bytes_flat;
    console.log(`| ${process.env.LABEL} | ${n(r.primitives)} | ${n(r.nodes)} | ${n(r.objects)} | ${n(r.instances)} | ${n(Math.round(r.compression))}:1 | ${n(r.bytes_graph)} | ${n(r.bytes_flat)} | ${ratio.toExponential(1)} | ${times[2].toFixed(3)} | ${r.method} |`);'
done
