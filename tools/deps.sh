#!/usr/bin/env bash
# Installs every Debian 12 package the project needs, and only what is missing.
# This is the one list; run.sh, test.sh and the other scripts call it. Safe to
# run again: when all packages are present it returns at once without apt.
# Usage: tools/deps.sh [fuzz] [bench]
#   fuzz:  clang and libFuzzer for tools/fuzz.sh
#   bench: hyperfine for the peer benchmarks in tools/bench/
# cpp, the C preprocessor, is a run-time need too: cpfg files are read through
# it as cpfg reads them through vlabcpp (docs/DIALECTS.md).
# pybind11, the Python headers, pytest and NumPy build and test the Python
# module (tools/python, docs/PYTHON.md).
# ffmpeg encodes plantfield --video (engine/image/video_encoder.h), a program
# run, not a library linked.
# Node.js and npm are in the default list (tests/export runs the Khronos
# glTF-Validator with them); a machine that already has node and npm, from
# Debian or elsewhere, keeps its own.
set -euo pipefail

PACKAGES=(
  build-essential cmake ninja-build pkg-config
  cpp
  libvulkan-dev mesa-vulkan-drivers vulkan-validationlayers glslang-tools
  libglm-dev libglfw3-dev libstb-dev libcli11-dev nlohmann-json3-dev
  libgtest-dev libbenchmark-dev xvfb xauth libtinygltf-dev gnuplot-nox
  clang-format
  pybind11-dev python3-dev python3-pytest python3-numpy
  ffmpeg
)
command -v node >/dev/null && command -v npm >/dev/null || PACKAGES+=(nodejs npm)
FUZZ_PACKAGES=(clang libclang-rt-14-dev)
BENCH_PACKAGES=(hyperfine)

for group in "$@"; do
  case "$group" in
    fuzz) PACKAGES+=("${FUZZ_PACKAGES[@]}") ;;
    bench) PACKAGES+=("${BENCH_PACKAGES[@]}") ;;
    *) echo "deps.sh: unknown package group '$group' (known: fuzz, bench)" >&2; exit 2 ;;
  esac
done

missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "deps: installing ${missing[*]}" >&2
SUDO=""
[ "$(id -u)" -ne 0 ] && SUDO="sudo"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
