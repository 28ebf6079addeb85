#!/bin/sh
# The compare page in headless Chromium (tests/html_check.sh): every image
# loads and is a link to the full-size picture, no two pictures or
# captions of the page overlap as the browser lays them out, the crops of
# every filter stand in one row, no console errors, and a screenshot is
# taken (WORKDIR/compare_page.png). A copy with one broken link checks that
# the hook does see failures. Skips (77) without Chromium.
# Usage: compare_html.sh TEXSAMPLE WORKDIR
set -u
exe=$1
work=$2
. "$(dirname "$0")/html_check.sh"
html_check_init
if ! "$exe" compare --scene plane --scene teapot --size 32 --runs 1 --out "$work/page" >"$work/compare.txt" 2>&1; then
  echo "FAIL: texsample compare failed"; cat "$work/compare.txt"; exit 1
fi
page="$work/page/index.html"
expected=$(grep -o '<img ' "$page" | wc -l)
status=0
html_check "$work/page" index.html ok
html_check_clean ok "$expected" || status=1
# One strip per scene, holding the crop of the truth and of every filter
# that ran, in the table's order.
configs=$(grep -c '^plane,' "$work/page/results.csv")
for scene in plane teapot; do
  strip=$(sed -n '/<div class="strip">/,/<\/div>/p' "$page" | grep -o "src=\"$scene/[^\"]*_crop.png\"" | wc -l)
  if [ "$strip" != $((configs + 1)) ]; then
    echo "FAIL: $scene: $strip crops in the strip, $((configs + 1)) expected"; status=1
  fi
done
html_check "$work/page" index.html broken 's|src="plane/truth.png"|src="plane/missing.png"|'
if ! grep -q "^IMAGES $expected BROKEN 1 plane/missing.png" "$work/broken.verdict"; then
  echo "FAIL: the hook did not notice a broken image"; cat "$work/broken.verdict"; status=1
fi
chrome --window-size=1400,2200 --screenshot="$work/compare_page.png" "file://$page" >"$work/shot.log" 2>&1
if ! head -c 8 "$work/compare_page.png" 2>/dev/null | grep -q PNG; then
  echo "FAIL: no screenshot"; cat "$work/shot.log"; status=1
fi
[ $status = 0 ] && echo "OK: $expected images loaded and linked, nothing overlaps, no console errors; screenshot $work/compare_page.png"
exit $status
