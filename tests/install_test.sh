#!/bin/sh
# Installs the build tree into a scratch prefix, then builds and runs a
# program against it twice: through the CMake package and through pkg-config.
set -eu
build=$1; src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cmake --install "$build" --prefix "$work/prefix" --component Unspecified >/dev/null
cmake -S "$src/tests/install_example" -B "$work/ex" -DCMAKE_PREFIX_PATH="$work/prefix" >/dev/null
cmake --build "$work/ex" >/dev/null
test "$("$work/ex/example")" = 2.5
echo "find_package(libsample): ok"
PKG_CONFIG_PATH="$work/prefix/lib/pkgconfig:$work/prefix/lib/$(gcc -print-multiarch 2>/dev/null)/pkgconfig" \
  sh -c 'cc "$0" $(pkg-config --cflags --libs --static libsample) -o "$1"' \
  "$src/tests/install_example/example.c" "$work/ex2"
LD_LIBRARY_PATH="$work/prefix/lib" test "$("$work/ex2")" = 2.5
echo "pkg-config libsample: ok"
echo "2 passed, 0 failed"
