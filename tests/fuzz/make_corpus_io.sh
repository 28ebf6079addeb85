#!/bin/sh
# Seeds for fuzz_io: each test image behind the byte that selects its format
# hint in fuzz_io.c (png 0, jpg 1, tif 2, exr 3, hdr 4, tga 5).
set -eu
cd "$(dirname "$0")"
img=../../testimages
mkdir -p corpus_io
seed() { { printf "\\$(printf %03o "$1")"; cat "$img/$2"; } > "corpus_io/$3"; }
seed 0 rgb8.png png_rgb8
seed 0 rgba8.png png_rgba8
seed 0 grey8.png png_grey8
seed 1 rgb8.jpg jpg_rgb8
seed 2 rgba16.tif tif_rgba16
seed 3 rgba_half.exr exr_half
seed 3 rgb_float.exr exr_float
seed 4 rgb.hdr hdr_rgb
seed 5 rgb8.tga tga_rgb8
# Tiled, mip-mapped OpenEXR (8² tiles, ZIP and uncompressed, as maketx
# writes them) for the texture system's tile readers (fuzz_io's second half:
# the direct OpenEXR tile reader, OpenImageIO's read_tiles for .tx).
tmp=$(mktemp -d)
maketx "$img/rgba_half.exr" -o "$tmp/zip.exr" --tile 8 8 --compression zip -d half >/dev/null
maketx "$img/rgba_half.exr" -o "$tmp/none.exr" --tile 8 8 --compression none -d half >/dev/null
img=$tmp
seed 3 zip.exr exr_tiled_zip
seed 3 none.exr exr_tiled_none
seed 7 zip.exr tx_tiled_zip
rm -r "$tmp"
