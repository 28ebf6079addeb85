#!/bin/sh
# Build a developer's probe against a build's libsample and run it: the probe
# is this script's own name (scripts/perf_probe.sh runs scripts/perf_probe.c,
# scripts/lean_footprint.sh, a link to this file, runs scripts/lean_footprint.c).
#
# perf_probe: doc/performance-passes.md's step tables (issue 10's passes).
#   scripts/perf_probe.sh BUILD_DIR FILTER SET FORMAT [QUERIES [RUNS]]
#   e.g. scripts/perf_probe.sh build ewa aniso8 float 65536 5
# Instructions a query (AVX2 kernels; valgrind has no AVX-512), the way
# the tables count them, over QUERIES × (RUNS + 1) queries:
#   PB_CALLGRIND=1 scripts/perf_probe.sh build ewa aniso8 float 8192 1
#
# lean_footprint: libsample's trilinear and Blinn–Newell or EWA beside a lean
# version of the footprint filter written only for the bench's case
# (doc/performance-passes-2.md, fourteenth pass; PB_SIZE=256: in cache).
#   scripts/lean_footprint.sh BUILD_DIR [blinn-newell|ewa [SET [QUERIES [RUNS]]]]
#   e.g. scripts/lean_footprint.sh build blinn-newell minify 65536 5
set -eu
probe=$(basename "$0" .sh)
if [ "$#" -lt 1 ]; then
    echo "usage: $0 BUILD_DIR ARGS... (scripts/$probe.c says which)" >&2
    exit 2
fi
build=$1
shift
src=$(cd "$(dirname "$0")/.." && pwd)
exe="$build/$probe"
cc -O2 -ffp-contract=off -std=c11 -I"$src/libsample/include" -I"$src/libsample/src" -I"$src/tools/bench" \
    -I"$src/tools/oiio" "$src/scripts/$probe.c" "$src/tools/bench/queries.c" \
    "$src/tools/bench/engines.c" "$src/tools/filters.c" \
    "$build/libsample/libsample.a" -lm -lpthread -o "$exe"
if [ -n "${PB_CALLGRIND:-}" ]; then
    valgrind --tool=callgrind --callgrind-out-file="$build/$probe.callgrind" \
        --toggle-collect=sample_batch "$exe" "$@" 2>&1 | grep -E "refs|M/s"
else
    "$exe" "$@"
fi
