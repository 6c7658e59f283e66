#!/bin/bash
# cg trace: step tables compared with values worked by hand from
# Algorithms 1 and 2 of the notes.
set -u
CG=$1
fail=0
check() { # name expected actual
    if [ "$2" != "$3" ]; then
        echo "FAIL: $1"; echo "expected:"; echo "$2"; echo "got:"; echo "$3"; fail=1
    fi
}
# The step rows only (step, f, move, f', pixel), blanks squeezed; the line's
# octant table (its own phase) is left out.
rows() {
    awk '/^[^ ].*:$/ { phase = $0 } phase != "octant:" && /^ +[0-9]+ /' |
        tr -s ' ' | sed 's/^ //'
}

# Line (0,0)-(8,3): dx = 8, dy = 3, f0 = 2dy - dx = -2, dE = 6, dNE = -10.
out=$("$CG" trace line 0 0 8 3) || { echo "FAIL: trace line exit"; fail=1; }
check "line header" "f = 2dy - dx = -2, dE = 2dy = 6, dNE = 2(dy - dx) = -10" \
      "$(echo "$out" | grep '^f = ')"
check "line steps" "0 - start -2 (0, 0)
1 -2 E 4 (1, 0)
2 4 NE -6 (2, 1)
3 -6 E 0 (3, 1)
4 0 E 6 (4, 1)
5 6 NE -4 (5, 2)
6 -4 E 2 (6, 2)
7 2 NE -8 (7, 3)
8 -8 E -2 (8, 3)" "$(echo "$out" | rows)"

# The same line given backwards is walked from (0, 0) too.
check "line reversed" "$(echo "$out" | rows)" "$("$CG" trace line 8 3 0 0 | rows)"

# A steep line in the third octant: (0,0)-(-2,5): dx = 5, dy = 2 after the
# exchange, f0 = -1, dE = 4, dNE = -6.
out=$("$CG" trace line 0 0 -2 5)
check "steep header" "f = 2dy - dx = -1, dE = 2dy = 4, dNE = 2(dy - dx) = -6" \
      "$(echo "$out" | grep '^f = ')"
check "steep steps" "0 - start -1 (0, 0)
1 -1 E 3 (0, 1)
2 3 NE -3 (-1, 2)
3 -3 E 1 (-1, 3)
4 1 NE -5 (-2, 4)
5 -5 E -1 (-2, 5)" "$(echo "$out" | rows)"

# Horizontal and single-pixel lines.
check "horizontal" "0 - start -3 (2, 2)
1 -3 E -3 (3, 2)
2 -3 E -3 (4, 2)
3 -3 E -3 (5, 2)" "$("$CG" trace line 2 2 5 2 | rows)"
check "single pixel" "0 - start 0 (4, 4)" "$("$CG" trace line 4 4 4 4 | rows)"

# Circle r = 7: f = 1 - r = -6, dE = 3, dSE = -2r + 5 = -9.
#   f < 0: E, f += dE; else SE, f += dSE; then dE += 2, dSE += 2 or 4.
out=$("$CG" trace circle 7) || { echo "FAIL: trace circle exit"; fail=1; }
check "circle steps" "0 - - - start -6 3 -9 (0, 7)
1 -6 3 -9 E -3 5 -7 (1, 7)
2 -3 5 -7 E 2 7 -5 (2, 7)
3 2 7 -5 SE -3 9 -1 (3, 6)
4 -3 9 -1 E 6 11 1 (4, 6)
5 6 11 1 SE 7 13 5 (5, 5)" "$(echo "$out" | rows)"
check "circle count" "6 steps; with 8-way symmetry the circle has 40 pixels" "$(echo "$out" | tail -n 1)"

# Circle r = 10: f0 = -9, dE = 3, dSE = -15.
check "circle 10" "0 - - - start -9 3 -15 (0, 10)
1 -9 3 -15 E -6 5 -13 (1, 10)
2 -6 5 -13 E -1 7 -11 (2, 10)
3 -1 7 -11 E 6 9 -9 (3, 10)
4 6 9 -9 SE -3 11 -5 (4, 9)
5 -3 11 -5 E 8 13 -3 (5, 9)
6 8 13 -3 SE 5 15 1 (6, 8)
7 5 15 1 SE 6 17 5 (7, 7)" "$("$CG" trace circle 10 | rows)"

check "circle 0" "1 step; with 8-way symmetry the circle has 1 pixel" "$("$CG" trace circle 0 | tail -n 1)"

# Bad input: usage errors (exit 2) with a message on stderr.
for args in "line 0 0 8" "line 0 0 8 x" "circle -1" "circle 1.5" "square 3" "" \
            "line 0 0 2147483648 0" "line 0 0 200000 0"; do
    # shellcheck disable=SC2086
    "$CG" trace $args >/dev/null 2>/tmp/cg_trace_err.$$
    status=$?
    if [ $status -eq 0 ] || [ ! -s /tmp/cg_trace_err.$$ ]; then
        echo "FAIL: 'cg trace $args' should fail with a message (status $status)"; fail=1
    fi
done
rm -f /tmp/cg_trace_err.$$
[ $fail -eq 0 ] && echo "cg trace: all checks passed"
exit $fail
