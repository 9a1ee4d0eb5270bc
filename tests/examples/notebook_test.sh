#!/usr/bin/env bash
# CTest notebook_example: executes examples/session.ipynb with nbconvert
# (Debian python3-nbconvert, python3-ipykernel, python3-matplotlib) against
# the build tree's clips_assist, then checks that no cell failed, that the
# plots were shown in the notebook, and that it wrote them as PNG files.
# Usage: notebook_test.sh BUILD_DIR SOURCE_DIR PYTHON
set -euo pipefail
build=$(realpath "$1")
src=$(realpath "$2")
python=$3
fail() { echo "FAIL: $*" >&2; exit 1; }
"$python" -c "import nbconvert, ipykernel, matplotlib" 2>/dev/null \
  || fail "$python lacks nbconvert, ipykernel or matplotlib (scripts/install-deps.sh installs them)"
out="$build/notebook"
rm -rf "$out"
mkdir -p "$out"
CLIPS_NOTEBOOK_OUT="$out" PYTHONPATH="$build/python" MPLCONFIGDIR="$out/mpl" \
  "$python" -m nbconvert --to notebook --execute --ExecutePreprocessor.timeout=600 \
  --output-dir "$out" --output session.executed.ipynb "$src/examples/session.ipynb" \
  || fail "the notebook did not run"
"$python" - "$out/session.executed.ipynb" <<'PY' || fail "the executed notebook is not as expected"
import json, sys
nb = json.load(open(sys.argv[1]))
outputs = [o for c in nb["cells"] if c["cell_type"] == "code" for o in c.get("outputs", [])]
errors = [o for o in outputs if o.get("output_type") == "error"]
if errors:
    sys.exit(f"a cell raised {errors[0].get('ename')}")
images = [o for o in outputs if "image/png" in o.get("data", {})]
if len(images) != 2:
    sys.exit(f"{len(images)} plots shown, expected 2")
PY
for f in posterior.png final-posterior.png; do
  [ -f "$out/$f" ] || fail "the notebook wrote no $f"
  [ "$(head -c 8 "$out/$f" | od -An -tx1 | tr -d ' \n')" = "89504e470d0a1a0a" ] || fail "$f is not a PNG"
  [ "$(stat -c %s "$out/$f")" -gt 5000 ] || fail "$f is too small to hold a plot"
done
echo "notebook_example: OK ($out)"
