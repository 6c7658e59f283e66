#!/usr/bin/env bash
# The cg tool's common behaviour: help, version, errors, convert and demo.
# Usage: test_cli.sh CG SOURCE_DIR BUILD_DIR
set -u
cg="$1"
src="$2"
. "$src/tests/cli_checks.sh"

expect 0 "--help" "$cg" --help
grep -q "convert" "$work/out" && pass || fail "--help lists convert"
expect 0 "--version" "$cg" --version
grep -Eq '^cg [0-9]+\.[0-9]+\.[0-9]+$' "$work/out" && pass || fail "--version format"
expect 0 "help convert" "$cg" help convert
grep -q "usage: cg convert" "$work/out" && pass || fail "help convert shows usage"
expect 0 "convert --help" "$cg" convert --help
expect 2 "no command" "$cg"
expect 2 "unknown command" "$cg" frobnicate
[ "$(wc -l < "$work/err")" = 1 ] && pass || fail "one line for an unknown command"
expect 2 "help unknown" "$cg" help frobnicate
expect 2 "convert unknown option" "$cg" convert --bogus a b
[ "$(wc -l < "$work/err")" = 1 ] && pass || fail "one line for an unknown option"
expect 2 "convert missing args" "$cg" convert only-one.png

# convert: PNG -> PPM -> PNG keeps the pixels; bad input is refused.
expect 0 "demo" "$cg" demo -o "$work/gallery"
[ -s "$work/gallery/index.html" ] && pass || fail "demo writes index.html"
missing=0
for img in $(grep -o 'src="[^"]*"' "$work/gallery/index.html" | cut -d'"' -f2); do
  [ -s "$work/gallery/$img" ] || missing=$((missing + 1))
done
[ "$missing" = 0 ] && pass || fail "$missing pictures referenced by index.html are missing"
first=$(ls "$work/gallery"/*.png | head -1)
expect 0 "convert to ppm" "$cg" convert "$first" "$work/a.ppm"
expect 0 "convert back" "$cg" convert "$work/a.ppm" "$work/b.png"
expect 0 "convert again" "$cg" convert "$work/b.png" "$work/c.ppm"
cmp -s "$work/a.ppm" "$work/c.ppm" && pass || fail "PNG/PPM round trip changed pixels"
expect 0 "convert to pgm" "$cg" convert "$first" "$work/a.pgm"
head -c 2 "$work/a.pgm" | grep -q P5 && pass || fail "pgm is P5"

printf 'P6\n10 10\n255\nshort' > "$work/truncated.ppm"
cp "$work/b.png" "$work/keep.png"
expect 1 "truncated input" "$cg" convert "$work/truncated.ppm" "$work/keep.png"
grep -q "truncated" "$work/err" && pass || fail "message says truncated"
cmp -s "$work/b.png" "$work/keep.png" && pass || fail "failed convert left the output untouched"
: > "$work/empty.png"
expect 1 "empty input" "$cg" convert "$work/empty.png" "$work/x.png"
grep -q "empty" "$work/err" && pass || fail "message says empty"
expect 2 "unknown output format" "$cg" convert "$work/b.png" "$work/x.gif"
expect 1 "missing input" "$cg" convert "$work/nope.png" "$work/x.png"

finish
