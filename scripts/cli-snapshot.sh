#!/usr/bin/env bash
# Runs a broad sample of cg commands (every subcommand, the gallery, error
# cases) and prints one line per run: the md5 of its exit status, stdout,
# stderr and every file it wrote, then the label.  Two builds of cg that print
# the same lines behave the same on the sample; diff the two outputs to see
# which runs changed.  Timings ("12.3 ms", "Mrays/s") are blanked in stderr.
# `cg help` texts are listed separately ("help ...") from the rest.
# With KEEP_DIR, each run's stdout and stderr are also kept there as
# NNN.out and NNN.err, to diff the texts of two builds.
# Usage: scripts/cli-snapshot.sh CG [SOURCE_DIR [KEEP_DIR]] > snapshot.txt
set -u
cg="$(cd "$(dirname "$1")" && pwd)/$(basename "$1")" src="${2:-$(cd "$(dirname "$0")/.." && pwd)}" keep="${3:-}"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
mesh="$src/data/meshes/bunny.obj" teapot="$src/data/meshes/teapot.obj"
wkt="$src/tests/fuzz/corpus/wkt"
scene="$src/examples/scenes"

# run LABEL ARGS...: runs cg ARGS in a fresh folder, prints the digest.
n=0
run() {
  local label=$1; shift
  n=$((n + 1))
  local dir="$work/run$n"
  mkdir "$dir"
  (cd "$dir" && "$cg" "$@" >"$work/stdout" 2>"$work/stderr" </dev/null; echo "exit $?" >"$work/status")
  sed -E "s|$work|WORK|g" "$work/stderr" |
    sed -E 's/[0-9]+(\.[0-9]+)? ms/N ms/g; s/[0-9.]+ Mrays\/s/N Mrays\/s/; s/rays: [0-9]+/rays: N/' >"$work/stderr.blank"
  if [ -n "$keep" ]; then
    mkdir -p "$keep"
    cp "$work/stdout" "$keep/$(printf %03d $n).out"
    cp "$work/stderr.blank" "$keep/$(printf %03d $n).err"
  fi
  local files
  files=$(cd "$dir" && find . -type f | LC_ALL=C sort | xargs -r md5sum | md5sum | cut -c1-32)
  local all
  all=$(cat "$work/status" "$work/stdout" "$work/stderr.blank" | md5sum | cut -c1-32)
  echo "$all $files $label"
}

printf 'size 40 30\nbackground white\ncolor red\nline 0 0 39 29\ncircle 20 15 10\n' >"$work/a.txt"
printf 'size 40 30\ncolor blue\npolygon 2 2 30 5 20 25\npath M 1 1 L 30 2 Q 20 20 3 25 Z\nstroke\n' >"$work/b.txt"
printf 'size 20 20\naacircle 10 10 1e12\n' >"$work/bad.txt"

# ---- the tool itself
run "no command"
run "version" --version
run "unknown command" frobnicate
run "help unknown" help frobnicate
# ---- convert
run "convert png-ppm" convert "$src/tests/fuzz/corpus/image/small.png" x.ppm
run "convert ppm-pgm" convert "$src/tests/fuzz/corpus/image/small.ppm" x.pgm
run "convert not image" convert "$src/README.md" x.png
run "convert bogus option" convert --bogus a b
run "convert one arg" convert only.png
run "convert three args" convert a b c
run "convert bad format" convert a.png b.gif
# ---- color
run "color rgb-hsv" color rgb-hsv 1 0.5 0
run "color srgb-linear" color srgb-linear 0.5 0.5 0.5
run "color name" color rgb-lab cornflowerblue
run "color cmyk" color rgb-cmyk 0.2 0.4 0.6
run "color bad model" color foo-bar 1 2 3
run "color count" color rgb-hsv 1 2
run "color bad value" color rgb-hsv 1 x 0
run "color option" color --bogus
run "color none" color
# ---- clip
run "clip none" clip
run "clip bogus" clip bogus
run "clip line" clip line 0 0 10 10 -5 3 15 8
run "clip line lb" clip line 0 0 10 10 -5 3 15 8 --algorithm liang-barsky
run "clip line trace" clip line 0 0 10 10 -5 3 15 8 --trace
run "clip line reject" clip line 0 0 10 10 -5 -3 -1 -8
run "clip line few" clip line 0 0 10 10
run "clip line ninth" clip line 0 0 10 10 1 2 3 4 5
run "clip line nan" clip line 0 0 10 10 1 2 3 nan
run "clip line window" clip line 10 0 0 10 1 2 3 4
run "clip line trace lb" clip line 0 0 10 10 1 2 3 4 --trace --algorithm=liang-barsky
run "clip line bad alg" clip line --algorithm foo 0 0 10 10 1 2 3 4
run "clip line option" clip line --bogus 0 0 10 10 1 2 3 4
run "clip line no value" clip line 0 0 10 10 1 2 3 4 --algorithm
for op in intersection union difference xor; do
  run "clip boolean $op" clip boolean $op "$wkt/square.wkt" "$wkt/hole.wkt"
