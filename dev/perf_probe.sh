#!/bin/sh
# Build a developer's probe against a build's libsample and run it: the probe
# is this script's own name and its source sits beside the name it was run
# by (dev/perf_probe.sh runs dev/perf_probe.c; tests/oracles/lean_footprint.sh,
# a link to this file, runs tests/oracles/lean_footprint.c). Both include
# dev/probe_util.h.
#
# perf_probe: one filter's best 1-thread time and output hash, so that a
# change can be timed and shown to keep the bits (the step tables of
# doc/history/performance-passes*.md were measured with it).
#   dev/perf_probe.sh BUILD_DIR FILTER SET FORMAT [QUERIES [RUNS]]
#   e.g. dev/perf_probe.sh build ewa aniso8 float 65536 5
# Instructions a query (AVX2 kernels; valgrind has no AVX-512), over
# QUERIES × (RUNS + 1) queries:
#   PB_CALLGRIND=1 dev/perf_probe.sh build ewa aniso8 float 8192 1
#
# lean_footprint: libsample's trilinear and Blinn–Newell or EWA beside a lean
# version of the footprint filter written only for the bench's case
# (PB_SIZE=256: in cache; the measurements are in
# doc/history/performance-passes-2.md).
#   tests/oracles/lean_footprint.sh BUILD_DIR [blinn-newell|ewa [SET [QUERIES [RUNS]]]]
#   e.g. tests/oracles/lean_footprint.sh build blinn-newell minify 65536 5
set -eu
probe=$(basename "$0" .sh)
here=$(cd "$(dirname "$0")" && pwd)
if [ "$#" -lt 1 ]; then
    echo "usage: $0 BUILD_DIR ARGS... ($here/$probe.c says which)" >&2
    exit 2
fi
build=$1
shift
# The repository root, found from this file's real place (dev/), whatever
# link it was run through.
src=$(cd "$(dirname "$(readlink -f "$0")")/.." && pwd)
exe="$build/$probe"
cc -O2 -ffp-contract=off -std=c11 -I"$src/libsample/include" -I"$src/libsample/src" -I"$src/tools/bench" \
    -I"$src/tools/oiio" -I"$src/dev" "$here/$probe.c" "$src/tools/bench/queries.c" "$src/tools/bench/engines.c" \
    "$src/tools/filters.c" "$src/tools/backend.c" "$src/tools/backends/libsample.c" -I"$src/tools" \
    "$build/libsample/libsample.a" -lm -lpthread -o "$exe"
if [ -n "${PB_CALLGRIND:-}" ]; then
    valgrind --tool=callgrind --callgrind-out-file="$build/$probe.callgrind" \
        --toggle-collect=sample_batch "$exe" "$@" 2>&1 | grep -E "refs|M/s"
else
    "$exe" "$@"
fi
