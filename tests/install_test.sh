#!/bin/sh
# Two checks of libsample as a package (tests/install.cmake).
#
#   install_test.sh install BUILD SRC LIBDIR CC IO [PYDIR PYTHON...]
# installs the build tree into a scratch prefix, then builds and runs small
# programs (tests/install_example/, copied out of the source tree) against
# that prefix only: a CMake project (find_package(libsample):
# libsample::sample, libsample::sample_static, and with IO=ON
# libsample::sample_io and libsample::sample_io_static), pkg-config for the
# shared libraries, and `pkg-config --static` for the static ones. No
# include path may name the source or build tree. With IO=ON, the installed
# texsample is also moved and run from $PATH elsewhere. With PYDIR (the
# Python package's folder under the prefix), the first PYTHON that has
# numpy imports the installed package, which must load the installed
# libsample.so and sample with it, and with IO=ON (the tools built)
# libsample_measure.so.
#
#   install_test.sh symbols NM HEADERS LIB PREFIX [HEADERS LIB PREFIX]...
# checks that LIB's dynamic symbol table defines exactly the functions
# HEADERS (one header, or several joined by ':') declare with their export
# macro, each named PREFIX* (an extended regular expression: a|b for two
# prefixes), and that every function they declare carries the macro.
# Exits 77 (skipped) without nm.
set -eu
export LC_ALL=C
mode=$1; shift

if [ "$mode" = symbols ]; then
  nm=$1; shift
  command -v "$nm" >/dev/null 2>&1 || { echo "no nm: skipped"; exit 77; }
  fail=0
  while [ $# -ge 3 ]; do
    header=$(printf '%s' "$1" | tr ':' ' '); lib=$2; prefix=$3; shift 3
    # Declarations start a line with a return type and name a sample_ function.
    # shellcheck disable=SC2086 # $header: the headers, split on purpose
    unmarked=$(grep -hE '^[a-z].*[ *]sample_[a-z0-9_]+\(' $header | grep -v '^SAMPLE_' || true)
    if [ -n "$unmarked" ]; then
      echo "$header: function declared without the export macro:"; echo "$unmarked"; fail=1
    fi
    # shellcheck disable=SC2086
    declared=$(sed -n 's/^SAMPLE_[A-Z_]*API .*[ *]\(sample_[a-z0-9_]*\)(.*/\1/p' $header | sort)
    exported=$("$nm" -D --defined-only "$lib" | awk '{print $NF}' | sort)
    extra=$(printf '%s\n' "$exported" | grep -Ev "^($prefix)" || true)
    if [ -n "$extra" ]; then
      echo "$lib exports symbols not named $prefix*:"; echo "$extra"; fail=1
    fi
    if [ "$declared" != "$exported" ]; then
      echo "$lib: exported functions differ from $header's (< declared, > exported):"
      printf '%s\n' "$declared" > "${TMPDIR:-/tmp}/symbols.$$.d"
      printf '%s\n' "$exported" > "${TMPDIR:-/tmp}/symbols.$$.e"
      diff "${TMPDIR:-/tmp}/symbols.$$.d" "${TMPDIR:-/tmp}/symbols.$$.e" || true
      rm -f "${TMPDIR:-/tmp}/symbols.$$.d" "${TMPDIR:-/tmp}/symbols.$$.e"
      fail=1
    fi
    [ $fail = 0 ] && echo "$lib: $(printf '%s\n' "$exported" | wc -l) symbols, all $prefix*, as $header declares"
  done
  exit $fail
fi

build=$1; src=$2; libdir=$3; cc=$4; io=$5
shift 5
pydir=${1:-}; [ $# -gt 0 ] && shift
pythons=$* # interpreter paths hold no spaces here (PATH lookups, /usr/bin/python3)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
prefix=$work/prefix
cmake --install "$build" --prefix "$prefix" --component Unspecified >/dev/null
cp -R "$src/tests/install_example" "$work/ex-src"
unset OCIO # libsample_io's shipped config, found beside the installed library
unset CPATH C_INCLUDE_PATH LIBRARY_PATH LD_LIBRARY_PATH LIBSAMPLE_LIBRARY_PATH PYTHONPATH
image=$src/testimages/rgb8.png
passed=0

# No include path may name the source or the build tree.
check_flags() {
  case "$1" in
    *"$src"* | *"$build"*) echo "$2 names the source or build tree: $1"; exit 1 ;;
  esac
}
# A program linked against the shared libraries needs them; a static one not.
check_needed() {
  needed=$(readelf -d "$1" 2>/dev/null | grep NEEDED || true)
  case "$needed" in
    *libsample*) [ "$2" = shared ] || { echo "$1 needs a shared libsample: $needed"; exit 1; } ;;
    *) [ "$2" = static ] || { echo "$1 does not need libsample.so: $needed"; exit 1; } ;;
  esac
}
ok() { echo "$1: ok"; passed=$((passed + 1)); }

# CMake.
with_io=OFF; [ "$io" = ON ] && with_io=ON
cmake -S "$work/ex-src" -B "$work/ex" -DCMAKE_C_COMPILER="$cc" -DCMAKE_PREFIX_PATH="$prefix" \
  -DCMAKE_EXPORT_COMPILE_COMMANDS=ON -DWITH_IO=$with_io >/dev/null
