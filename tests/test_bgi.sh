#!/usr/bin/env bash
# BGI: the lab programs of tests/bgi/ build unchanged against an installed cg
# with `cc prog.c $(pkg-config --cflags --libs cg-bgi)`, run headless to
# their end (getch and kbhit do not wait), and write bgi.png (or
# $CG_BGI_OUTPUT).  Each picture is compared byte for byte with `cg draw`'s
# picture of the same shapes, and checked pixel by pixel against counts
# worked out by hand (bar areas, the house's walls) and against cg check
# (the circles are digital circles, the filled polygon follows the
# pixel-centre rule).
# Usage: test_bgi.sh CG SOURCE_DIR BUILD_DIR
set -u
CG=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
source_dir="$2"
build_dir="$3"
command -v python3 >/dev/null || { echo "test_bgi: needs python3 (Debian package python3)" >&2; exit 77; }
source "$source_dir/tests/cli_checks.sh"
prefix="$work/prefix"
cmake --install "$build_dir" --prefix "$prefix" >/dev/null || { echo "FAIL: cmake --install"; exit 1; }
for f in include/cg/bgi.h include/cg-bgi/graphics.h include/cg-bgi/conio.h include/cg-bgi/dos.h; do
  [ -f "$prefix/$f" ] && pass || fail "$f is installed"
done
pc=$(ls "$prefix"/lib*/pkgconfig/cg-bgi.pc 2>/dev/null | head -1)
[ -n "$pc" ] && pass || { fail "cg-bgi.pc is installed"; finish; exit 1; }
export PKG_CONFIG_PATH=$(dirname "$pc")
# libcg-bgi exports the cg_bgi_ functions of cg/bgi.h and nothing else.
lib=$(ls "$prefix"/lib*/libcg-bgi.so | head -1)
exports=$(nm -D --defined-only "$lib" | awk 'NF == 3 { print $3 }' | sed 's/@.*//' | sort -u)
declared=$(grep -o 'cg_bgi_[a-z]*(' "$source_dir/include/cg/bgi.h" | tr -d '(' | sort -u)
[ -n "$exports" ] && [ "$exports" = "$declared" ] && pass ||
  fail "libcg-bgi.so exports exactly cg/bgi.h's functions: $(diff <(echo "$exports") <(echo "$declared") | head -5)"
# The headers compile as C++ too, and a variable may be called line.
printf '#include <graphics.h>\n#include <conio.h>\n#include <dos.h>\nint main() { int line = 3; return line - 3 + getmaxx() * 0; }\n' > "$work/names.cpp"
if command -v c++ >/dev/null; then
  c++ "$work/names.cpp" -o "$work/names" $(pkg-config --cflags --libs cg-bgi) 2>"$work/err" && "$work/names" && pass ||
    fail "graphics.h in C++ with a variable called line: $(cat "$work/err")"
fi
# Headless: no display, whatever the caller has.
run() { # DIR PROGRAM: runs it in DIR
  (cd "$1" && env -u DISPLAY -u WAYLAND_DISPLAY -u SDL_VIDEODRIVER -u CG_BGI_OUTPUT \
     timeout 30 "./$2" </dev/null)
}
# ppm FILE.png: the picture as binary PPM, for cmp and for the pixel checks.
ppm() { "$CG" convert "$1" "${1%.png}.ppm" >/dev/null 2>&1; }
programs="lines circles house barchart polygon"
for p in $programs; do
  mkdir -p "$work/$p"
  # The build line of the docs, exactly.
  if cc "$source_dir/tests/bgi/$p.c" -o "$work/$p/$p" $(pkg-config --cflags --libs cg-bgi) \
       2>"$work/$p/cc.txt"; then pass; else fail "$p builds: $(cat "$work/$p/cc.txt")"; continue; fi
  # Ends by itself (circles.c is a "void main()" program: its exit status
  # is whatever was left in a register, so only a timeout or a signal fails).
  run "$work/$p" "$p"; status=$?
  [ "$status" -lt 124 ] && pass || fail "$p runs headless to its end (status $status)"
  [ -f "$work/$p/bgi.png" ] && [ "$(png_size "$work/$p/bgi.png")" = 640x480 ] && pass ||
    fail "$p writes a 640x480 bgi.png"
  ppm "$work/$p/bgi.png"
done
# $CG_BGI_OUTPUT names the file instead.
(cd "$work/lines" && env -u DISPLAY -u WAYLAND_DISPLAY CG_BGI_OUTPUT=other.png ./lines </dev/null)
[ -f "$work/lines/other.png" ] && cmp -s "$work/lines/other.png" "$work/lines/bgi.png" && pass ||
  fail "CG_BGI_OUTPUT names the picture"
