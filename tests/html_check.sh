# Sourced by the tests of the generated HTML pages (compare_html.sh,
# freq_html.sh): load a page in headless Chromium with tests/html_check.js
# injected and read back its verdict line. Exits 77 (skipped) when no
# Chromium is installed.
#   html_check_init            find the browser, make a private profile and
#                              an empty $work
#   chrome ARGS...             run it headless
#   html_check DIR PAGE NAME [SED]
#                              copy DIR/PAGE to DIR/NAME.html with the hook
#                              (after its <head>) and the sed expression SED
#                              applied, load it; the verdict goes to
#                              $work/NAME.verdict, the log to $work/NAME.log
#   html_check_clean NAME N    whether the verdict of NAME is clean for a
#                              page of N images (all load and are links,
#                              nothing overlaps) and the log has no console
#                              message; says what is wrong otherwise
html_check_js=$(dirname "$0")/html_check.js

html_check_init() {
  browser=$(command -v chromium || command -v chromium-browser || true)
  if [ -z "$browser" ]; then
    echo "SKIP: chromium not installed"
    exit 77
  fi
  profile=$(mktemp -d)
  trap 'rm -rf "$profile"' EXIT
  rm -rf "$work"
  mkdir -p "$work"
}

chrome() {
  timeout 120 "$browser" --headless --no-sandbox --disable-gpu --disable-quic --no-first-run \
    --disable-background-networking --disable-component-update --disable-sync \
    --user-data-dir="$profile" "$@"
}

html_check() {
  awk -v js="$html_check_js" '{print} /<head>/ && !done {
      print "<script>"; while ((getline l < js) > 0) print l; print "</script>"; done = 1 }' \
    "$1/$2" >"$1/$3.html"
  [ $# -ge 4 ] && sed -i "$4" "$1/$3.html"
  chrome --enable-logging=stderr --v=0 --virtual-time-budget=10000 --window-size=1400,2000 \
    --dump-dom "file://$1/$3.html" >"$work/$3.dom" 2>"$work/$3.log"
  sed -n 's|.*<p id="pagecheck">\(IMAGES [^<]* END\)</p>.*|\1|p' "$work/$3.dom" >"$work/$3.verdict"
  [ -s "$work/$3.verdict" ] || echo "(no verdict in the DOM)" >"$work/$3.verdict"
}

html_check_clean() {
  ok=0
  if ! grep -q "^IMAGES $2 BROKEN 0  UNLINKED 0  OVERLAPS 0  END" "$work/$1.verdict"; then
    echo "FAIL: page check ($2 images expected):"; cat "$work/$1.verdict"; ok=1
  fi
  if grep -q "CONSOLE" "$work/$1.log"; then
    echo "FAIL: console messages:"; grep "CONSOLE" "$work/$1.log"; ok=1
  fi
  return $ok
}
