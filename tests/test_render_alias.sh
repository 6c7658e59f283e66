#!/usr/bin/env bash
# One front door for ray tracing: `cg render --algorithm raytrace` takes every
# option of `cg trace-render` with the same meaning, and the two spellings
# write the same bytes for many random combinations of options.  The options
# of one algorithm are refused, with one line, by the others.
# Usage: test_render_alias.sh CG SOURCE_DIR BUILD_DIR
set -u
cg="$1"
src="$2"
. "$src/tests/cli_checks.sh"

bunny="$src/data/meshes/bunny.obj"
base="--size 40x30 --quiet"

# Each of the ray tracer's options is taken by cg render and changes the
# picture (so identical files below are not identical by ignoring them).
"$cg" render "$bunny" --algorithm raytrace -o "$work/plain.ppm" $base 2>/dev/null
for opt in "--spp 3" "--depth 0 --floor" "--no-shadows --floor" "--floor" "--view-from 1,0.5,1" \
           "--specular 1 --shininess 4" "--crease 0 --shading gouraud"; do
  expect 0 "render --algorithm raytrace $opt" "$cg" render "$bunny" --algorithm raytrace \
    -o "$work/one.ppm" $base $opt
  cmp -s "$work/plain.ppm" "$work/one.ppm" && fail "$opt did not change the picture" || pass
done
expect 0 "render --stats" "$cg" render "$bunny" --algorithm raytrace -o "$work/st.ppm" $base --stats
grep -Eq '^bvh build: [0-9.]+ ms$' "$work/err" && grep -Eq 'Mrays/s$' "$work/err" && pass \
  || fail "render --stats prints the build time and rays per second: $(cat "$work/err")"
expect 0 "render --scene spheres" "$cg" render --scene spheres --algorithm raytrace -o "$work/s1.ppm" $base
expect 0 "trace-render --scene spheres" "$cg" trace-render --scene spheres -o "$work/s2.ppm" $base
cmp -s "$work/s1.ppm" "$work/s2.ppm" && pass || fail "--scene spheres differs between the spellings"

# Random combinations: the same bytes from both spellings.
RANDOM=19
pool=("--spp 2" "--spp 4" "--depth 0" "--depth 2" "--no-shadows" "--floor" "--shading flat"
      "--shading phong" "--eye 3,6,20" "--target 0,3,0" "--up 0,1,0.2" "--fov 30" "--ortho 9"
      "--light-dir 1,1,1" "--light-dir -1,0.5,0" "--ambient 0.4" "--color orange"
      "--background #203040" "--threads 2" "--view-from 1,1,0.5" "--specular 0.9"
      "--shininess 8" "--crease 15" "--repeat 2")
cases=0
for k in $(seq 1 40); do
  opts=()
  n=$((RANDOM % 5 + 1))
  for _ in $(seq 1 $n); do
    read -r -a words <<< "${pool[RANDOM % ${#pool[@]}]}"
    opts+=("${words[@]}")
  done
  case " ${opts[*]} " in *" --eye "*" --view-from "*|*" --view-from "*" --eye "*) continue ;; esac
  "$cg" render "$bunny" --algorithm raytrace -o "$work/a.ppm" $base "${opts[@]}" 2>"$work/ea"
  a=$?
  "$cg" trace-render "$bunny" -o "$work/b.ppm" $base "${opts[@]}" 2>"$work/eb"
  b=$?
  if [ $a = 0 ] && [ $b = 0 ] && cmp -s "$work/a.ppm" "$work/b.ppm"; then
    pass
  else
    fail "${opts[*]}: render exit $a, trace-render exit $b, or the files differ: $(cat "$work/ea" "$work/eb")"
  fi
  cases=$((cases + 1))
  rm -f "$work/a.ppm" "$work/b.ppm"
done
[ $cases -ge 30 ] && pass || fail "only $cases combinations compared"

# The same refusals from both spellings, one line each, nothing written.
for cmd in "render --algorithm raytrace" "trace-render"; do
  for opt in "--wireframe" "--hidden-line" "--edges" "--edge-color red" "--output-depth" "--cull none"; do
    expect 2 "$cmd $opt" "$cg" $cmd "$bunny" -o "$work/x.ppm" $base $opt; one_line "$cmd $opt"
    grep -q -- "${opt%% *}: not available with the ray tracer" "$work/err" && pass \
      || fail "$cmd $opt: the message names the option: $(cat "$work/err")"
  done
  expect 2 "$cmd --eye with --view-from" "$cg" $cmd "$bunny" -o "$work/x.ppm" --eye 1,2,3 --view-from 1,0,0
  one_line "$cmd --eye with --view-from"
done
expect 2 "trace-render --algorithm zbuffer" "$cg" trace-render "$bunny" -o "$work/x.ppm" --algorithm zbuffer
one_line "trace-render --algorithm zbuffer"
expect 0 "trace-render --algorithm raytrace" "$cg" trace-render "$bunny" -o "$work/y.ppm" $base --algorithm raytrace
for alg in zbuffer painter depth-sort; do
  for opt in "--spp 2" "--depth 1" "--stats" "--no-shadows" "--floor" "--scene spheres"; do
    expect 2 "$alg $opt" "$cg" render "$bunny" --algorithm $alg -o "$work/x.ppm" $base $opt
    one_line "$alg $opt"
    grep -q -- "${opt%% *}: only the ray tracer uses it" "$work/err" && pass \
      || fail "$alg $opt: the message names the option: $(cat "$work/err")"
  done
done
[ ! -e "$work/x.ppm" ] && pass || fail "a refused command wrote its output"

finish
