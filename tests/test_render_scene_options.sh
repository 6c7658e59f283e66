#!/usr/bin/env bash
# Scene files and command-line options: every option of cg render and cg
# trace-render that has a meaning for a scene is applied, and gives the
# picture of the scene file that says the same in its own keys (and another
# picture than the scene alone); the others are refused with one line.
# Usage: test_render_scene_options.sh CG SOURCE_DIR BUILD_DIR
set -u
cg="$1"
src="$2"
. "$src/tests/cli_checks.sh"

# scene FILE IMAGE CAMERA RENDER LIGHTS [MATERIAL]: a box and a sphere, of
# the material m when MATERIAL (its keys) is given.
scene() {
  cat > "$1" <<JSON
{"image": {"width": 48, "height": 36, $2},
 "camera": {$3},
 "render": {"threads": 1 $4},
 "lights": [{"type": "ambient", "intensity": 0.3} $5],
 "materials": {"m": {${6:-}}},
 "objects": [{"type": "box", "lo": [-1, -1, -1], "hi": [0.2, 0.5, 0.3] ${6:+, \"material\": \"m\"}},
             {"type": "sphere", "center": [0.8, 0.2, 0], "radius": 0.6 ${6:+, \"material\": \"m\"}}]}
JSON
}
img='"background": "#101418"'
cam='"eye": [2, 1.5, 3], "target": [0, 0, 0], "frame": true'
light=', {"type": "directional", "direction": [-0.3, -1, -0.5]}'
scene "$work/base.json" "$img" "$cam" "" "$light"

# same OPTIONS -- IMAGE CAMERA RENDER LIGHTS: cg render base.json OPTIONS
# equals the scene written with those keys, and differs from base.json.
check() {
  local what="$1" alg="$2" options="$3"; shift 3
  scene "$work/keys.json" "$@"
  "$cg" render "$work/base.json" -o "$work/base.ppm" $alg --quiet 2>"$work/err0"
  expect 0 "$what" "$cg" render "$work/base.json" -o "$work/opt.ppm" $alg $options
  "$cg" render "$work/keys.json" -o "$work/keys.ppm" $alg 2>>"$work/err0"
  cmp -s "$work/opt.ppm" "$work/keys.ppm" && pass \
    || fail "$what: the option does not give the picture of the scene's own keys $(cat "$work/err0")"
  cmp -s "$work/opt.ppm" "$work/base.ppm" && fail "$what: the option was ignored" || pass
}
for alg in "--algorithm zbuffer" "--algorithm painter" "--algorithm raytrace"; do
  check "$alg --background" "$alg" "--background #405060" '"background": "#405060"' "$cam" "" "$light"
  check "$alg --eye" "$alg" "--eye 3,1,-2" "$img" '"eye": [3, 1, -2], "target": [0, 0, 0]' "" "$light"
  check "$alg --target" "$alg" "--target 0.5,0,0" "$img" '"eye": [2, 1.5, 3], "target": [0.5, 0, 0], "frame": true' "" "$light"
  check "$alg --up" "$alg" "--up 1,1,0" "$img" '"eye": [2, 1.5, 3], "up": [1, 1, 0], "frame": true' "" "$light"
  check "$alg --fov" "$alg" "--fov 25" "$img" '"eye": [2, 1.5, 3], "fov": 25, "frame": true' "" "$light"
  check "$alg --ortho" "$alg" "--ortho 3" "$img" '"eye": [2, 1.5, 3], "projection": "orthographic", "height": 3, "frame": true' "" "$light"
  check "$alg --view-from" "$alg" "--view-from 0,3,1" "$img" '"eye": [0, 3, 1], "frame": true' "" "$light"
  check "$alg --light-dir" "$alg" "--light-dir 1,0.5,0.2" "$img" "$cam" "" ', {"type": "directional", "direction": [-1, -0.5, -0.2]}'
done
for alg in "--algorithm zbuffer" "--algorithm painter"; do
  check "$alg --shading flat" "$alg" "--shading flat" "$img" "$cam" ', "shading": "flat"' "$light"
  check "$alg --cull none" "$alg" "--cull none --eye 0.1,0.1,0.1" "$img" '"eye": [0.1, 0.1, 0.1]' ', "cull": "none"' "$light"
  check "$alg --wireframe" "$alg" "--wireframe" "$img" "$cam" ', "edges": "wireframe"' "$light"
  check "$alg --hidden-line" "$alg" "--hidden-line" "$img" "$cam" ', "edges": "hidden-line"' "$light"
  check "$alg --edges" "$alg" "--edges" "$img" "$cam" ', "edges": "overlay"' "$light"
done
check "--spp" "--algorithm raytrace" "--spp 3" "$img" "$cam" ', "samples": 3' "$light"
check "--no-shadows" "--algorithm raytrace" "--no-shadows" "$img" "$cam" ', "shadows": false' "$light"
check "--algorithm raytrace" "" "--algorithm raytrace" "$img" "$cam" ', "algorithm": "raytrace"' "$light"

# The surface where the file names none: the default material (grey 0.7,
# ka 0.15, kd 0.85, ks 0.25, shininess 32, Blinn-Phong).
for opt in "--color orange" "--ambient 0.5" "--specular 0.9" "--shininess 4"; do
  c='[0.7, 0.7, 0.7]' ka=0.15 ks=0.25 n=32
  case $opt in
    --color*) c='"orange"' ;; --ambient*) ka=0.5 ;; --specular*) ks=0.9 ;; --shininess*) n=4 ;;
  esac
  scene "$work/k2.json" "$img" "$cam" "" "$light" \
    "\"color\": $c, \"ka\": $ka, \"kd\": 0.85, \"ks\": $ks, \"shininess\": $n, \"specular\": \"blinn\""
  for alg in zbuffer raytrace; do
    expect 0 "default material $opt ($alg)" "$cg" render "$work/base.json" -o "$work/opt.ppm" --algorithm $alg $opt
    expect 0 "material m ($opt, $alg)" "$cg" render "$work/k2.json" -o "$work/keys.ppm" --algorithm $alg
    cmp -s "$work/opt.ppm" "$work/keys.ppm" && pass || fail "$opt ($alg): not the material's key"
    "$cg" render "$work/base.json" -o "$work/base.ppm" --algorithm $alg
    cmp -s "$work/opt.ppm" "$work/base.ppm" && fail "$opt ($alg) was ignored" || pass
  done
done

expect 0 "--size" "$cg" render "$work/base.json" -o "$work/s.png" --size 30x20
[ "$(png_size "$work/s.png")" = 30x20 ] && pass || fail "--size 30x20 on a scene"
expect 0 "--repeat" "$cg" render "$work/base.json" -o "$work/r.png" --repeat 2 --threads 2 --quiet
grep -Eq '^frame: [0-9]+\.[0-9] ms$' "$work/err" && pass || fail "--repeat on a scene"
expect 0 "trace-render applies them too" "$cg" trace-render "$work/base.json" -o "$work/t.ppm" --eye 3,1,-2
"$cg" render "$work/base.json" -o "$work/u.ppm" --algorithm raytrace --eye 3,1,-2
cmp -s "$work/t.ppm" "$work/u.ppm" && pass || fail "trace-render and render --algorithm raytrace differ on a scene"

# Options without a meaning for a scene: one line, exit 2, nothing written.
for cmd in "render" "render --algorithm raytrace" "trace-render"; do
  for opt in "--crease 20" "--edge-color red" "--output-depth" "--floor" "--scene spheres" "--stats"; do
    expect 2 "$cmd SCENE $opt" "$cg" $cmd "$work/base.json" -o "$work/x.png" $opt
    one_line "$cmd SCENE $opt"
    grep -q -- "${opt%% *}: not available with a scene file" "$work/err" && pass \
      || fail "$cmd SCENE $opt: the message names the option and the scene: $(cat "$work/err")"
  done
done
expect 2 "depth-sort on a scene" "$cg" render "$work/base.json" -o "$work/x.png" --algorithm depth-sort
one_line "depth-sort on a scene"
[ ! -e "$work/x.png" ] && pass || fail "a refused command wrote its output"

finish
