#!/usr/bin/env bash
# cg render on the textured glTF models of Debian's assimp-testmodels: the
# base-colour texture shows (the Cesium logo's blue sky, green hills and
# white ground all present, many distinct colours), the .gltf with a data:
# URI and the .glb draw the same picture, on any thread count, the filters differ where the
# texture is minified, a missing texture file is a warning naming it with
# the material's colour drawn, and bad options are one-line errors that
# leave an existing output untouched.
# Usage: test_render_textured_models.sh CG SOURCE_DIR BUILD_DIR
set -u
cg="$1"
src="$2"
. "$src/tests/cli_checks.sh"

models=/usr/share/assimp/models/glTF2
if [ ! -r "$models/BoxTextured-glTF-Binary/BoxTextured.glb" ]; then
  echo "skipped: $models (Debian assimp-testmodels) is not installed"
  exit 77
fi

# census FILE.ppm: "blue green white distinct" pixel counts of a P6 image.
census() {
  local header
  header=$(head -n 3 "$1" | wc -c)
  tail -c +$((header + 1)) "$1" | od -An -v -tu1 -w3 | awk '
    NF == 3 { r = $1; g = $2; b = $3
              if (b > r + 40 && b > g) blue++
              if (g > r + 30 && g > b + 30) green++
              if (r > 200 && g > 200 && b > 200) white++
              seen[r " " g " " b] = 1 }
    END { n = 0; for (k in seen) n++; print blue + 0, green + 0, white + 0, n }'
}

view="--view-from 1,1,2 --size 128x128 --background black"
for file in BoxTextured-glTF-Binary/BoxTextured.glb BoxTextured-glTF-Embedded/BoxTextured.gltf \
            BoxTextured-glTF/BoxTextured.gltf; do
  for shading in unlit phong gouraud; do
    expect 0 "$file $shading" "$cg" render "$models/$file" -o "$work/box.ppm" $view \
      --shading $shading
    read -r blue green white distinct <<<"$(census "$work/box.ppm")"
    [ "$blue" -gt 800 ] && [ "$green" -gt 800 ] && [ "$distinct" -gt 100 ] && pass \
      || fail "$file $shading: blue $blue, green $green, $distinct colours: no texture drawn"
    if [ "$shading" = unlit ]; then
      [ "$white" -gt 300 ] && pass || fail "$file unlit: $white white pixels"
    fi
  done
done

# The data: URI and the GLB buffer view hold the same image and mesh.
"$cg" render "$models/BoxTextured-glTF-Binary/BoxTextured.glb" -o "$work/a.ppm" $view --shading unlit
"$cg" render "$models/BoxTextured-glTF-Embedded/BoxTextured.gltf" -o "$work/b.ppm" $view \
  --shading unlit
cmp -s "$work/a.ppm" "$work/b.ppm" && pass || fail "embedded .gltf and .glb draw differently"

# The same bytes on any thread count.
for threads in 1 3; do
  "$cg" render "$models/BoxTextured-glTF-Binary/BoxTextured.glb" -o "$work/t$threads.ppm" \
    --view-from 1,1,2 --size 300x200 --threads $threads
done
cmp -s "$work/t1.ppm" "$work/t3.ppm" && pass || fail "1 and 3 threads draw differently"

# Minified (the 256-texel logo on a few dozen pixels): nearest aliases,
# trilinear averages; both show the texture.
small="--view-from 1,1,2 --size 40x40 --background black --shading unlit"
for filter in nearest bilinear trilinear; do
  expect 0 "filter $filter" "$cg" render "$models/BoxTextured-glTF-Binary/BoxTextured.glb" \
    -o "$work/$filter.ppm" $small --texture-filter $filter
done
cmp -s "$work/nearest.ppm" "$work/trilinear.ppm" && fail "nearest and trilinear draw alike" || pass
cmp -s "$work/bilinear.ppm" "$work/trilinear.ppm" && fail "bilinear and trilinear draw alike" \
  || pass

# A missing texture: a warning naming it, the material's colour drawn.
mkdir -p "$work/missing"
cp "$models/BoxTextured-glTF/BoxTextured.gltf" "$models/BoxTextured-glTF/BoxTextured0.bin" \
  "$work/missing/"
expect 0 "missing texture" "$cg" render "$work/missing/BoxTextured.gltf" -o "$work/m.ppm" $view \
  --shading unlit
grep -q "warning: .*CesiumLogoFlat.png" "$work/err" && pass \
  || fail "missing texture: no warning naming it: $(cat "$work/err")"
read -r blue green white distinct <<<"$(census "$work/m.ppm")"
[ "$distinct" -le 3 ] && pass || fail "missing texture: $distinct colours, want the flat colour"

# Bad options: one line, the existing output kept.
cp "$work/a.ppm" "$work/keep.ppm"
expect 2 "bad filter" "$cg" render "$models/BoxTextured-glTF-Binary/BoxTextured.glb" \
  -o "$work/keep.ppm" --texture-filter cubic
one_line "bad filter"
expect 2 "filter with the ray tracer" "$cg" render \
  "$models/BoxTextured-glTF-Binary/BoxTextured.glb" -o "$work/keep.ppm" --texture-filter nearest \
  --algorithm raytrace
one_line "filter with the ray tracer"
expect 2 "unlit with the ray tracer" "$cg" render "$models/BoxTextured-glTF-Binary/BoxTextured.glb" \
  -o "$work/keep.ppm" --shading unlit --algorithm raytrace
one_line "unlit with the ray tracer"
cmp -s "$work/a.ppm" "$work/keep.ppm" && pass || fail "a failed command changed the output"

finish
