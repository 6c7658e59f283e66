#!/usr/bin/env bash
# cg mesh info / subdivide / repair: the output contract and bad input.
# Usage: test_mesh.sh CG_BINARY SOURCE_DIR BUILD_DIR
set -u
cg="$1"
src="$2"
tmp=$(mktemp -d)
work="$tmp"
trap 'rm -rf "$tmp"' EXIT
. "$src/tests/cli_checks.sh"

expect_key() { # expect_key FILE KEY VALUE
  local got
  got=$(value "$2" "$1")
  [ "$got" = "$3" ] && pass || fail "$1: $2 is '$got', expected '$3'"
}

write_cube_obj "$tmp/cube.obj"
cat > "$tmp/tetra.obj" <<'EOF'
v 1 1 1
v 1 -1 -1
v -1 1 -1
v -1 -1 1
f 1 2 3
f 1 3 4
f 1 4 2
f 2 4 3
EOF
# a torus of 8 x 6 quads plus, as a second component, a tetrahedron
awk 'BEGIN { n = 8; m = 6; pi = 3.14159265358979
  for (i = 0; i < n; i++) for (j = 0; j < m; j++) {
    u = 2 * pi * i / n; v = 2 * pi * j / m; r = 1 + 0.3 * cos(v)
    printf("v %.6f %.6f %.6f\n", r * cos(u), r * sin(u), 0.3 * sin(v)) }
  for (i = 0; i < n; i++) for (j = 0; j < m; j++) {
    a = i * m + j; b = ((i + 1) % n) * m + j; c = ((i + 1) % n) * m + (j + 1) % m; d = i * m + (j + 1) % m
    printf("f %d %d %d %d\n", a + 1, b + 1, c + 1, d + 1) }
  print "v 5 5 5"; print "v 5 4 4"; print "v 4 5 4"; print "v 4 4 5"
  print "f 49 50 51"; print "f 49 51 52"; print "f 49 52 50"; print "f 50 52 51" }' > "$tmp/mixed.obj"
# two triangles meeting at one vertex, and two running along an edge the same way
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nv -1 0 0\nv 0 -1 0\nf 1 2 3\nf 1 4 5\n' > "$tmp/bowtie.obj"
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nf 1 2 3\nf 1 2 4\n' > "$tmp/flipped.obj"
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\n' > "$tmp/nofaces.obj"

# ---- info: every key of the contract, one "key: value" a line
"$cg" mesh info "$tmp/cube.obj" > "$tmp/cube.txt" 2> "$tmp/err.txt" || fail "info cube exited $?"
for key in vertices edges faces boundary_loops components euler_characteristic genus manifold \
           oriented bounding_box_min bounding_box_max; do
  grep -q "^$key: ." "$tmp/cube.txt" || fail "info: no '$key: value' line"
done
grep -v -q '^[a-z_]*: ' "$tmp/cube.txt" && fail "info: a line that is not 'key: value'"
expect_key "$tmp/cube.txt" vertices 8
expect_key "$tmp/cube.txt" edges 12
expect_key "$tmp/cube.txt" faces 6
expect_key "$tmp/cube.txt" boundary_loops 0
expect_key "$tmp/cube.txt" components 1
expect_key "$tmp/cube.txt" euler_characteristic 2
expect_key "$tmp/cube.txt" genus 0
expect_key "$tmp/cube.txt" manifold yes
expect_key "$tmp/cube.txt" oriented yes
expect_key "$tmp/cube.txt" bounding_box_min "-1 -1 -1"
[ -s "$tmp/err.txt" ] && fail "info wrote to stderr without --repeat"

"$cg" mesh info "$tmp/mixed.obj" > "$tmp/mixed.txt" || fail "info mixed exited $?"
expect_key "$tmp/mixed.txt" genus mixed
expect_key "$tmp/mixed.txt" genus_per_component "1 0"
expect_key "$tmp/mixed.txt" components 2
expect_key "$tmp/mixed.txt" euler_characteristic 2

