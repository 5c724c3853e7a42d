#!/usr/bin/env bash
# Fuzzes one loader with libFuzzer (clang, with address and undefined-behaviour
# sanitizers) for SECONDS (default 120):
#   lsys   the dialect-aware .lsys parser, the rewriter and the turtle
#   scene  the scene loader (JSON, validation, paths, placement rules)
#   components  component plants (.comp.json: reader, counts, builder)
#   gltf   the glTF surface loader (tinygltf behind our own checks)
#   view, func, surface, colour   a vlab object's readers (lsystem/vlab): the
#          view file, function files and sets, surface files, colour maps
#          and material files; seeded from their corpus alone
#   ramification  ramification matrices (.ram.json): reader, generator, turtle
#   terrain  terrain L-systems: derivation, the mountain turtle, the bumps
#   cloud  cloud L-systems: derivation, turtle, the spheres of a cloud
# It works on a scratch corpus in build-fuzz/run-TARGET seeded from
# tests/fuzz/corpus/TARGET and the shipped files of that kind, then keeps in
# tests/fuzz/corpus/TARGET the fewest inputs that reach every edge either
# reached, which the regular test suite replays. A crash leaves build-fuzz/crash-*: fix it, then add the
# input to tests/fuzz/crashers/TARGET.
# Usage: tools/fuzz.sh [lsys|scene|components|gltf|view|func|surface|colour|ramification|terrain|cloud] [SECONDS]
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
target=${1:-lsys}
seconds=${2:-120}
case "$target" in
  lsys) seeds=("$root/data/plants") options=(-dict="$root/tests/fuzz/lsys.dict" -max_len=4096) ;;
  scene) seeds=("$root/data/scenes") options=(-dict="$root/tests/fuzz/scene.dict" -max_len=8192) ;;
  components) seeds=("$root/data/components") options=(-dict="$root/tests/fuzz/components.dict" -max_len=8192) ;;
  gltf) seeds=("$root/data/meshes") options=(-dict="$root/tests/fuzz/gltf.dict" -max_len=16384) ;;
  view | func | surface) seeds=() options=(-dict="$root/tests/fuzz/$target.dict" -max_len=4096) ;;
  colour) seeds=() options=(-max_len=4096) ;;
  ramification) seeds=("$root/data/ramified") options=(-dict="$root/tests/fuzz/ramification.dict" -max_len=4096) ;;
  terrain) seeds=("$root/data/terrain") options=(-dict="$root/tests/fuzz/lsys.dict" -max_len=4096) ;;
  cloud) seeds=("$root/data/clouds") options=(-dict="$root/tests/fuzz/lsys.dict" -max_len=4096) ;;
  *) echo "fuzz.sh: unknown target '$target' (known: lsys, scene, components, gltf, view, func, surface, colour, ramification, terrain, cloud)" >&2; exit 2 ;;
esac
build=$root/build-fuzz
"$root/tools/deps.sh" fuzz
if [ ! -f "$build/build.ninja" ]; then
  cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ -DPLANTFIELD_FUZZ=ON >/dev/null
fi
cmake --build "$build" --target "${target}_fuzzer"
fuzzer=$build/tests/fuzz/${target}_fuzzer
corpus=$root/tests/fuzz/corpus/$target
mkdir -p "$build/run-$target" "$corpus"
cd "$build"
"$fuzzer" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=4096 "${options[@]}" \
  "$build/run-$target" "$corpus" "${seeds[@]}"
# The repository keeps the fewest inputs that reach every edge the corpus and
# this run reached (-use_counters=0: edges, not hit counts, which would keep
# five times as many), so that ctest replays it in seconds.
minimal=$(mktemp -d)
"$fuzzer" -merge=1 -use_counters=0 -timeout=10 "$minimal" "$corpus" "$build/run-$target" 2>/dev/null
rm -f "$corpus"/*
mv "$minimal"/* "$corpus"/ 2>/dev/null || true
rmdir "$minimal"
echo "fuzz.sh: the $target corpus now has $(ls "$corpus" | wc -l) inputs"