cmake --build "$work/ex" >/dev/null
check_flags "$(cat "$work/ex/compile_commands.json")" "find_package(libsample)'s compile commands"
test "$("$work/ex/example")" = 2.5
check_needed "$work/ex/example" shared
ok "find_package(libsample): libsample::sample"
test "$("$work/ex/example_static")" = 2.5
check_needed "$work/ex/example_static" static
ok "find_package(libsample): libsample::sample_static"
if [ "$io" = ON ]; then
  test "$("$work/ex/example_io" "$image")" = "19x13 3"
  check_needed "$work/ex/example_io" shared
  ok "find_package(libsample): libsample::sample_io"
  test "$("$work/ex/example_io_static" "$image")" = "19x13 3"
  check_needed "$work/ex/example_io_static" static
  ok "find_package(libsample): libsample::sample_io_static"
fi

# pkg-config: the shared libraries, found at run time through
# LD_LIBRARY_PATH; then the static ones, picked by file name from the
# flags `--static` gives (-lsample → -l:libsample.a), run without it.
export PKG_CONFIG_PATH="$prefix/$libdir/pkgconfig${PKG_CONFIG_PATH:+:$PKG_CONFIG_PATH}"
pc() {
  flags=$(pkg-config "$@")
  check_flags "$flags" "pkg-config $*"
}
to_static() { printf '%s\n' "$1" | sed -e 's/-lsample_io\( \|$\)/-l:libsample_io.a\1/' -e 's/-lsample\( \|$\)/-l:libsample.a\1/'; }
mods=libsample; [ "$io" = ON ] && mods="libsample libsample_io"
for m in $mods; do
  if [ "$m" = libsample ]; then prog=example; want=2.5; set --; else prog=example_io; want="19x13 3"; set -- "$image"; fi
  pc --cflags "$m"; cflags=$flags
  pc --libs "$m"; libs=$flags
  pc --static --libs "$m"; static_libs=$(to_static "$flags")
  # shellcheck disable=SC2086 # the flags are split into words on purpose
  "$cc" "$work/ex-src/$prog.c" $cflags $libs -o "$work/pc_$prog"
  check_needed "$work/pc_$prog" shared
  test "$(LD_LIBRARY_PATH="$prefix/$libdir" "$work/pc_$prog" "$@")" = "$want"
  ok "pkg-config $m"
  # shellcheck disable=SC2086
  "$cc" "$work/ex-src/$prog.c" $cflags $static_libs -o "$work/pc_static_$prog"
  check_needed "$work/pc_static_$prog" static
  test "$("$work/pc_static_$prog" "$@")" = "$want"
  ok "pkg-config --static $m"
done
# The installed texsample, moved to another prefix and run from $PATH in
# another directory: it finds its image program (libexec/libsample) and the
# OCIO config installed below it, not the source tree's. The moved config
# alone names the colour space asked for, so the source tree's config (or
# none) fails the read.
if [ "$io" = ON ]; then
  cp -R "$prefix" "$work/moved"
  config=$work/moved/share/libsample/ocio/config.ocio
  sed 's/aliases: \[linear, /aliases: [installed_config_marker, linear, /' "$config" > "$work/config.ocio"
  cp "$work/config.ocio" "$config"
  grep -q installed_config_marker "$config"
  mkdir "$work/elsewhere"
  info=$(cd "$work/elsewhere" && PATH="$work/moved/bin:$PATH" texsample info --colorspace installed_config_marker "$image")
  case "$info" in
    *"size      19 x 13"*"colorspace installed_config_marker"*) ;;
    *) echo "installed texsample info: $info"; exit 1 ;;
  esac
  ok "installed texsample, moved and run from \$PATH: its image program and its OCIO config"
fi
# The Python package, imported from the install tree in another directory.
if [ -n "$pydir" ]; then
  py=""
  for p in $pythons; do
    if [ -n "$p" ] && "$p" -c "import numpy" 2>/dev/null; then py=$p; break; fi
  done
  if [ -z "$py" ]; then
    echo "installed Python package: no python3 with numpy: not checked"
  else
    mkdir -p "$work/elsewhere"
    out=$(cd "$work/elsewhere" && PYTHONPATH="$prefix/$pydir" "$py" -c '
import sys, numpy as np, libsample as ls
t = ls.Texture(np.full((4, 4), 2.5, np.float32))
measured = sys.argv[1] != "ON" or len(ls.freq("nearest", m=[2.0], theta=[0.0], n=16, f_step=0.5, f_max=1.0,
                                               phases=4).points) > 0
print(ls.__file__, ls._lib.core._name, t.sample(ls.Sampler(), s=[0.5], t=[0.5])[0, 0], measured)' "$io")
    case "$out" in
      "$prefix/$pydir/libsample/__init__.py $prefix/$libdir/libsample.so.0 2.5 True") ;;
      *) echo "installed Python package: $out"; exit 1 ;;
    esac
    ok "installed Python package: imported, loads the installed libsample.so (and libsample_measure.so)"
  fi
fi
echo "$passed passed, 0 failed"
