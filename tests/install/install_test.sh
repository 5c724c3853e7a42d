#!/bin/sh
# InstallTree.ConsumerProjectBuildsAgainstTheInstalledLibrary (docs/INSTALL.md):
# installs the build tree to a temporary prefix, checks the layout, builds
# tests/install/consumer against it with find_package and with pkg-config,
# runs it, and runs the installed tools, checking that they find the installed
# data (and that PLANTFIELD_DATA_DIR still overrides it). No Vulkan device needed.
# Usage: install_test.sh CMAKE BUILD_DIR CONFIG CONSUMER_DIR GENERATOR CXX LIBDIR VERSION
set -u
CMAKE=$1 BUILD=$2 CONFIG=$3 CONSUMER=$4 GENERATOR=$5 CXX=$6 LIBDIR=$7 VERSION=$8
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
WORK=$(cd "$WORK" && pwd -P) # the tools see their real path (/proc/self/exe)
PREFIX=$WORK/prefix
failures=0
. "$(dirname "$0")/../support/expect.sh"

if ! "$CMAKE" --install "$BUILD" --config "$CONFIG" --prefix "$PREFIX" > "$WORK/install.log" 2>&1; then
    cat "$WORK/install.log"
    echo "FAIL: cmake --install $BUILD (build every target first)"
    exit 1
fi

for path in bin/plantfield bin/plantbench bin/physics_bench bin/lsys \
    "$LIBDIR/libplantfield_lsystem_common.a" \
    include/plantfield/lsystem/rewriting/rewriter.h include/plantfield/lsystem/dialects/dialect.h \
    include/plantfield/lsystem/vlab/object.h \
    "$LIBDIR/cmake/plantfield/plantfieldConfig.cmake" "$LIBDIR/cmake/plantfield/plantfieldConfigVersion.cmake" \
    "$LIBDIR/cmake/plantfield/plantfieldTargets.cmake" "$LIBDIR/pkgconfig/plantfield-lsystem.pc" \
    share/plantfield/data/scenes/default.json share/plantfield/data/plants/fractal_bush.lsys; do
    [ -e "$PREFIX/$path" ] || fail "not installed: $path"
done
[ -e "$PREFIX/include/plantfield/lsystem/CMakeLists.txt" ] && fail "install copies more than the headers"
# Every L-system library the .pc file links is installed (one per concern, lsystem/CMakeLists.txt).
for flag in $(sed -n 's/^Libs: //p' "$PREFIX/$LIBDIR/pkgconfig/plantfield-lsystem.pc"); do
    case $flag in
    -lplantfield_*) [ -e "$PREFIX/$LIBDIR/lib${flag#-l}.a" ] || fail "not installed: $LIBDIR/lib${flag#-l}.a" ;;
    esac
done

# find_package(plantfield COMPONENTS lsystem), target plantfield::lsystem.
if "$CMAKE" -S "$CONSUMER" -B "$WORK/consumer-cmake" -G "$GENERATOR" -DCMAKE_CXX_COMPILER="$CXX" \
    -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$PREFIX" > "$WORK/configure.log" 2>&1 &&
    "$CMAKE" --build "$WORK/consumer-cmake" > "$WORK/build.log" 2>&1; then
    expect_run cmake-consumer 0 '^modules 66$' -- "$WORK/consumer-cmake/consumer" "$WORK/cmake.glb"
else
    fail "consumer project (CMake) does not build: $(cat "$WORK/configure.log" "$WORK/build.log" 2>/dev/null)"
fi
# A component the package does not have is an error.
mkdir -p "$WORK/bad-component"
printf 'cmake_minimum_required(VERSION 3.25)\nproject(bad LANGUAGES CXX)\nfind_package(plantfield REQUIRED COMPONENTS engine)\n' \
    > "$WORK/bad-component/CMakeLists.txt"
"$CMAKE" -S "$WORK/bad-component" -B "$WORK/bad-component/build" -DCMAKE_PREFIX_PATH="$PREFIX" > "$WORK/out" 2>&1 &&
    fail "find_package(plantfield COMPONENTS engine) succeeds"

# pkg-config, where there is one.
if command -v pkg-config > /dev/null 2>&1; then
    export PKG_CONFIG_PATH="$PREFIX/$LIBDIR/pkgconfig"
    expect_run pc-version 0 "^$VERSION\$" -- pkg-config --modversion plantfield-lsystem
    # shellcheck disable=SC2046 # the flags are words
    if "$CXX" -std=c++20 -O1 "$CONSUMER/main.cpp" -o "$WORK/consumer-pc" \
        $(pkg-config --cflags --libs plantfield-lsystem) > "$WORK/pc.log" 2>&1; then
        expect_run pc-consumer 0 '^modules 66$' -- "$WORK/consumer-pc" "$WORK/pc.glb"
    else
        fail "consumer (pkg-config) does not build: $(cat "$WORK/pc.log")"
    fi
else
    echo "pkg-config not found: the .pc file is not checked"
fi

# The installed tools.
for tool in plantfield plantbench physics_bench lsys; do
    expect_run "$tool-version" 0 "$VERSION" -- "$PREFIX/bin/$tool" --version
done
expect_run lsys-installed-data 0 '"modules":1388' -- \
    "$PREFIX/bin/lsys" derive "$PREFIX/share/plantfield/data/plants/fractal_bush.lsys" -n 3 --json

# Data resolution (tools/data_dir.h). Each run stops at option checking, so
# no device is needed: a --capture path in a missing folder fails only after
# the scene file was found.
unset PLANTFIELD_DATA_DIR
expect_run installed-data 2 'cannot write --capture file' -- \
    "$PREFIX/bin/plantfield" --capture "$WORK/no/such/folder/frame.png"
# The tree moved elsewhere: its binary reads its own share/, not the source tree's data/.
mv "$PREFIX" "$WORK/moved"
rm "$WORK/moved/share/plantfield/data/scenes/default.json"
expect_run moved-tree 2 "scene file '$WORK/moved/share/plantfield/data/scenes/default.json' does not exist" -- \
    "$WORK/moved/bin/plantfield" --capture "$WORK/frame.png"
expect_run moved-tree-plantbench 2 "$WORK/moved/share/plantfield/data/scenes/default.json" -- \
    "$WORK/moved/bin/plantbench" --counts 1000
mkdir -p "$WORK/elsewhere"
expect_run env-overrides 2 "scene file '$WORK/elsewhere/scenes/default.json' does not exist" -- \
    env PLANTFIELD_DATA_DIR="$WORK/elsewhere" "$WORK/moved/bin/plantfield" --capture "$WORK/frame.png"

if [ "$failures" -ne 0 ]; then
    echo "$failures check(s) failed"
    exit 1
fi
echo "install tree, consumer (CMake$(command -v pkg-config > /dev/null 2>&1 && echo ' and pkg-config')) and installed tools: ok"
