#!/usr/bin/env bash
# cg trace-render and cg render --algorithm raytrace: the contract's options,
# the ray tracer's own, the timing and stats lines, identical pictures on
# any thread count, clear errors for bad input.
# Usage: test_trace_render.sh CG SOURCE_DIR BUILD_DIR
set -u
cg="$1"
src="$2"
. "$src/tests/cli_checks.sh"

bunny="$src/data/meshes/bunny.obj"
small="--size 64x48 --quiet"

expect 0 "help" "$cg" help trace-render
grep -q -- "--spp" "$work/out" && pass || fail "help lists --spp"

expect 0 "scene" "$cg" trace-render --scene spheres -o "$work/s.png" --size 96x64 --spp 2 --quiet
[ "$(png_size "$work/s.png")" = 96x64 ] && pass || fail "--size 96x64"
expect 0 "every contract option" "$cg" trace-render "$bunny" -o "$work/b.png" --size 80x60 \
  --eye 0,5,25 --target 0,4,0 --up 0,1,0 --fov 40 --light-dir 1,1,1 --light-dir -1,0,0 \
  --ambient 0.2 --shading flat --threads 2 --background '#102030' --color orange --quiet
expect 0 "ortho, ppm" "$cg" trace-render "$bunny" -o "$work/o.ppm" --ortho 12 $small
head -c 2 "$work/o.ppm" | grep -q P6 && pass || fail "PPM output by extension"

# The same bytes on 1 and 3 threads, with supersampling, soft shadows, glass.
expect 0 "1 thread" "$cg" trace-render --scene spheres -o "$work/t1.ppm" --size 70x50 --spp 3 --threads 1 --quiet
expect 0 "3 threads" "$cg" trace-render --scene spheres -o "$work/t3.ppm" --size 70x50 --spp 3 --threads 3 --quiet
cmp -s "$work/t1.ppm" "$work/t3.ppm" && pass || fail "pictures differ between 1 and 3 threads"

expect 0 "repeat" "$cg" trace-render "$bunny" -o "$work/r.png" $small --repeat 3
grep -Eq '^frame: [0-9]+\.[0-9] ms$' "$work/err" && pass || fail "--repeat prints 'frame: N ms': $(cat "$work/err")"
expect 0 "stats" "$cg" trace-render "$bunny" -o "$work/st.png" $small --stats
grep -Eq '^bvh build: [0-9.]+ ms$' "$work/err" && pass || fail "--stats prints the build time"
grep -Eq 'Mrays/s$' "$work/err" && pass || fail "--stats prints rays per second"
expect 0 "depth 0, no shadows, floor" "$cg" trace-render "$bunny" -o "$work/d.png" $small --depth 0 --no-shadows --floor

# A scene file, ray traced with the command line's size and samples.
expect 0 "scene file" "$cg" trace-render "$src/examples/scenes/spheres.json" -o "$work/sc.png" --size 48x32 --spp 2
[ "$(png_size "$work/sc.png")" = 48x32 ] && pass || fail "scene file: --size overrides the scene's"

# cg render --algorithm raytrace is the same ray tracer.
expect 0 "render raytrace" "$cg" render "$bunny" --algorithm raytrace -o "$work/rr.ppm" --size 64x48
expect 0 "trace-render" "$cg" trace-render "$bunny" -o "$work/tr.ppm" --size 64x48 --quiet
cmp -s "$work/rr.ppm" "$work/tr.ppm" && pass || fail "render --algorithm raytrace differs from trace-render"

# Bad input: one clear line, non-zero status, nothing written.
expect 2 "no input" "$cg" trace-render -o "$work/x.png"; one_line "no input"
expect 2 "both inputs" "$cg" trace-render "$bunny" --scene spheres -o "$work/x.png"; one_line "both inputs"
expect 2 "no output" "$cg" trace-render "$bunny"; one_line "no output"
expect 2 "bad format" "$cg" trace-render "$bunny" -o "$work/x.gif"; one_line "bad format"
expect 2 "spp 0" "$cg" trace-render "$bunny" -o "$work/x.png" --spp 0; one_line "spp 0"
expect 2 "depth 65" "$cg" trace-render "$bunny" -o "$work/x.png" --depth 65; one_line "depth 65"
expect 2 "bad scene" "$cg" trace-render --scene cubes -o "$work/x.png"; one_line "bad scene"
expect 2 "bad fov" "$cg" trace-render "$bunny" -o "$work/x.png" --fov 180; one_line "bad fov"
expect 2 "zero light" "$cg" trace-render "$bunny" -o "$work/x.png" --light-dir 0,0,0; one_line "zero light"
expect 2 "eye is target" "$cg" trace-render "$bunny" -o "$work/x.png" --eye 1,1,1 --target 1,1,1; one_line "eye is target"
expect 2 "unknown option" "$cg" trace-render "$bunny" -o "$work/x.png" --bogus; one_line "unknown option"
expect 1 "missing file" "$cg" trace-render "$work/none.obj" -o "$work/x.png"; one_line "missing file"
printf 'OFF\n3 1 0\n0 0 0\n1 0 0\nnan 1 0\n3 0 1 2\n' > "$work/nan.off"
"$cg" trace-render "$work/nan.off" -o "$work/nan.png" $small >/dev/null 2>&1
[ $? -le 1 ] && pass || fail "NaN vertex: crashed"
printf 'OFF\n3 1 0\n0 0 0\n1 0 0\n2 0 0\n3 0 1 2\n' > "$work/flat.off"
expect 0 "degenerate triangle" "$cg" trace-render "$work/flat.off" -o "$work/flat.png" $small
[ ! -e "$work/x.png" ] && pass || fail "a failed run wrote its output"

finish
