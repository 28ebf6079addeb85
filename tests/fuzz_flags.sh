#!/bin/sh
# The fuzzing build compiles the libraries under test with libFuzzer's
# coverage instrumentation and ASan/UBSan, not only the fuzzers' own files
# (top CMakeLists.txt, SAMPLE_FUZZ; doc/testing.md, "libFuzzer").
# Reads the compile commands CMake generated (compile_commands.json, the
# commands the build runs) and fails when
#   - a library target named on the command line has no compile command
#     (so that a renamed or moved target cannot pass unseen), or
#   - any compile command lacks -fsanitize=fuzzer-no-link (or fuzzer),
#     address or undefined, or -fno-sanitize-recover=undefined (without it
#     a UBSan report would not stop the fuzzer).
# Usage: fuzz_flags.sh COMPILE_COMMANDS_JSON TARGET...
set -u
db=$1
shift
[ -r "$db" ] || { echo "fuzz_flags: cannot read $db" >&2; exit 1; }
cmds=$(grep '"command":' "$db")
[ -n "$cmds" ] || { echo "fuzz_flags: no compile command in $db" >&2; exit 1; }

fail=0
# A flag may come in one -fsanitize= list or several.
for want in 'fuzzer(-no-link)?' address undefined; do
  missing=$(printf '%s\n' "$cmds" | grep -Ev -- "-fsanitize=([a-z-]+,)*${want}(,|[ \"])")
  if [ -n "$missing" ]; then
    echo "fuzz_flags: compiled without -fsanitize=$want:" >&2
    printf '%s\n' "$missing" | sed 's/.* -o \([^ ]*\) .*/  \1/' >&2
    fail=1
  fi
done
# Leaving out single UBSan checks is allowed (the fast path leaves out the
# pointer checks, libsample/CMakeLists.txt); turning off a whole sanitizer
# is not.
off=$(printf '%s\n' "$cmds" | grep -E -- "-fno-sanitize=([a-z-]+,)*(fuzzer(-no-link)?|address|undefined)(,|[ \"])")
if [ -n "$off" ]; then
  echo "fuzz_flags: a sanitizer turned off again:" >&2
  printf '%s\n' "$off" | sed 's/.* -o \([^ ]*\) .*/  \1/' >&2
  fail=1
fi
missing=$(printf '%s\n' "$cmds" | grep -Fv -- "-fno-sanitize-recover=undefined")
if [ -n "$missing" ]; then
  echo "fuzz_flags: compiled without -fno-sanitize-recover=undefined:" >&2
  printf '%s\n' "$missing" | sed 's/.* -o \([^ ]*\) .*/  \1/' >&2
  fail=1
fi

for t in "$@"; do
  # Makefiles write "-o CMakeFiles/T.dir/…", Ninja "-o dir/CMakeFiles/T.dir/…".
  n=$(printf '%s\n' "$cmds" | grep -Ec -- "-o ([^ ]*/)?CMakeFiles/${t}\.dir/")
  if [ "$n" -eq 0 ]; then
    echo "fuzz_flags: no compile command for library target $t" >&2
    fail=1
  else
    echo "$t: $n compile commands"
  fi
done
[ "$fail" -eq 0 ] && echo "fuzz_flags: $(printf '%s\n' "$cmds" | wc -l) compile commands, all instrumented"
exit "$fail"
