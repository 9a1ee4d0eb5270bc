#!/usr/bin/env bash
# CTest deb_install: builds the Debian package (cpack -G DEB, prefix /usr),
# installs it with dpkg beside Debian's `clips` and `libclips-dev` (CLIPS, the
# expert system: /usr/bin/clips, /usr/include/clips/, libclips.a), checks that
# neither package lost a file, then with no source tree in reach (from an
# empty folder, CLIPS_DATA_DIR and PYTHONPATH unset, the binaries built
# without the checkout's path):
#   1. the installed CLI, clips-assist, runs inference on the installed example;
#   2. a C++ consumer (a copy of examples/consumer) builds with
#      find_package(ClipsAssist) and with pkg-config, and reads /usr/share/clips-assist;
#   3. the README's Python example runs on Debian's python3 with the installed module,
#      whose dist-info importlib.metadata reads;
#   4. it feels native: `lintian` finds no error, `man clips-assist` renders the
#      manual page, the bash completion completes, --version and messages say
#      clips-assist, the changelog is there, the shared library has its soname
#      and a program links with it (lintian comes through scripts/install-deps.sh).
# The package is removed at the end. Needs root and dpkg: otherwise it skips
# (exit 77); so does a machine where clips-assist is already installed.
# Usage: deb_install.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build=$(realpath "$1")
src=$(realpath "$2")
if [ "$(id -u)" -ne 0 ] || ! command -v dpkg >/dev/null || ! command -v cpack >/dev/null; then
  echo "deb_install: needs root, dpkg and cpack; skipped"
  exit 77
fi
if dpkg-query -W -f='${Status}' clips-assist 2>/dev/null | grep -q "install ok installed"; then
  echo "deb_install: clips-assist is already installed here; skipped (it would be removed)"
  exit 77
fi
fail() { echo "FAIL: $*" >&2; exit 1; }
for p in clips libclips-dev; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" \
    || fail "Debian's $p is not installed (scripts/install-deps.sh installs it)"
done
tmp=$(mktemp -d /tmp/clips-deb-XXXXXX)
installed=0
cleanup() {
  if [ "$installed" = 1 ]; then with_dpkg_lock dpkg -r clips-assist || echo "deb_install: dpkg -r clips-assist failed" >&2; fi
  rm -rf "$tmp"
}
trap cleanup EXIT

# The package's own build folder beside build/ (same depth: ccache, with
# CCACHE_BASEDIR as `make test` sets it, serves build/'s objects).
debbuild="$src/build-deb"
cmake -S "$src" -B "$debbuild" -DCMAKE_BUILD_TYPE=Release -DCMAKE_INSTALL_PREFIX=/usr -DCLIPS_BUILD_TESTS=OFF \
  -DCLIPS_BUILD_BENCH=OFF -DCLIPS_SOURCE_DATA=OFF -DPython3_EXECUTABLE=/usr/bin/python3 >/dev/null
cmake --build "$debbuild" -j "${CLIPS_DEB_JOBS:-2}" >/dev/null
(cd "$debbuild" && rm -f clips-assist_*.deb && cpack -G DEB >/dev/null)
deb=$(ls "$debbuild"/clips-assist_*.deb)
[ -f "$deb" ] || fail "cpack made no .deb"
[ "$(dpkg-deb -f "$deb" Package)" = clips-assist ] || fail "the package is not named clips-assist"
dpkg-deb -c "$deb" | awk '{print $6}' >"$tmp/files"
for f in ./usr/bin/clips-assist ./usr/include/clips-assist/clips/clips.hpp ./usr/share/clips-assist/language/corpus-dkg.tsv \
         ./usr/share/clips-assist/examples/doors-keys-gems/domain.pddl ./usr/lib/python3/dist-packages/clips_assist/__init__.py \
         ./usr/share/man/man1/clips-assist.1.gz ./usr/share/bash-completion/completions/clips-assist \
         ./usr/share/doc/clips-assist/changelog.gz ./usr/share/doc/clips-assist/copyright \
         ./usr/share/clips-assist/schema/serve-api.openapi.json \
         ./usr/lib/python3/dist-packages/clips_assist-$(dpkg-deb -f "$deb" Version).dist-info/METADATA; do
  grep -qx "$f" "$tmp/files" || fail "the package lacks $f"
done
grep -Eq '^\./usr/lib/.*libclips_assist\.a$' "$tmp/files" || fail "the package lacks libclips_assist.a"
# The HTTP server is a module the CLI opens; libcurl and cairo are opened at
# run time too, so the package must depend on them by name.
grep -Eq '^\./usr/lib/.*/clips-assist/clips-http\.so$' "$tmp/files" || fail "the package lacks the HTTP module clips-http.so"
for dep in libcurl4 libcairo2 libcpp-httplib; do
  dpkg-deb -f "$deb" Depends | grep -q "$dep" || fail "Depends lacks $dep: $(dpkg-deb -f "$deb" Depends)"
