#!/bin/sh
# Regenerates the small test images of libsample_io (tests/io*.c and the
# fuzz corpus) with oiiotool. Output is deterministic (fixed noise seeds).
# Licence of the generated files: CC0 (testimages/README.md).
set -eu
cd "$(dirname "$0")"
noise() { echo "noise:type=uniform:min=0:max=1:seed=$1"; }
# 8-bit: odd sizes so that the pyramid's odd-axis path is used too.
oiiotool --pattern "$(noise 1)" 19x13 3 -d uint8 -o rgb8.png
oiiotool --pattern "$(noise 2)" 17x11 4 -d uint8 -o rgba8.png
oiiotool --pattern "$(noise 3)" 16x9 1 -d uint8 -o grey8.png
oiiotool --pattern "$(noise 4)" 12x10 3 -d uint8 -o rgb8.tga
oiiotool --pattern "$(noise 5)" 16x16 3 -d uint8 --quality 90 -o rgb8.jpg
# 16-bit integer TIFF.
oiiotool --pattern "$(noise 6)" 15x14 4 -d uint16 -o rgba16.tif
# Half and float OpenEXR with values outside [0, 1] (scene-linear HDR data).
oiiotool --pattern "$(noise 7)" 13x9 4 --mulc 8 --subc 1 -d half -o rgba_half.exr
oiiotool --pattern "$(noise 8)" 11x7 3 --mulc 100 --subc 10 -d float -o rgb_float.exr
# Radiance HDR (RGBE).
oiiotool --pattern "$(noise 9)" 8x8 3 --mulc 4 -o rgb.hdr
