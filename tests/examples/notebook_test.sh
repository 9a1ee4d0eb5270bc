#!/usr/bin/env bash
# CTest notebook_example: executes examples/session.ipynb as docs/library.md
# ("Notebooks") tells a user to: in a Jupyter kernel installed into the venv
# that holds clips_assist. The venv is made from PYTHON with its system
# site-packages (Debian's python3-ipykernel, python3-nbconvert and
# python3-matplotlib); clips_assist is in the venv only (a .pth naming the
# build tree's package), so the default kernel could not import it. Checks
# that the notebook ran in the venv's kernel, that no cell failed, that the
# session showed itself (scene as PNG, posterior as HTML) and the plots were
# shown, and that the plots were written as PNG files.
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
tmp=$(mktemp -d /tmp/clips-nb-XXXXXX)
trap 'rm -rf "$tmp"' EXIT
unset PYTHONPATH CLIPS_DATA_DIR

# The venv, clips_assist in it, and its kernel (installed into the venv's prefix, not ~/.local).
"$python" -m venv --system-site-packages "$tmp/venv" || fail "$python -m venv failed (Debian: python3-venv)"
site=$("$tmp/venv/bin/python" -c 'import sysconfig; print(sysconfig.get_paths()["platlib"])')
echo "$build/python" >"$site/clips-assist-build-tree.pth"
"$tmp/venv/bin/python" -m ipykernel install --prefix "$tmp/venv" --name clips-venv --display-name "Python (clips venv)" \
  >/dev/null || fail "ipykernel install into the venv failed"
[ -f "$tmp/venv/share/jupyter/kernels/clips-venv/kernel.json" ] || fail "no kernel.json in the venv"

CLIPS_NOTEBOOK_OUT="$out" MPLCONFIGDIR="$out/mpl" PYDEVD_DISABLE_FILE_VALIDATION=1 JUPYTER_PATH="$tmp/venv/share/jupyter" \
  "$python" -m nbconvert --to notebook --execute --ExecutePreprocessor.timeout=600 \
  --ExecutePreprocessor.kernel_name=clips-venv \
  --output-dir "$out" --output session.executed.ipynb "$src/examples/session.ipynb" \
  || fail "the notebook did not run"
"$python" - "$out/session.executed.ipynb" "$tmp/venv" <<'PY' || fail "the executed notebook is not as expected"
import json, sys
nb = json.load(open(sys.argv[1]))
cells = [c for c in nb["cells"] if c["cell_type"] == "code"]
outputs = [o for c in cells for o in c.get("outputs", [])]
errors = [o for o in outputs if o.get("output_type") == "error"]
if errors:
    sys.exit(f"a cell raised {errors[0].get('ename')}: {errors[0].get('evalue')}")
text = "".join("".join(o.get("text", "")) for o in outputs if o.get("output_type") == "stream")
if f"in {sys.argv[2]}" not in text:
    sys.exit(f"the notebook did not run in the venv's kernel ({sys.argv[2]}): {text[:300]}")
shown = [o for c in cells for o in c.get("outputs", []) if o.get("output_type") == "execute_result"]
session = [o for o in shown if "clips-assist-session" in "".join(o.get("data", {}).get("text/html", ""))]
if len(session) != 1 or "image/png" not in session[0]["data"]:
    sys.exit("the session did not show itself as HTML (scene and posterior) and PNG")
if "data:image/png;base64," not in "".join(session[0]["data"]["text/html"]):
    sys.exit("the session's HTML has no scene")
plots = [o for o in outputs if o.get("output_type") == "display_data" and "image/png" in o.get("data", {})]
if len(plots) != 2:
    sys.exit(f"{len(plots)} plots shown, expected 2")
PY
for f in posterior.png final-posterior.png; do
  [ -f "$out/$f" ] || fail "the notebook wrote no $f"
  [ "$(head -c 8 "$out/$f" | od -An -tx1 | tr -d ' \n')" = "89504e470d0a1a0a" ] || fail "$f is not a PNG"
  [ "$(stat -c %s "$out/$f")" -gt 5000 ] || fail "$f is too small to hold a plot"
done
echo "notebook_example: OK ($out)"
