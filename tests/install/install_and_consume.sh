#!/usr/bin/env bash
# CTest install_and_consume: `cmake --install` into a temporary prefix, then
#   1. build examples/consumer/ with find_package(clips CONFIG) and run it on
#      the repo's Doors-Keys-Gems example: it must print a normalised goal
#      posterior with the instruction's gem first and an assistant action;
#   2. build the same source through pkg-config (clips.pc);
#   3. run the installed CLI from /tmp with $CLIPS_DATA_DIR unset.
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
for f in include/clips/clips.hpp include/clips/session.hpp include/clips/version.hpp share/clips/language/corpus-dkg.tsv \
         share/clips/domains/doors-keys-gems/pack.json share/clips/schema/pack.schema.json bin/clips; do
  [ -e "$prefix/$f" ] || fail "$f was not installed"
done
lib=$(find "$prefix" -name 'libclips.a' | head -1)
[ -n "$lib" ] || fail "libclips.a was not installed"
libdir=$(dirname "$lib")
[ -f "$libdir/cmake/clips/clipsConfig.cmake" ] && [ -f "$libdir/cmake/clips/clipsConfigVersion.cmake" ] \
  || fail "no CMake package under $libdir/cmake/clips"
[ -f "$libdir/pkgconfig/clips.pc" ] || fail "no clips.pc under $libdir/pkgconfig"

# 1. CMake package. Cached objects are not needed: it is one small file.
cmake -S "$src/examples/consumer" -B "$tmp/consumer" -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$tmp/consumer" >/dev/null
# A static library cannot see the prefix it was installed to (the program
# lives elsewhere), so the consumer is pointed at the installed data.
export CLIPS_DATA_DIR="$prefix/share/clips"
out=$(cd /tmp && "$tmp/consumer/consumer" "$src/data/examples/doors-keys-gems")
echo "$out"
echo "$out" | grep -q "data in $prefix/share/clips" || fail "the library did not read the installed data"
echo "$out" | grep -Eq '^assistant: \(.* robot.*\)$' || fail "no assistant action"
# Printed to 4 decimals: the sum is 1 within their rounding.
total=$(echo "$out" | awk -F' = ' '/^P\(/ {s += $2; n++} END {if (n == 4 && s > 0.9997 && s < 1.0003) print "ok"}')
[ "$total" = "ok" ] || fail "posterior over the 4 gems does not sum to 1"
# The instruction asks for the yellow key, which opens the way to gem3
# (problems/e1.txt): it must be the most probable goal.
best=$(echo "$out" | awk -F'[()= ]+' '/^P\(/ {if ($3 > m) {m = $3; g = $2}} END {print g}')
[ "$best" = "gem3" ] || fail "most probable goal is '$best', expected gem3"

# 2. pkg-config.
flags=$(PKG_CONFIG_PATH="$libdir/pkgconfig" pkg-config --cflags --libs clips)
g++ -std=c++17 "$src/examples/consumer/main.cpp" $flags -o "$tmp/consumer-pc"
out_pc=$(cd /tmp && "$tmp/consumer-pc" "$src/data/examples/doors-keys-gems")
[ "$out_pc" = "$out" ] || fail "the pkg-config build printed something else"

# 3. The installed CLI from /tmp, $CLIPS_DATA_DIR unset: it finds
# <prefix>/share/clips beside its own bin/.
unset CLIPS_DATA_DIR
(cd /tmp && "$prefix/bin/clips" infer --dataset "$src/data/examples/doors-keys-gems" --plan e1.1.keys --json >"$tmp/infer.json") \
  || fail "installed clips infer failed"
grep -q '"posterior"' "$tmp/infer.json" || fail "installed clips infer printed no posterior"
echo "install_and_consume: OK"
