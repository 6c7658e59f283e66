#!/usr/bin/env bash
# The size rules of the house (docs/design.md):
#  - no file in src/ is over 800 lines;
#  - no function in src/ or tools/ is over 120 lines, counted from the line
#    of its name to its closing brace as universal-ctags's C parser finds
#    them (it skips braces in strings, character literals and comments);
#  - tests/house_rules_exceptions.txt lists the known offenders, one per
#    line ("path" for a file, "path:function" for a function) with the
#    reason.  The list may only shrink: an offender missing from it fails
#    the test, and so does an entry that no longer offends, so the list
#    never goes stale.
# The measure itself is checked first on a small tree whose answers are
# known: braces in strings, character literals and comments, functions of
# 120 and 121 lines, files of 800 and 801 lines.
# Usage: test_house_rules.sh CG SOURCE_DIR BUILD_DIR
set -eu
source_dir="$2"
max_file_lines=800
max_function_lines=120
exceptions="$source_dir/tests/house_rules_exceptions.txt"

if ! ctags --version 2>/dev/null | grep -q "Universal Ctags"; then
  echo "test_house_rules: needs universal-ctags (Debian package universal-ctags)" >&2
  exit 77
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failed=0
fail() { echo "FAIL: $*" >&2; failed=$((failed + 1)); }

# Prints "key<TAB>what" for every offender under the tree at $1.
offenders() {
  local root="$1"
  (cd "$root" && find src -name '*.[ch]' -type f | LC_ALL=C sort | while read -r file; do
     lines=$(wc -l < "$file")
     [ "$lines" -le $max_file_lines ] || printf '%s\t%s\n' "$file" \
       "file of $lines lines (limit $max_file_lines): split it one job per file"
   done)
  # .h files hold static inline functions: read them as C too.
  local dirs=()
  for dir in src tools; do [ -d "$root/$dir" ] && dirs+=("$dir"); done
  (cd "$root" && ctags --languages=C --langmap=C:.c.h --kinds-C=f --fields=+ne -x \
     --_xformat='%{input}	%{name}	%{line}	%{end}' -R "${dirs[@]}") |
    awk -F'\t' -v limit=$max_function_lines '
      $4 == "" { printf "%s:%s\tfunction whose end ctags cannot find\n", $1, $2; next }
      $4 - $3 + 1 > limit {
        printf "%s:%s\tfunction of %d lines (lines %d-%d, limit %d): split it into its phases\n",
               $1, $2, $4 - $3 + 1, $3, $4, limit }' | LC_ALL=C sort
}

# 1. The measure on a tree with known answers.
fixture="$work/fixture"
mkdir -p "$fixture/src/part" "$fixture/tools"
lines_of() { # N: N lines of "    x += i;"
  local i
  for ((i = 0; i < $1; i++)); do echo "    x += $i;"; done
}
{
  echo 'static int long_one(int x)'          # line 1
  echo '{'
  echo '    const char *s = "}}} { \" }";'
  echo "    char c = '}';"
  echo '    /* } } } */'
  echo '    // }'
  lines_of 113
  echo '    return x + s[0] + c;'
  echo '}'                                    # line 121
  echo 'static int exactly_limit(int x)'      # line 122
  echo '{'
  echo '    const char *s = "{";'
  lines_of 115
  echo '    return x + s[0];'
  echo '}'                                    # line 241: 120 lines
  echo '#define OPEN "{"'
  echo 'static int after_macro(int x) { return x + OPEN[0]; }'
} > "$fixture/src/part/functions.c"
{ echo '/*'; for ((i = 0; i < 799; i++)); do echo ' *'; done; echo ' */'; } > "$fixture/src/part/big.c"
{ echo '/*'; for ((i = 0; i < 798; i++)); do echo ' *'; done; echo ' */'; } > "$fixture/src/part/limit.h"
{ echo 'int tool_main(void)'; echo '{'; echo '    int x = 0;'; lines_of 118; echo '    return x;'; echo '}'; } \
  > "$fixture/tools/tool.c"
offenders "$fixture" | cut -f1 > "$work/fixture_found.txt"
printf '%s\n' src/part/big.c src/part/functions.c:long_one tools/tool.c:tool_main \
  > "$work/fixture_expected.txt"
if ! diff -u "$work/fixture_expected.txt" "$work/fixture_found.txt" >&2; then
  fail "the measure gives the wrong offenders on the fixture tree (expected - found +)"
fi

# 2. The known offenders, each with a reason, each once.
: > "$work/listed.txt"
if [ -f "$exceptions" ]; then
  while IFS= read -r line || [ -n "$line" ]; do
    case "$line" in '#'* | '') continue ;; esac
    key=$(echo "$line" | awk '{print $1}')
    reason=$(echo "$line" | awk '{$1 = ""; print}' | sed 's/^ *//')
    [ -n "$reason" ] || fail "$key in house_rules_exceptions.txt gives no reason"
    echo "$key" >> "$work/listed.txt"
  done < "$exceptions"
fi
dups=$(LC_ALL=C sort "$work/listed.txt" | uniq -d)
[ -z "$dups" ] || fail "listed twice in house_rules_exceptions.txt: $dups"

# 3. cg's own tree.
offenders "$source_dir" > "$work/found.txt"
found_count=$(wc -l < "$work/found.txt")
while IFS=$'\t' read -r key what; do
  grep -qxF "$key" "$work/listed.txt" || fail "$key: $what"
done < "$work/found.txt"
while read -r key; do
  cut -f1 "$work/found.txt" | grep -qxF "$key" ||
    fail "$key is in tests/house_rules_exceptions.txt but no longer offends: remove its line"
done < "$work/listed.txt"

listed_count=$(wc -l < "$work/listed.txt")
if [ "$failed" -ne 0 ]; then
  echo "test_house_rules: $failed failure(s); $found_count offender(s), $listed_count known" >&2
  exit 1
fi
echo "test_house_rules: ok; $found_count known offender(s) left in tests/house_rules_exceptions.txt"
