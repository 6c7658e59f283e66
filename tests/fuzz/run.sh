#!/bin/sh
# One fuzz test: runs a libFuzzer target for SECONDS from the seeds and every
# kept failure of tests/fuzz/corpus/NAME/ (which libFuzzer runs first, so they
# are replayed too), adding what it learns to a corpus in the build tree.
# An input that fails (crash, leak, timeout, out of memory) is kept as a
# regression case: copied into tests/fuzz/corpus/NAME/ under libFuzzer's name
# for it, and printed in base64 so that a log alone is enough to recover it.
# One input may take at most 60 s (libFuzzer's default, 1,200 s, would let a
# single slow input run past the whole stage's budget unseen).
# Usage: run.sh FUZZER NAME SECONDS WORK_DIR CORPUS_DIR [DICTIONARY]
fuzzer=$1 name=$2 seconds=$3 work=$4 corpus=$5 dict=${6:-}
rm -rf "$work/failures"
mkdir -p "$work/corpus" "$work/failures" || exit 1
set -- -max_total_time="$seconds" -timeout=60 -rss_limit_mb=2048 -artifact_prefix="$work/failures/"
[ -n "$dict" ] && set -- "$@" -dict="$dict"
if [ -d "$corpus" ]; then
  set -- "$@" "$work/corpus" "$corpus"
else
  set -- "$@" "$work/corpus"
fi
"$fuzzer" "$@"
status=$?
[ $status -eq 0 ] && exit 0
for input in "$work/failures"/*; do
  [ -f "$input" ] || continue
  mkdir -p "$corpus" && cp "$input" "$corpus/" \
    && echo "$name: the failing input is kept as $corpus/$(basename "$input"): commit it with the fix"
  if [ "$(wc -c <"$input")" -le 65536 ]; then
    echo "$name: $(basename "$input") in base64 (base64 -d > FILE):"
    base64 "$input"
  fi
done
exit 1   # not libFuzzer's 77, which ctest could read as "skipped"
