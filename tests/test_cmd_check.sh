#!/bin/bash
# cg check: cg's own results pass; random mutations of them (a pixel moved,
# dropped, duplicated, an endpoint off by one, a clipped point moved) fail
# with the wrong pixel's coordinates in the message, exactly when an
# independent implementation of the definition (here, in Python with exact
# fractions) says they are wrong; another tie choice of a line passes with a
# note; bad input exits 2 with one line on stderr.
# Usage: test_cmd_check.sh CG [SOURCE_DIR BUILD_DIR]
set -u
CG=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
command -v python3 >/dev/null || { echo "test_cmd_check: needs python3 (Debian package python3)" >&2; exit 77; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# The room the flood fills are checked in (as in test_cg_trace.sh).
printf 'size 16 12\nbackground white\ncolor black\npolyline 1 1 14 1 14 10 1 10 1 1\nline 7 1 7 7\nline 10 4 14 4\n' \
    >"$work/room.txt"
"$CG" draw "$work/room.txt" -o "$work/room.png" || { echo "FAIL: cannot draw the room"; exit 1; }
# The examples of docs/teaching.md ("$ printf ... | cg check ...") print
# what the docs show.
docs_fail=0 docs_count=0
if [ -n "${2:-}" ] && [ -f "$2/docs/teaching.md" ]; then
  while IFS= read -r command; do
    expected=$(c="$command" awk '$0 == "$ " ENVIRON["c"] { on = 1; next } on && /^(\$ |```)/ { exit } on' "$2/docs/teaching.md")
    actual=$(eval "${command/| cg check/| \"\$CG\" check}")
    if [ "$expected" != "$actual" ]; then
      echo "FAIL: docs example: $command"; echo "expected: $expected"; echo "got: $actual"; docs_fail=1
    fi
    docs_count=$((docs_count + 1))
  done < <(sed -n 's/^\$ \(printf .*| cg check .*\)/\1/p' "$2/docs/teaching.md")
  [ "$docs_count" -ge 5 ] || { echo "FAIL: docs/teaching.md has $docs_count cg check examples"; docs_fail=1; }
fi
CG="$CG" WORK="$work" python3 - <<'PYEOF'
import json, os, random, subprocess, sys
from fractions import Fraction

CG, WORK = os.environ["CG"], os.environ["WORK"]
random.seed(23)
passed = failed = 0

def ok(condition, what):
    global passed, failed
    if condition:
        passed += 1
    else:
        failed += 1
        print("FAIL:", what, file=sys.stderr)

def check(args, lines, extra=()):
    text = "".join("%s %s\n" % p for p in lines)
    r = subprocess.run([CG, "check"] + list(map(str, args)) + list(extra), input=text,
                       capture_output=True, text=True)
    return r.returncode, r.stdout, r.stderr

def trace(args):
    r = subprocess.run([CG, "trace"] + list(map(str, args)) + ["--json"], capture_output=True,
                       text=True, check=True)
    return json.loads(r.stdout)

def pixels(args):
    seen, out = set(), []
    for s in trace(args)["steps"]:
        for p in s.get("pixels", []):
            if tuple(p) not in seen:
                seen.add(tuple(p))
                out.append(tuple(p))
    return out

def named(message, p):
    return "(%d, %d)" % p in message

# ---- lines: the DLS definition, exactly --------------------------------
def is_dls(x1, y1, x2, y2, pts):
    if len(set(pts)) != len(pts):
        return False
    steep = abs(y2 - y1) > abs(x2 - x1)
    f = (lambda p: (p[1], p[0])) if steep else (lambda p: p)
    (u1, v1), (u2, v2) = f((x1, y1)), f((x2, y2))
    cols = {}
    for p in pts:
        u, v = f(p)
        if not min(u1, u2) <= u <= max(u1, u2):
            return False
        line = Fraction(v1) if u1 == u2 else v1 + Fraction((u - u1) * (v2 - v1), u2 - u1)
        if abs(v - line) > Fraction(1, 2):
            return False
        cols.setdefault(u, []).append(v)
    return all(len(cols.get(u, [])) == 1 for u in range(min(u1, u2), max(u1, u2) + 1)) and \
        f((x1, y1)) in [f(p) for p in pts] and f((x2, y2)) in [f(p) for p in pts]

def tie_variants(x1, y1, x2, y2, pts):
    """The same DLS with each tie pixel swapped for the other candidate."""
    steep = abs(y2 - y1) > abs(x2 - x1)
    out = []
    for p in pts:
        u, v = (p[1], p[0]) if steep else p
        (u1, v1), (u2, v2) = ((y1, x1), (y2, x2)) if steep else ((x1, y1), (x2, y2))
        line = Fraction(v1) if u1 == u2 else v1 + Fraction((u - u1) * (v2 - v1), u2 - u1)
        if abs(v - line) == Fraction(1, 2) and random.random() < 0.7:
            v = int(2 * line - v)
        out.append((v, u) if steep else (u, v))
    return out

lines = [(1, 1, 22, 9), (0, 0, 8, 3), (0, 0, 4, 2), (5, 5, 5, 5), (3, 9, 3, -4), (-7, 2, 6, 2)]
for _ in range(150):
    x1, y1 = random.randint(-30, 30), random.randint(-30, 30)
    d = random.choice([6, 20, 60])
    x2, y2 = x1 + random.randint(-d, d), y1 + random.randint(-d, d)
    lines.append((x1, y1, x2, y2))
ties = 0
for (x1, y1, x2, y2) in lines:
    args = ["line", x1, y1, x2, y2]
    pts = pixels(args)
    code, out, err = check(args, pts)
    ok(code == 0 and out.startswith("right:"), "cg's own line %s: %s%s" % (args, out, err))
    ok(is_dls(x1, y1, x2, y2, pts), "cg's line %s is a DLS by the definition" % args)
    code, out, _ = check(args, list(reversed(pts)))
    ok(code == 0, "line %s in reverse order" % args)
    variant = tie_variants(x1, y1, x2, y2, pts)
    if variant != pts:
        ties += 1
        code, out, _ = check(args, variant)
        ok(code == 0 and "only at" in out and "tie" in out,
           "line %s with other tie choices passes with a note: %s" % (args, out))
    # Mutations: expected status from the definition, coordinates named.
    for kind in ["move", "drop", "duplicate", "past the end", "endpoint off"]:
        m = list(pts)
        i = random.randrange(len(m))
        was = m[i]
        if kind == "move":
            dx, dy = random.choice([(0, 1), (0, -1), (1, 0), (-1, 0), (1, 1)])
            m[i] = (m[i][0] + dx, m[i][1] + dy)
            bad = m[i]
        elif kind == "drop":
            bad = m.pop(i)
        elif kind == "duplicate":
            m.insert(random.randrange(len(m) + 1), m[i])
            bad = m[i] if m[i] == pts[i] else pts[i]
        elif kind == "past the end":
            sx = (x2 > x1) - (x2 < x1)
            sy = (y2 > y1) - (y2 < y1)
            if abs(x2 - x1) >= abs(y2 - y1):
                sy = 0 if abs(x2 - x1) > abs(y2 - y1) else sy
                sx = sx or 1
            else:
                sx = 0
            bad = (x2 + sx, y2 + sy)
            m.append(bad)
        else:
            end = (x1, y1) if random.random() < 0.5 else (x2, y2)
            j = m.index(end)
            m[j] = (end[0], end[1] + 1) if abs(x2 - x1) >= abs(y2 - y1) else (end[0] + 1, end[1])
            bad = m[j]
        code, out, _ = check(args, m)
        want = 0 if is_dls(x1, y1, x2, y2, m) else 1
        ok(code == want, "line %s, %s: exit %d, want %d: %s" % (args, kind, code, want, out))
        if want == 1:
            # A moved pixel may be right where it lands and leave its
            # column empty, which the walk from the first endpoint names.
            ok(out.startswith("wrong:") and (named(out, bad) or kind == "move" and
                                             named(out, was)),
               "line %s, %s of %s: the message names it: %s" % (args, kind, bad, out))
ok(ties > 10, "some random lines have ties (%d)" % ties)
code, out, _ = check(["line", 1, 1, 22, 9], [(7, 4)] + [p for p in pixels(["line", 1, 1, 22, 9]) if p[0] != 7])
ok(code == 1 and "pixel (7, 4) is 5/7 = 0.71 from the line along y; a DLS pixel is at most 1/2 away" in out,
   "the notes' line with (7, 4): %s" % out)

# ---- circles and ellipses ------------------------------------------------
def circle_ok(r, cx, cy, pts):
    """The digital circle by its definition: first-octant y = round(sqrt(r^2 - x^2))."""
    want = set()
    x, y = 0, r
    while True:
        for a, b in [(x, y), (y, x)]:
            for sa in (1, -1):
                for sb in (1, -1):
                    want.add((cx + sa * a, cy + sb * b))
        if x >= y:
            break
        x += 1
        if 4 * x * x + (2 * y - 1) ** 2 - 4 * r * r >= 0:
            y -= 1
        if x > y:
            break
    return len(set(pts)) == len(pts) and set(pts) == want

for r in [0, 1, 2, 3, 5, 11, 41] + [random.randint(0, 80) for _ in range(60)]:
    cx, cy = random.randint(-20, 20), random.randint(-20, 20)
    args = ["circle", r, cx, cy]
    pts = pixels(["circle", r])
    pts = [(x + cx, y + cy) for (x, y) in pts]
    code, out, err = check(args, pts)
    ok(code == 0 and circle_ok(r, cx, cy, pts), "cg's own circle %s: %s%s" % (args, out, err))
    for kind in ["move", "drop", "duplicate"]:
        m = list(pts)
        i = random.randrange(len(m))
        if kind == "move":
            m[i] = (m[i][0] + random.choice([-1, 1]), m[i][1])
            bad = m[i]
        elif kind == "drop":
            bad = m.pop(i)
        else:
            m.append(m[i])
            bad = m[i]
        code, out, _ = check(args, m)
        want = 0 if circle_ok(r, cx, cy, m) else 1
        ok(code == want and (want == 0 or named(out, bad) or kind == "move"
                             and named(out, pts[i])),
           "circle %s, %s of %s: exit %d: %s" % (args, kind, bad, code, out))
code, out, _ = check(["circle", 11], pixels(["circle", 11]))
ok(code == 0 and "8-symmetric" in out, "the notes' circle of radius 11")

for _ in range(80):
    rx, ry = random.randint(0, 40), random.randint(0, 40)
    args = ["ellipse", rx, ry]
    pts = pixels(args if rx != ry else ["circle", rx])
    code, out, err = check(args, pts)
    ok(code == 0, "cg's own ellipse %s: %s%s" % (args, out, err))
    if len(pts) > 1:
        m = list(pts)
        bad = m.pop(random.randrange(len(m)))
        code, out, _ = check(args, m)
        ok(code == 1 and named(out, bad), "ellipse %s without %s: %s" % (args, bad, out))
        m = list(pts)
        i = random.randrange(len(m))
        m[i] = (m[i][0], m[i][1] + 3)
        code, out, _ = check(args, m)
        ok(code == 1 and named(out, m[i]) if m[i] not in pts else code == 1,
           "ellipse %s with %s moved: %s" % (args, m[i], out))

# ---- polygon fill: cg's own fills pass; a pixel dropped or added fails ---
def polygon_text(pts):
    return " ".join("%s,%s" % p for p in pts)

polys = ["1,1 9,2 5,8", "0,0 4,0 4,4 0,4", "0.5,0.5 6.5,0.5 6.5,3.5 0.5,3.5",
         "2,1 12,1 12,9 7,4 2,9; 4,2 6,2 6,3 4,3", "-3,-2 5,-1 1,6"]
for _ in range(80):
    n = random.randint(3, 7)
    grid = random.choice([1, 2, 0])
    def coord():
        v = random.uniform(-5, 25)
        return round(v) if grid == 1 else round(v * 2) / 2 if grid == 2 else round(v, 3)
    polys.append(polygon_text([(coord(), coord()) for _ in range(n)]))
for poly in polys:
    for rule in ["even-odd", "nonzero"]:
        args = ["polygon-fill", poly, rule]
        pts = pixels(["scanline", poly, rule])
        code, out, err = check(args, pts)
        ok(code == 0, "cg's own fill %s: %s%s" % (args, out, err))
        if pts:
            m = list(pts)
            bad = m.pop(random.randrange(len(m)))
            code, out, _ = check(args, m)
            ok(code == 1 and named(out, bad) and "is not filled" in out,
               "fill %s without %s: %s" % (args, bad, out))
            m = list(pts)
            m.append(m[random.randrange(len(m))])
            code, out, _ = check(args, m)
            ok(code == 1 and "listed twice" in out, "fill %s with a pixel twice" % args)
        s = set(pts)
        outside = [(x, y) for (x, y) in [(p[0] + 1, p[1]) for p in pts] + [(p[0], p[1] - 1) for p in pts]
                   if (x, y) not in s]
        if outside:
            bad = random.choice(outside)
            code, out, _ = check(args, pts + [bad])
            ok(code == 1 and named(out, bad) and "is filled" in out,
               "fill %s with %s added: %s" % (args, bad, out))

# ---- flood fill -----------------------------------------------------------
room = os.path.join(WORK, "room.png")
for seed in [(3, 3), (12, 2), (12, 8), (0, 0), (8, 5), (1, 1)]:
    for conn in ["4", "8"]:
        args = ["flood-fill", room, seed[0], seed[1], conn]
        pts = pixels(["flood", room, seed[0], seed[1], conn])
        code, out, err = check(args, pts)
        ok(code == 0, "cg's own flood fill %s: %s%s" % (args, out, err))
        if len(pts) > 1:
            m = list(pts)
            bad = m.pop(random.randrange(len(m)))
            code, out, _ = check(args, m)
            ok(code == 1 and named(out, bad), "flood %s without %s: %s" % (args, bad, out))
            s = set(pts)
            extra = [p for p in [(x, y) for x in range(16) for y in range(12)] if p not in s]
            bad = random.choice(extra)
            code, out, _ = check(args, pts + [bad])
            ok(code == 1 and named(out, bad), "flood %s with %s: %s" % (args, bad, out))

# ---- Cohen-Sutherland and Sutherland-Hodgman -------------------------------
def clip_line(w, p0, p1):
    r = subprocess.run([CG, "clip", "line"] + [str(v) for v in w] + [str(v) for v in p0 + p1],
                       capture_output=True, text=True)
    words = r.stdout.split()
    return [] if len(words) < 4 else [(words[0], words[1]), (words[2], words[3])]

for _ in range(120):
    w = (0, 0, random.randint(4, 20), random.randint(4, 20))
    p0 = (random.randint(-10, 30), random.randint(-10, 30))
    p1 = (random.randint(-10, 30), random.randint(-10, 30))
    args = ["cohen-sutherland"] + list(w) + ["%d,%d" % p0, "%d,%d" % p1]
    res = clip_line(w, p0, p1)
    code, out, err = check(args, res)
    ok(code == 0, "cg's own clip %s -> %s: %s%s" % (args, res, out, err))
    if res:
        code, out, _ = check(args, list(reversed(res)))
        ok(code == 0, "clip %s reversed" % args)
        code, out, _ = check(args, [])
        ok(code == 1 and "rejected, but" in out, "clip %s rejected wrongly: %s" % (args, out))
        i = random.randrange(2)
        m = list(res)
        m[i] = ("%g" % (float(m[i][0]) + 0.5), m[i][1])
        code, out, _ = check(args, m)
        ok(code == 1 and "(%s, %g)" % (m[i][0], float(m[i][1])) in out,
           "clip %s with %s moved: %s" % (args, m[i], out))
    else:
        code, out, _ = check(args, [(1, 1), (2, 2)])
        ok(code == 1, "clip %s: points where all is rejected: %s" % (args, out))

def sh_output(window, subject):
    steps = trace(["sutherland-hodgman", window, subject])["steps"]
    return [tuple(p) for p in steps[-1]["values"]["output"]] if steps else []

for _ in range(60):
    xmax, ymax = random.randint(4, 20), random.randint(4, 20)
    window = polygon_text([(0, 0), (xmax, 0), (xmax, ymax), (0, ymax)])
    subject = polygon_text([(random.randint(-8, 28), random.randint(-8, 28)) for _ in range(random.randint(3, 6))])
    args = ["sutherland-hodgman", window, subject]
    res = sh_output(window, subject)
    res_text = [("%.17g" % x, "%.17g" % y) for (x, y) in res]
    code, out, err = check(args, res_text)
    ok(code == 0, "cg's own SH %s: %s%s" % (args, out, err))
    if len(res) >= 3:
        k = random.randrange(len(res))
        code, out, _ = check(args, res_text[k:] + res_text[:k])
        ok(code == 0, "SH %s rotated" % args)
        m = list(res)
        i = random.randrange(len(m))
        m[i] = (m[i][0] + 3, m[i][1] + 100)
        code, out, _ = check(args, m)
        ok(code == 1 and "(%g, %g)" % m[i] in out, "SH %s with %s moved out: %s" % (args, m[i], out))

# ---- bad input: exit 2, one line on stderr --------------------------------
for args, text in [(["line", 0, 0, 4, 2], "0 0\nfoo\n"), (["line", 0, 0, 4, 2], "0 0 0\n"),
                   (["line", 0, 0, 4, 2], "0 1.5\n"), (["line", 0, 0, 4], ""),
                   (["nonsense"], ""), ([], ""), (["circle", -1], ""),
                   (["polygon-fill", "0,0 1,1"], ""), (["polygon-fill", "0,0 9,0 9,9", "odd"], ""),
                   (["flood-fill", os.path.join(WORK, "none.png"), 1, 1], ""),
                   (["flood-fill", room, 99, 1], ""), (["flood-fill", room, 1, 1, 6], ""),
                   (["cohen-sutherland", 0, 0, 10, 10, "1,1", "2,2"], "1 1\n2 2\n3 3\n"),
                   (["cohen-sutherland", 10, 0, 0, 10, "1,1", "2,2"], ""),
                   (["sutherland-hodgman", "0,0 1,0", "0,0 1,0 1,1"], ""),
                   (["line", 0, 0, 4, 2, "--tolerance", "-1"], "")]:
    r = subprocess.run([CG, "check"] + list(map(str, args)), input=text, capture_output=True, text=True)
    ok(r.returncode == 2 and len(r.stderr.splitlines()) == 1 and r.stderr.startswith("cg: check:"),
       "bad input %s %r: exit %d, %r" % (args, text, r.returncode, r.stderr))
# Comments, blank lines and the other spellings of a pair are accepted.
code, out, _ = check(["line", 0, 0, 3, 1], [])
ok(code == 1 and "endpoint (0, 0) is missing" in out, "no pixel at all: %s" % out)
r = subprocess.run([CG, "check", "line", "0", "0", "3", "1"], capture_output=True, text=True,
                   input="# my Bresenham\n\n(0, 0)\n1,0  # E\n  2 1\r\n3\t1\n")
ok(r.returncode == 0, "comments and spellings: %s%s" % (r.stdout, r.stderr))
r = subprocess.run([CG, "help", "check"], capture_output=True, text=True)
ok(r.returncode == 0 and all(a in r.stdout for a in ["line X1 Y1 X2 Y2", "circle R", "ellipse RX RY",
   "polygon-fill", "flood-fill", "cohen-sutherland", "sutherland-hodgman"]), "cg help check")
print("%d passed, %d failed" % (passed, failed))
sys.exit(1 if failed else 0)
PYEOF
status=$?
[ "$docs_fail" = 0 ] && [ "$status" = 0 ]
