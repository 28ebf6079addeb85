#!/bin/sh
# Build scripts/perf_probe.c against a build's libsample and run it
# (doc/performance-passes.md: the step tables of issue 10's passes).
#   scripts/perf_probe.sh BUILD_DIR FILTER SET FORMAT [QUERIES [RUNS]]
# e.g. scripts/perf_probe.sh build ewa aniso8 float 65536 5
# Instructions a query (AVX2 kernels; valgrind has no AVX-512), the way
# the tables count them, over QUERIES × (RUNS + 1) queries:
#   PB_CALLGRIND=1 scripts/perf_probe.sh build ewa aniso8 float 8192 1
set -eu
if [ "$#" -lt 4 ]; then
    echo "usage: $0 BUILD_DIR FILTER SET FORMAT [QUERIES [RUNS]]" >&2
    exit 2
fi
build=$1
shift
src=$(cd "$(dirname "$0")/.." && pwd)
exe="$build/perf_probe"
cc -O2 -ffp-contract=off -std=c11 -I"$src/libsample/include" -I"$src/tools/bench" -I"$src/tools/oiio" \
    "$src/scripts/perf_probe.c" "$src/tools/bench/queries.c" "$src/tools/bench/engines.c" \
    "$build/libsample/libsample.a" -lm -lpthread -o "$exe"
if [ -n "${PB_CALLGRIND:-}" ]; then
    valgrind --tool=callgrind --callgrind-out-file="$build/perf_probe.callgrind" \
        --toggle-collect=sample_batch "$exe" "$@" 2>&1 | grep -E "refs|M/s"
else
    "$exe" "$@"
fi
