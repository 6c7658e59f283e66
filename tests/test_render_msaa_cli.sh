#!/usr/bin/env bash
# cg render --msaa and a scene's render.msaa: one sample is today's picture
# byte for byte, more samples change it and stay identical on any thread
# count, the scene key and the option agree, and every bad value or
# combination is refused with one line.
# Usage: test_render_msaa_cli.sh CG SOURCE_DIR BUILD_DIR
set -u
cg="$1"
src="$2"
. "$src/tests/cli_checks.sh"

bunny="$src/data/meshes/bunny.obj"
size="--size 160x120"

expect 0 "no --msaa" "$cg" render "$bunny" -o "$work/plain.png" $size
expect 0 "--msaa 1" "$cg" render "$bunny" -o "$work/m1.png" $size --msaa 1
cmp -s "$work/plain.png" "$work/m1.png" && pass || fail "--msaa 1 is the default picture"
for n in 2 4 8 16; do
  expect 0 "--msaa $n" "$cg" render "$bunny" -o "$work/m$n.png" $size --msaa $n --shading phong
  expect 0 "--msaa $n, 3 threads" "$cg" render "$bunny" -o "$work/m${n}t.png" $size --msaa $n \
    --shading phong --threads 3
  cmp -s "$work/m$n.png" "$work/m${n}t.png" && pass || fail "--msaa $n: same bytes on 1 and 3 threads"
  cmp -s "$work/m$n.png" "$work/m1.png" && fail "--msaa $n changes the picture" || pass
done
expect 0 "--msaa 4 with edges" "$cg" render "$bunny" -o "$work/e.png" $size --msaa 4 --edges
expect 0 "--msaa 4 depth" "$cg" render "$bunny" -o "$work/d.png" $size --msaa 4 --output-depth

for bad in 0 3 5 32 -4 four 4.0 ""; do
  expect 2 "--msaa '$bad'" "$cg" render "$bunny" -o "$work/x.png" --msaa "$bad"
  one_line "--msaa '$bad'"
  grep -q "1, 2, 4, 8 or 16" "$work/err" && pass || fail "--msaa '$bad': names the counts: $(cat "$work/err")"
done
[ ! -e "$work/x.png" ] && pass || fail "nothing written on a bad --msaa"
for algorithm in painter depth-sort; do
  expect 2 "--msaa with $algorithm" "$cg" render "$bunny" -o "$work/x.png" --msaa 4 --algorithm $algorithm
  one_line "--msaa with $algorithm"
  grep -q "only the z-buffer" "$work/err" && pass || fail "$algorithm: $(cat "$work/err")"
done
expect 0 "--msaa 1 with painter" "$cg" render "$bunny" -o "$work/p.png" $size --msaa 1 --algorithm painter
expect 2 "--msaa with the ray tracer" "$cg" render "$bunny" -o "$work/x.png" --msaa 4 --algorithm raytrace
one_line "--msaa with the ray tracer"
expect 2 "--msaa with trace-render" "$cg" trace-render "$bunny" -o "$work/x.png" --msaa 2
one_line "--msaa with trace-render"

# A scene's render.msaa, and --msaa over it.
scene() {
  cat > "$1" <<JSON
{"image": {"width": 64, "height": 48},
 "camera": {"eye": [2, 1.5, 3], "target": [0, 0, 0], "frame": true},
 "render": {"threads": 1 $2},
 "objects": [{"type": "box", "lo": [-1, -1, -1], "hi": [0.2, 0.5, 0.3]},
             {"type": "sphere", "center": [0.8, 0.2, 0], "radius": 0.6}]}
JSON
}
scene "$work/s1.json" ""
scene "$work/s4.json" ', "msaa": 4'
expect 0 "scene" "$cg" render "$work/s1.json" -o "$work/s1.png"
expect 0 "scene msaa 4" "$cg" render "$work/s4.json" -o "$work/s4.png"
expect 0 "scene --msaa 4" "$cg" render "$work/s1.json" -o "$work/s1m4.png" --msaa 4
expect 0 "scene msaa 4, --msaa 1" "$cg" render "$work/s4.json" -o "$work/s4m1.png" --msaa 1
cmp -s "$work/s4.png" "$work/s1m4.png" && pass || fail "render.msaa 4 = --msaa 4"
cmp -s "$work/s1.png" "$work/s4m1.png" && pass || fail "--msaa 1 overrides render.msaa"
cmp -s "$work/s1.png" "$work/s4.png" && fail "render.msaa 4 changes the scene's picture" || pass
for bad in 3 0 17 '"4"' 2.5; do
  scene "$work/bad.json" ", \"msaa\": $bad"
  expect 1 "scene msaa $bad" "$cg" render "$work/bad.json" -o "$work/x.png"
  grep -q "render.msaa" "$work/err" && pass || fail "scene msaa $bad names render.msaa: $(cat "$work/err")"
done
scene "$work/sp.json" ', "msaa": 4, "algorithm": "painter"'
expect 1 "scene msaa with painter" "$cg" render "$work/sp.json" -o "$work/x.png"
grep -q "render.msaa" "$work/err" && pass || fail "painter scene: $(cat "$work/err")"
finish
