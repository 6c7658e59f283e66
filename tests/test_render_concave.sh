#!/usr/bin/env bash
# Concave faces through the cg tool: an L-shaped hexagon whose fan from its
# first corner would cover the notch, and assimp's concave_polygon.obj (a
# ring drawn as one face, its hole joined to the outline by a bridge), in
# every renderer: the notch and the hole stay background.
# Usage: test_render_concave.sh CG SOURCE_DIR BUILD_DIR
set -u
cg="$1"
src="$2"
. "$src/tests/cli_checks.sh"

# pixel FILE X Y: "R G B" of a binary PPM written by cg (P6, one header
# line each for the magic, the size and the maximum).
pixel() {
  local width header
  width=$(sed -n 2p "$1" | cut -d' ' -f1)
  header=$(head -n 3 "$1" | wc -c)
  od -An -tu1 -j $((header + 3 * ($3 * width + $2))) -N3 "$1" | awk '{print $1, $2, $3}'
}
# drawn_in_row FILE Y: how many pixels of row Y are not black.
drawn_in_row() {
  local width header
  width=$(sed -n 2p "$1" | cut -d' ' -f1)
  header=$(head -n 3 "$1" | wc -c)
  od -An -v -tu1 -w3 -j $((header + 3 * $2 * width)) -N $((3 * width)) "$1" \
    | awk '$1 + $2 + $3 > 0 { n++ } END { print n + 0 }'
}

# The L: (0,0)-(2,2) without the notch (1,2)-(1,2), starting at the corner
# (2,1) from which the fan is wrong.  Camera: orthographic, 2.5 units on
# 64 pixels, centred on (1,1): world x = 1 + (px + 0.5 - 32) * 2.5 / 64.
printf 'v 2 1 0\nv 1 1 0\nv 1 2 0\nv 0 2 0\nv 0 0 0\nv 2 0 0\nf 1 2 3 4 5 6\n' > "$work/l.obj"
view="--size 64x64 --eye 1,1,4 --target 1,1,0 --up 0,1,0 --ortho 2.5 --background black --color white"
for algorithm in zbuffer painter raytrace depth-sort; do
  for cull in back none; do
    # The ray tracer sees both sides of every face and refuses --cull.
    cull_option="--cull $cull"
    [ "$algorithm" = raytrace ] && cull_option=""
    expect 0 "L $algorithm, cull $cull" "$cg" render "$work/l.obj" -o "$work/l.ppm" $view \
      --algorithm "$algorithm" $cull_option
    # notch (1.5, 1.5), the three arms, and outside
    [ "$(pixel "$work/l.ppm" 44 19)" = "0 0 0" ] && pass \
      || fail "L $algorithm, cull $cull: the notch is drawn ($(pixel "$work/l.ppm" 44 19))"
    for xy in "19 44" "44 44" "19 19" "32 32"; do
      [ "$(pixel "$work/l.ppm" $xy)" != "0 0 0" ] && pass \
        || fail "L $algorithm, cull $cull: pixel $xy of the L is background"
    done
    [ "$(pixel "$work/l.ppm" 2 2)" = "0 0 0" ] && pass || fail "L $algorithm: outside drawn"
  done
done
expect 0 "L trace-render" "$cg" trace-render "$work/l.obj" -o "$work/l.ppm" $view --quiet
[ "$(pixel "$work/l.ppm" 44 19)" = "0 0 0" ] && pass || fail "L trace-render: the notch is drawn"
[ "$(pixel "$work/l.ppm" 19 44)" != "0 0 0" ] && pass || fail "L trace-render: the L is missing"

# Its outline with --edges and back faces culled: the face is front-facing
# even though its first three corners turn clockwise, so the edges show.
expect 0 "L edges" "$cg" render "$work/l.obj" -o "$work/e.ppm" $view --color black \
  --specular 0 --edges --edge-color white
[ "$(drawn_in_row "$work/e.ppm" 32)" -ge 2 ] && pass || fail "L edges: the outline of a front-facing concave face is culled"

# The ring: the plane x = -1.146, seen along +x, framed automatically, so
# the centre of the picture is the centre of the hole.
ring=/usr/share/assimp/models/OBJ/concave_polygon.obj
if [ -r "$ring" ]; then
  for algorithm in zbuffer painter raytrace depth-sort; do
    cull_option="--cull none"
    [ "$algorithm" = raytrace ] && cull_option=""
    expect 0 "ring $algorithm" "$cg" render "$ring" -o "$work/r.ppm" --size 96x96 \
      --view-from -1,0,0 $cull_option --background black --color white --algorithm "$algorithm"
    [ "$(pixel "$work/r.ppm" 48 48)" = "0 0 0" ] && pass \
      || fail "ring $algorithm: the hole is filled ($(pixel "$work/r.ppm" 48 48))"
    drawn=$(drawn_in_row "$work/r.ppm" 48)
    # the ring crosses the middle row twice, a few pixels each time
    [ "$drawn" -ge 2 ] && [ "$drawn" -le 16 ] && pass \
      || fail "ring $algorithm: $drawn pixels of the middle row drawn, want a thin ring"
  done
else
  echo "skipped: $ring (Debian assimp-testmodels) is not installed"
fi

finish
