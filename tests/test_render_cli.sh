#!/usr/bin/env bash
# cg render: the options of the contract, output formats, timing line,
# identical pictures on any thread count, clear errors for bad input.
# Usage: test_render.sh CG SOURCE_DIR BUILD_DIR
set -u
cg="$1"
src="$2"
. "$src/tests/cli_checks.sh"

bunny="$src/data/meshes/bunny.obj"
printf 'OFF\n3 1 0\n-1 -1 0\n1 -1 0\n0 1 0\n3 0 1 2\n' > "$work/tri.off"

expect 0 "help render" "$cg" help render
grep -q -- "--light-dir" "$work/out" && pass || fail "help lists --light-dir"

expect 0 "default render" "$cg" render "$bunny" -o "$work/a.png"
[ "$(png_size "$work/a.png")" = 800x600 ] && pass || fail "default size 800x600"
expect 0 "every contract option" "$cg" render "$bunny" -o "$work/b.png" --size 320x200 \
  --eye 0.3,0.2,0.4 --target 0,0.1,0 --up 0,1,0 --fov 40 --light-dir 1,1,1 --light-dir -1,0,0 \
  --ambient 0.2 --shading phong --cull none --algorithm painter --threads 2 \
  --background '#102030' --color orange
[ "$(png_size "$work/b.png")" = 320x200 ] && pass || fail "--size 320x200"
expect 0 "ortho wireframe" "$cg" render "$bunny" -o "$work/c.ppm" --ortho 0.3 --wireframe --size 64x48
head -c 2 "$work/c.ppm" | grep -q P6 && pass || fail "PPM output by extension"
expect 0 "hidden line" "$cg" render "$bunny" -o "$work/d.png" --hidden-line --size 64x48
expect 0 "edges, flat" "$cg" render "$bunny" -o "$work/e.png" --edges --shading flat --size 64x48

expect 0 "repeat" "$cg" render "$bunny" -o "$work/f.png" --size 160x120 --repeat 3
grep -Eq '^frame: [0-9]+\.[0-9] ms$' "$work/err" && pass || fail "--repeat prints 'frame: N.N ms': $(cat "$work/err")"

for n in 1 2 3; do
  expect 0 "threads $n" "$cg" render "$bunny" -o "$work/t$n.png" --size 300x200 --threads $n --shading phong
done
cmp -s "$work/t1.png" "$work/t2.png" && cmp -s "$work/t1.png" "$work/t3.png" && pass \
  || fail "same picture on 1, 2 and 3 threads"

# The winding rule: the triangle faces +z.
expect 0 "front face" "$cg" render "$work/tri.off" -o "$work/front.png" --size 40x40 --eye 0,0,3 --background black --color white
expect 0 "back face" "$cg" render "$work/tri.off" -o "$work/back.png" --size 40x40 --eye 0,0,-3 --background black --color white
expect 0 "back face, no culling" "$cg" render "$work/tri.off" -o "$work/both.png" --size 40x40 --eye 0,0,-3 --cull none --background black --color white
if ! cmp -s "$work/front.png" "$work/back.png" && ! cmp -s "$work/back.png" "$work/both.png"; then pass; else fail "back faces culled, shown with --cull none"; fi

# Bad input: one clear line, exit 2 for usage, 1 for failures.
expect 2 "no mesh" "$cg" render -o "$work/x.png"; one_line "no mesh"
expect 2 "no output" "$cg" render "$bunny"; one_line "no output"
expect 2 "bad size" "$cg" render "$bunny" -o "$work/x.png" --size 0x0; one_line "bad size"
expect 2 "bad eye" "$cg" render "$bunny" -o "$work/x.png" --eye 1,2; one_line "bad eye"
expect 2 "bad fov" "$cg" render "$bunny" -o "$work/x.png" --fov 180; one_line "bad fov"
expect 2 "bad ortho" "$cg" render "$bunny" -o "$work/x.png" --ortho -1; one_line "bad ortho"
expect 2 "zero light" "$cg" render "$bunny" -o "$work/x.png" --light-dir 0,0,0; one_line "zero light"
expect 2 "bad shading" "$cg" render "$bunny" -o "$work/x.png" --shading smooth; one_line "bad shading"
expect 2 "bad cull" "$cg" render "$bunny" -o "$work/x.png" --cull front; one_line "bad cull"
expect 2 "bad algorithm" "$cg" render "$bunny" -o "$work/x.png" --algorithm scanline; one_line "bad algorithm"
expect 2 "bad threads" "$cg" render "$bunny" -o "$work/x.png" --threads 0; one_line "bad threads"
expect 2 "bad colour" "$cg" render "$bunny" -o "$work/x.png" --color notacolour; one_line "bad colour"
expect 2 "bad format" "$cg" render "$bunny" -o "$work/x.xyz"; one_line "bad format"
expect 2 "up along view" "$cg" render "$bunny" -o "$work/x.png" --eye 0,5,0 --target 0,0,0; one_line "up along view"
expect 1 "missing mesh" "$cg" render "$work/none.obj" -o "$work/x.png"; one_line "missing mesh"
printf 'v 0 0 0\nf 1 2 3\n' > "$work/bad.obj"
expect 1 "malformed mesh" "$cg" render "$work/bad.obj" -o "$work/x.png"; one_line "malformed mesh"
[ ! -e "$work/x.png" ] && pass || fail "nothing written on failure"
printf 'v 0 0 0\nv 1 0 0\n' > "$work/empty.obj"
expect 1 "mesh without faces" "$cg" render "$work/empty.obj" -o "$work/empty.png" --size 8x8
one_line "mesh without faces"
grep -q "empty.obj: nothing to draw" "$work/err" && pass || fail "no faces: the message names the file and why"
[ ! -e "$work/empty.png" ] && pass || fail "no faces: nothing written"
expect 0 "camera inside the mesh" "$cg" render "$bunny" -o "$work/in.png" --size 64x48 --eye -0.02,0.1,0 --target 1,0.1,0 --cull none
grep -q raytrace "$src/tools/cg/commands/raytracer.c" && pass || fail "raytrace dispatch file present"

finish
