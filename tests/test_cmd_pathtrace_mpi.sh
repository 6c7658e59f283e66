#!/usr/bin/env bash
# `mpirun -np N cg render MESH --algorithm pathtrace` and --checkpoint:
# the same bytes as one process on 1, 2 and 4 ranks, for whole pictures and
# for parts; a checkpoint that a rerun resumes from, on any rank count; a
# killed rank ends the job non-zero and leaves no output.
# usage: test_cmd_pathtrace_mpi.sh CG SOURCE_DIR BUILD_DIR
set -u
cg="$1"
src="$2"
failed=0
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mesh="$src/examples/teaching/cube.obj"
# 96 x 64 pixels and 40 samples: 3 x 2 tiles of 32 pixels, 3 sample ranges
# of 16: 18 units.
common=(--algorithm pathtrace --size 96x64 --spp 40 --seed 3 --max-depth 5)

fail() { echo "FAIL: $*"; failed=1; }

if ! command -v mpirun >/dev/null 2>&1; then
  echo "test_cmd_pathtrace_mpi: mpirun not found: skipped (apt-get install openmpi-bin)"
  exit 77
fi
# Open MPI refuses root unless told; CI runs as root.  The sanitizer build's
# leak checker would report Open MPI's own allocations at exit.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0"
mpi() { # NP ARGS...: cg under mpirun on NP local ranks
  local np="$1"
  shift
  timeout 300 mpirun --oversubscribe --bind-to none -np "$np" "$cg" "$@"
}

if ! mpi 2 render "$mesh" "${common[@]}" --quiet -o "$tmp/probe.pfm" 2>"$tmp/err"; then
  if grep -q "built without Open MPI" "$tmp/err"; then
    echo "test_cmd_pathtrace_mpi: cg built without Open MPI: skipped (apt-get install libopenmpi-dev, then make test)"
    exit 77
  fi
  fail "mpirun -np 2 failed: $(cat "$tmp/err")"
fi

"$cg" render "$mesh" "${common[@]}" --quiet -o "$tmp/one.pfm" || fail "one-process render failed"
"$cg" render "$mesh" "${common[@]}" --quiet -o "$tmp/one.png" || fail "one-process PNG failed"
for np in 1 2 4; do
  mpi "$np" render "$mesh" "${common[@]}" --quiet -o "$tmp/np$np.pfm" 2>"$tmp/err" \
    || fail "-np $np failed: $(cat "$tmp/err")"
  cmp -s "$tmp/one.pfm" "$tmp/np$np.pfm" || fail "-np $np differs from one process (PFM)"
  mpi "$np" render "$mesh" "${common[@]}" --quiet -o "$tmp/np$np.png" 2>"$tmp/err" \
    || fail "-np $np PNG failed: $(cat "$tmp/err")"
  cmp -s "$tmp/one.png" "$tmp/np$np.png" || fail "-np $np differs from one process (PNG)"
done

# A part (tile and sample range) over ranks is the one-process part.
part=(--tile 10,5,70,50 --sample-range 3..29)
"$cg" render "$mesh" "${common[@]}" "${part[@]}" --quiet -o "$tmp/one.part" || fail "part failed"
mpi 3 render "$mesh" "${common[@]}" "${part[@]}" --quiet -o "$tmp/np3.part" 2>"$tmp/err" \
  || fail "-np 3 part failed: $(cat "$tmp/err")"
cmp -s "$tmp/one.part" "$tmp/np3.part" || fail "-np 3 part differs from one process"

# Checkpoints: one process fills the directory with the 18 units and gives
# the same bytes; a rerun on 2 ranks after 5 units are lost and one is
# truncated renders only those 6 and gives the same bytes again.
ck="$tmp/checkpoint"
"$cg" render "$mesh" "${common[@]}" --checkpoint "$ck" -o "$tmp/ck1.pfm" 2>"$tmp/err" \
  || fail "--checkpoint render failed: $(cat "$tmp/err")"
cmp -s "$tmp/one.pfm" "$tmp/ck1.pfm" || fail "--checkpoint render differs"
grep -q "0 of 18 units from the checkpoint" "$tmp/err" || fail "fresh checkpoint: $(cat "$tmp/err")"
[ "$(ls "$ck" | wc -l)" -eq 18 ] || fail "checkpoint holds $(ls "$ck" | wc -l) files, not 18"
ls "$ck"/* | head -5 | xargs rm -f
victim=$(ls "$ck"/* | head -1)
truncate -s 100 "$victim"
mpi 2 render "$mesh" "${common[@]}" --checkpoint "$ck" -o "$tmp/ck2.pfm" 2>"$tmp/err" \
  || fail "resumed -np 2 render failed: $(cat "$tmp/err")"
cmp -s "$tmp/one.pfm" "$tmp/ck2.pfm" || fail "resumed render differs"
grep -q "12 of 18 units from the checkpoint" "$tmp/err" || fail "resume: $(cat "$tmp/err")"
grep -q "rendering that unit again" "$tmp/err" || fail "a truncated unit was not reported"
[ "$(ls "$ck" | wc -l)" -eq 18 ] || fail "resumed checkpoint holds $(ls "$ck" | wc -l) files"
# Another seed shares the directory without touching this render's units.
"$cg" render "$mesh" "${common[@]}" --seed 4 --checkpoint "$ck" --quiet -o "$tmp/seed4.pfm" \
  || fail "second render in the checkpoint failed"
[ "$(ls "$ck" | wc -l)" -eq 36 ] || fail "two renders' checkpoint holds $(ls "$ck" | wc -l) files"
"$cg" render "$mesh" "${common[@]}" --checkpoint "$ck" -o "$tmp/ck3.pfm" 2>"$tmp/err" \
  || fail "third checkpoint render failed"
grep -q "18 of 18 units from the checkpoint" "$tmp/err" || fail "complete checkpoint: $(cat "$tmp/err")"
cmp -s "$tmp/one.pfm" "$tmp/ck3.pfm" || fail "render from a full checkpoint differs"

# --time needs one process: a usage error under mpirun.
if mpi 2 render "$mesh" "${common[@]}" --time 1 -o "$tmp/time.pfm" 2>"$tmp/err"; then
  fail "--time under mpirun succeeded"
fi
grep -q -- "--time renders in one process" "$tmp/err" || fail "--time message: $(cat "$tmp/err")"

# A rank killed in the middle: the job ends non-zero, with no output.
long=(--algorithm pathtrace --size 96x64 --spp 100000 --quiet)
mpi 2 render "$mesh" "${long[@]}" -o "$tmp/killed.pfm" 2>"$tmp/killed.err" &
job=$!
victim=""
for _ in $(seq 200); do
  for pid in $(pgrep -f -- "$tmp/killed.pfm"); do
    if tr '\0' '\n' <"/proc/$pid/environ" 2>/dev/null | grep -qx "OMPI_COMM_WORLD_RANK=1"; then
      victim=$pid
    fi
  done
  [ -n "$victim" ] && break
  sleep 0.1
done
if [ -z "$victim" ]; then
  fail "rank 1 of the long render was not found"
  kill "$job" 2>/dev/null
else
  sleep 0.5
  kill -9 "$victim"
fi
if wait "$job"; then
  fail "the job with a killed rank exited 0"
fi
[ -e "$tmp/killed.pfm" ] && fail "the job with a killed rank left an output"
ls "$tmp" | grep -q "killed.pfm" && fail "the job with a killed rank left a temporary file"
[ -s "$tmp/killed.err" ] || fail "the job with a killed rank said nothing"

[ "$failed" -eq 0 ] && echo "test_cmd_pathtrace_mpi: all passed"
exit "$failed"
