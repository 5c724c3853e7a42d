#!/bin/sh
# End-to-end checks of the lsys command line: output formats, exit codes and
# error messages. Usage: cli_test.sh LSYS DATA_DIR VERSION
set -u
LSYS=$1
DATA=$2
VERSION=$3
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
failures=0
. "$(dirname "$0")/../support/expect.sh"

expect_run json 0 '"modules":1249' -- "$LSYS" derive "$DATA/plants/koch_curve.lsys" -n 4 --json
expect_run json-counts 0 '"F":625' -- "$LSYS" derive "$DATA/plants/koch_curve.lsys" -n 4 --json
expect_run json-steps 0 '"steps":4' -- "$LSYS" derive "$DATA/plants/koch_curve.lsys" --json
expect_run print 0 '^D(0)C(1,2)D(3)$' -- "$LSYS" derive "$DATA/plants/parametric.lsys" --print
expect_run plain 0 '6263 modules after 5 steps' -- "$LSYS" derive "$DATA/plants/fractal_tree.lsys"

printf '#define N 1\nAxiom: A(N)\nA(x) --> A(x*2)\n' > "$WORK/define.lsys"
expect_run define 0 '^A(24)$' -- "$LSYS" derive "$WORK/define.lsys" -n 3 -D N=3 --print
expect_run bad-define 2 'NAME=NUMBER' -- "$LSYS" derive "$WORK/define.lsys" -D N=x

expect_run seed 0 '^F' -- "$LSYS" derive "$DATA/plants/stochastic.lsys" --seed 9 --print
"$LSYS" derive "$DATA/plants/stochastic.lsys" --seed 9 --print > "$WORK/a"
"$LSYS" derive "$DATA/plants/stochastic.lsys" --seed 9 --print --threads 1 > "$WORK/b"
cmp -s "$WORK/a" "$WORK/b" || fail "seed: 2 threads and 1 thread differ"

# --format cpfg lays the string out as cpfg's -str does: a break before a module once 70 characters are on a line.
printf 'Axiom: A(1)\nA(x) --> F(x)[+A(x/2)]A(x*2)\n' > "$WORK/cpfg.l"
"$LSYS" derive "$WORK/cpfg.l" -n 3 --print --format cpfg > "$WORK/cpfg.str"
printf 'F(1)[+F(0.5)[+F(0.25)[+A(0.125)]A(0.5)]F(1)[+A(0.5)]A(2)]F(2)[+F(1)[+A(0.5)\n]A(2)]F(4)[+A(2)]A(8)\n' > "$WORK/cpfg.expected"
cmp -s "$WORK/cpfg.str" "$WORK/cpfg.expected" || fail "format cpfg: $(cat "$WORK/cpfg.str")"
printf 'Axiom: A\nA --> F[+F\n' > "$WORK/open.lsys"
expect_run warning 0 'open.lsys:2:1: warning: the successor.s brackets do not balance' -- "$LSYS" check "$WORK/open.lsys"
expect_run compare-same 0 'is the same string: 36 modules' -- "$LSYS" derive "$WORK/cpfg.l" -n 3 --compare "$WORK/cpfg.expected"
expect_run compare-differs 1 'differs: module 9: another module: derived F(0.125), the text has A(0.125)' -- "$LSYS" derive "$WORK/cpfg.l" -n 4 --compare "$WORK/cpfg.expected"
expect_run format-unknown 2 'xml not in' -- "$LSYS" derive "$WORK/cpfg.l" --print --format xml

expect_run dialect-header 0 '"F":1330' -- "$LSYS" derive "$DATA/plants/dialects/gravity_tree_2d.crankshaw" --json
printf 'FP A\nA --> FP B\nB --> [ & A ]\nFP --> F\n' > "$WORK/robbins.txt"
expect_run dialect-option 0 '^FF\[&A\]$' -- "$LSYS" derive "$WORK/robbins.txt" --dialect robbins -n 2 --print
expect_run dialect-option-case 0 '^FF\[&A\]$' -- "$LSYS" derive "$WORK/robbins.txt" --dialect Robbins -n 2 --print
expect_run dialect-native 2 'robbins.txt:1:' -- "$LSYS" check "$WORK/robbins.txt" --dialect native
expect_run dialect-unknown 2 "unknown dialect 'klingon'" -- "$LSYS" derive "$WORK/robbins.txt" --dialect klingon
printf 'dialect: klingon\nAxiom: F\n' > "$WORK/klingon.lsys"
expect_run dialect-unknown-header 2 'klingon.lsys:1:1: error: unknown or misplaced dialect line' -- "$LSYS" check "$WORK/klingon.lsys"
printf 'dialect: crankshaw\n#w : A;\n\n  #p1 : A : * : B(1 +);\n' > "$WORK/bad.crankshaw"
expect_run dialect-error-position 2 'bad.crankshaw:4:22: error:' -- "$LSYS" check "$WORK/bad.crankshaw"

