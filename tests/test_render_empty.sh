#!/usr/bin/env bash
# Silent blank pictures: a mesh with no faces is an error that names the file
# and says why nothing could be drawn; a frame in which every face was culled
# (or none is in view) is drawn with a one-line warning naming --cull none.
# Usage: test_render_empty.sh CG SOURCE_DIR BUILD_DIR
set -u
cg="$1"
src="$2"
. "$src/tests/cli_checks.sh"

printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nl 1 2 3\n' > "$work/lines.obj"
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\np 1 2 3\n' > "$work/points.obj"
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\n' > "$work/truncated.obj"
printf 'ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nend_header\n0 0 0\n1 0 0\n0 1 0\n' > "$work/cloud.ply"
printf 'OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n' > "$work/nofaces.off"
for f in lines.obj points.obj truncated.obj cloud.ply nofaces.off; do
  for cmd in "render" "render --algorithm painter" "render --algorithm raytrace" "trace-render"; do
    expect 1 "$cmd $f" "$cg" $cmd "$work/$f" -o "$work/x.png" --size 16x16
    one_line "$cmd $f"
    grep -q "$f: nothing to draw: the file has 3 vertices and no faces" "$work/err" && pass \
      || fail "$cmd $f: the message names the file and why: $(cat "$work/err")"
  done
done
[ ! -e "$work/x.png" ] && pass || fail "a mesh without faces wrote a picture"

# One triangle, counter-clockwise seen from +z.
printf 'OFF\n3 1 0\n-1 -1 0\n1 -1 0\n0 1 0\n3 0 1 2\n' > "$work/tri.off"
for alg in zbuffer painter depth-sort; do
  expect 0 "$alg: seen from behind" "$cg" render "$work/tri.off" -o "$work/back.png" --size 16x16 \
    --eye 0,0,-3 --algorithm $alg
  one_line "$alg: seen from behind"
  grep -q "warning: .*tri.off: every face was culled.*--cull none" "$work/err" && pass \
    || fail "$alg: a fully culled mesh warns and names --cull none: $(cat "$work/err")"
  [ -e "$work/back.png" ] && pass || fail "$alg: the culled frame is still written"
  rm -f "$work/back.png"
  expect 0 "$alg: --cull none" "$cg" render "$work/tri.off" -o "$work/both.png" --size 16x16 \
    --eye 0,0,-3 --cull none --algorithm $alg
  [ ! -s "$work/err" ] && pass || fail "$alg: a drawn frame warns: $(cat "$work/err")"
  expect 0 "$alg: from the front" "$cg" render "$work/tri.off" -o "$work/front.png" --size 16x16 \
    --eye 0,0,3 --algorithm $alg
  [ ! -s "$work/err" ] && pass || fail "$alg: a drawn frame warns: $(cat "$work/err")"
  expect 0 "$alg: out of view" "$cg" render "$work/tri.off" -o "$work/away.png" --size 16x16 \
    --eye 0,0,3 --target 0,10,3 --up 0,0,1 --algorithm $alg
  one_line "$alg: out of view"
  grep -q "warning: .*tri.off: the mesh is outside the view" "$work/err" && pass \
    || fail "$alg: a mesh outside the view warns: $(cat "$work/err")"
done
expect 0 "bunny" "$cg" render "$src/data/meshes/bunny.obj" -o "$work/b.png" --size 64x48
[ ! -s "$work/err" ] && pass || fail "a mesh in view warns: $(cat "$work/err")"
expect 0 "wireframe from behind" "$cg" render "$work/tri.off" -o "$work/w.png" --size 16x16 --eye 0,0,-3 --wireframe --cull none
[ ! -s "$work/err" ] && pass || fail "wireframe warns: $(cat "$work/err")"

finish
