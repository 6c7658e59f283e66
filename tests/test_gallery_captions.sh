#!/usr/bin/env bash
# Every caption of the gallery makes its picture again.  Renders the gallery
# with `cg demo`, reads each caption's command from index.html (the
# data-command and data-output attributes of its <code>, docs/gallery.md),
# runs it in a copy of the gallery folder with the picture removed, and
# compares the file it writes with the gallery's picture, byte for byte or,
# failing that, pixel for pixel after decoding.  A caption whose command
# prints text (data-stdout) is compared with the text the page shows.
# Usage: test_gallery_captions.sh CG SOURCE_DIR BUILD_DIR
set -u
cg="$1" source_dir="$2"
. "$source_dir/tests/cli_checks.sh"

"$cg" demo -o "$work/gallery" >/dev/null 2>"$work/demo.err" && pass || fail "cg demo: $(cat "$work/demo.err")"
cp -r "$work/gallery" "$work/run"
# The captions say `cg`: the tool under test comes first on PATH.
mkdir -p "$work/bin" && ln -s "$(cd "$(dirname "$cg")" && pwd)/$(basename "$cg")" "$work/bin/cg"

python3 - "$work/gallery" "$work/run" "$work/bin" <<'PY'
import html, os, re, subprocess, sys
gallery, run, bindir = sys.argv[1:4]
page = open(os.path.join(gallery, "index.html"), encoding="utf-8").read()
figures = re.findall(r'<figure><img src="([^"]*)".*?</figure>', page, re.S)
codes = re.findall(r'<figure><img src="([^"]*)".*?<code ([^>]*)>.*?</figure>', page, re.S)
env = dict(os.environ, PATH=bindir + os.pathsep + os.environ.get("PATH", ""))
passed = failed = 0
demo_captions = 0
problems = []

def attribute(attributes, name):
    m = re.search(r'\b%s="([^"]*)"' % name, attributes)
    return html.unescape(m.group(1)) if m else None

def pixels(path):
    # Decoded by cg itself: a PPM holds exactly the pixels.
    out = path + ".ppm"
    r = subprocess.run(["cg", "convert", path, out], env=env, capture_output=True)
    if r.returncode != 0:
        return None
    with open(out, "rb") as f:
        return f.read()

if len(figures) < 100:
    problems.append("only %d pictures on the page" % len(figures))
if len(codes) != len(figures):
    problems.append("%d pictures but %d captions with a command" % (len(figures), len(codes)))
for picture, attributes in codes:
    command = attribute(attributes, "data-command")
    output = attribute(attributes, "data-output")
    stdout = attribute(attributes, "data-stdout")
    if not command or not command.startswith("cg "):
        problems.append("%s: no data-command" % picture)
        continue
    if command.startswith("cg demo "):
        demo_captions += 1
    if stdout is None:
        if not output:
            problems.append("%s: no data-output" % picture)
            continue
        target = os.path.join(run, output)
        if os.path.exists(target):
            os.remove(target)
    r = subprocess.run(["bash", "-c", command], cwd=run, env=env, capture_output=True, timeout=600)
    if r.returncode != 0:
        problems.append("%s: `%s` exited %d: %s" % (picture, command, r.returncode,
                                                     r.stderr.decode(errors="replace").strip()[:200]))
        continue
    if stdout is not None:
        if r.stdout.decode(errors="replace") != stdout:
            problems.append("%s: `%s` printed other text than the page shows" % (picture, command))
        else:
            passed += 1
        continue
    expected = os.path.join(gallery, picture)
    if not os.path.exists(target):
        problems.append("%s: `%s` wrote no %s" % (picture, command, output))
        continue
    if open(target, "rb").read() == open(expected, "rb").read():
        passed += 1
        continue
    a, b = pixels(target), pixels(expected)
    if a is not None and a == b:
        passed += 1
    else:
        problems.append("%s: `%s` draws a different picture" % (picture, command))
# Only the pictures computed per pixel, with no cg command of their own,
# may fall back on `cg demo --only` (docs/gallery.md): no new ones.
if demo_captions > 26:
    problems.append("%d captions say only `cg demo --only` (at most 26)" % demo_captions)
for p in problems:
    print("FAIL: " + p, file=sys.stderr)
print("%d of %d captions reproduce their picture (%d by `cg demo --only`)"
      % (passed, len(codes), demo_captions))
sys.exit(1 if problems else 0)
PY
[ $? = 0 ] && pass || fail "some captions do not reproduce their picture"
finish
