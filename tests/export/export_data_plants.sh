#!/bin/sh
# Exports every plant in data/plants (dialect files included) with `lsys
# export`, flat .glb and instanced .gltf, and every component plant in
# data/components (flat only: it has no b-grammar), for the glTF-Validator test.
# Usage: export_data_plants.sh LSYS DATA_DIR OUT_DIR
set -eu
lsys=$1 data=$2 out=$3
rm -rf "$out"
mkdir -p "$out"
for file in "$data"/plants/*.lsys "$data"/plants/dialects/*; do
  name=$(basename "$file" | tr . _)
  "$lsys" export "$file" -o "$out/$name.glb" 2>/dev/null
  "$lsys" export "$file" -o "$out/${name}_instanced.gltf" --instanced 2>/dev/null
done
for file in "$data"/components/*.comp.json; do
  "$lsys" export "$file" -o "$out/$(basename "$file" | tr . _).glb" 2>/dev/null
done
echo "exported $(ls "$out" | wc -l) files to $out"
