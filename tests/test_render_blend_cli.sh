#!/usr/bin/env bash
# cg render with an OBJ material of dissolve d below 1: the face is blended
# over the one behind it in linear light (in either order of the faces in
# the file, at 1 and 4 samples), and a file without such materials draws
# the same bytes as before blending existed (its opaque faces untouched).
# Usage: test_render_blend_cli.sh CG SOURCE_DIR BUILD_DIR
set -u
cg="$1"
src="$2"
. "$src/tests/cli_checks.sh"

cat > "$work/m.mtl" <<'MTL'
newmtl back
Kd 1 0 0
newmtl front
Kd 0 0 1
d 0.5
newmtl solid
Kd 0 0 1
MTL
# quads FILE FIRST SECOND: the back quad (z = -1) and the front one (z = 0),
# in the order given, the front of material FRONT.
quads() {
  {
    echo "mtllib m.mtl"
    echo "v -2 -2 -1"; echo "v 2 -2 -1"; echo "v 2 2 -1"; echo "v -2 2 -1"
    echo "v -2 -2 0"; echo "v 2 -2 0"; echo "v 2 2 0"; echo "v -2 2 0"
    if [ "$2" = back ]; then
      echo "usemtl back"; echo "f 1 2 3 4"; echo "usemtl $3"; echo "f 5 6 7 8"
    else
      echo "usemtl $3"; echo "f 5 6 7 8"; echo "usemtl back"; echo "f 1 2 3 4"
    fi
  } > "$1"
}
# centre FILE.ppm: the "R G B" of the centre pixel of a 20x20 binary PPM.
centre() { tail -c $((20 * 20 * 3)) "$1" | od -An -tu1 -j $(((10 * 20 + 10) * 3)) -N3 | xargs; }

for order in back front; do
  quads "$work/q_$order.obj" $order front
  for n in 1 4; do
    expect 0 "blend, $order first, msaa $n" "$cg" render "$work/q_$order.obj" -o "$work/q_${order}_$n.ppm" \
      --size 20x20 --eye 0,0,3 --fov 20 --shading unlit --cull none --msaa $n
    # Half red, half blue in linear light: 0.5 encodes to 188.
    [ "$(centre "$work/q_${order}_$n.ppm")" = "188 0 188" ] && pass \
      || fail "$order first, msaa $n: centre $(centre "$work/q_${order}_$n.ppm"), expected 188 0 188"
  done
done
cmp -s "$work/q_back_1.ppm" "$work/q_front_1.ppm" && pass || fail "the same picture in either order"

quads "$work/s.obj" back solid
expect 0 "opaque" "$cg" render "$work/s.obj" -o "$work/s.ppm" --size 20x20 --eye 0,0,3 --fov 20 --shading unlit --cull none
[ "$(centre "$work/s.ppm")" = "0 0 255" ] && pass || fail "opaque front: $(centre "$work/s.ppm")"
finish
