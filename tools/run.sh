#!/usr/bin/env bash
# The main job: install, build, and render the default forest (data/scenes/default.json) to
# out/default.png (1280x720). Extra arguments go to plantfield, e.g.
#   tools/run.sh --window        real-time view (also saves the last frame)
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
"$root/tools/build.sh" plantfield
mkdir -p "$root/out"
output="$root/out/default.png"
"${BUILD_DIR:-$root/build}/tools/plantfield/plantfield" --capture "$output" --size 1280x720 "$@"
echo "run.sh: the default scene is in $output"
