#!/usr/bin/env bash
# The fill commands of `cg draw` (docs/draw-script.md, "Filling"): pixels of
# small scripts read back from binary PPM, and bad lines refused with their
# line number.
# Usage: test_draw_fill.sh CG SOURCE_DIR BUILD_DIR
set -u
cg="$1"
src="$2"
. "$src/tests/cli_checks.sh"

# pixel FILE.ppm X Y -> "R G B" (binary P6 with a "P6\nW H\n255\n" header)
pixel() {
  local file=$1 x=$2 y=$3
  local size width skip
  size=$(head -n 2 "$file" | tail -n 1)
  width=${size%% *}
  skip=$(printf 'P6\n%s\n255\n' "$size" | wc -c)
  od -An -tu1 -j $((skip + (y * width + x) * 3)) -N3 "$file" | awk '{print $1, $2, $3}'
}

draw() { # draw NAME: script on stdin -> $work/NAME.ppm
  "$cg" draw - -o "$work/$1.ppm" 2>"$work/err"
}

check_pixel() { # check_pixel NAME X Y "R G B" DESCRIPTION
  local got
  got=$(pixel "$work/$1.ppm" "$2" "$3")
  if [ "$got" = "$4" ]; then pass; else fail "$5: pixel ($2, $3) is '$got', want '$4'"; fi
}

# A square with a square hole (contour), even-odd and non-zero with the hole
# reversed: the hole stays background.
for rule in evenodd nonzero; do
  if [ $rule = evenodd ]; then hole="4 4 12 4 12 12 4 12"; else hole="4 4 4 12 12 12 12 4"; fi
  draw "hole-$rule" <<SCRIPT && pass || fail "polygon with contour ($rule): $(cat "$work/err")"
size 16 16
background #000000
color #ffffff
fillrule $rule
polygon 2 2 14 2 14 14 2 14
contour $hole
SCRIPT
  check_pixel "hole-$rule" 3 3 "255 255 255" "$rule: ring"
  check_pixel "hole-$rule" 8 8 "0 0 0" "$rule: hole"
  check_pixel "hole-$rule" 1 1 "0 0 0" "$rule: outside"
  check_pixel "hole-$rule" 13 13 "255 255 255" "$rule: last pixel inside"
  check_pixel "hole-$rule" 14 14 "0 0 0" "$rule: pixel-centre rule at the far corner"
done

# A pentagram: even-odd leaves the centre empty, non-zero fills it.
for rule in evenodd nonzero; do
  draw "star-$rule" <<SCRIPT && pass || fail "pentagram ($rule): $(cat "$work/err")"
size 40 40
background black
color white
fillrule $rule
polygon 20 2 31 36 2 14 38 14 9 36
SCRIPT
done
check_pixel star-evenodd 20 20 "0 0 0" "even-odd pentagram centre"
check_pixel star-nonzero 20 20 "255 255 255" "non-zero pentagram centre"

# Anti-aliased: a rectangle ending half way through a pixel column gives
# half coverage in linear light (code 188 of white over black).
draw aa <<'SCRIPT' && pass || fail "aapolygon: $(cat "$work/err")"
size 20 10
background black
color white
aapolygon 0 0 10.5 0 10.5 10 0 10
SCRIPT
check_pixel aa 9 5 "255 255 255" "aapolygon inside"
check_pixel aa 10 5 "188 188 188" "aapolygon half-covered pixel"
check_pixel aa 11 5 "0 0 0" "aapolygon outside"

# path + fill and stroke with width, caps, joins, dashes.
draw path <<'SCRIPT' && pass || fail "path fill/stroke: $(cat "$work/err")"
size 40 20
background black
color white
path M 2 2 H 18 V 18 H 2 Z
fill
path M 22 10 L 38 10
width 4
cap butt
join bevel
dash 4 4
stroke
SCRIPT
check_pixel path 10 10 "255 255 255" "filled path"
check_pixel path 19 10 "0 0 0" "outside the filled path"
check_pixel path 23 10 "255 255 255" "first dash"
check_pixel path 27 10 "0 0 0" "first gap"
check_pixel path 31 10 "255 255 255" "second dash"
check_pixel path 23 13 "0 0 0" "beyond the half width"

# Flood fill: 4-connected stops at a diagonal, 8-connected crosses it;
# boundary fill stops at the boundary colour.
diagonal="polygon 0 10 1 10 1 9 2 9 2 8 3 8 3 7 4 7 4 6 5 6 5 5 6 5 6 4 7 4 7 3 8 3 8 2 9 2 9 1 10 1 10 0 11 0 11 -1"
draw flood4 <<SCRIPT && pass || fail "flood: $(cat "$work/err")"
size 10 10
background white
color black
$diagonal
color red
flood 0 0
SCRIPT
check_pixel flood4 0 0 "255 0 0" "flood seed"
check_pixel flood4 9 9 "255 255 255" "flood stops at a diagonal"
draw flood8 <<SCRIPT && pass || fail "flood8: $(cat "$work/err")"
size 10 10
background white
color black
$diagonal
color red
flood8 0 0
SCRIPT
check_pixel flood8 9 9 "255 0 0" "flood8 crosses a diagonal"
draw boundary <<'SCRIPT' && pass || fail "boundaryfill: $(cat "$work/err")"
size 12 12
background white
color blue
polygon 2 2 10 2 10 10 2 10
color white
polygon 4 4 8 4 8 8 4 8
color green
boundaryfill 6 6 blue
SCRIPT
check_pixel boundary 6 6 "0 128 0" "boundary fill inside"
check_pixel boundary 3 3 "0 0 255" "boundary kept"
check_pixel boundary 0 0 "255 255 255" "outside the boundary"

