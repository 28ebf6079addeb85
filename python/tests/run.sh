#!/bin/sh
# Runs the Python package's tests or its example (tests/python.cmake):
#   run.sh tests PYTHON...
#   run.sh example OUT.png PYTHON...
# with the first interpreter given that has what they need (numpy and
# pytest; numpy and matplotlib). A python3 earlier in PATH, such as a
# pyenv shim, may lack Debian's python3-numpy and python3-pytest, which
# /usr/bin/python3 has. Exits 77 (skipped) when none has them. No bytecode
# or pytest cache is written into the source tree.
set -eu
# Texture.load reads with the shipped OCIO config, whatever $OCIO the
# developer has set (as the io tests do).
unset OCIO
here=$(cd "$(dirname "$0")" && pwd)
mode=$1; shift
case "$mode" in
  tests) needs="numpy, pytest" ;;
  example) needs="numpy, matplotlib"; out=$1; shift ;;
  *) echo "usage: run.sh tests|example [OUT] PYTHON..." >&2; exit 2 ;;
esac
export PYTHONDONTWRITEBYTECODE=1
for py in "$@"; do
  [ -n "$py" ] || continue
  command -v "$py" >/dev/null 2>&1 || continue
  "$py" -c "import $needs" 2>/dev/null || continue
  if [ "$mode" = tests ]; then
    exec "$py" -m pytest -q -p no:cacheprovider --rootdir "$here" "$here"
  fi
  rm -f "$out"
  "$py" "$here/../examples/plot_filters.py" "$out"
  # A PNG file, not empty.
  test "$(head -c 4 "$out" | tail -c 3)" = PNG
  exit 0
done
echo "no python3 with $needs among: $*: skipped"
exit 77