done
run "clip boolean nonzero" clip boolean union "$wkt/bowtie.wkt" "$wkt/multi.wkt" --fill nonzero
run "clip boolean png" clip boolean xor "$wkt/square.wkt" "$wkt/bowtie.wkt" -o x.png
run "clip boolean repeat" clip boolean union "$wkt/square.wkt" "$wkt/hole.wkt" --repeat 3
run "clip boolean bad op" clip boolean join "$wkt/square.wkt" "$wkt/hole.wkt"
run "clip boolean bad fill" clip boolean union a b --fill odd
run "clip boolean stdin twice" clip boolean union - -
run "clip boolean missing" clip boolean union nope.wkt "$wkt/hole.wkt"
run "clip boolean extra" clip boolean union a b c
run "clip boolean few" clip boolean union a
run "clip boolean format" clip boolean union a b -o x.gif
run "clip boolean repeat 0" clip boolean union a b --repeat 0
run "clip boolean option" clip boolean --nope union a b
run "clip polygon" clip polygon "$wkt/square.wkt" "$wkt/bowtie.wkt"
run "clip polygon wa" clip polygon "$wkt/square.wkt" "$wkt/hole.wkt" --algorithm weiler-atherton
run "clip polygon png" clip polygon "$wkt/square.wkt" "$wkt/hole.wkt" -o p.ppm
run "clip polygon bad alg" clip polygon a b --algorithm x
run "clip polygon empty" clip polygon "$wkt/empty.wkt" "$wkt/hole.wkt"
run "clip polygon few" clip polygon a
run "clip polygon extra" clip polygon a b c
run "clip polygon option" clip polygon a b -x
# ---- draw
run "draw a" draw "$work/a.txt" -o a.png
run "draw b" draw "$work/b.txt" --output b.ppm
run "draw repeat" draw "$work/b.txt" -o b.png --repeat 3
run "draw bad" draw "$work/bad.txt" -o bad.png
run "draw none" draw
run "draw no out" draw "$work/a.txt"
run "draw format" draw "$work/a.txt" -o a.gif
run "draw two" draw "$work/a.txt" "$work/b.txt" -o a.png
run "draw option" draw "$work/a.txt" -o a.png --bogus
run "draw repeat bad" draw "$work/a.txt" -o a.png --repeat 0
run "draw missing" draw nope.txt -o a.png
# ---- trace (step by step)
run "trace line" trace line 0 0 7 3
run "trace line steep" trace line 5 9 -2 0
run "trace circle" trace circle 6
run "trace none" trace
run "trace bad figure" trace square
run "trace line args" trace line 0 0 1
run "trace line bad" trace line 0 0 1 x
run "trace circle bad" trace circle -1
run "trace line long" trace line 0 0 200000 0
# ---- mesh
run "mesh info" mesh info "$mesh"
run "mesh info teapot" mesh info "$teapot"
run "mesh info repeat" mesh info "$mesh" --repeat 2
run "mesh info none" mesh info
run "mesh info two" mesh info a b
run "mesh info option" mesh info "$mesh" --bogus
run "mesh info missing" mesh info nope.obj
run "mesh subdivide loop" mesh subdivide --loop 1 "$mesh" s.obj
run "mesh subdivide cc" mesh subdivide --catmull-clark=1 "$teapot" s.ply
run "mesh subdivide both" mesh subdivide --loop 1 --catmull-clark 1 a b
run "mesh subdivide none" mesh subdivide a b
run "mesh subdivide levels" mesh subdivide --loop 13 a b
run "mesh subdivide format" mesh subdivide --loop 1 "$mesh" s.stl
run "mesh subdivide three" mesh subdivide --loop 1 a b c
run "mesh repair" mesh repair "$teapot" r.obj
run "mesh repair few" mesh repair a
run "mesh repair option" mesh repair -q a b
run "mesh none" mesh
run "mesh bogus" mesh bogus
# ---- render and trace-render
run "render zbuffer" render "$mesh" -o r.png --size 96x72 --quiet
run "render painter" render "$teapot" -o r.png --size 80x60 --algorithm painter --shading flat
run "render depth-sort" render "$mesh" -o r.ppm --size 64x48 --algorithm depth-sort --cull none
run "render phong edges" render "$mesh" -o r.png --size 64x48 --shading phong --edges --edge-color red
run "render wireframe" render "$mesh" -o r.png --size 64x48 --wireframe --background white
run "render hidden" render "$teapot" -o r.png --size 64x48 --hidden-line
run "render depth" render "$mesh" -o r.pgm --size 64x48 --output-depth
run "render camera" render "$mesh" -o r.png --size 64x48 --eye 1,1,1 --target 0,0.1,0 --up 0,1,0 --fov 30
run "render ortho" render "$mesh" -o r.png --size 64x48 --ortho 0.3 --view-from 1,0,1 --near 0.01 --far 5
run "render lights" render "$mesh" -o r.png --size 64x48 --light-dir 1,1,1 --light-dir -1,0,0 --ambient 0.3 --specular 0.5 --shininess 8 --color '#ff8800' --crease 30
run "render threads" render "$mesh" -o r.png --size 64x48 --threads 3 --repeat 2
run "render raytrace" render "$mesh" -o r.png --size 48x36 --algorithm raytrace --spp 2 --depth 2 --no-shadows --floor --stats
run "render spheres" render --scene spheres --algorithm raytrace -o r.png --size 48x36
run "render scene" render "$scene/bunny.json" -o r.png --size 64x48
run "render scene opts" render "$scene/spheres.json" -o r.png --size 48x36 --eye 0,1,5 --light-dir 0,1,1 --shading flat --spp 1
run "render projections" render "$scene/projections.json" -o r.png --size 64x48
run "render transforms" render "$scene/transforms.json" -o r.png --size 64x48 --algorithm painter
run "trace-render" trace-render "$mesh" -o t.png --size 48x36
run "trace-render spheres" trace-render --scene spheres -o t.png --size 48x36 --spp 2
run "trace-render scene" trace-render "$scene/bunny.json" -o t.png --size 48x36
run "render none" render
run "render no out" render "$mesh"
run "render format" render "$mesh" -o r.gif
run "render two" render "$mesh" "$teapot" -o r.png
run "render option" render "$mesh" -o r.png --bogus
run "render no value" render "$mesh" -o
run "render size" render "$mesh" -o r.png --size 0x10
run "render size text" render "$mesh" -o r.png --size axb
run "render eye" render "$mesh" -o r.png --eye 1,2
run "render fov" render "$mesh" -o r.png --fov 180
run "render ortho bad" render "$mesh" -o r.png --ortho -1
run "render near" render "$mesh" -o r.png --near inf
run "render near 0" render "$mesh" -o r.png --near 0
run "render far" render "$mesh" -o r.png --near 2 --far 1
run "render light zero" render "$mesh" -o r.png --light-dir 0,0,0
run "render lights 9" render "$mesh" -o r.png --light-dir 1,0,0 --light-dir 1,0,0 --light-dir 1,0,0 --light-dir 1,0,0 --light-dir 1,0,0 --light-dir 1,0,0 --light-dir 1,0,0 --light-dir 1,0,0 --light-dir 0,0,0
run "trace-render lights 9" trace-render "$mesh" -o r.png --light-dir 1,0,0 --light-dir 1,0,0 --light-dir 1,0,0 --light-dir 1,0,0 --light-dir 1,0,0 --light-dir 1,0,0 --light-dir 1,0,0 --light-dir 1,0,0 --light-dir 0,0,0
run "render ambient" render "$mesh" -o r.png --ambient -1
run "render specular" render "$mesh" -o r.png --specular x
run "render crease" render "$mesh" -o r.png --crease 200
run "render shading" render "$mesh" -o r.png --shading toon
run "render cull" render "$mesh" -o r.png --cull front
run "render algorithm" render "$mesh" -o r.png --algorithm scanline
run "render threads bad" render "$mesh" -o r.png --threads 65
run "render repeat bad" render "$mesh" -o r.png --repeat 0
run "render color bad" render "$mesh" -o r.png --color nocolor
run "render view-from zero" render "$mesh" -o r.png --view-from 0,0,0
run "render eye view-from" render "$mesh" -o r.png --eye 1,1,1 --view-from 1,0,0
run "render up zero" render "$mesh" -o r.png --up 0,0,0
run "render up parallel" render "$mesh" -o r.png --up 0,0,1
run "render eye target" render "$mesh" -o r.png --eye 1,1,1 --target 1,1,1
run "render spp raster" render "$mesh" -o r.png --spp 4
run "render wireframe rt" render "$mesh" -o r.png --algorithm raytrace --wireframe
run "render scene crease" render "$scene/bunny.json" -o r.png --crease 10
run "render scene floor" render "$scene/bunny.json" -o r.png --floor
run "render scene depth-sort" render "$scene/bunny.json" -o r.png --algorithm depth-sort
run "render scene bad" render --scene cubes --algorithm raytrace -o r.png
run "render missing" render nope.obj -o r.png
run "trace-render algorithm" trace-render "$mesh" -o r.png --algorithm zbuffer
run "trace-render none" trace-render -o r.png
run "trace-render both" trace-render "$mesh" --scene spheres -o r.png
run "trace-render spp" trace-render "$mesh" -o r.png --spp 0
run "trace-render depth" trace-render "$mesh" -o r.png --depth 65
# ---- view (no display here)
run "view none" view
run "view option" view a.obj --bogus
run "view size" view a.obj --size 1x0
run "view threads" view a.obj --threads 0
run "view two" view a.obj b.obj
run "view nodisplay" view "$mesh"
# ---- demo
run "demo clipping" demo --only Clipping -o g
run "demo nomatch" demo --only NOMATCH -o g
run "demo bogus" demo --bogus
run "demo positional" demo extra
run "demo no value" demo --only
run "demo all" demo -o gallery

# ---- help texts
for name in "" clip color convert demo draw mesh render trace trace-render view; do
  run "help $name" help $name
done
run "help --help" --help
run "help convert --help" convert --help
run "help render -h" render -h
