#!/bin/sh
# End-to-end checks of `lsys render`: a PNG written, the same bytes on any
# thread count and through either tracer's budget check, the lazy tracer's
# bytes under any cache budget, and its errors (exit codes and messages).
# Usage: render_cli_test.sh LSYS DATA_DIR
set -u
LSYS=$1
DATA=$2
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
failures=0
. "$(dirname "$0")/../support/expect.sh"
BUSH="$DATA/plants/fractal_bush.lsys"

# A PNG, with the rays and their rate on stderr.
expect_run render 0 'bush.png: 64x48, graph tracer, 3072 camera and [0-9]* shadow rays in .* rays/s on 1 thread), .* s in all' -- \
    "$LSYS" render "$BUSH" -n 4 -o "$WORK/bush.png" --size 64x48 --threads 1
head -c 8 "$WORK/bush.png" | od -An -c | grep -q 'P   N   G' || fail "render: bush.png is not a PNG"
"$LSYS" render "$BUSH" -n 4 -o "$WORK/bush3.png" --size 64x48 --threads 3 2> /dev/null
cmp -s "$WORK/bush.png" "$WORK/bush3.png" || fail "render: 3 threads gave other bytes than 1"
expect_run flat 0 'flat tracer' -- "$LSYS" render "$BUSH" -n 4 -o "$WORK/flat.png" --size 64x48 --tracer flat
expect_run options 0 'camera.png: 40x30' -- "$LSYS" render "$BUSH" -n 3 -o "$WORK/camera.png" --size 40x30 \
    --camera 30,20,40,0,10,0,30 --sun 90,60 --samples 2 --no-shadows --no-ground -D X=1
expect_run view 0 'view.png' -- "$LSYS" render "$BUSH" -n 3 -o "$WORK/view.png" --size 40x30 --view 0,10
# Straight down from above the bush: the plant on the ground, so another
# plant gives another picture (a NaN basis gave one colour whatever the plant).
expect_run camera-vertical 0 'down.png: 40x30' -- "$LSYS" render "$BUSH" -n 3 -o "$WORK/down.png" --size 40x30 \
    --camera 0,70,0,0,0,0
"$LSYS" render "$BUSH" -n 1 -o "$WORK/down-n1.png" --size 40x30 --camera 0,70,0,0,0,0 2> /dev/null
cmp -s "$WORK/down.png" "$WORK/down-n1.png" && fail "camera-vertical: the same bytes for two different plants"

# The lazy tracer: the same bytes whether its cache holds nothing (1 byte),
# evicts (2 KiB of 484 objects' expansions) or holds everything (1 GiB), and
# the graph tracer's from the same camera; what the cache did on stderr.
TREE="$DATA/plants/monopodial_tree.lsys"
TREE_CAMERA=3,4,12,0,3,0
expect_run lazy-nothing-held 0 'lazy tracer: 484 objects, [1-9][0-9]* expansions, 0 evictions, at most 0 B held of a 1 B cache budget' -- \
    "$LSYS" render "$TREE" -o "$WORK/lazy-1.png" --size 64x48 --camera $TREE_CAMERA --tracer lazy --cache-budget 1
expect_run lazy-evicting 0 'lazy tracer: 484 objects, [0-9]* expansions, [1-9][0-9]* evictions, at most .* held of a 2.0 KiB cache budget' -- \
    "$LSYS" render "$TREE" -o "$WORK/lazy-2k.png" --size 64x48 --camera $TREE_CAMERA --tracer lazy --cache-budget 2K
expect_run lazy-all-held 0 'lazy tracer: 484 objects, [0-9]* expansions, 0 evictions, at most .* held of a 1.0 GiB cache budget' -- \
    "$LSYS" render "$TREE" -o "$WORK/lazy-1g.png" --size 64x48 --camera $TREE_CAMERA --tracer lazy --cache-budget 1G
