#!/bin/sh
# End-to-end checks of `lsys ramify`: compiled matrices, .ram.json files,
# generated trees, located errors and exit codes.
# Usage: ramify_cli_test.sh LSYS DATA_DIR TEST_DATA_DIR
set -u
LSYS=$1
DATA=$2
TESTDATA=$3
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
failures=0
. "$(dirname "$0")/../support/expect.sh"

# Tankard 2001's Figure 3 matrix, from the hand-checked tree.
expect_run figure3-json 0 '^{"orders":3,"a":\[8,5,2\],"p":\[\[1.0\],\[0.6,0.4\],\[0.5,0.0,0.5\]\]}$' -- \
    "$LSYS" ramify "$TESTDATA/figure3.lsys" --json
expect_run figure3-table 0 '^k=2 a=5 p: 0.6 0.4$' -- "$LSYS" ramify "$TESTDATA/figure3.lsys"
expect_run vlab-object 0 '"orders":7,"a":\[729,' -- "$LSYS" ramify "$DATA/plants/abop/fig2_8a_ternary_tree" --json
expect_run steps 0 '"orders":4,' -- "$LSYS" ramify "$DATA/plants/monopodial_tree.lsys" -n 4 --json
# A component plant (Tankard 2001, §3.2) compiles as any plant does.
expect_run component 0 '^{"orders":[2-9],"a":\[' -- "$LSYS" ramify "$DATA/components/broadleaf_sapling.comp.json" --json
printf '{ "root": "s", "components": { "s": { "kind": "stem", "lenght": 1 } } }' > "$WORK/bad.comp.json"
expect_run component-error 2 'bad.comp.json:1:' -- "$LSYS" ramify "$WORK/bad.comp.json"

# What --json prints is a .ram.json file; the file prints the matrix it generates with.
"$LSYS" ramify "$TESTDATA/figure3.lsys" --json > "$WORK/figure3.ram.json"
expect_run ram-json 0 '^{"orders":3,"p":\[\[1.0\],\[0.6,0.4\],\[0.5,0.0,0.5\]\]}$' -- \
    "$LSYS" ramify "$WORK/figure3.ram.json" --json
printf '{"balance": 0, "depth": 3}' > "$WORK/balance.ram.json"
expect_run guarded 0 '^k=3 p: 0.735 0.245 0.02$' -- "$LSYS" ramify "$WORK/balance.ram.json"

# Generation: deterministic per seed, an L-system the compiler reads back, or a mesh.
for species in oak pine shrub; do
    expect_run "generate-$species" 0 "$species.lsys: [0-9]* branches" -- \
        "$LSYS" ramify "$DATA/ramified/$species.ram.json" -o "$WORK/$species.lsys"
    expect_run "compile-$species" 0 '^{"orders":' -- "$LSYS" ramify "$WORK/$species.lsys" --json
done
"$LSYS" ramify "$DATA/ramified/oak.ram.json" -o "$WORK/again.lsys" 2> /dev/null
# The pine's needles are foliage, not branches: its matrix is the 6 orders it was generated with.
expect_run compile-pine-orders 0 '^{"orders":6,' -- "$LSYS" ramify "$WORK/pine.lsys" --json
cmp -s "$WORK/oak.lsys" "$WORK/again.lsys" || fail "generate: the same seed gave another tree"
"$LSYS" ramify "$DATA/ramified/oak.ram.json" --seed 2 -o "$WORK/other.lsys" 2> /dev/null
cmp -s "$WORK/oak.lsys" "$WORK/other.lsys" && fail "generate: --seed 2 gave the file's seed's tree"
expect_run glb 0 'shrub.glb: [0-9]* branches, [0-9]* primitives' -- \
    "$LSYS" ramify "$DATA/ramified/shrub.ram.json" -o "$WORK/shrub.glb"
[ -s "$WORK/shrub.glb" ] || fail "glb: nothing written"

# lsys export generates the tree too, --seed replacing the file's.
expect_run export-glb 0 'oak.glb: [0-9]* primitives, [0-9]* joints' -- \
    "$LSYS" export "$DATA/ramified/oak.ram.json" -o "$WORK/oak.glb"
[ -s "$WORK/oak.glb" ] || fail "export: nothing written"
"$LSYS" export "$DATA/ramified/oak.ram.json" -o "$WORK/oak-again.glb" 2> /dev/null
cmp -s "$WORK/oak.glb" "$WORK/oak-again.glb" || fail "export: the same seed gave another tree"
"$LSYS" export "$DATA/ramified/oak.ram.json" --seed 2 -o "$WORK/oak-seed2.glb" 2> /dev/null
cmp -s "$WORK/oak.glb" "$WORK/oak-seed2.glb" && fail "export: --seed 2 gave the file's seed's tree"

# Errors: located, exit 2.
expect_run budget 2 'passes its budget of 10 branches (--max-branches' -- \
    "$LSYS" ramify "$DATA/ramified/oak.ram.json" --max-branches 10 -o "$WORK/x.lsys"
printf '{\n  "p": [[1], [0.5, 0.5]],\n  "depth": 0\n}\n' > "$WORK/bad.ram.json"
expect_run bad-file 2 'bad.ram.json:3:12: error: /depth must be an integer in \[1, 64\] (got 0)$' -- \
    "$LSYS" ramify "$WORK/bad.ram.json"
# The offending line, a caret under its column 12.
expect_run bad-file-caret 2 '^             \^$' -- "$LSYS" ramify "$WORK/bad.ram.json"
expect_run export-bad-file 2 'bad.ram.json:3:12: error: /depth must be an integer in \[1, 64\] (got 0)$' -- \
    "$LSYS" export "$WORK/bad.ram.json" -o "$WORK/x.glb"
printf '{\n  "p": [[1]],\n  "foliage": {"kind": "leaves", "sise": 0.2}\n}\n' > "$WORK/typo.ram.json"
expect_run misspelt-key 2 'typo.ram.json:3:33: error: /foliage/sise is an unknown key; did you mean "size"?$' -- \
    "$LSYS" ramify "$WORK/typo.ram.json"
expect_run plant-output 2 '-o generates a tree from a .ram.json file' -- \
    "$LSYS" ramify "$TESTDATA/figure3.lsys" -o "$WORK/x.glb"
printf 'Axiom: F(\n' > "$WORK/bad.lsys"
expect_run bad-plant 2 'bad.lsys:1:' -- "$LSYS" ramify "$WORK/bad.lsys"
expect_run help 0 '--max-branches' -- "$LSYS" ramify --help

[ "$failures" = 0 ] && echo "all lsys ramify checks passed"
[ "$failures" = 0 ]
