#!/usr/bin/env bash
# libcg links cleanly into someone else's program:
#  1. the global symbols that libcg.a and libcg.so define are exactly the
#     functions the public headers declare (as the compiler lists them with
#     gcc -aux-info, independently of the build's own list);
#  2. a program that defines every name libcg uses internally links against
#     both libraries and runs.
# Usage: test_symbols.sh CG SOURCE_DIR BUILD_DIR
set -eu
source_dir="$2"
build_dir="$3"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
passed=0
failed=0
check() { # NAME COMMAND...
  local name="$1"; shift
  if "$@"; then passed=$((passed + 1)); else echo "FAIL: $name" >&2; failed=$((failed + 1)); fi
}
for tool in gcc nm; do
  command -v $tool >/dev/null || { echo "test_symbols: needs $tool (Debian package build-essential)" >&2; exit 1; }
done

# The public API as the compiler sees it: every function declared in
# include/cg/*.h that is not static inline.
echo '#include <cg.h>' > "$work/all.c"
gcc -std=c11 -I "$source_dir/include" -aux-info "$work/aux.txt" -c "$work/all.c" -o "$work/all.o"
grep '^/\* [^ ]*include/cg/[a-z0-9_]*\.h:' "$work/aux.txt" | grep -v '\*/ static ' |
  sed 's/^[^(]*[ *]\(cg_[A-Za-z0-9_]*\) (.*/\1/' | sort -u > "$work/declared.txt"
[ -s "$work/declared.txt" ] || { echo "FAIL: no public declaration found" >&2; exit 1; }

# OpenEXRCore when this build has OpenEXR (libcg.a then calls exr_*).
exr_libs=
if nm -u "$build_dir/libcg.a" | grep -q ' exr_start_read$'; then exr_libs=-lOpenEXRCore-3_1; fi
nm -g --defined-only "$build_dir/libcg.a" | awk 'NF == 3 { print $3 }' | sort -u > "$work/static.txt"
nm -D --defined-only "$build_dir/libcg.so" | awk 'NF == 3 && $3 !~ /^CG_/ { print $3 }' |
  sed 's/@.*//' | sort -u > "$work/shared.txt"
same_as_declared() { # LIST
  if ! diff -u "$work/declared.txt" "$1" > "$work/diff.txt"; then
    echo "$1: global symbols differ from the public headers' (- declared only, + defined only):" >&2
    grep '^[-+][a-z_]' "$work/diff.txt" | head -20 >&2
    return 1
  fi
}
check "libcg.a defines only the public API" same_as_declared "$work/static.txt"
check "libcg.so exports only the public API" same_as_declared "$work/shared.txt"

# Every global name of the modules (the library before its internal names
# are made local), less the public ones: the names a user's program must be
# free to define.
nm -g --defined-only "$build_dir/libcg_internal.a" | awk 'NF == 3 { print $3 }' | sort -u |
  comm -23 - "$work/declared.txt" > "$work/internal.txt"
count=$(wc -l < "$work/internal.txt")
check "the modules have internal names to hide ($count)" test "$count" -gt 50
sed 's/.*/int &[4] = {1};/' "$work/internal.txt" > "$work/names.c"
# The README's bunny scene, small, with its mesh found from the work folder.
scene="$work/bunny.json"
sed -e 's/"width": 640, "height": 480/"width": 160, "height": 120/' \
    -e "s|\\.\\./\\.\\./data/|$source_dir/data/|" "$source_dir/examples/scenes/bunny.json" > "$scene"
user="$source_dir/tests/symbols_user_program.c"
run_user() { # PROGRAM [ENV...]
  "$@" "$scene" "$work/out.png" > "$work/run.txt" 2>&1 && grep -q '^union area 7$' "$work/run.txt"
}
link_static() {
  gcc -std=c11 -I "$source_dir/include" "$user" "$work/names.c" "$build_dir/libcg.a" \
    $(pkg-config --libs libpng zlib libcjson libjpeg expat freetype2 harfbuzz fontconfig) $exr_libs -lm -lpthread -o "$work/user-static" 2> "$work/link.txt" ||
    { head -5 "$work/link.txt" >&2; return 1; }
  run_user "$work/user-static"
}
link_shared() {
  gcc -std=c11 -I "$source_dir/include" "$user" "$work/names.c" -L "$build_dir" -lcg \
    -Wl,-rpath,"$build_dir" -o "$work/user-shared" 2> "$work/link.txt" ||
    { head -5 "$work/link.txt" >&2; return 1; }
  run_user "$work/user-shared"
}
check "a program defining every internal name links libcg.a and runs" link_static
check "a program defining every internal name links libcg.so and runs" link_shared
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
