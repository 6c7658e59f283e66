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

# ---- the option parser (tools/cg/options.c), as every command meets it:
# --name=value is --name value, -o has the long spelling --output, a flag
# takes no value, and `cg help` lists each option from the same table.
line="0 0 10 10 -5 3 15 8"
expect 0 "clip line --algorithm VALUE" "$cg" clip line $line --algorithm liang-barsky
cp "$work/out" "$work/spaced"
expect 0 "clip line --algorithm=VALUE" "$cg" clip line $line --algorithm=liang-barsky
cmp -s "$work/out" "$work/spaced" && pass || fail "--algorithm=VALUE differs from --algorithm VALUE"
expect 2 "a flag with a value" "$cg" clip line $line --trace=yes
one_line "a flag with a value"
grep -q "option --trace takes no value" "$work/err" && pass || fail "flag value: $(cat "$work/err")"
expect 2 "a missing value" "$cg" clip boolean union a b --fill
grep -q "option --fill needs a value" "$work/err" && pass || fail "missing value: $(cat "$work/err")"
expect 2 "a bad choice" "$cg" clip boolean union a b --fill odd
grep -qF "clip: --fill: expected evenodd, nonzero, positive or negative, got 'odd' (see 'cg help clip')" \
  "$work/err" && pass || fail "bad choice: $(cat "$work/err")"
expect 2 "an unknown option names the action" "$cg" clip polygon a b --bogus
grep -qF "clip: polygon: unknown option '--bogus'" "$work/err" && pass || fail "unknown: $(cat "$work/err")"
wkt="$src/tests/fuzz/corpus/wkt"
expect 0 "clip -o" "$cg" clip boolean xor "$wkt/square.wkt" "$wkt/bowtie.wkt" -o "$work/short.png"
expect 0 "clip --output" "$cg" clip boolean xor "$wkt/square.wkt" "$wkt/bowtie.wkt" --output "$work/long.png"
cmp -s "$work/short.png" "$work/long.png" && pass || fail "-o and --output differ"
expect 0 "help clip" "$cg" help clip
for spelling in "--algorithm cohen-sutherland|liang-barsky" "--trace" \
                "--fill evenodd|nonzero|positive|negative" "-o, --output OUT.png" "--repeat N"; do
  grep -qF -- "  $spelling" "$work/out" && pass || fail "cg help clip does not list '$spelling'"
done
for action in line polygon boolean; do
  grep -q "^Options of cg clip $action:" "$work/out" && pass || fail "help clip: no options of $action"
done
# Every option `cg help` lists is one the command knows (the help and the
# parser read the same table): given alone, none is an unknown option.
listed=0
for name in clip color convert demo draw mesh render trace trace-render view; do
  "$cg" help "$name" | awk '/^Options of cg [a-z-]+ [a-z-]+:$/ {action = $5; sub(":", "", action)}
                           /^Options:$/ {action = ""}
                           /^  -/ {sub(",", "", $1); print action, $1}' > "$work/listed"
  while read -r action option; do
    [ -n "$option" ] || { option=$action; action=""; }
    listed=$((listed + 1))
    "$cg" $name $action "$option" >/dev/null 2>"$work/err" </dev/null
    grep -q "unknown option" "$work/err" && fail "cg $name $action: $option is listed but unknown" || pass
  done < "$work/listed"
done
[ "$listed" -ge 50 ] && pass || fail "cg help lists only $listed options in all"

finish
