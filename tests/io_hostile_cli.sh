#!/bin/sh
# texsample info / mip on hostile files (doc/guarantees.md): a 130-byte TIFF
# claiming 32768 x 32768 is refused from its strip table, under a 1 GiB
# address-space limit (ulimit -v), before its 1 GiB of pixels is allocated;
# /dev/zero, a FIFO and a directory are refused at once (a timeout ends a
# hang). Each failure exits 1 with a message and leaves no output file.
# Where texsample cannot start under the limit at all (a sanitizer build
# reserves terabytes of address space) that part is skipped: exit 77.
# Usage: io_hostile_cli.sh TEXSAMPLE SCRATCH
set -u
ts=$1 dir=$2
fail=0 skipped=0
rm -rf "$dir" && mkdir -p "$dir"
check() { if eval "$2"; then :; else echo "FAIL: $1"; fail=1; fi; }

# Little-endian integers as printf escapes.
le16() { printf "\\$(printf %03o $(($1 & 255)))\\$(printf %03o $(($1 >> 8 & 255)))"; }
le32() { le16 $(($1 & 65535)); le16 $(($1 >> 16 & 65535)); }
entry() { le16 "$1"; le16 "$2"; le32 "$3"; le32 "$4"; }

# TIFF 6.0: "II", 42, directory at 16; 8 data bytes; 9 entries: 32768 x
# 32768, 8-bit grey, uncompressed, one row per strip, but one strip only.
{
  printf 'II*\000'; le32 16; printf '\200\200\200\200\200\200\200\200'
  le16 9
  entry 256 4 1 32768; entry 257 4 1 32768; entry 258 3 1 8; entry 259 3 1 1; entry 262 3 1 1
  entry 273 4 1 8; entry 277 3 1 1; entry 278 4 1 1; entry 279 4 1 8
  le32 0
} > "$dir/huge.tif"
check "crafted TIFF is 130 bytes" '[ "$(wc -c < "$dir/huge.tif")" -eq 130 ]'

# A process that cannot start under the limit (the loader cannot map a
# library, a sanitizer cannot reserve its shadow memory) exits with another
# status and no message of texsample's: that part is then skipped.
for cmd in info mip; do
  if [ $cmd = info ]; then args="$dir/huge.tif"; else args="$dir/huge.tif $dir/out.exr"; fi
  msg=$( (ulimit -v 1048576; exec timeout 20 "$ts" $cmd $args) 2>&1 >/dev/null); rc=$?
  if [ $rc -gt 2 ] && ! echo "$msg" | grep -q "^texsample"; then
    echo "SKIP: texsample $cmd does not start under ulimit -v 1048576 (sanitizer build?): $msg" | head -3
    skipped=1; continue
  fi
  check "$cmd huge.tif under 1 GiB: exit 1 (got $rc: $msg)" '[ $rc -eq 1 ]'
  check "$cmd huge.tif: says why ($msg)" 'echo "$msg" | grep -q "strip table has 1 entries of the 32768 it needs"'
done
check "no output from the refused mip" '[ ! -e "$dir/out.exr" ] && [ -z "$(ls "$dir" | grep tmp)" ]'

# One command each (the library's check is the same for all; io_hostile
# tests it on every kind): info /dev/zero, mip of a FIFO, info of a directory.
# The timeout only stops a read that would block for ever; 30 s leaves a
# loaded machine (the process start loads OpenImageIO) far from it.
mkfifo "$dir/fifo.png"
for run in "info /dev/zero" "mip $dir/fifo.png $dir/out.exr" "info $dir"; do
  msg=$(timeout 30 "$ts" $run 2>&1 >/dev/null); rc=$?
  check "$run: exit 1 at once (got $rc: $msg)" '[ $rc -eq 1 ]'
  check "$run: says it is not a regular file ($msg)" 'echo "$msg" | grep -q "only regular files are read"'
done
check "no output from the refused reads" '[ ! -e "$dir/out.exr" ]'

[ $fail -ne 0 ] && exit 1
[ $skipped -ne 0 ] && exit 77
echo "io_hostile_cli: all passed"
exit 0
