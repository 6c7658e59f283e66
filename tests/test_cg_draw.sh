#!/bin/bash
# cg draw: scripts, output formats, error messages with line numbers, no
# output on error, --repeat timing.
set -u
CG=$1
BUILD=$3
dir=$(mktemp -d "${BUILD:-/tmp}/cg_draw_test.XXXXXX")
trap 'rm -rf "$dir"' EXIT
fail=0
ok() { echo "FAIL: $*"; fail=1; }

# Pixel bytes of a binary PPM/PGM (after the three header lines).
pixels() { tail -c "$2" "$1" | od -An -tu1 -v | tr -s ' \n' ' ' | sed 's/^ //; s/ $//'; }

# A 4 x 3 canvas, black background, a white Bresenham line (0,0)-(3,2):
# dx = 3, dy = 2, f0 = 1 -> NE (1,1), f = -1 -> E (2,1), f = 3 -> NE (3,2).
cat > "$dir/line.draw" <<'SCRIPT'
# comment line
size 4 3          # the canvas
background black
color white
line 0 0 3 2
SCRIPT
"$CG" draw "$dir/line.draw" -o "$dir/line.pgm" || ok "line script failed"
want="255 0 0 0 0 255 255 0 0 0 0 255"
[ "$(pixels "$dir/line.pgm" 12)" = "$want" ] || ok "line pixels: $(pixels "$dir/line.pgm" 12)"

# From stdin, reversed endpoints: same pixels.
printf 'size 4 3\nbackground #000000\ncolor #ffffff\nline 3 2 0 0\n' |
    "$CG" draw - -o "$dir/stdin.pgm" || ok "stdin script failed"
[ "$(pixels "$dir/stdin.pgm" 12)" = "$want" ] || ok "reversed line differs"

# PPM output and a colour with alpha over a colour, a circle of radius 1.
printf 'size 3 3\nbackground black\ncolor #ff0000\ncircle 1 1 1\n' > "$dir/circle.draw"
"$CG" draw "$dir/circle.draw" -o "$dir/circle.ppm" || ok "circle script failed"
[ "$(pixels "$dir/circle.ppm" 27)" = "0 0 0 255 0 0 0 0 0 255 0 0 0 0 0 255 0 0 0 0 0 255 0 0 0 0 0" ] ||
    ok "circle pixels: $(pixels "$dir/circle.ppm" 27)"

# Every command of the language runs.
cat > "$dir/all.draw" <<'SCRIPT'
size 120 90
background white
color #1f77b4
line 5 5 115 85
aaline 5.5 85.5 115.5 5.5
polyline 10 10 20 30 40 10
circle 60 45 30
disc 20 70 10
aacircle 60 45 20.5
color #ff000080
ellipse 60 45 50 20
aaellipse 60 45 40 15.5
arc 60 45 35 0 135
ellipsearc 60 45 55 25 180 300
tolerance 0.1
bezier 10 80 40 10 80 80 110 10
hermite 10 45 110 45 200 -100 200 100
antialias on
bspline 10 10 30 80 60 10 90 80 110 10
catmullrom 10 10 30 80 60 10 90 80 110 10
SCRIPT
"$CG" draw "$dir/all.draw" -o "$dir/all.png" || ok "full script failed"
[ -s "$dir/all.png" ] || ok "no png written"

# --repeat prints the median drawing time.
"$CG" draw "$dir/all.draw" -o "$dir/all2.png" --repeat 3 2> "$dir/time.txt" || ok "--repeat failed"
grep -Eq '^draw: [0-9]+(\.[0-9]+)? ms$' "$dir/time.txt" || ok "--repeat output: $(cat "$dir/time.txt")"
cmp -s "$dir/all.png" "$dir/all2.png" || ok "--repeat drew a different picture"

