#!/usr/bin/env bash
# cg render --shadows against the ray tracer's shadow rays: a box floating
# over a floor, lit by one directional light from three directions and seen
# from two eyes; the pixels lit by the ambient light alone (in a shadow, or
# turned away from the light) must be the same pixels in the rasterizer's
# Phong picture with shadow maps and in the ray tracer's, on at least 99%
# of the picture, at 1 and 4 samples; without --shadows the floor under the
# box is lit.  --shadows is refused where it means nothing.
# Usage: test_render_shadows.sh CG SOURCE_DIR BUILD_DIR
set -u
cg="$1"
src="$2"
. "$src/tests/cli_checks.sh"

mesh="$src/tests/data/shadow_box.obj"
# dark A.ppm B.ppm: "agreeing total darkA darkB" over the pixels whose green
# is between the background and the lit surfaces (ambient light only).
dark() {
  local ha hb
  ha=$(head -n 3 "$1" | wc -c)
  hb=$(head -n 3 "$2" | wc -c)
  paste <(tail -c +$((ha + 1)) "$1" | od -An -v -tu1 -w3) \
        <(tail -c +$((hb + 1)) "$2" | od -An -v -tu1 -w3) | awk '
    NF == 6 { a = ($2 > 50 && $2 < 110); b = ($5 > 50 && $5 < 110)
              n++; same += (a == b); da += a; db += b }
    END { print same + 0, n + 0, da + 0, db + 0 }'
}

for light in 0.6,1,0.3 -0.4,1,0.5 0.2,1,-0.7; do
  for eye in 3,4,5 -4,3,2; do
    view="--size 160x120 --eye $eye --target 0,0.5,0 --light-dir $light --specular 0"
    expect 0 "ray tracer, light $light, eye $eye" "$cg" render "$mesh" -o "$work/t.ppm" $view \
      --algorithm raytrace
    for n in 1 4; do
      expect 0 "shadow maps, light $light, eye $eye, msaa $n" "$cg" render "$mesh" \
        -o "$work/r.ppm" $view --shading phong --shadows --msaa $n
      read -r same total dr dt <<<"$(dark "$work/r.ppm" "$work/t.ppm")"
      [ $((same * 100)) -ge $((total * 99)) ] && pass \
        || fail "light $light, eye $eye, msaa $n: masks agree on $same of $total pixels"
      [ "$dt" -gt 150 ] && pass || fail "light $light, eye $eye: only $dt dark pixels"
    done
    expect 0 "no shadows, light $light, eye $eye" "$cg" render "$mesh" -o "$work/n.ppm" $view \
      --shading phong
    read -r same total dn dt <<<"$(dark "$work/n.ppm" "$work/t.ppm")"
    [ "$dn" -lt $((dt - 100)) ] && pass \
      || fail "light $light, eye $eye: without --shadows $dn dark pixels, ray tracer $dt"
  done
done

expect 2 "--shadows with the ray tracer" "$cg" render "$mesh" -o "$work/x.png" --shadows \
  --algorithm raytrace
one_line "--shadows with the ray tracer"
printf '{"objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1}]}' > "$work/s.json"
expect 2 "--shadows with a scene" "$cg" render "$work/s.json" -o "$work/x.png" --shadows
one_line "--shadows with a scene"
finish
