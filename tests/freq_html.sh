#!/bin/sh
# The freq page in headless Chromium (tests/html_check.sh): every image
# loads and opens at full size, and no two texts of a figure (title, panel
# titles, tick labels, axis names, legend) intersect, nor pictures and
# captions of the page, as the browser lays them out; no console errors.
# Skips (77) without Chromium.
# Usage: freq_html.sh TEXSAMPLE WORKDIR
set -u
exe=$1
work=$2
. "$(dirname "$0")/html_check.sh"
html_check_init
if ! "$exe" freq --quick --theta 0 --r 1,4 --out "$work/page" >"$work/freq.txt" 2>&1; then
  echo "FAIL: texsample freq failed"; cat "$work/freq.txt"; exit 1
fi
expected=$(grep -o '<img ' "$work/page/index.html" | wc -l)
figures=$(grep -o '<svg xmlns="http://www.w3.org/2000/svg" class="figure"' "$work/page/index.html" | wc -l)
status=0
[ "$figures" = 2 ] || { echo "FAIL: $figures inline figures, 2 expected"; status=1; }
html_check "$work/page" index.html ok
html_check_clean ok "$expected" || status=1
# The check sees an overlap: the same page with every legend entry moved
# onto the first one.
html_check "$work/page" index.html overlap \
  's|<text class="legend" x="[0-9.]*" y="[0-9.]*"|<text class="legend" x="20" y="284"|g'
if ! grep -q "OVERLAPS [1-9]" "$work/overlap.verdict"; then
  echo "FAIL: the check did not notice overlapping legend entries:"; cat "$work/overlap.verdict"; status=1
fi
[ $status = 0 ] && echo "OK: $figures figures, $expected images, nothing overlaps"
exit $status