"$cg" mesh info "$tmp/bowtie.obj" > "$tmp/bowtie.txt" || fail "info bowtie exited $?"
expect_key "$tmp/bowtie.txt" manifold no
expect_key "$tmp/bowtie.txt" oriented yes
"$cg" mesh info "$tmp/flipped.obj" > "$tmp/flipped.txt" || fail "info flipped exited $?"
expect_key "$tmp/flipped.txt" manifold yes
expect_key "$tmp/flipped.txt" oriented no

# --repeat: medians on stderr in the contract's format
"$cg" mesh info "$tmp/cube.obj" --repeat 3 > /dev/null 2> "$tmp/times.txt" || fail "--repeat exited $?"
grep -Eq '^build: [0-9]+(\.[0-9]+)? ms$' "$tmp/times.txt" || fail "--repeat: no 'build: N ms' line"
grep -Eq '^one-ring: [0-9]+(\.[0-9]+)? ms$' "$tmp/times.txt" || fail "--repeat: no 'one-ring: N ms' line"

if [ -f "$src/data/meshes/bunny.obj" ]; then
  "$cg" mesh info "$src/data/meshes/bunny.obj" > "$tmp/bunny.txt" || fail "info bunny exited $?"
  expect_key "$tmp/bunny.txt" faces 3674
  expect_key "$tmp/bunny.txt" genus 0
  expect_key "$tmp/bunny.txt" manifold yes
fi

# ---- subdivide: counts worked by hand
"$cg" mesh subdivide --loop 2 "$tmp/tetra.obj" "$tmp/tetra2.obj" || fail "subdivide --loop exited $?"
"$cg" mesh info "$tmp/tetra2.obj" > "$tmp/t2.txt"
expect_key "$tmp/t2.txt" vertices 34   # 4 -> 4 + 6 = 10 -> 10 + 24 = 34
expect_key "$tmp/t2.txt" edges 96      # 6 -> 2*6 + 3*4 = 24 -> 2*24 + 3*16 = 96
expect_key "$tmp/t2.txt" faces 64
expect_key "$tmp/t2.txt" genus 0
"$cg" mesh subdivide --catmull-clark 1 "$tmp/cube.obj" "$tmp/cube1.ply" || fail "subdivide --catmull-clark exited $?"
"$cg" mesh info "$tmp/cube1.ply" > "$tmp/c1.txt"
expect_key "$tmp/c1.txt" vertices 26
expect_key "$tmp/c1.txt" edges 48
expect_key "$tmp/c1.txt" faces 24
"$cg" mesh subdivide --loop 1 "$tmp/cube.obj" "$tmp/no.obj" 2> "$tmp/err.txt" && fail "Loop on quads succeeded"
grep -q "triangle" "$tmp/err.txt" || fail "Loop on quads: unclear message: $(cat "$tmp/err.txt")"
[ -e "$tmp/no.obj" ] && fail "Loop on quads left an output file"

# ---- repair: reorients and reports it; the result is oriented
"$cg" mesh repair "$tmp/flipped.obj" "$tmp/fixed.obj" > "$tmp/repair.txt" || fail "repair exited $?"
grep -q "reversed 1 face" "$tmp/repair.txt" || fail "repair did not report the reversal"
"$cg" mesh info "$tmp/fixed.obj" > "$tmp/fixed.txt"
expect_key "$tmp/fixed.txt" oriented yes
"$cg" mesh repair "$tmp/bowtie.obj" "$tmp/bowtie2.obj" > "$tmp/repair.txt" || fail "repair bowtie exited $?"
"$cg" mesh info "$tmp/bowtie2.obj" > "$tmp/b2.txt"
expect_key "$tmp/b2.txt" manifold yes
expect_key "$tmp/b2.txt" vertices 6

