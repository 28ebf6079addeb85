#!/bin/bash
# Samples/s of a 2 x 2 UDIM set of 1024^2 tiles against one 2048^2 file (the
# same noise, tiled half OpenEXR by maketx, 64^2 tiles; --cache-mb 512: all
# fits), one thread, through `texsample lookup --cache-mb` (doc/texture-system.md,
# "UDIM"). Per filter: user time of 3M queries minus that of the same 1M
# (2M queries sampled with every tile loaded), best of 3.
#   dev/udim_timing.sh TEXSAMPLE_IMAGE WORKDIR   (needs oiiotool, maketx)
set -eu
ts=$1 w=$2 here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$w" && cd "$w"
if [ ! -f one.exr ]; then
    oiiotool --pattern noise:type=uniform 2048x2048 4 -d half -o big.exr
    for v in 0 1; do for u in 0 1; do
        oiiotool big.exr --cut 1024x1024+$((u * 1024))+$((v * 1024)) -o part.exr
        maketx -d half --tile 64 64 part.exr -o set.$((1001 + u + 10 * v)).exr >/dev/null
    done; done
    maketx -d half --tile 64 64 big.exr -o one.exr >/dev/null
    for k in bilinear trilo trihi aniso; do for s in 1 2; do
        python3 "$here/udim_queries.py" $k 1000000 $s 2048 q${s}_$k.raw
        cat q${s}_$k.raw q${s}_$k.raw q${s}_$k.raw >q${s}_${k}_x3.raw
    done; done
fi
ut() { /usr/bin/time -o t.out -f %U "$@" >/dev/null 2>&1; tail -1 t.out; }
for cfg in "bilinear bilinear" "trilo trilinear" "trihi trilinear" "aniso aniso16"; do
    set -- $cfg
    for which in one set; do
        if [ $which = one ]; then img=one.exr s=1; else img='set.<UDIM>.exr' s=2; fi
        b1=99 b3=99
        for r in 1 2 3; do
            t1=$(ut "$ts" lookup --image "$img" --cache-mb 512 --queries q${s}_$1.raw --filter $2)
            t3=$(ut "$ts" lookup --image "$img" --cache-mb 512 --queries q${s}_$1_x3.raw --filter $2)
            b1=$(echo "$t1 $b1" | awk '{print ($1 < $2) ? $1 : $2}')
            b3=$(echo "$t3 $b3" | awk '{print ($1 < $2) ? $1 : $2}')
        done
        echo "$1 ($2) $which: $(echo "$b1 $b3" | awk '{printf "%.2f", 2 / ($2 - $1)}') M samples/s"
    done
done
