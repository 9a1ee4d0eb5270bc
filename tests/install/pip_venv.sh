#!/usr/bin/env bash
# CTest pip_install_venv: `pip install --no-build-isolation` of the source tree
# into a temporary venv (--system-site-packages: Debian's setuptools, pybind11
# and pytest, nothing downloaded), then from /tmp with no PYTHONPATH:
#   1. `import clips_assist` gives the venv's package, which reads the data
#      installed inside it;
#   2. the README's Python example runs and ends with the assistant's action;
#   3. pytest python/tests runs against the installed package.
# Usage: pip_venv.sh BUILD_DIR SOURCE_DIR PYTHON
# The CMake build folder of the pip build is setup.py's default,
# SOURCE_DIR/build-pip-<SOABI> (kept, so a second run rebuilds little; with
# CCACHE_BASEDIR set, as `make test` does, its objects come from ccache).
set -euo pipefail
build=$(realpath "$1")
src=$(realpath "$2")
python=$3
tmp=$(mktemp -d /tmp/clips-pip-XXXXXX)
trap 'rm -rf "$tmp"' EXIT
unset CLIPS_DATA_DIR PYTHONPATH
fail() { echo "FAIL: $*" >&2; exit 1; }

"$python" -m venv --system-site-packages "$tmp/venv" || fail "$python -m venv failed (Debian: python3-venv)"
venv_python="$tmp/venv/bin/python"
"$venv_python" -m pip install --no-build-isolation --no-index -q "$src" \
  || fail "pip install --no-build-isolation failed"

# 1. The installed package, with its own data.
site=$("$venv_python" -c 'import sysconfig; print(sysconfig.get_paths()["purelib"])')
got=$(cd /tmp && "$venv_python" -c 'import clips_assist as c; print(c.__file__); print(c.data_directory()); print(c.example_dataset())')
echo "$got"
[ "$(echo "$got" | sed -n 1p)" = "$site/clips_assist/__init__.py" ] || fail "imported another clips_assist"
[ "$(echo "$got" | sed -n 2p)" = "$site/clips_assist/data" ] || fail "the installed package does not read its own data"
[ -f "$site/clips_assist/_core.pyi" ] && [ -f "$site/clips_assist/py.typed" ] || fail "no type stubs installed"

# 2. The README's Python example (its first python block that imports clips_assist).
"$python" - "$src/README.md" >"$tmp/example.py" <<'PY'
import re, sys
text = open(sys.argv[1], encoding="utf-8").read()
blocks = [b for b in re.findall(r"```python\n(.*?)```", text, re.S) if "import clips_assist" in b]
if not blocks:
    sys.exit("no python example importing clips_assist in README.md")
print(blocks[0])
PY
out=$(cd /tmp && "$venv_python" "$tmp/example.py") || fail "the README's Python example failed"
echo "$out"
echo "$out" | grep -Eq '^t=0 \(start\)' || fail "the example printed no start step"
echo "$out" | grep -Eq '^assistant: \(.*robot.*\)$' || fail "the example printed no assistant action"

# 3. The Python tests, against the installed package.
(cd /tmp && CLIPS_ASSIST_EXPECTED_DIR="$site/clips_assist" CLIPS_BINARY_DIR="$build" \
   "$venv_python" -m pytest -q -p no:cacheprovider "$src/python/tests") || fail "pytest against the installed package failed"
echo "pip_venv: OK"
