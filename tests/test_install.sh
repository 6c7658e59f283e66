#!/usr/bin/env bash
# Installs cg into a temporary prefix and builds the examples out of tree
# against it, once through CMake's find_package(cg) and once through
# pkg-config, then runs them.
# Usage: test_install.sh CG SOURCE_DIR BUILD_DIR
set -eu
source_dir="$2"
build_dir="$3"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
prefix="$work/prefix"

cmake --install "$build_dir" --prefix "$prefix" >/dev/null
test -f "$prefix/include/cg.h"
test -f "$prefix/lib/libcg.a" || test -f "$prefix/lib64/libcg.a" || ls "$prefix"/lib*/libcg.a >/dev/null

# 1. CMake package.
cmake -S "$source_dir/examples" -B "$work/cmake-build" -DCMAKE_PREFIX_PATH="$prefix" >/dev/null
cmake --build "$work/cmake-build" >/dev/null
"$work/cmake-build/example_transform_points" | head -1 | grep -q '^10 0 0$'
(cd "$work" && "$work/cmake-build/example_draw_png" "$work/a.png" && test -s "$work/a.png")

# 2. pkg-config: shared library, and the static archive with --static.
pcdir=$(dirname "$(ls "$prefix"/lib*/pkgconfig/cg.pc)")
libdir=$(dirname "$pcdir")
export PKG_CONFIG_PATH="$pcdir"
cc -std=c11 "$source_dir/examples/transform_points.c" -o "$work/tp-shared" $(pkg-config --cflags --libs cg)
# As a user runs it: no LD_LIBRARY_PATH (the link line carries the rpath).
env -u LD_LIBRARY_PATH "$work/tp-shared" | head -1 | grep -q '^10 0 0$'
ldd "$work/tp-shared" | grep "libcg\.so" | grep -qv "not found"
static_libs=$(pkg-config --static --libs cg | sed "s|-lcg|$libdir/libcg.a|")
cc -std=c11 "$source_dir/examples/transform_points.c" -o "$work/tp-static" $(pkg-config --cflags cg) $static_libs
"$work/tp-static" | head -1 | grep -q '^10 0 0$'
echo "3 passed, 0 failed"
