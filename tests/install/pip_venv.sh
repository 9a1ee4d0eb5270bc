#!/usr/bin/env bash
# CTest pip_install_venv: pip install of the source tree with the project's own
# build backend (python/backend/clips_backend.py: nothing from PyPI, no
# setuptools or wheel) for a Python that is not Debian's, then:
#   1. into venv A of that Python (no system site-packages, pip's own build
#      isolation): `import clips_assist` from /tmp gives the venv's package with
#      its own data and dist-info, the README's Python example runs, and
#      `pip install -v` showed the build's progress;
#   2. `pip wheel` makes a wheel, which installs into another venv B;
#   3. pytest python/tests runs against the package installed from that wheel
#      (or, when the wheel is for another Python than Debian's, built again)
#      in a venv of Debian's python3 that sees Debian's pytest.
# The Python: $CLIPS_PIP_TEST_PYTHON, else python3 on PATH when it is not
# Debian's (pyenv, conda), else a venv of Debian's python3 made without pip
# and without system site-packages, into which Debian's pip installs
# (`pip --python`): either way no Debian build tools are in reach of pip.
# Usage: pip_venv.sh BUILD_DIR SOURCE_DIR DEBIAN_PYTHON
# The CMake build folders are the backend's default,
# SOURCE_DIR/build-pip-<SOABI>-<interpreter> (kept: a second run rebuilds
# little; with CCACHE_BASEDIR set, its objects come from ccache).
set -euo pipefail
build=$(realpath "$1")
src=$(realpath "$2")
debian_python=$3
tmp=$(mktemp -d /tmp/clips-pip-XXXXXX)
trap 'rm -rf "$tmp"' EXIT
unset CLIPS_DATA_DIR PYTHONPATH PIP_REQUIRE_VIRTUALENV
export PIP_DISABLE_PIP_VERSION_CHECK=1 CLIPS_PIP_QUIET=1
fail() { echo "FAIL: $*" >&2; exit 1; }

python=${CLIPS_PIP_TEST_PYTHON:-}
if [ -z "$python" ] && command -v python3 >/dev/null; then
  candidate=$(python3 -c 'import sys; print(sys.executable if sys.base_prefix != "/usr" else "")' 2>/dev/null || true)
  [ -n "$candidate" ] && python=$candidate
fi

# pip_into VENV ARGS...: pip install into VENV, with the venv's pip or Debian's.
if [ -n "$python" ]; then
  echo "pip_venv: a non-Debian Python: $python ($("$python" --version 2>&1))"
  make_venv() { "$python" -m venv "$1" || fail "$python -m venv $1 failed"; }
  pip_into() { local v=$1; shift; "$v/bin/python" -m pip "$@"; }
else
  echo "pip_venv: no non-Debian Python here: a venv of $debian_python without pip or system site-packages"
  make_venv() { "$debian_python" -m venv --without-pip "$1" || fail "venv --without-pip failed (Debian: python3-venv)"; }
  pip_into() { local v=$1; shift; "$debian_python" -m pip --python "$v/bin/python" "$@"; }
fi

