#!/usr/bin/env bash
# CTest install_and_consume: `cmake --install` into a temporary prefix, then
#   1. build examples/consumer/ with find_package(ClipsAssist CONFIG) and run it on
#      the repo's Doors-Keys-Gems example: it must print a normalised goal
#      posterior with the instruction's gem first and an assistant action;
#   2. build the same source through pkg-config (clips-assist.pc);
#   3. run the installed CLI (clips-assist) from /tmp with $CLIPS_DATA_DIR unset.
# The installed names are those of docs/decisions.md ("Installed names").
# Usage: install_and_consume.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build=$(realpath "$1")
src=$(realpath "$2")
tmp=$(mktemp -d /tmp/clips-install-XXXXXX)
trap 'rm -rf "$tmp"' EXIT
prefix="$tmp/prefix"
unset CLIPS_DATA_DIR
fail() { echo "FAIL: $*" >&2; exit 1; }

cmake --install "$build" --prefix "$prefix" >/dev/null
for f in include/clips-assist/clips/clips.hpp include/clips-assist/clips/session.hpp include/clips-assist/clips/version.hpp \
         share/clips-assist/language/corpus-dkg.tsv share/clips-assist/domains/doors-keys-gems/pack.json \
         share/clips-assist/schema/pack.schema.json share/clips-assist/examples/doors-keys-gems/domain.pddl \
         bin/clips-assist; do
  [ -e "$prefix/$f" ] || fail "$f was not installed"
done
# The licence and the citation, under the package's name.
grep -q "Copyright (c) 2026 The clips-assist authors" "$prefix/share/doc/clips-assist/copyright" \
  || fail "no MIT licence in share/doc/clips-assist/copyright"
grep -q "arXiv:2402.17930" "$prefix/share/doc/clips-assist/CITATION.cff" || fail "CITATION.cff does not cite the paper"
# Nothing under a name Debian's CLIPS (clips, libclips-dev) or PyPI's clipspy uses.
for f in bin/clips include/clips share/clips; do
  [ ! -e "$prefix/$f" ] || fail "$f was installed: it clashes with Debian's clips / libclips-dev"
done
[ -z "$(find "$prefix" -name 'libclips.*' -o -name 'clips.pc' -o -name 'clips' -path '*-packages/*')" ] \
  || fail "a file named as Debian's or PyPI's clips was installed"
lib=$(find "$prefix" -name 'libclips_assist.a' | head -1)
[ -n "$lib" ] || fail "libclips_assist.a was not installed"
libdir=$(dirname "$lib")
[ -f "$libdir/cmake/ClipsAssist/ClipsAssistConfig.cmake" ] && [ -f "$libdir/cmake/ClipsAssist/ClipsAssistConfigVersion.cmake" ] \
  || fail "no CMake package under $libdir/cmake/ClipsAssist"
[ -f "$libdir/pkgconfig/clips-assist.pc" ] || fail "no clips-assist.pc under $libdir/pkgconfig"

# 1. CMake package. Cached objects are not needed: it is one small file.
cmake -S "$src/examples/consumer" -B "$tmp/consumer" -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$tmp/consumer" >/dev/null
# The installed library never reads the source tree's data/ (which exists
# here): with no installed data where it looks (its configured prefix,
# /usr/local, /usr), it stops with an error naming CLIPS_DATA_DIR.
if [ ! -d /usr/local/share/clips-assist ] && [ ! -d /usr/share/clips-assist ]; then
  set +e
  err=$(cd /tmp && "$tmp/consumer/consumer" "$src/data/examples/doors-keys-gems" 2>&1 >/dev/null)
  rc=$?
  set -e
  [ "$rc" -eq 1 ] || fail "without installed data the consumer exited $rc, expected 1"
  echo "$err" | grep -q "CLIPS_DATA_DIR" || fail "the missing-data error does not mention CLIPS_DATA_DIR: $err"
fi
# The library was installed to a prefix other than its configured one (the
# program lives elsewhere), so the consumer is pointed at the installed data.
export CLIPS_DATA_DIR="$prefix/share/clips-assist"
out=$(cd /tmp && "$tmp/consumer/consumer" "$src/data/examples/doors-keys-gems")
echo "$out"
echo "$out" | grep -q "data in $prefix/share/clips-assist" || fail "the library did not read the installed data"
echo "$out" | grep -Eq '^assistant: \(.* robot.*\)$' || fail "no assistant action"
# Printed to 4 decimals: the sum is 1 within their rounding.
total=$(echo "$out" | awk -F' = ' '/^P\(/ {s += $2; n++} END {if (n == 4 && s > 0.9997 && s < 1.0003) print "ok"}')
[ "$total" = "ok" ] || fail "posterior over the 4 gems does not sum to 1"
# The instruction asks for the yellow key, which opens the way to gem3
# (problems/e1.txt): it must be the most probable goal.
best=$(echo "$out" | awk -F'[()= ]+' '/^P\(/ {if ($3 > m) {m = $3; g = $2}} END {print g}')
[ "$best" = "gem3" ] || fail "most probable goal is '$best', expected gem3"

# 2. pkg-config.
flags=$(PKG_CONFIG_PATH="$libdir/pkgconfig" pkg-config --cflags --libs clips-assist)
g++ -std=c++17 "$src/examples/consumer/main.cpp" $flags -o "$tmp/consumer-pc"
out_pc=$(cd /tmp && "$tmp/consumer-pc" "$src/data/examples/doors-keys-gems")
[ "$out_pc" = "$out" ] || fail "the pkg-config build printed something else"

# 3. The installed CLI from /tmp, $CLIPS_DATA_DIR unset: it finds
# <prefix>/share/clips-assist beside its own bin/.
unset CLIPS_DATA_DIR
(cd /tmp && "$prefix/bin/clips-assist" infer --dataset "$prefix/share/clips-assist/examples/doors-keys-gems" --plan e1.1.keys \
   --json >"$tmp/infer.json") \
  || fail "installed clips-assist infer failed"
grep -q '"posterior"' "$tmp/infer.json" || fail "installed clips-assist infer printed no posterior"

# 4. The Python package, when built: installed where Debian's python3 looks
# under this prefix, it finds <prefix>/share/clips-assist by itself.
pydir=$(find "$prefix" -type d -name clips_assist -path '*dist-packages*' | head -1)
if [ -n "$pydir" ]; then
  python=${CLIPS_TEST_PYTHON:-/usr/bin/python3}
  got=$(cd /tmp && PYTHONPATH=$(dirname "$pydir") "$python" -c \
        'import clips_assist as c; print(c.data_directory()); print(c.__file__)')
  [ "$(echo "$got" | sed -n 1p)" = "$prefix/share/clips-assist" ] || fail "the installed module reads data from: $got"
  echo "$got" | sed -n 2p | grep -q "^$pydir/" || fail "python imported another clips_assist: $got"
fi
echo "install_and_consume: OK"
