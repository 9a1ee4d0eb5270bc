#!/usr/bin/env bash
# The main job behind `make run`: validate the bundled examples, the repo's
# own domains (data/datasets/*) and the paper's dataset ($CLIPS_DATASET or
# ../shared/dataset) where present, then reproduce the result tables with `clips bench` (results under
# out/), the repo's own domains included.
set -euo pipefail
BUILD_DIR=${1:-build}
DATASET=${2:-../shared/dataset}
CLIPS="$BUILD_DIR/clips"
status=0
echo "== validate: bundled examples and the workshop domain"
"$CLIPS" validate --dataset data/examples/doors-keys-gems --quiet || status=1
for d in workshop kitchen garden lab hospital warehouse; do "$CLIPS" validate --dataset "data/datasets/$d" --quiet || status=1; done
for dom in doors-keys-gems virtual-home; do
  if [ -f "$DATASET/$dom/domain.pddl" ]; then
    echo "== validate: $DATASET/$dom"
    "$CLIPS" validate --dataset "$DATASET/$dom" --quiet || status=1
  fi
done
echo "== bench: bundled examples"
"$CLIPS" bench --dataset data/examples/doors-keys-gems --out out/examples || status=1
for d in workshop kitchen garden lab; do
  echo "== bench: data/datasets/$d (a domain of the repo's own, from its pack; test split in the table by split)"
  "$CLIPS" bench --dataset "data/datasets/$d" --out "out/$d" -j 2 || status=1
done
for dom in doors-keys-gems virtual-home; do
  if [ -f "$DATASET/$dom/domain.pddl" ]; then
    echo "== bench: $DATASET/$dom"
    "$CLIPS" bench --dataset "$DATASET/$dom" --out "out/$dom" --report "out/$dom/report" || status=1
  else
    echo "== $DATASET/$dom not found: skipped (set CLIPS_DATASET to the folder holding doors-keys-gems/ and virtual-home/)"
  fi
done
exit $status