# ---- info describes the file as read; repair converges in one pass
# a square of two triangles with the first one's reversed copy on it
printf 'v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3\nf 1 3 4\nf 1 3 2\n' > "$tmp/reversed.obj"
"$cg" mesh info "$tmp/reversed.obj" > "$tmp/rev.txt" || fail "info reversed exited $?"
expect_key "$tmp/rev.txt" vertices 4
expect_key "$tmp/rev.txt" edges 5
expect_key "$tmp/rev.txt" faces 3
expect_key "$tmp/rev.txt" components 1
expect_key "$tmp/rev.txt" euler_characteristic 2
expect_key "$tmp/rev.txt" manifold no
# the bow-tie as read: 5 vertices, one component; repaired: 6 and 2
expect_key "$tmp/bowtie.txt" vertices 5
expect_key "$tmp/bowtie.txt" components 1
expect_key "$tmp/bowtie.txt" repaired_vertices 6
expect_key "$tmp/bowtie.txt" repaired_components 2
grep -q '^genus_note: ' "$tmp/bowtie.txt" || fail "bowtie: no genus_note line"
grep -q '^genus_note: ' "$tmp/cube.txt" && fail "cube: a genus_note line for a manifold input"
expect_key "$tmp/cube.txt" repaired_vertices 8
# repair(x) is a manifold that a second repair leaves byte for byte
converges() { # converges NAME FILE
  "$cg" mesh repair "$2" "$tmp/$1.1.obj" > /dev/null || fail "$1: repair exited $?"
  "$cg" mesh info "$tmp/$1.1.obj" > "$tmp/$1.info" || fail "$1: info of the repair exited $?"
  expect_key "$tmp/$1.info" manifold yes
  expect_key "$tmp/$1.info" oriented yes
  "$cg" mesh repair "$tmp/$1.1.obj" "$tmp/$1.2.obj" > "$tmp/$1.out" || fail "$1: second repair exited $?"
  grep -q "nothing to repair" "$tmp/$1.out" || fail "$1: second repair: $(head -c 200 "$tmp/$1.out")"
  cmp -s "$tmp/$1.1.obj" "$tmp/$1.2.obj" && pass || fail "$1: a second repair changed the mesh"
}
converges reversed "$tmp/reversed.obj"
converges bowtie "$tmp/bowtie.obj"
converges flipped "$tmp/flipped.obj"
dragon="$src/data/meshes/dragon_vrip_res4.ply.gz"
if [ -f "$dragon" ]; then
  "$cg" mesh info "$dragon" > "$tmp/dragon.txt" || fail "info dragon exited $?"
  expect_key "$tmp/dragon.txt" vertices 5205
  expect_key "$tmp/dragon.txt" faces 11102
  # distinct vertex pairs of the faces, counted here from the file itself
  pairs=$(gzip -dc "$dragon" | awk '/^end_header/ { body = 1; next }
    body && NF == 4 && $1 == 3 { for (i = 2; i <= 4; i++) { a = $i; b = (i < 4 ? $(i + 1) : $2)
      if (a > b) { t = a; a = b; b = t } seen[a " " b] = 1 } }
    END { n = 0; for (k in seen) n++; print n }')
  expect_key "$tmp/dragon.txt" edges "$pairs"
  expect_key "$tmp/dragon.txt" manifold no
  converges dragon "$dragon"
fi

# ---- bad input: clear one-line errors, non-zero exits, no crash
expect 1 "no faces" "$cg" mesh info "$tmp/nofaces.obj"
one_line "no faces"
grep -q "no faces" "$work/err" && pass || fail "no faces: message '$(cat "$work/err")'"
expect 1 "missing file" "$cg" mesh info "$tmp/missing.obj"
one_line "missing file"
expect 2 "no FILE" "$cg" mesh info
expect 2 "--repeat 0" "$cg" mesh info "$tmp/cube.obj" --repeat 0
expect 2 "unknown option" "$cg" mesh info "$tmp/cube.obj" --frobnicate
one_line "unknown option"
expect 2 "negative levels" "$cg" mesh subdivide --loop -1 "$tmp/tetra.obj" "$tmp/x.obj"
expect 2 ".off output" "$cg" mesh subdivide --loop 1 "$tmp/tetra.obj" "$tmp/x.off"
expect 2 "no scheme" "$cg" mesh subdivide "$tmp/tetra.obj" "$tmp/x.obj"
expect 2 "two schemes" "$cg" mesh subdivide --loop 1 --catmull-clark 1 "$tmp/tetra.obj" "$tmp/x.obj"
expect 2 "unknown action" "$cg" mesh frobnicate
expect 2 "repair without OUT" "$cg" mesh repair "$tmp/cube.obj"

finish
