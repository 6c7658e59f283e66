#!/usr/bin/env bash
# cg render and cg trace-render with cameras placed by hand: near and far
# enclose the mesh's depth range (not its distance from the eye) in every
# renderer, --near and --far set them, a scene camera does the same, the
# framing fills the picture, and --view-from along up works.
# Usage: test_render_camera.sh CG SOURCE_DIR BUILD_DIR
set -u
cg="$1"
src="$2"
. "$src/tests/cli_checks.sh"

# lit FILE.pgm W H: the number of pixels brighter than black.
lit() { tail -c $(($2 * $3)) "$1" | od -An -tu1 -v | tr -s ' ' '\n' | awk '$1 > 0 {n++} END {print n + 0}'; }
# extent FILE.pgm W H: "width height" of the box around the lit pixels.
extent() {
  tail -c $(($2 * $3)) "$1" | od -An -tu1 -v | tr -s ' ' '\n' | awk -v w="$2" '
    NF { if ($1 > 0) { x = i % w; y = int(i / w);
           if (n++ == 0) { x0 = x1 = x; y0 = y1 = y }
           if (x < x0) x0 = x; if (x > x1) x1 = x; if (y < y0) y0 = y; if (y > y1) y1 = y }
         i++ }
    END { print x1 - x0 + 1, y1 - y0 + 1 }'
}
plain="--background black --color white --ambient 1 --size 128x128"

# A strip at z = 0 off to the side of an eye 10 above it, looking straight
# down: 40 x 2 units, 1 pixel per unit with --ortho 128 (x 84..123, rows
# 63 and 64): 80 pixels; with a 170 degree field of view, 46.
printf 'OFF\n4 2 0\n52 31 0\n92 31 0\n92 33 0\n52 33 0\n3 0 1 2\n3 0 2 3\n' > "$work/strip.off"
for algorithm in zbuffer painter raytrace; do
  for view in "--ortho 128:80" "--fov 170:46"; do
    expect 0 "$algorithm ${view%:*}" "$cg" render "$work/strip.off" -o "$work/s.pgm" $plain \
      --eye 32,32,10 --target 32,32,0 ${view%:*} --algorithm $algorithm
    n=$(lit "$work/s.pgm" 128 128)
    [ "$n" = "${view#*:}" ] && pass || fail "$algorithm ${view%:*}: $n pixels lit, want ${view#*:}"
  done
done
expect 0 "trace-render ortho" "$cg" trace-render "$work/strip.off" -o "$work/t.pgm" $plain \
  --eye 32,32,10 --target 32,32,0 --ortho 128 --quiet
n=$(lit "$work/t.pgm" 128 128)
[ "$n" = 80 ] && pass || fail "trace-render --ortho: $n pixels lit, want 80"
# A parallel eye inside the strip's depth range (the strip tilted through
# the eye's plane): the parts behind the eye are in the view box too.
printf 'OFF\n4 2 0\n52 31 -20\n92 31 20\n92 33 20\n52 33 -20\n3 0 1 2\n3 0 2 3\n' > "$work/tilted.off"
for algorithm in zbuffer raytrace; do
  expect 0 "tilted $algorithm" "$cg" render "$work/tilted.off" -o "$work/s.pgm" $plain \
    --eye 32,32,0 --target 32,32,-1 --ortho 128 --algorithm $algorithm
  n=$(lit "$work/s.pgm" 128 128)
  [ "$n" = 80 ] && pass || fail "tilted strip, $algorithm: $n pixels lit, want 80"
done

# --near and --far cut by hand: the tilted strip seen from above is at
# depth 30 at x = 52, 10 at its middle and -10 (behind the eye) at x = 92.
expect 0 "--far cuts" "$cg" render "$work/tilted.off" -o "$work/s.pgm" $plain \
  --eye 32,32,10 --target 32,32,0 --ortho 128 --far 10
n=$(lit "$work/s.pgm" 128 128)
[ "$n" = 40 ] && pass || fail "--far 10 keeps the nearer half: $n pixels lit, want 40"
expect 0 "--near cuts" "$cg" render "$work/tilted.off" -o "$work/s.pgm" $plain \
  --eye 32,32,10 --target 32,32,0 --ortho 128 --near 10 --far 100
n=$(lit "$work/s.pgm" 128 128)
[ "$n" = 40 ] && pass || fail "--near 10 keeps the farther half: $n pixels lit, want 40"
for algorithm in painter raytrace; do
  expect 0 "--far cuts, $algorithm" "$cg" render "$work/tilted.off" -o "$work/s.pgm" $plain \
    --eye 32,32,10 --target 32,32,0 --ortho 128 --far 10 --algorithm $algorithm
  n=$(lit "$work/s.pgm" 128 128)
  [ "$n" = 40 ] && pass || fail "--far 10, $algorithm: $n pixels lit, want 40"