"$LSYS" render "$TREE" -o "$WORK/graph.png" --size 64x48 --camera $TREE_CAMERA 2> /dev/null
cmp -s "$WORK/lazy-1.png" "$WORK/lazy-1g.png" || fail "lazy: a 1-byte cache gave other bytes than a 1 GiB one"
cmp -s "$WORK/lazy-2k.png" "$WORK/lazy-1g.png" || fail "lazy: a 2 KiB cache gave other bytes than a 1 GiB one"
cmp -s "$WORK/lazy-1g.png" "$WORK/graph.png" || fail "lazy: other bytes than the graph tracer's from the same camera"
expect_run lazy-default 0 'held of a 256.0 MiB cache budget' -- \
    "$LSYS" render "$BUSH" -n 4 -o "$WORK/lazy.png" --size 64x48 --tracer lazy

# Errors: exit 2 and a message naming the problem.
expect_run size 2 "'1280' is not a size" -- "$LSYS" render "$BUSH" -o "$WORK/x.png" --size 1280
expect_run size-zero 2 "'0x720' is not a size" -- "$LSYS" render "$BUSH" -o "$WORK/x.png" --size 0x720
expect_run camera 2 "'1,2,3' is not a camera" -- "$LSYS" render "$BUSH" -o "$WORK/x.png" --camera 1,2,3
expect_run camera-at-target 2 "is not a camera" -- "$LSYS" render "$BUSH" -o "$WORK/x.png" --camera 1,5,0,1,5,0
expect_run camera-too-far 2 'camera is 1e+20 from the plant.s box, more than 100000 times the plant.s size' -- \
    "$LSYS" render "$BUSH" -n 3 -o "$WORK/x.png" --size 40x30 --camera 0,1e20,0,0,0,0
expect_run sun 2 "'10,95' is not AZ,EL" -- "$LSYS" render "$BUSH" -o "$WORK/x.png" --sun 10,95
expect_run unknown-flag 2 '--shiny' -- "$LSYS" render "$BUSH" -o "$WORK/x.png" --shiny
expect_run tracer 2 'tracer' -- "$LSYS" render "$BUSH" -o "$WORK/x.png" --tracer bvh
expect_run missing 2 'no-such-plant.lsys' -- "$LSYS" render "$WORK/no-such-plant.lsys" -o "$WORK/x.png"
expect_run no-output 2 'output' -- "$LSYS" render "$BUSH"
expect_run folder 2 'is a folder' -- "$LSYS" render "$BUSH" -n 2 -o "$WORK"
expect_run flat-budget 2 'more than the flat tracer.s budget of 1000 (--max-flat-primitives' -- \
    "$LSYS" render "$BUSH" -n 4 -o "$WORK/x.png" --tracer flat --max-flat-primitives 1000
expect_run cache-budget 2 "'12Q' is not a size: expected bytes or a number with K, M, G or T" -- \
    "$LSYS" render "$BUSH" -o "$WORK/x.png" --tracer lazy --cache-budget 12Q
expect_run cache-budget-zero 2 "'0' is not a size" -- "$LSYS" render "$BUSH" -o "$WORK/x.png" --tracer lazy --cache-budget 0
expect_run cache-budget-graph 2 'cache-budget .* needs --tracer lazy' -- \
    "$LSYS" render "$BUSH" -n 2 -o "$WORK/x.png" --cache-budget 64M
expect_run cache-budget-memory 2 'expansion cache (--cache-budget) needs 1.0 GiB, the limit is 100.0 MiB' -- \
    "$LSYS" render "$BUSH" -n 2 -o "$WORK/x.png" --tracer lazy --cache-budget 1G --memory-budget 100M
[ -e "$WORK/x.png" ] && fail "errors: x.png was written"
expect_run component 2 'component plant or ramification tree' -- \
    "$LSYS" render "$DATA/components/sunflower.comp.json" -o "$WORK/x.png"
printf 'Axiom: F\nF --> F(\n' > "$WORK/bad.lsys"
expect_run parse-error 2 'bad.lsys:2:' -- "$LSYS" render "$WORK/bad.lsys" -o "$WORK/x.png"

[ "$failures" -eq 0 ] || { echo "$failures failure(s)"; exit 1; }
echo "lsys render: all checks passed"
