#!/bin/sh
# The compare page in headless Chromium: every image loads, no console
# errors, and a screenshot is taken (WORKDIR/compare_page.png). A copy of
# the page gets a small script that counts the images that failed to load
# (capturing 'error' listener plus naturalWidth after 'load') and writes the
# count into the DOM, which --dump-dom prints; a copy with one broken link
# checks that the hook does see failures. Skips (77) without Chromium.
# Usage: compare_html.sh TEXSAMPLE WORKDIR
set -u
exe=$1
work=$2
browser=$(command -v chromium || command -v chromium-browser || true)
if [ -z "$browser" ]; then
  echo "SKIP: chromium not installed"
  exit 77
fi
rm -rf "$work"
mkdir -p "$work"
if ! "$exe" compare --scene plane --scene teapot --size 32 --out "$work/page" >"$work/compare.txt" 2>&1; then
  echo "FAIL: texsample compare failed"; cat "$work/compare.txt"; exit 1
fi
profile=$(mktemp -d)
trap 'rm -rf "$profile"' EXIT
chrome() {
  timeout 120 "$browser" --headless --no-sandbox --disable-gpu --disable-quic --no-first-run \
    --disable-background-networking --disable-component-update --disable-sync \
    --user-data-dir="$profile" "$@"
}
hook='<script>
var broken = [];
window.addEventListener("error", function (e) {
  if (e.target && e.target.tagName === "IMG") broken.push(e.target.getAttribute("src"));
}, true);
window.addEventListener("load", function () {
  var imgs = document.images, i;
  for (i = 0; i < imgs.length; ++i)
    if (imgs[i].naturalWidth === 0 && broken.indexOf(imgs[i].getAttribute("src")) < 0)
      broken.push(imgs[i].getAttribute("src"));
  var d = document.createElement("p");
  d.id = "imgcheck";
  d.textContent = "IMAGES " + imgs.length + " BROKEN " + broken.length + " " + broken.join(" ");
  document.body.appendChild(d);
});
</script>'
# check PAGE NAME: DOM and log of PAGE with the hook in its head.
check() {
  awk -v hook="$hook" '{print} /<head>/ {print hook}' "$work/page/index.html" >"$work/page/$2.html"
  [ "$2" = broken ] && sed -i 's|src="plane/truth.png"|src="plane/missing.png"|' "$work/page/$2.html"
  chrome --enable-logging=stderr --v=0 --virtual-time-budget=10000 --dump-dom \
    "file://$work/page/$2.html" >"$work/$2.dom" 2>"$work/$2.log"
}
expected=$(grep -o '<img ' "$work/page/index.html" | wc -l)
status=0
check page ok
if ! grep -q "IMAGES $expected BROKEN 0 " "$work/ok.dom"; then
  echo "FAIL: not every image loaded ($expected expected):"
  grep -o 'IMAGES [^<]*' "$work/ok.dom" || echo "(no result in the DOM)"
  status=1
fi
if grep -q "CONSOLE" "$work/ok.log"; then
  echo "FAIL: console messages:"; grep "CONSOLE" "$work/ok.log"; status=1
fi
check page broken
if ! grep -q "IMAGES $expected BROKEN 1 plane/missing.png" "$work/broken.dom"; then
  echo "FAIL: the hook did not notice a broken image"; grep -o 'IMAGES [^<]*' "$work/broken.dom"; status=1
fi
chrome --window-size=1400,2200 --screenshot="$work/compare_page.png" \
  "file://$work/page/index.html" >"$work/shot.log" 2>&1
if ! head -c 8 "$work/compare_page.png" 2>/dev/null | grep -q PNG; then
  echo "FAIL: no screenshot"; cat "$work/shot.log"; status=1
fi
[ $status = 0 ] && echo "OK: $expected images loaded, no console errors; screenshot $work/compare_page.png"
exit $status
