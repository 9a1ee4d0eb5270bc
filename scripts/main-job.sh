#!/usr/bin/env bash
# The main job behind `make run`: validate the bundled examples and, where
# present, the paper's dataset ($CLIPS_DATASET or ../shared/dataset).
set -euo pipefail
BUILD_DIR=${1:-build}
DATASET=${2:-../shared/dataset}
CLIPS="$BUILD_DIR/clips"
status=0
echo "== bundled examples"
"$CLIPS" validate --dataset data/examples/doors-keys-gems || status=1
for dom in doors-keys-gems virtual-home; do
  if [ -f "$DATASET/$dom/domain.pddl" ]; then
    echo "== $DATASET/$dom"
    "$CLIPS" validate --dataset "$DATASET/$dom" --quiet || status=1
  else
    echo "== $DATASET/$dom not found: skipped (set CLIPS_DATASET to the folder holding doors-keys-gems/ and virtual-home/)"
  fi
done
exit $status