done
expect 0 "trace-render --near" "$cg" trace-render "$work/tilted.off" -o "$work/s.pgm" $plain \
  --eye 32,32,10 --target 32,32,0 --fov 170 --near 10 --far 100 --quiet
expect 0 "render raytrace --near" "$cg" render "$work/tilted.off" -o "$work/z.pgm" $plain \
  --eye 32,32,10 --target 32,32,0 --fov 170 --near 10 --far 100 --algorithm raytrace
n=$(lit "$work/s.pgm" 128 128)
[ "$n" -gt 0 ] && cmp -s "$work/s.pgm" "$work/z.pgm" && pass \
  || fail "trace-render and render --algorithm raytrace cut at --near alike ($n pixels)"
expect 0 "zbuffer --near" "$cg" render "$work/tilted.off" -o "$work/z.pgm" $plain \
  --eye 32,32,10 --target 32,32,0 --fov 170 --near 10 --far 100
m=$(lit "$work/z.pgm" 128 128)
[ "$n" = "$m" ] && pass || fail "--near 10 --fov 170: ray tracer $n pixels, z-buffer $m"
expect 2 "far before near" "$cg" render "$work/strip.off" -o "$work/x.pgm" --near 5 --far 2
one_line "far before near"
expect 2 "perspective near 0" "$cg" render "$work/strip.off" -o "$work/x.pgm" --near 0
one_line "perspective near 0"
expect 2 "bad near" "$cg" render "$work/strip.off" -o "$work/x.pgm" --near far
one_line "bad near"
expect 2 "trace-render far before near" "$cg" trace-render "$work/strip.off" -o "$work/x.pgm" \
  --near 5 --far 2
one_line "trace-render far before near"
"$cg" help render > "$work/help" 2>&1; grep -q -- "--near" "$work/help" && pass || fail "help lists --near"

# A scene camera far from the strip (eye 200 above it: beyond the old
# default far of 100) and its own near and far keys.
scene() {
  printf '{"image": {"width": 128, "height": 128, "background": "black"},\n'
  printf ' "camera": {"eye": [32, 32, 200], "target": [32, 32, 0], "projection": "orthographic", "height": 128%s},\n' "$1"
  printf ' "lights": [{"type": "ambient", "color": [1, 1, 1], "intensity": 1}],\n'
  printf ' "objects": [{"type": "mesh", "file": "strip.off"}]}\n'
}
scene "" > "$work/far.json"
expect 0 "scene eye far away" "$cg" render "$work/far.json" -o "$work/s.pgm"
n=$(lit "$work/s.pgm" 128 128)
[ "$n" = 80 ] && pass || fail "scene eye 200 away: $n pixels lit, want 80"
scene ', "near": 1, "far": 150' > "$work/cut.json"
expect 0 "scene far key" "$cg" render "$work/cut.json" -o "$work/s.pgm"
n=$(lit "$work/s.pgm" 128 128)
[ "$n" = 0 ] && pass || fail "scene far 150 cuts the strip at 200: $n pixels lit"

# Framing fits the projected box: a 4 x 1 x 1 box fills 95% of the width
# (perspective and parallel), and looking straight down works.
printf 'OFF\n8 6 0\n-2 -0.5 -0.5\n2 -0.5 -0.5\n2 0.5 -0.5\n-2 0.5 -0.5\n-2 -0.5 0.5\n2 -0.5 0.5\n2 0.5 0.5\n-2 0.5 0.5\n4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 2 3 7 6\n4 1 2 6 5\n4 0 4 7 3\n' > "$work/box.off"
expect 0 "framed box" "$cg" render "$work/box.off" -o "$work/f.pgm" $plain --cull none
set -- $(extent "$work/f.pgm" 128 128)
[ "$1" -ge 118 ] && [ "$1" -le 124 ] && pass || fail "framed box spans $1 of 128 columns, want about 122"
expect 0 "from above" "$cg" render "$work/box.off" -o "$work/f.pgm" $plain --view-from 0,1,0
set -- $(extent "$work/f.pgm" 128 128)
[ "$1" -ge 118 ] && [ "$1" -le 124 ] && pass || fail "box from above spans $1 of 128 columns"
expect 0 "from below" "$cg" render "$work/box.off" -o "$work/f.pgm" $plain --view-from 0,-1,0
expect 2 "eye straight above still needs --up" "$cg" render "$work/box.off" -o "$work/x.pgm" \
  --eye 0,5,0 --target 0,0,0
one_line "eye straight above"
finish