check_installed() {  # VENV: the package, its data and dist-info, and the README's example, from /tmp
  local venv_python="$1/bin/python"
  local site
  site=$("$venv_python" -c 'import sysconfig; print(sysconfig.get_paths()["platlib"])')
  local got
  got=$(cd /tmp && "$venv_python" -c 'import clips_assist as c, importlib.metadata as m
print(c.__file__); print(c.data_directory()); print(m.version("clips-assist"))')
  echo "$got"
  [ "$(echo "$got" | sed -n 1p)" = "$site/clips_assist/__init__.py" ] || fail "$1 imported another clips_assist"
  [ "$(echo "$got" | sed -n 2p)" = "$site/clips_assist/data" ] || fail "$1's package does not read its own data"
  [ "$(echo "$got" | sed -n 3p)" = "$(sed -n 's/^project(clips VERSION \([0-9.]*\).*/\1/p' "$src/CMakeLists.txt")" ] \
    || fail "$1: no dist-info with the project's version"
  [ -f "$site/clips_assist/_core.pyi" ] && [ -f "$site/clips_assist/py.typed" ] || fail "no type stubs installed"
  local out
  out=$(cd /tmp && "$venv_python" "$tmp/example.py") || fail "the README's Python example failed in $1"
  echo "$out" | grep -Eq '^t=0 \(start\)' || fail "the example printed no start step"
  echo "$out" | grep -Eq '^assistant: \(.*robot.*\)$' || fail "the example printed no assistant action"
}

"$debian_python" - "$src/README.md" >"$tmp/example.py" <<'PY'
import re, sys
text = open(sys.argv[1], encoding="utf-8").read()
blocks = [b for b in re.findall(r"```python\n(.*?)```", text, re.S) if "import clips_assist" in b]
if not blocks:
    sys.exit("no python example importing clips_assist in README.md")
print(blocks[0])
PY

# 1. pip install from the source tree, with build isolation (nothing to fetch: requires = []).
make_venv "$tmp/a"
start=$(date +%s)
pip_into "$tmp/a" install --no-index -v "$src" >"$tmp/pip-a.log" 2>&1 || { tail -40 "$tmp/pip-a.log"; fail "pip install failed"; }
echo "pip_venv: pip install took $(( $(date +%s) - start )) s"
grep -q "clips-assist: building the Python module for" "$tmp/pip-a.log" || fail "pip -v showed no word from the backend"
grep -Eq '^ *\[ *[0-9]+%\] ' "$tmp/pip-a.log" || fail "pip -v showed no build progress"
if grep -q "Building CXX object CMakeFiles/test_" "$tmp/pip-a.log"; then fail "the pip build compiled tests"; fi
check_installed "$tmp/a"

# 2. A wheel, installed into another venv.
pip_into "$tmp/a" wheel --no-index --no-deps -w "$tmp/wheels" "$src" >"$tmp/pip-wheel.log" 2>&1 \
  || { tail -40 "$tmp/pip-wheel.log"; fail "pip wheel failed"; }
wheel=$(ls "$tmp"/wheels/clips_assist-*.whl)
echo "pip_venv: $(basename "$wheel")"
"$debian_python" - "$wheel" <<'PY' || fail "the wheel's RECORD does not match its files"
import base64, hashlib, sys, zipfile
z = zipfile.ZipFile(sys.argv[1])
record = [n for n in z.namelist() if n.endswith(".dist-info/RECORD")][0]
listed = {}
for line in z.read(record).decode().splitlines():
    name, digest, size = line.rsplit(",", 2)
    listed[name] = digest
for name in z.namelist():
    if name == record:
        continue
    want = "sha256=" + base64.urlsafe_b64encode(hashlib.sha256(z.read(name)).digest()).rstrip(b"=").decode()
    if listed.get(name) != want:
        sys.exit(f"{name}: RECORD says {listed.get(name)}, the file is {want}")
PY
make_venv "$tmp/b"
pip_into "$tmp/b" install --no-index "$wheel" >"$tmp/pip-b.log" 2>&1 || { cat "$tmp/pip-b.log"; fail "the wheel did not install"; }
check_installed "$tmp/b"

# 3. The Python tests against an installed package, in a venv of Debian's python3 (its pytest).
"$debian_python" -m venv --system-site-packages "$tmp/c" || fail "$debian_python -m venv failed"
if ! "$tmp/c/bin/python" -m pip install --no-index "$wheel" >"$tmp/pip-c.log" 2>&1; then
  echo "pip_venv: the wheel is not for $debian_python; building for it"
  "$tmp/c/bin/python" -m pip install --no-index "$src" >"$tmp/pip-c.log" 2>&1 || { tail -40 "$tmp/pip-c.log"; fail "pip install for $debian_python failed"; }
fi
site=$("$tmp/c/bin/python" -c 'import sysconfig; print(sysconfig.get_paths()["platlib"])')
(cd /tmp && CLIPS_ASSIST_EXPECTED_DIR="$site/clips_assist" CLIPS_BINARY_DIR="$build" \
   "$tmp/c/bin/python" -m pytest -q -p no:cacheprovider "$src/python/tests") || fail "pytest against the installed package failed"
echo "pip_venv: OK"