printf 'Axiom: A\nA --> B(1 +)\nC --> D\nnonsense here\n' > "$WORK/bad.lsys"
expect_run check-bad 2 'bad.lsys:2:12: error:' -- "$LSYS" check "$WORK/bad.lsys"
expect_run check-caret 2 '^             \^$' -- "$LSYS" check "$WORK/bad.lsys"
expect_run check-all 2 'bad.lsys:4:1: error: unrecognised line' -- "$LSYS" check "$WORK/bad.lsys"
expect_run check-count 2 '^2 errors$' -- "$LSYS" check "$WORK/bad.lsys"
expect_run derive-bad 2 'bad.lsys:2:12' -- "$LSYS" derive "$WORK/bad.lsys"
expect_run check-good 0 'ok' -- "$LSYS" check "$DATA/plants/monopodial_tree.lsys"
expect_run missing 2 'cannot read file' -- "$LSYS" derive "$WORK/does-not-exist.lsys"
expect_run budget 2 'module budget exceeded at derivation step 6.*--max-modules sets the budget' -- "$LSYS" derive "$DATA/plants/fractal_bush.lsys" -n 7 --max-modules 100000
expect_run instance 0 '"primitives":134217728,"joints":134217728,"nodes":9,"objects":9,"instances":72,' -- "$LSYS" instance "$DATA/plants/fractal_bush.lsys" -n 9 --json
expect_run instance-bytes 0 '"bytes_flat":[1-9][0-9]*,"method":"memoised","seconds":' -- "$LSYS" instance "$DATA/plants/fractal_bush.lsys" --json
expect_run instance-plain 0 '^32768 primitives (32768 joints) in 40 instances of 5 objects from 5 nodes' -- "$LSYS" instance "$DATA/plants/fractal_bush.lsys"
expect_run instance-context 0 '"method":"compressed"' -- "$LSYS" instance "$DATA/plants/hogeweg_1_31a.lsys" --json
expect_run instance-random-exact 0 '"method":"compressed"' -- "$LSYS" instance "$DATA/plants/stochastic.lsys" --json
expect_run instance-randomness 0 '"method":"pseudo-stochastic"' -- "$LSYS" instance "$DATA/plants/stochastic.lsys" --randomness 3 --json
expect_run instance-dialect 0 '"primitives":1330,' -- "$LSYS" instance "$DATA/plants/dialects/gravity_tree_2d.crankshaw" --json
printf '#define N 1\nAxiom: A(N)\nA(x) : x > 0 --> F A(x-1)\n' > "$WORK/count.lsys"
expect_run instance-define 0 '^3 primitives' -- "$LSYS" instance "$WORK/count.lsys" -n 10 -D N=3
expect_run instance-budget 2 'b-grammar budget exceeded: more than 3 nodes' -- "$LSYS" instance "$DATA/plants/fractal_bush.lsys" --max-nodes 3
expect_run instance-word-budget 2 'module budget exceeded' -- "$LSYS" instance "$DATA/plants/context_benchmark.lsys" --max-modules 1000
expect_run instance-bad 2 'bad.lsys:2:12' -- "$LSYS" instance "$WORK/bad.lsys"
expect_run instance-missing 2 'cannot read file' -- "$LSYS" instance "$WORK/does-not-exist.lsys"
# A folder is read as a vlab object: without a .l it is an error naming the folder.
mkdir "$WORK/empty"
expect_run check-folder 2 'empty: error: the vlab object holds no cpfg L-system' -- "$LSYS" check "$WORK/empty"
expect_run check-device 2 'is not a regular file' -- "$LSYS" check /dev/zero
mkfifo "$WORK/fifo.lsys"
expect_run derive-fifo 2 'fifo.lsys.*is not a regular file (a fifo, a device or a socket)' -- "$LSYS" derive "$WORK/fifo.lsys"
expect_run instance-bad-randomness 2 'randomness' -- "$LSYS" instance "$DATA/plants/stochastic.lsys" --randomness -1
expect_run instance-help 0 'instances = references to objects' -- "$LSYS" instance --help
expect_run export 0 '625 primitives, 625 joints' -- "$LSYS" export "$DATA/plants/koch_curve.lsys" -o "$WORK/koch.glb"
[ -s "$WORK/koch.glb" ] || fail "export: no .glb written"
expect_run export-instanced 0 'primitives' -- "$LSYS" export "$DATA/plants/abop_1_24a.lsys" -o "$WORK/a.gltf" --instanced
expect_run export-obj 0 'primitives' -- "$LSYS" export "$DATA/plants/koch_curve.lsys" -o "$WORK/koch.obj" --generalized-cylinders
[ -s "$WORK/koch.mtl" ] || fail "export-obj: no .mtl beside the .obj"
expect_run export-extension 2 "unknown extension '.stl'" -- "$LSYS" export "$DATA/plants/koch_curve.lsys" -o "$WORK/koch.stl"
[ -e "$WORK/koch.stl" ] && fail "export-extension: a file was written"
expect_run export-folder 2 'no-such-folder' -- "$LSYS" export "$DATA/plants/koch_curve.lsys" -o "$WORK/no-such-folder/k.glb"
echo keep > "$WORK/keep.glb"
expect_run export-bad-input 2 'bad.lsys:2:12' -- "$LSYS" export "$WORK/bad.lsys" -o "$WORK/keep.glb"
[ "$(cat "$WORK/keep.glb")" = keep ] || fail "export-bad-input: an existing file was overwritten"
expect_run export-no-output 2 'output' -- "$LSYS" export "$DATA/plants/koch_curve.lsys"
# Only regular files are replaced: a read-only file, a fifo and a folder stay as they are.
echo locked > "$WORK/locked.glb"
chmod 444 "$WORK/locked.glb"
expect_run export-read-only 2 'locked.glb.* is read-only' -- "$LSYS" export "$DATA/plants/koch_curve.lsys" -o "$WORK/locked.glb"
[ "$(cat "$WORK/locked.glb")" = locked ] || fail "export-read-only: a read-only file was replaced"
mkfifo "$WORK/pipe.glb"
expect_run export-fifo 2 'is a fifo' -- "$LSYS" export "$DATA/plants/koch_curve.lsys" -o "$WORK/pipe.glb"
[ -p "$WORK/pipe.glb" ] || fail "export-fifo: the fifo was replaced"
printf 'Axiom: F(1) F(0/0)\n' > "$WORK/nan.lsys"
expect_run export-not-a-number 2 "the turtle's F got NaN" -- "$LSYS" export "$WORK/nan.lsys" -o "$WORK/nan.glb"
[ -e "$WORK/nan.glb" ] && fail "export-not-a-number: a file was written"
printf 'Axiom: F(3e38) F(3e38) F(3e38)\n' > "$WORK/overflow.lsys"
expect_run export-past-float-range 2 "the turtle's F moved it past the float range" -- "$LSYS" export "$WORK/overflow.lsys" -o "$WORK/overflow.glb"
[ -e "$WORK/overflow.glb" ] && fail "export-past-float-range: a file was written"
# The memory budget: each stage refuses before it allocates, naming itself, the need and the limit.
expect_run export-memory-budget 2 'export .*budget.glb: memory budget: export needs 208.0 MiB, the limit is 16.0 MiB (set with --memory-budget)' -- "$LSYS" export "$DATA/plants/fractal_bush.lsys" -n 5 -o "$WORK/budget.glb" --memory-budget 16M
[ -e "$WORK/budget.glb" ] && fail "export-memory-budget: a file was written"
expect_run turtle-memory-budget 2 'memory budget: turtle needs' -- "$LSYS" export "$DATA/plants/fractal_bush.lsys" -n 5 -o "$WORK/budget.obj" --memory-budget 4M
expect_run derive-memory-budget 2 'memory budget: derivation needs' -- "$LSYS" derive "$DATA/plants/fractal_bush.lsys" -n 7 --memory-budget 10M
expect_run instance-memory-budget 2 'memory budget: instance graph needs' -- "$LSYS" instance "$DATA/plants/monopodial_tree.lsys" -n 40 --memory-budget 64M
expect_run memory-budget-fits 0 '88940 modules' -- "$LSYS" derive "$DATA/plants/fractal_bush.lsys" -n 5 --memory-budget 1G
expect_run bad-memory-budget 2 "'lots' is not a size" -- "$LSYS" derive "$DATA/plants/koch_curve.lsys" --memory-budget lots
expect_run zero-memory-budget 2 "'0' is not a size" -- "$LSYS" instance "$DATA/plants/koch_curve.lsys" --memory-budget 0
expect_run memory-budget-help 0 '--memory-budget SIZE' -- "$LSYS" export --help
expect_run derive-negative-steps 2 'steps' -- "$LSYS" derive "$DATA/plants/koch_curve.lsys" -n -1
expect_run help 0 'derive' -- "$LSYS" --help
expect_run version 0 "^lsys $VERSION\$" -- "$LSYS" --version
expect_run derive-help 0 '--max-modules' -- "$LSYS" derive --help
expect_run help-lists-turtle 0 '--help-turtle' -- "$LSYS" --help
expect_run help-turtle 0 '^F  *l = length, w = width  *draw a segment' -- "$LSYS" --help-turtle
# A row for every symbol of the turtle's commands (lsystem/turtle/turtle_commands.cpp), first on its line.
for symbol in F f G g + - '&' '^' '\' / '|' '$' '[' ']' '!' ';' "'" % @Lm @La @Ls @Am @Aa @As @Wm @Wa @Ca @K @Ts @Tv \
    @M @R @O '~name' '{' . '}' @Oc; do
    SYMBOL=$symbol awk '$1 == ENVIRON["SYMBOL"] { found = 1 } END { exit !found }' "$WORK/out" ||
        fail "help-turtle: no row for $symbol: $(cat "$WORK/out")"
