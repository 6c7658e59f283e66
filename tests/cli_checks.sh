# Helpers for the shell tests of the cg tool.  $work is their scratch folder:
# set it in the script before sourcing this file, or leave it unset to get a
# new one that is removed when the script exits (a $work inherited from the
# environment is not used).  Counts in $passed and $failed.
case "$(declare -p work 2>/dev/null)" in
  "declare -- work="*) ;;
  *) work=$(mktemp -d); trap 'rm -rf "$work"' EXIT ;;
esac
passed=0 failed=0
pass() { passed=$((passed + 1)); }
fail() { failed=$((failed + 1)); echo "FAIL: $*" >&2; }
# expect STATUS DESCRIPTION COMMAND...: runs COMMAND (stdout in $work/out,
# stderr in $work/err) and checks its exit status.
expect() {
  local want=$1 what=$2; shift 2
  "$@" >"$work/out" 2>"$work/err"; local got=$?
  if [ "$got" = "$want" ]; then pass; else fail "$what: exit $got, want $want: $(cat "$work/err")"; fi
}
# one_line DESCRIPTION: the last command printed exactly one line on stderr.
one_line() { [ "$(wc -l < "$work/err")" = 1 ] && pass || fail "$1: expected one line on stderr, got: $(cat "$work/err")"; }
# png_size FILE: WIDTHxHEIGHT from the PNG's IHDR.
png_size() {
  od -An -tu1 -j16 -N8 "$1" | awk '{printf "%dx%d", $1*16777216+$2*65536+$3*256+$4, $5*16777216+$6*65536+$7*256+$8}'
}
# value KEY FILE: the value of "KEY: value" in FILE (as cg mesh info prints).
value() { sed -n "s/^$1: //p" "$2" | head -1; }
# write_cube_obj FILE: the cube [-1, 1]^3 as 8 vertices and 6 quads (12
# triangles once triangulated), closed, genus 0.
write_cube_obj() {
  cat > "$1" <<'EOT'
v -1 -1 -1
v 1 -1 -1
v -1 1 -1
v 1 1 -1
v -1 -1 1
v 1 -1 1
v -1 1 1
v 1 1 1
f 1 3 4 2
f 5 6 8 7
f 1 2 6 5
f 3 7 8 4
f 1 5 7 3
f 2 4 8 6
EOT
}
# finish: prints the counts; the script's exit status.
finish() { echo "$passed passed, $failed failed"; [ "$failed" = 0 ]; }
