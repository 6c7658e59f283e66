#!/usr/bin/env bash
# A `polygon` or `aapolygon` line of `cg draw`, with its contour lines, needs
# memory for its points and edges only, never a copy of the canvas rows it
# covers (docs/draw-script.md, "Filling").  A 16 x 2,097,152 canvas
# (128 MiB) is filled by polygons that span every row, with the program's
# address space limited to the canvas plus 112 MiB: a copy of the rows would
# need 128 MiB more.  The script ends with a line that fails on purpose, so
# that no image is encoded and the test stays fast; the message must name
# that last line, after every polygon has been drawn.
# Usage: test_draw_polygon_memory.sh CG SOURCE_DIR BUILD_DIR
set -u
cg="$1"
src="$2"
build="$3"
. "$src/tests/cli_checks.sh"

if grep -q '^CG_SANITIZE:BOOL=ON' "$build/CMakeCache.txt" 2>/dev/null; then
  echo "skipped: a sanitizer build reserves terabytes of address space, so ulimit -v cannot work"
  exit 77
fi
limit_kb=$(((128 + 112) * 1024))

run_limited() { # run_limited SCRIPT -> stderr in $work/err
  (ulimit -v $limit_kb && printf '%b\n' "$1" | "$cg" draw - -o "$work/tall.pgm") 2>"$work/err"
}

# The canvas alone fits in the limit (else the limit says nothing).
run_limited 'size 16 2097152\nline 0 0 1 1'
if [ $? -ne 0 ]; then
  echo "skipped: the canvas alone does not fit in $limit_kb KiB here: $(cat "$work/err")"
  exit 77
fi
rm -f "$work/tall.pgm"

tall='size 16 2097152\ncolor #808080
polygon 1 0 2 0 2 2097152 1 2097152
contour 3 0 4 0 4 2097152 3 2097152
contour 5 0 6 0 6 2097152 5 2097152
aapolygon 8 0 9.5 0 9.5 2097152 8 2097152
contour 10 0 11 0 11 2097152 10 2097152
fillrule evenodd
polygon 12 0 15 0 15 2097152 12 2097152
contour 13 0 14 0 14 2097152 13 2097152
line 0 0 1 1
contour 1 1 2 1 2 2'
run_limited "$tall"
want="<stdin>:12: 'contour' must follow a polygon, aapolygon or contour line"
if [ "$(cat "$work/err")" = "$want" ]; then pass; else
  fail "polygons over every row of a 128 MiB canvas: '$(cat "$work/err")', want '$want'"; fi
[ ! -e "$work/tall.pgm" ] && pass || fail "an image was written for a script with an error"

finish