# Errors: FILE:LINE: message, non-zero exit, no output written.
expect_error() { # name, script text, pattern of the message
    printf '%b' "$2" > "$dir/bad.draw"
    rm -f "$dir/bad.png"
    if "$CG" draw "$dir/bad.draw" -o "$dir/bad.png" 2> "$dir/err.txt"; then
        ok "$1: should fail"
    fi
    grep -Eq "$3" "$dir/err.txt" || ok "$1: message '$(cat "$dir/err.txt")' does not match '$3'"
    [ ! -e "$dir/bad.png" ] || ok "$1: output written despite the error"
}
expect_error "unknown command" 'size 4 4\n\nsquare 1 2 3\n' 'bad.draw:3: unknown command .square.'
expect_error "missing argument" 'size 4 4\nline 0 0 3\n' "bad.draw:2: 'line' expects 4 arguments"
expect_error "not a number" 'size 4 4\ncircle 1 x 1\n' 'bad.draw:2: expected an integer for CY'
expect_error "decimal for Bresenham" 'size 4 4\nline 0 0 3.5 1\n' 'bad.draw:2: expected an integer for X1'
expect_error "negative radius" 'size 4 4\ncircle 1 1 -2\n' 'bad.draw:2: expected a radius R >= 0'
expect_error "nan" 'size 4 4\naaline 0 0 nan 1\n' 'bad.draw:2: expected a finite number for X1'
expect_error "inf" 'size 4 4\naacircle 1 1 inf\n' 'bad.draw:2: expected a finite number for R'
expect_error "no size" 'color red\nline 0 0 1 1\n' "bad.draw:2: expected 'size W H' before"
expect_error "size twice" 'size 4 4\nsize 5 5\n' 'bad.draw:2: .*only once'
expect_error "huge size" 'size 100000000 100000000\n' 'bad.draw:1: expected a canvas size'
expect_error "zero size" 'size 0 4\n' 'bad.draw:1: expected a canvas size'
expect_error "bad colour" 'size 4 4\ncolor #12345\n' 'bad.draw:2: expected a colour'
expect_error "zero tolerance" 'size 4 4\ntolerance 0\n' 'bad.draw:2: expected a tolerance T > 0'
expect_error "negative tolerance" 'size 4 4\ntolerance -1\n' 'bad.draw:2: expected a tolerance T > 0'
expect_error "odd bezier" 'size 4 4\nbezier 0 0 1 1 2\n' "bad.draw:2: 'bezier' expects two or more X Y pairs"
expect_error "short bspline" 'size 4 4\nbspline 0 0 1 1 2 2\n' "bad.draw:2: 'bspline' expects four or more"
expect_error "zero-length curve" 'size 4 4\nbezier 1 1 1 1 1 1\n' 'bad.draw:2: zero-length curve'
expect_error "antialias word" 'size 4 4\nantialias maybe\n' "bad.draw:2: expected 'on' or 'off'"
expect_error "empty script" '# nothing\n' "bad.draw:1: expected a 'size W H' command"
expect_error "int overflow" 'size 4 4\nline 0 0 2147483648 0\n' 'bad.draw:2: X1 = 2147483648 is outside the int range'

# An existing output is left alone by a failing script.
echo keep > "$dir/keep.png"
printf 'size 4 4\nline 0 0\n' | "$CG" draw - -o "$dir/keep.png" 2>/dev/null && ok "bad stdin script succeeded"
[ "$(cat "$dir/keep.png")" = keep ] || ok "existing output overwritten on error"

# Usage errors.
"$CG" draw "$dir/line.draw" 2>/dev/null; [ $? -eq 2 ] || ok "missing -o should be a usage error"
"$CG" draw "$dir/line.draw" -o "$dir/x.gif" 2>/dev/null; [ $? -eq 2 ] || ok "unknown format"
"$CG" draw "$dir/line.draw" -o "$dir/x.png" --repeat 0 2>/dev/null; [ $? -eq 2 ] || ok "--repeat 0"
"$CG" draw "$dir/missing.draw" -o "$dir/x.png" 2>/dev/null; [ $? -eq 1 ] || ok "missing script"

# Far-away coordinates draw only what is visible, quickly.
printf 'size 64 64\nline -2147483648 -2147483647 2147483647 2147483646\ncircle 0 -2000000000 2000000020\nellipse 32 32 1000000000 20\naaline -1e15 3.5 1e15 40.5\n' |
    "$CG" draw - -o "$dir/far.png" || ok "far-away primitives failed"

[ $fail -eq 0 ] && echo "cg draw: all checks passed"
exit $fail
