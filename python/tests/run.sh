#!/bin/sh
# Runs the Python package's tests (tests/python.cmake):
#   run.sh PYTHON...
# with the first interpreter given that has numpy and pytest (a python3
# earlier in PATH, such as a pyenv shim, may lack Debian's python3-numpy
# and python3-pytest, which /usr/bin/python3 has). Exits 77 (skipped)
# when none has them. No bytecode or pytest cache is written into the
# source tree.
set -eu
# Texture.load reads with the shipped OCIO config, whatever $OCIO the
# developer has set (as the io tests do).
unset OCIO
here=$(cd "$(dirname "$0")" && pwd)
for py in "$@"; do
  [ -n "$py" ] || continue
  command -v "$py" >/dev/null 2>&1 || continue
  if "$py" -c "import numpy, pytest" 2>/dev/null; then
    PYTHONDONTWRITEBYTECODE=1 exec "$py" -m pytest -q -p no:cacheprovider --rootdir "$here" "$here"
  fi
done
echo "no python3 with numpy and pytest among: $*: skipped"
exit 77
