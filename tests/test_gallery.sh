#!/usr/bin/env bash
# Renders the gallery with `cg demo` and opens its page in headless Chromium:
# every picture loads, the page logs no console error, sections follow the
# chapters in order, figures neither overlap nor overflow their column, and
# each has a caption and the command that makes it.  A screenshot of the page
# is checked to be a real rendering (not blank).
# Usage: test_gallery.sh CG SOURCE_DIR BUILD_DIR
set -u
cg="$1" source_dir="$2"
browser=$(command -v chromium || command -v chromium-browser || true)
if [ -z "$browser" ]; then
  echo "test_gallery: chromium is not installed; skipped (apt-get install chromium)"
  echo "0 passed, 0 failed, 1 skipped"
  exit 77
fi
. "$source_dir/tests/cli_checks.sh"

"$cg" demo -o "$work/gallery" >/dev/null 2>"$work/demo.err" && pass || fail "cg demo: $(cat "$work/demo.err")"
flags=(--headless --no-sandbox --disable-gpu --disable-quic --no-first-run
       --disable-background-networking --disable-component-update --disable-sync
       --user-data-dir="$work/profile" --allow-file-access-from-files
       --virtual-time-budget=20000)
timeout 120 "$browser" "${flags[@]}" --enable-logging=stderr --v=0 --dump-dom \
  "file://$source_dir/tests/gallery/check.html?page=file://$work/gallery/index.html" \
  >"$work/dom.html" 2>"$work/browser.log"
result=$(grep -o 'RESULT {.*}' "$work/dom.html" | sed 's/^RESULT //; s/&quot;/"/g')
if [ -z "$result" ]; then
  fail "the check page produced no result"
  tail -5 "$work/browser.log" >&2
else
  pass
  python3 - "$result" <<'PY' && pass || fail "layout check: $result"
import json, sys
r = json.loads(sys.argv[1])
problems = []
# Built from the source tree, every section finds its data: a drop means
# pictures were skipped silently.
if r["images"] < 100: problems.append("only %d pictures" % r["images"])
if r["broken"]: problems.append("pictures that did not load: %s" % r["broken"])
if r["sections"] != sorted(r["sections"]) or len(set(r["sections"])) != len(r["sections"]):
    problems.append("sections out of chapter order: %s" % r["sections"])
for key in ("overlaps", "too_wide", "missing_caption", "missing_command"):
    if r[key]: problems.append("%s: %d" % (key, r[key]))
if problems:
    print("; ".join(problems), file=sys.stderr)
    sys.exit(1)
PY
fi
# Console errors from the gallery page (not from the browser's own start-up).
if grep 'CONSOLE' "$work/browser.log" | grep -v 'check.html' | grep -qi 'error'; then
  fail "console errors: $(grep 'CONSOLE' "$work/browser.log" | head -3)"
else
  pass
fi
timeout 120 "$browser" "${flags[@]}" --window-size=1280,2400 --screenshot="$work/page.png" \
  "file://$work/gallery/index.html" >/dev/null 2>&1
if [ -s "$work/page.png" ]; then
  # A rendered page has many distinct colours; a blank one has one or two.
  "$cg" convert "$work/page.png" "$work/page.ppm" >/dev/null 2>&1
  colours=$(python3 -c "
import sys
data = open(sys.argv[1], 'rb').read()
parts = data.split(b'\n', 3)
pixels = parts[3]
print(len({pixels[i:i+3] for i in range(0, len(pixels), 3 * 97)}))" "$work/page.ppm")
  [ "$colours" -gt 20 ] && pass || fail "screenshot looks blank ($colours colours)"
  [ -n "${CG_GALLERY_SCREENSHOT:-}" ] && cp "$work/page.png" "$CG_GALLERY_SCREENSHOT"
else
  fail "no screenshot"
fi
finish