# Bad lines: a clear message with the line number, non-zero exit.
bad() { # bad DESCRIPTION SCRIPT
  printf '%b\n' "$2" | "$cg" draw - -o "$work/bad.png" 2>"$work/err"
  local status=$?
  if [ $status -ne 0 ] && grep -q -- '-:[0-9]*: \|<stdin>:[0-9]*: ' "$work/err" \
     && [ "$(wc -l < "$work/err")" = 1 ]; then pass; else
    fail "$1: exit $status, message '$(cat "$work/err")'"; fi
  [ ! -e "$work/bad.png" ] && pass || fail "$1: an image was written"
}
bad "contour without polygon" 'size 10 10\ncontour 1 1 5 1 5 5'
bad "contour after another command" 'size 10 10\npolygon 1 1 5 1 5 5\ncolor red\ncontour 2 2 3 2 3 3'
bad "negative width" 'size 10 10\nwidth -1'
bad "NaN width" 'size 10 10\nwidth nan'
bad "unknown join" 'size 10 10\njoin sharp'
bad "unknown cap" 'size 10 10\ncap flat'
bad "unknown rule" 'size 10 10\nfillrule odd'
bad "negative dash" 'size 10 10\ndash 1 -2'
bad "two points" 'size 10 10\npolygon 1 1 2 2'
bad "odd number count" 'size 10 10\naapolygon 1 1 2 2 3'
bad "huge coordinate" 'size 10 10\npolygon 1 1 1e300 2 3 3'
bad "bad path data" 'size 10 10\npath M 1 1 L 5'
bad "path without moveto" 'size 10 10\npath L 3 3'
bad "fill without path" 'size 10 10\nfill'
bad "stroke with arguments" 'size 10 10\nstroke 3'
bad "flood outside" 'size 10 10\nflood 10 3'
bad "flood8 not an integer" 'size 10 10\nflood8 1.5 3'
bad "boundaryfill bad colour" 'size 10 10\nboundaryfill 1 1 nocolor'
bad "dash too fine" 'size 10 10\npath M 0 0 L 9 9\ndash 0.000001 0.000001\nstroke'

# A polygon line and the contour lines after it are drawn as one polygon, but
# each error still names the line it is on, in the order of the lines.
names() { # names DESCRIPTION SCRIPT MESSAGE: the one line of stderr
  local got
  got=$(printf '%b\n' "$2" | "$cg" draw - -o "$work/bad.png" 2>&1 >/dev/null)
  if [ "$got" = "$3" ]; then pass; else fail "$1: message '$got', want '$3'"; fi
}
names "bad number in the second contour" \
  'size 10 10\npolygon 1 1 9 1 9 9\ncontour 2 2 3 2 3 3\ncontour 4 4 5 4 5 x' \
  "<stdin>:4: expected a number for Y2, got 'x'"
names "too few points in a contour" 'size 10 10\naapolygon 1 1 9 1 9 9\ncontour 2 2 3 2' \
  "<stdin>:3: 'contour' expects three or more X Y pairs (contour X0 Y0 X1 Y1 X2 Y2 ...), got 4 numbers"
names "coordinate beyond the fill's range on the polygon line, before a bad contour" \
  'size 10 10\npolygon 1 1 9 1 9 2e12\ncontour 2 2 3 2 3 y' \
  "<stdin>:2: Y2 = 2e12 is out of range: coordinates are at most 2^40 = 1099511627776 in magnitude"
names "coordinate beyond the fill's range on a contour line" \
  'size 10 10\npolygon 1 1 9 1 9 9\ncontour 2 2 3 2 3 -2e12' \
  "<stdin>:3: Y2 = -2e12 is out of range: coordinates are at most 2^40 = 1099511627776 in magnitude"
names "contour after a polygon that came before a line" \
  'size 10 10\npolygon 1 1 9 1 9 9\nline 0 0 1 1\ncontour 2 2 3 2 3 3' \
  "<stdin>:4: 'contour' must follow a polygon, aapolygon or contour line"

# Three contour lines after an aapolygon, each a square hole of an 8-pixel
# square, even-odd: exactly the holes stay background, and a half-covered
# column of the outer square is half blended.
draw holes <<SCRIPT && pass || fail "aapolygon with three contours: $(cat "$work/err")"
size 12 4
background #000000
color #ffffff
fillrule evenodd
aapolygon 0 0 11.5 0 11.5 3 0 3
contour 1 1 2 1 2 2 1 2
contour 4 1 5 1 5 2 4 2
contour 7 1 8 1 8 2 7 2
SCRIPT
for x in 1 4 7; do check_pixel holes $x 1 "0 0 0" "hole at x=$x"; done
for x in 0 2 3 5 6 8 9 10; do check_pixel holes $x 1 "255 255 255" "ring at x=$x"; done
check_pixel holes 11 1 "188 188 188" "half-covered pixel (half white in linear light)"
check_pixel holes 0 3 "0 0 0" "below the polygon"

finish