# With a display: a window, getch waits for a key typed into it, and the
# picture goes to $CG_BGI_OUTPUT only (xvfb and xdotool, as test_view.sh).
if command -v xvfb-run >/dev/null && command -v xdotool >/dev/null && [ -x "$work/house/house" ]; then
  (cd "$work/house" && timeout 60 xvfb-run -a sh -c '
     CG_BGI_OUTPUT=window.png ./house & pid=$!
     for i in 1 2 3 4 5 6 7 8 9 10; do xdotool search --name "cg BGI" >/dev/null 2>&1 && break; sleep 0.5; done
     xdotool search --name "cg BGI" >/dev/null 2>&1 && echo window > found.txt
     sleep 0.5; xdotool key q; wait $pid' </dev/null >/dev/null 2>&1)
  [ -f "$work/house/found.txt" ] && pass || fail "house opens a window under xvfb"
  cmp -s "$work/house/window.png" "$work/house/bgi.png" && pass ||
    fail "the window's program ends at a key and writes CG_BGI_OUTPUT, the same picture"
else
  fail "the window test needs xvfb-run and xdotool (Debian packages xvfb, xdotool)"
fi
# The same shapes through cg draw (the 16 colours as #rrggbb).
reference() { # NAME: compares NAME/bgi.ppm with the script on stdin
  "$CG" draw - -o "$work/$1/expected.ppm" >"$work/err" 2>&1 || fail "$1: reference: $(cat "$work/err")"
  cmp -s "$work/$1/bgi.ppm" "$work/$1/expected.ppm" && pass || fail "$1: picture differs from cg draw's"
}
python3 - "$work" >"$work/lines.txt" <<'PYEOF'
pal = ["#000000", "#0000aa", "#00aa00", "#00aaaa", "#aa0000", "#aa00aa", "#aa5500", "#aaaaaa",
       "#555555", "#5555ff", "#55ff55", "#55ffff", "#ff5555", "#ff55ff", "#ffff55", "#ffffff"]
print("size 640 480\nbackground black")
for i in range(16):
    print("color %s\nline 320 240 %d %d" % (pal[15 if i == 0 else i], 320 + (i - 8) * 35, 20 + (i % 2) * 440))
print("color #ffff55\npolyline 10 10 200 60 30 150\ncolor #ff5555\nline 600 400 600 400")
PYEOF
reference lines <"$work/lines.txt"
{
  echo "size 640 480"; echo "background black"
  pal=(x "#0000aa" "#00aa00" "#00aaaa" "#aa0000" "#aa00aa" "#aa5500" "#aaaaaa")
  for r in 20 50 80 110 140 170 200; do echo "color ${pal[$((r / 30 + 1))]}"; echo "circle 319 239 $r"; done
  echo "color white"; echo "arc 100 100 50 0 90"; echo "ellipse 500 380 100 40"
} | reference circles
printf 'size 640 480\nbackground #0000aa\ncolor #55ff55\npolyline 40 300 160 260 220 380 120 450 60 400 40 300\ncolor #00aaaa\npolygon 300.5 60.5 560.5 140.5 480.5 300.5 340.5 260.5\ncolor white\npolyline 300 60 560 140 480 300 340 260 300 60\n' |
  reference polygon
# Pixel checks by hand, and with cg check.
python3 - "$work" "$CG" <<'PYEOF'
import subprocess, sys
work, cg = sys.argv[1], sys.argv[2]
passed = failed = 0
def ok(c, what):
    global passed, failed
    if c: passed += 1
    else:
        failed += 1
        print("FAIL:", what, file=sys.stderr)
def load(name):
    data = open("%s/%s/bgi.ppm" % (work, name), "rb").read()
    parts = data.split(maxsplit=4)
    w, h = int(parts[1]), int(parts[2])
    body = parts[4][-w * h * 3:]
    return w, h, {(x, y): tuple(body[3 * (y * w + x):3 * (y * w + x) + 3]) for y in range(h) for x in range(w)}
pal = [(0, 0, 0), (0, 0, 170), (0, 170, 0), (0, 170, 170), (170, 0, 0), (170, 0, 170), (170, 85, 0),
       (170, 170, 170), (85, 85, 85), (85, 85, 255), (85, 255, 85), (85, 255, 255), (255, 85, 85),
       (255, 85, 255), (255, 255, 85), (255, 255, 255)]
BLACK, BLUE, GREEN, CYAN, RED, MAGENTA, BROWN, LIGHTBLUE, YELLOW, WHITE, LIGHTRED, LIGHTGREEN = \
    pal[0], pal[1], pal[2], pal[3], pal[4], pal[5], pal[6], pal[9], pal[14], pal[15], pal[12], pal[10]
def count(img, c):
    return sum(1 for v in img.values() if v == c)
def cg_check(args, pixels):
    r = subprocess.run([cg, "check"] + args, input="".join("%d %d\n" % p for p in pixels),
                       capture_output=True, text=True)
    return r.returncode, r.stdout
# lines: the putpixel, and the two lineto lines (191 + 171 pixels, one shared).
w, h, img = load("lines")
ok(img[(600, 400)] == LIGHTRED, "lines: putpixel(600, 400, LIGHTRED)")
left = sum(1 for p, v in img.items() if v == YELLOW and p[0] <= 200)  # line 14 is yellow too, on the right
ok(left == 191 + 171 - 1, "lines: lineto draws 361 yellow pixels, got %d" % left)
line1 = [p for p, v in img.items() if v == YELLOW and 10 <= p[0] <= 200
         and abs(p[1] - (10 + (p[0] - 10) * 50 / 190)) <= 0.5]
code, out = cg_check(["line", "10", "10", "200", "60"], line1)
ok(code == 0, "lines: the first lineto is a digital line segment: %s" % out)
# circles: getmaxx() / 2 = 319; the inner circles are digital circles.
w, h, img = load("circles")
for r in (20, 50, 80, 110):
    c = pal[r // 30 + 1]
    code, out = cg_check(["circle", str(r), "319", "239"], [p for p, v in img.items() if v == c])
    ok(code == 0, "circles: radius %d: %s" % (r, out))
# house: the walls (yellow) are their inside less the door and the window.
w, h, img = load("house")
ok(img[(320, 150)] == RED and img[(210, 350)] == YELLOW and img[(320, 350)] == BROWN,
   "house: roof red, walls yellow, door brown")
ok(count(img, YELLOW) == 239 * 199 - 61 * 100 - 41 * 41, "house: yellow walls %d" % count(img, YELLOW))
ok(count(img, BROWN) == 59 * 99, "house: brown door %d" % count(img, BROWN))
inside = [img[(x, y)] for x in range(231, 270) for y in range(231, 270)]
ok(set(inside) == {LIGHTBLUE, BLACK} and inside.count(LIGHTBLUE) > 39 * 8,
   "house: the window is hatched light blue on black")
ok(img[(100, 100)] == BLACK and img[(319, 99)] == BLACK and img[(320, 100)] == WHITE,
   "house: outside stays black, the roof's top is white")
ok(count(img, WHITE) > 0 and any(img[(x, y)] == WHITE for x in range(280, 330) for y in range(420, 427)),
   "house: the label is drawn")
# barchart: solid bars of 61 x marks pixels, the fifth LINE_FILL (rows y & 7 in 0, 1, 4, 5).
w, h, img = load("barchart")
marks = [120, 250, 180, 300, 90]
for i in range(4):
    ok(count(img, pal[i + 1]) == 61 * marks[i], "barchart: bar %d has %d pixels" % (i + 1, count(img, pal[i + 1])))
rows = sum(1 for y in range(420 - 90, 420) if y & 7 in (0, 1, 4, 5))
ok(count(img, MAGENTA) == 61 * rows, "barchart: the LINE_FILL bar %d" % count(img, MAGENTA))
ok(img[(50, 200)] == WHITE and img[(300, 420)] == WHITE, "barchart: the axes")
# polygon: cyan where the centre is inside (and not on the white outline),
# by cg check's pixel-centre rule once the outline's pixels inside are added.
w, h, img = load("polygon")
ok(img[(5, 5)] == BLUE, "polygon: cleardevice paints the background")
from fractions import Fraction
vertices = [(300, 60), (560, 140), (480, 300), (340, 260)]
def centre_inside(x, y):
    # The pixel-centre rule with vertices at pixel centres: exact fractions.
    yc, crossings = Fraction(2 * y + 1, 2), 0
    for (ax, ay), (bx, by) in zip(vertices, vertices[1:] + vertices[:1]):
        ay, by, ax, bx = Fraction(2 * ay + 1, 2), Fraction(2 * by + 1, 2), Fraction(2 * ax + 1, 2), Fraction(2 * bx + 1, 2)
        if ay == by or not min(ay, by) <= yc < max(ay, by):
            continue
        crossings += ax + (yc - ay) * (bx - ax) / (by - ay) <= Fraction(2 * x + 1, 2)
    return crossings % 2 == 1
filled = {(x, y) for x in range(295, 566) for y in range(55, 306) if centre_inside(x, y)}
cyan = {p for p, v in img.items() if v == CYAN}
white = {p for p, v in img.items() if v == WHITE}
ok(cyan == filled - white, "polygon: cyan is the pixel-centre fill less the outline (%d, %d)" % (len(cyan), len(filled - white)))
code, out = cg_check(["polygon-fill", "300.5,60.5 560.5,140.5 480.5,300.5 340.5,260.5"], sorted(filled))
ok(code == 0, "polygon: the fill counted here passes cg check: %s" % out)
ok(all(img[p] == LIGHTGREEN for p in [(40, 300), (160, 260), (220, 380), (120, 450), (60, 400)]),
   "polygon: drawpoly's vertices")
print("%d passed, %d failed" % (passed, failed))
sys.exit(1 if failed else 0)
PYEOF
[ $? = 0 ] && pass || fail "pixel checks"
finish