done
grep -Eq '^\./usr/lib/.*libclips_assist\.so\.[0-9]+\.[0-9]+$' "$tmp/files" || fail "the package lacks libclips_assist.so.X.Y"
dpkg-deb -f "$deb" Maintainer | grep -Eq '^[^<>]+ <[^@<> ]+@[^@<> ]+\.[a-z]+>$' \
  || fail "Maintainer has no e-mail address: $(dpkg-deb -f "$deb" Maintainer)"

# lintian (a Debian package the build does not need: installed for this test).
bash "$src/scripts/install-deps.sh" lintian || fail "cannot install lintian"
lintian --no-tag-display-limit "$deb" >"$tmp/lintian.txt" 2>&1 || true
cat "$tmp/lintian.txt"
if grep -q '^E: ' "$tmp/lintian.txt"; then fail "lintian reports errors: $(grep '^E: ' "$tmp/lintian.txt" | head -5)"; fi
grep -Eq '^\./usr/lib/python3/dist-packages/clips_assist/_core\..*\.so$' "$tmp/files" || fail "the package lacks the module"
# No file of Debian's clips packages, nor any path they use.
dpkg -L clips libclips-dev | sed 's|^|.|' | sort >"$tmp/theirs"
clash=$(sort "$tmp/files" | grep -v '/$' | comm -12 - "$tmp/theirs" || true)
[ -z "$clash" ] || fail "the package ships files of Debian's clips packages: $clash"
grep -Eq '^\./usr/(bin/clips|include/clips/.*|lib/.*libclips\..*|lib/python3/dist-packages/clips/.*)$' "$tmp/files" \
  && fail "the package uses a path of Debian's clips or PyPI's clipspy"
# Nothing in the package names the checkout's data.
dpkg-deb -x "$deb" "$tmp/unpacked"
if grep -rlF "$src/data" "$tmp/unpacked" >/dev/null; then fail "the packaged binaries name $src/data"; fi

# dpkg waits for nobody: another apt or dpkg run holds its lock for a while.
with_dpkg_lock() {
  for _ in $(seq 60); do
    "$@" >"$tmp/dpkg.log" 2>&1 && return 0
    grep -q "lock" "$tmp/dpkg.log" || { cat "$tmp/dpkg.log" >&2; return 1; }
    sleep 5
  done
  cat "$tmp/dpkg.log" >&2
  return 1
}
with_dpkg_lock dpkg -i "$deb" || fail "dpkg -i failed"
installed=1
[ "$(dpkg-query -S /usr/bin/clips | cut -d: -f1)" = clips ] || fail "/usr/bin/clips no longer belongs to Debian's clips"
[ "$(dpkg-query -S /usr/include/clips/clips.h | cut -d: -f1)" = libclips-dev ] || fail "libclips-dev lost clips.h"
[ -z "$(dpkg --verify clips libclips-dev)" ] || fail "Debian's clips packages changed: $(dpkg --verify clips libclips-dev)"

run=(env -i HOME="$tmp" PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin)
mkdir "$tmp/work"
cd "$tmp/work"
example=/usr/share/clips-assist/examples/doors-keys-gems

# 1. The CLI.
[ "$(command -v clips-assist)" = /usr/bin/clips-assist ] || fail "clips-assist is not /usr/bin/clips-assist"
"${run[@]}" clips-assist infer --dataset "$example" --plan e1.1.keys --json >"$tmp/infer.json" || fail "clips-assist infer failed"
grep -q '"posterior"' "$tmp/infer.json" || fail "clips-assist infer printed no posterior"
# The installed CLI finds its HTTP module.
"${run[@]}" clips-assist serve --port 0 --dataset "$example" >"$tmp/serve.log" 2>&1 &
serve_pid=$!
for _ in $(seq 100); do grep -q "listening on" "$tmp/serve.log" && break; sleep 0.1; done
url=$(grep -o 'http://[^ ]*/' "$tmp/serve.log" | head -1)
health=$(python3 -c 'import sys, urllib.request; print(urllib.request.urlopen(sys.argv[1], timeout=10).read().decode())' \
         "${url}api/health" 2>&1 || true)
kill "$serve_pid" 2>/dev/null; wait "$serve_pid" 2>/dev/null
echo "$health" | grep -q '"sessions"' || fail "the installed clips-assist serve did not answer /api/health: $(cat "$tmp/serve.log")"