done
# A vlab object folder is one plant: its specifications name the .l and the view file.
OBJECT="$DATA/plants/abop/fig2_6a_monopodial_tree"
expect_run object-derive 0 '"modules":7162' -- "$LSYS" derive "$OBJECT" --json
expect_run object-export 0 'object.glb: 1023 primitives' -- "$LSYS" export "$OBJECT" -o "$WORK/object.glb"
expect_run object-instanced 0 'instanced.glb: 1023 primitives' -- "$LSYS" export "$OBJECT" --instanced -o "$WORK/instanced.glb"
mkdir "$WORK/object"
printf 'Lsystem: 1\nAxiom: F\nendlsystem\n' > "$WORK/object/plant.l"
printf 'angle increment: 30\ninitial line width: thin\n' > "$WORK/object/plant.v"
expect_run object-bad-view 2 'plant.v:2:21: error: ' -- "$LSYS" check "$WORK/object"
expect_run object-bad-view-line 2 '^  initial line width: thin$' -- "$LSYS" check "$WORK/object"
# What is exported is what is drawn: --sides, --no-skeleton and --height, read back from the glTF
# (gltf_summary.mjs prints vertices=V nodes=N joints=J skins=S height=H).
SUMMARY="$(dirname "$0")/gltf_summary.mjs"
command -v node > /dev/null || fail "export-drawn: node is missing (tools/deps.sh installs it)"
summary() { node "$SUMMARY" "$1" 2>&1; }
# A frustum with caps has 4(sides+1) vertices: the Koch curve's 625 segments 36 each, 24 with 5 sides.
"$LSYS" export "$DATA/plants/koch_curve.lsys" -o "$WORK/sides8.glb" --geometry frusta 2> /dev/null
"$LSYS" export "$DATA/plants/koch_curve.lsys" -o "$WORK/sides5.gltf" --geometry frusta --sides 5 --skeleton 2> /dev/null
case $(summary "$WORK/sides8.glb") in *'vertices=22500 nodes=627 joints=625 skins=0 '*) ;; *) fail "export-sides-default: $(summary "$WORK/sides8.glb")" ;; esac
case $(summary "$WORK/sides5.gltf") in *'vertices=15000 nodes=627 joints=625 '*) ;; *) fail "export-sides: $(summary "$WORK/sides5.gltf")" ;; esac
# The drawn form (the default) has the renderer's bark tubes: fewer vertices than the frusta, and
# --geometry tubes is --generalized-cylinders.
"$LSYS" export "$DATA/plants/koch_curve.lsys" -o "$WORK/drawn.glb" 2> /dev/null
case $(summary "$WORK/drawn.glb") in *'vertices=22500 '*) fail "export-drawn-default: frusta written" ;; *'vertices='*) ;; *) fail "export-drawn-default: $(summary "$WORK/drawn.glb")" ;; esac
"$LSYS" export "$DATA/plants/koch_curve.lsys" -o "$WORK/tubes.glb" --geometry tubes 2> /dev/null
"$LSYS" export "$DATA/plants/koch_curve.lsys" -o "$WORK/tubes-alias.glb" --generalized-cylinders 2> /dev/null
cmp -s "$WORK/tubes.glb" "$WORK/tubes-alias.glb" || fail "export-geometry-tubes: --generalized-cylinders writes another file"
expect_run export-bad-geometry 2 '--geometry' -- "$LSYS" export "$DATA/plants/koch_curve.lsys" -o "$WORK/bad-geometry.glb" --geometry cones
[ -e "$WORK/bad-geometry.glb" ] && fail "export-bad-geometry: a file was written"
expect_run export-help-geometry 0 'drawn|frusta|tubes' -- "$LSYS" export --help
"$LSYS" export "$DATA/plants/abop_1_24a.lsys" -o "$WORK/sides5-instanced.glb" --instanced --geometry frusta --sides 5 2> /dev/null
case $(summary "$WORK/sides5-instanced.glb") in *'vertices=120 '*) ;; *) fail "export-sides-instanced: $(summary "$WORK/sides5-instanced.glb")" ;; esac
expect_run export-no-skeleton 0 '625 joints' -- "$LSYS" export "$DATA/plants/koch_curve.lsys" -o "$WORK/bare.glb" --no-skeleton
case $(summary "$WORK/bare.glb") in *'nodes=2 joints=0 skins=0 '*) ;; *) fail "export-no-skeleton: $(summary "$WORK/bare.glb")" ;; esac
# --height H: the meshes' y extent is H (within 1e-3 relative) in both forms, whatever the sides, with
# pixel-wide lines (the vlab object) too.
expect_height() { # NAME H FILE
    h=$(summary "$3" | sed -n 's/.*height=\([0-9.]*\).*/\1/p')
    awk -v h="${h:-0}" -v want="$2" 'BEGIN { d = h - want; exit !(d * d <= (1e-3 * want) ^ 2) }' ||
        fail "$1: height ${h:-none}, expected $2: $(summary "$3")"
}
expect_run export-height 0 '10 m tall (scaled by 1.267' -- "$LSYS" export "$DATA/plants/monopodial_tree.lsys" -o "$WORK/tall.glb" --height 10 --sides 5 --no-skeleton
expect_height export-height 10 "$WORK/tall.glb"
"$LSYS" export "$DATA/plants/monopodial_tree.lsys" -o "$WORK/tall-instanced.glb" --height 10 --sides 5 --instanced 2> /dev/null
expect_height export-height-instanced 10 "$WORK/tall-instanced.glb"
"$LSYS" export "$DATA/plants/fractal_bush.lsys" -o "$WORK/bush.gltf" --height 0.5 --instanced --generalized-cylinders 2> /dev/null
expect_height export-height-instanced-bush 0.5 "$WORK/bush.gltf"
"$LSYS" export "$OBJECT" -o "$WORK/object-tall.glb" --height 3 2> /dev/null
expect_height export-height-pixel-lines 3 "$WORK/object-tall.glb"
for bad in 'sides 2:--sides 2' 'sides x:--sides many' 'height 0:--height 0' 'height -1:--height -1' 'height nan:--height nan' 'height inf:--height inf'; do
    # shellcheck disable=SC2086 # the flag and its value are two words
    expect_run "export-bad-${bad%%:*}" 2 "--${bad%% *}" -- "$LSYS" export "$DATA/plants/koch_curve.lsys" -o "$WORK/bad-value.glb" ${bad#*:}
    [ -e "$WORK/bad-value.glb" ] && fail "export-bad-${bad%%:*}: a file was written"
done
printf 'Axiom: A\n' > "$WORK/nothing.lsys"
expect_run export-height-nothing 2 'no height to scale' -- "$LSYS" export "$WORK/nothing.lsys" -o "$WORK/nothing.glb" --height 2
[ -e "$WORK/nothing.glb" ] && fail "export-height-nothing: a file was written"
expect_run export-help-drawn 0 '--no-skeleton' -- "$LSYS" export --help
expect_run export-help-height 0 '--height H' -- "$LSYS" export --help
expect_run no-command 2 'subcommand' -- "$LSYS"
expect_run bad-option 2 'steps' -- "$LSYS" derive "$DATA/plants/koch_curve.lsys" -n many

[ "$failures" = 0 ] && echo "all lsys CLI checks passed"
[ "$failures" = 0 ]
