#!/usr/bin/env bash
# The README's quick start on a clean clone of this checkout: `make run`, then
# `make test`, in that order, as a new user types them.  Fails when either
# fails, when a test of the source tree is not registered, or when a test
# reports itself skipped or did not run.
# Usage: .ci/readme-path.sh [--fresh]   (root or sudo for the Debian packages)
#   --fresh  first removes the packages that only the tests need (those of
#            deps/test*.txt that deps/build*.txt does not list), as on a new
#            machine, so that `make test` must install them and find them.
set -euo pipefail
source_dir=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
git clone -q "$source_dir" "$work/cg"
cd "$work/cg"

packages() { sed 's/#.*//' "$@" | tr -s ' \t' '\n' | grep . | sort -u; }
if [ "${1:-}" = --fresh ]; then
  test_only=$(comm -13 <(packages deps/build*.txt) <(packages deps/test*.txt))
  installed=()
  for package in $test_only; do
    dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" || continue
    # A package others depend on (fonts-dejavu-core, which fontconfig pulls
    # in with the build packages) is on a new machine anyway: keep it.
    [ "$(apt-get -s remove "$package" 2>/dev/null | grep -c '^Remv')" -eq 1 ] || continue
    installed+=("$package")
  done
  if [ ${#installed[@]} -gt 0 ]; then
    echo "readme-path: removing the test-only packages: ${installed[*]}"
    DEBIAN_FRONTEND=noninteractive apt-get remove -y -q "${installed[@]}" >"$work/remove.log" 2>&1 \
      || { tail -20 "$work/remove.log"; exit 1; }
  fi
fi

echo "readme-path: make run"
if ! make run >"$work/run.log" 2>&1; then
  tail -30 "$work/run.log"
  echo "readme-path: make run failed" >&2
  exit 1
fi
echo "readme-path: make test"
status=0
make test >"$work/test.log" 2>&1 || status=$?
tail -5 "$work/test.log"

# The tests the source tree defines: every tests/test_*.c and tests/test_*.sh,
# every add_test(NAME ...) of a tests/*.cmake, and the corpus replay of every
# fuzz target that has a corpus (tests/CMakeLists.txt).
expected="$work/expected" registered="$work/registered"
{
  for file in tests/test_*.c tests/test_*.sh; do basename "${file%.*}"; done
  # (a name built from a variable, as test_${name} in a loop, is not read here;
  # the skip check below still catches such a test when its peer is missing)
  sed -n 's/.*add_test(NAME \([A-Za-z0-9_]*\)[ )].*/\1/p' tests/*.cmake
  for file in tests/fuzz/fuzz_*.c; do
    name=$(basename "${file%.c}")
    [ -d "tests/fuzz/corpus/${name#fuzz_}" ] && echo "test_fuzz_replay_${name#fuzz_}"
  done
} | sort -u >"$expected"
ctest --test-dir build -N | sed -n 's/^ *Test *#[0-9]*: *//p' | sort -u >"$registered"
problems=0
missing=$(comm -23 "$expected" "$registered")
if [ -n "$missing" ]; then
  echo "readme-path: tests not registered after make run, make test:" $missing >&2
  problems=1
fi
echo "readme-path: $(wc -l <"$registered") tests registered, $(wc -l <"$expected") expected"

# Skipped or not run: ctest's own words, and every test's own output (all of
# it, passing tests included, is in LastTest.log).
if grep -E '\*\*\*Skipped|Not Run|Disabled|did not run' "$work/test.log" >&2; then
  problems=1
fi
if grep -iE '(^|[^a-z])skipp(ed|ing)' build/Testing/Temporary/LastTest.log >"$work/skips"; then
  echo "readme-path: tests that say they skipped something:" >&2
  cat "$work/skips" >&2
  problems=1
fi
if [ $status -ne 0 ]; then
  grep -A30 "tests failed\|The following tests FAILED" "$work/test.log" >&2 || tail -30 "$work/test.log" >&2
  echo "readme-path: make test failed" >&2
  exit 1
fi
[ $problems -eq 0 ] || exit 1
echo "readme-path: the whole suite ran, nothing skipped"