# 2. A C++ consumer, both ways.
cp "$src/examples/consumer/CMakeLists.txt" "$src/examples/consumer/main.cpp" "$tmp/work/"
"${run[@]}" cmake -S "$tmp/work" -B "$tmp/work/b" -DCMAKE_BUILD_TYPE=Release >/dev/null || fail "find_package(ClipsAssist) failed"
"${run[@]}" cmake --build "$tmp/work/b" >/dev/null || fail "the consumer did not build"
out=$("${run[@]}" "$tmp/work/b/consumer" "$example") || fail "the consumer failed"
echo "$out"
echo "$out" | grep -q "data in /usr/share/clips-assist" || fail "the consumer did not read /usr/share/clips-assist"
echo "$out" | grep -Eq '^assistant: \(.* robot.*\)$' || fail "the consumer printed no assistant action"
"${run[@]}" sh -c 'g++ -std=c++17 main.cpp $(pkg-config --cflags --libs clips-assist) -o consumer-pc' \
  || fail "the pkg-config build failed"
[ "$("${run[@]}" ./consumer-pc "$example")" = "$out" ] || fail "the pkg-config build printed something else"

# 3. The README's Python example on Debian's python3.
/usr/bin/python3 - "$src/README.md" >"$tmp/work/example.py" <<'PY'
import re, sys
text = open(sys.argv[1], encoding="utf-8").read()
blocks = [b for b in re.findall(r"```python\n(.*?)```", text, re.S) if "import clips_assist" in b]
if not blocks:
    sys.exit("no python example importing clips_assist in README.md")
print(blocks[0])
PY
pyout=$("${run[@]}" /usr/bin/python3 example.py) || fail "the README's Python example failed"
echo "$pyout"
echo "$pyout" | grep -Eq '^assistant: \(.*robot.*\)$' || fail "the Python example printed no assistant action"
got=$("${run[@]}" /usr/bin/python3 -c 'import clips_assist as c; print(c.__file__); print(c.data_directory())')
[ "$got" = "/usr/lib/python3/dist-packages/clips_assist/__init__.py
/usr/share/clips-assist" ] || fail "python3 imported $got"
[ "$("${run[@]}" /usr/bin/python3 -c 'import importlib.metadata as m; print(m.version("clips-assist"))')" = \
  "$(dpkg-deb -f "$deb" Version)" ] || fail "importlib.metadata does not see the installed clips-assist"

# 4. Native: the manual page, the completion, the name in --version and messages, the shared library.
man_out=$("${run[@]}" MANWIDTH=100 man clips-assist 2>"$tmp/man.err") || fail "man clips-assist failed: $(cat "$tmp/man.err")"
printf "%s\n" "$man_out" | sed -n 1,12p
grep -q "^NAME" <<<"$man_out" && grep -q "clips-assist infer" <<<"$man_out" && grep -q "EXIT STATUS" <<<"$man_out" \
  || fail "man clips-assist does not render the manual page"
"${run[@]}" man --warnings -E UTF-8 -l /usr/share/man/man1/clips-assist.1.gz 2>"$tmp/man.warn" >/dev/null
[ ! -s "$tmp/man.warn" ] || fail "groff warns on the manual page: $(head -3 "$tmp/man.warn")"
completed=$("${run[@]}" bash -c 'source /usr/share/bash-completion/completions/clips-assist
  COMP_WORDS=(clips-assist inf); COMP_CWORD=1; _clips_assist; echo "${COMPREPLY[*]}"
  COMP_WORDS=(clips-assist infer --lm ""); COMP_CWORD=3; _clips_assist; echo "${COMPREPLY[*]}"')
[ "$completed" = "infer
embedded openai" ] || fail "the bash completion completed: $completed"
"${run[@]}" clips-assist --version | grep -Eq '^clips-assist [0-9]+\.[0-9]+\.[0-9]+' || fail "--version does not say clips-assist"
err=$("${run[@]}" clips-assist infer --dataset /nonexistent 2>&1 >/dev/null || true)
echo "$err" | grep -q '^clips-assist: error: ' || fail "an error message does not start with clips-assist: $err"
so=$(dpkg -L clips-assist | grep -E '/libclips_assist\.so\.[0-9]+\.[0-9]+$' || true)
[ -n "$so" ] || fail "dpkg -L lists no libclips_assist.so.X.Y"
# (Into a file first: under pipefail, grep -q quitting at the match would
# fail the pipeline whenever objdump is still writing.)
objdump -p "$so" >"$tmp/so-headers.txt" || fail "objdump -p $so failed"
grep -Eq 'SONAME +libclips_assist\.so\.[0-9]+\.[0-9]+$' "$tmp/so-headers.txt" || fail "$so has no soname"
"${run[@]}" sh -c 'g++ -std=c++17 main.cpp -I/usr/include/clips-assist -lclips_assist -o consumer-so' \
  || fail "a program does not link with the shared library"
ldd "$tmp/work/consumer-so" >"$tmp/consumer-so.ldd" || fail "ldd consumer-so failed"
grep -q "libclips_assist.so" "$tmp/consumer-so.ldd" || fail "consumer-so is not linked with libclips_assist.so"
[ "$("${run[@]}" ./consumer-so "$example")" = "$out" ] || fail "the program linked with the shared library printed something else"
echo "deb_install: OK"
