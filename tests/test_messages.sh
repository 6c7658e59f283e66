#!/usr/bin/env bash
# What a user reads: `cg help draw` lists every command of the draw language,
# numbers out of range are refused with the range named, a UTF-8 byte-order
# mark before a script's first line is skipped, `cg demo --only` with no
# matching section fails, and an unknown command exits with the same status
# through `cg help NAME` and `cg NAME`.
# Usage: test_messages.sh CG SOURCE_DIR BUILD_DIR
set -u
cg="$1" src="$2"
. "$src/tests/cli_checks.sh"

# ---- cg help draw: every command of docs/draw-script.md's tables, each one
# known to the interpreter (not reported as an unknown command).
expect 0 "help draw" "$cg" help draw
cp "$work/out" "$work/help"
documented=$(grep -o '^| `[a-z0-9]*' "$src/docs/draw-script.md" | cut -c4-)
[ "$(echo "$documented" | wc -l)" -ge 30 ] && pass || fail "docs/draw-script.md lists too few commands"
for name in $documented polygon contour aapolygon path fill stroke width join cap dash flood \
            flood8 boundaryfill fillrule; do
  grep -qE "(^|[^a-z0-9])$name( |$)" "$work/help" && pass || fail "cg help draw does not list '$name'"
  printf 'size 8 8\n%s\n' "$name" > "$work/one.txt"
  "$cg" draw "$work/one.txt" -o "$work/one.png" 2>"$work/err"
  grep -q "unknown command" "$work/err" && fail "'$name' is listed but unknown" || pass
done

# ---- numbers out of range name the range: one line, status 1, no output.
# draw_bad LINE TEXT: the script "size 20 20" + LINE fails saying TEXT.
draw_bad() {
  printf 'size 20 20\n%s\n' "$1" > "$work/bad.txt"
  rm -f "$work/bad.png"
  expect 1 "draw '$1'" "$cg" draw "$work/bad.txt" -o "$work/bad.png"
  one_line "draw '$1'"
  grep -qF -- "$2" "$work/err" && pass || fail "draw '$1': '$(cat "$work/err")' lacks '$2'"
  [ ! -e "$work/bad.png" ] && pass || fail "draw '$1' wrote an image"
}
draw_bad "aacircle 10 10 1e12" "bad.txt:2: R = 1e12 is out of range: anti-aliased circles take radii up to 1e9"
draw_bad "aaellipse 10 10 3 2e9" "out of range: anti-aliased ellipses take radii up to 1e9"
draw_bad "ellipse 10 10 2000000000 3" "out of range: ellipses take radii up to 2^30 = 1073741824"
draw_bad "width 1e300" "expected a stroke width W > 0 and at most 2^40 = 1099511627776, got '1e300'"
draw_bad "width 0" "expected a stroke width W > 0 and at most 2^40"
draw_bad "path M 0 0 L 2e12 0 L 5 5 Z" "path data, offset 8: 2e12 after 'L' is out of range: coordinates are at most 2^40 = 1099511627776 in magnitude"
draw_bad "path M 0 0 L 1e300,0" "1e300 after 'L' is out of range"
draw_bad "path M -1.2e12 0 L 5 5" "-1.2e12 after 'M' is out of range"
draw_bad "polygon 0 0 3e12 0 5 5" "X1 = 3e12 is out of range: coordinates are at most 2^40"
draw_bad "aapolygon 0 0 3 0 5 -1e13" "Y2 = -1e13 is out of range"
draw_bad "bezier 0 0 2e9 1 3 3" "coordinates beyond 1e9 in magnitude"
# Within the limits the same commands draw.
printf 'size 20 20\naacircle 10 10 1e9\npath M 0 0 L 1e12 0 L 5 5 Z\nfill\npolygon 0 0 1e12 0 5 5\nwidth 1e12\nstroke\n' \
  > "$work/edge.txt"
expect 0 "coordinates at the limits" "$cg" draw "$work/edge.txt" -o "$work/edge.png"

# --size names both limits.
for size in 0x10 10x0 20000000x1 100000x100000 axb; do
  expect 2 "render --size $size" "$cg" render "$src/data/meshes/bunny.obj" --size "$size" -o "$work/s.png"
  one_line "--size $size"
  grep -qF "each from 1 to 16777216, at most 268435456 pixels in all, got '$size'" "$work/err" \
    && pass || fail "--size $size: $(cat "$work/err")"
done

# ---- a UTF-8 byte-order mark before line 1 is skipped: the same picture as
# without it; elsewhere it is still an error.
printf 'size 6 4\ncolor red\nline 0 0 5 3\n' > "$work/plain.txt"
printf '\357\273\277size 6 4\ncolor red\nline 0 0 5 3\n' > "$work/bom.txt"
expect 0 "script without a BOM" "$cg" draw "$work/plain.txt" -o "$work/plain.ppm"
expect 0 "script with a BOM" "$cg" draw "$work/bom.txt" -o "$work/bom.ppm"
cmp -s "$work/plain.ppm" "$work/bom.ppm" && pass || fail "a BOM changed the picture"
printf '\357\273\277size 6 4\n' | "$cg" draw - -o "$work/stdin.ppm" 2>"$work/err" && pass \
  || fail "BOM on stdin: $(cat "$work/err")"
printf 'size 6 4\n\357\273\277line 0 0 5 3\n' > "$work/bom2.txt"
expect 1 "a BOM on line 2" "$cg" draw "$work/bom2.txt" -o "$work/bom2.ppm"

# ---- cg demo --only with no matching section fails and writes nothing.
expect 2 "demo --only NOMATCH" "$cg" demo --only NOMATCH -o "$work/nomatch"
one_line "demo --only NOMATCH"
grep -q "no section title contains 'NOMATCH'" "$work/err" && pass || fail "demo --only: $(cat "$work/err")"
[ ! -e "$work/nomatch" ] && pass || fail "demo --only NOMATCH created its folder"
expect 0 "demo --only Clipping" "$cg" demo --only Clipping -o "$work/clipping"
ls "$work/clipping"/*.png >/dev/null 2>&1 && pass || fail "demo --only Clipping wrote no picture"

# ---- unknown commands: the same status both ways, one line each.
"$cg" bogus >/dev/null 2>"$work/err1"; direct=$?
"$cg" help bogus >/dev/null 2>"$work/err2"; helped=$?
[ "$direct" = 2 ] && [ "$helped" = 2 ] && pass || fail "cg bogus exits $direct, cg help bogus $helped"
[ "$(wc -l < "$work/err1")" = 1 ] && [ "$(wc -l < "$work/err2")" = 1 ] && pass || fail "unknown command: one line"

# ---- the docs stand on their own: every relative link of README.md and
# docs/*.md names a file of the repository, and none points at the lecture
# notes as a file (they are cited by chapter and section).
for page in "$src/README.md" "$src"/docs/*.md; do
  for target in $(grep -o '](\([^)#]*\))' "$page" | sed 's/^](//; s/)$//' | grep -v '://'); do
    [ -e "$(dirname "$page")/$target" ] && pass || fail "$(basename "$page") links to missing $target"
  done
done
grep -rlE 'lecture-notes\.txt|seed/' "$src/README.md" "$src/docs" && fail "docs refer to a notes file" || pass

finish
