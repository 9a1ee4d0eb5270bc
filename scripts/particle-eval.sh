#!/usr/bin/env bash
# Particle versus exact inference on generated Doors-Keys-Gems problems:
# generates a dataset with GEMS candidate goals (x 2 cost profiles =
# 2*GEMS hypotheses), then runs `clips bench particles` on it (total
# variation of the goal posterior and time ratios for N = 64, 128, 256).
#
#   scripts/particle-eval.sh [GEMS] [OUT_DIR]      e.g. scripts/particle-eval.sh 32 results/smc-32
#
# Environment: BUILD_DIR (build), SIZE (grid; default from GEMS), PROBLEMS (6),
# PLANS (2 per problem), SEED (21), KEYS (2), DOORS (2), PARTICLES (64,128,256),
# SEEDS (particle seeds per count, 3). Writes OUT_DIR/dataset, OUT_DIR/eval.json
# and OUT_DIR/eval.txt.
set -euo pipefail
GEMS=${1:-4}
OUT=${2:-results/particle-eval-$GEMS}
BUILD_DIR=${BUILD_DIR:-build}
if [ -z "${SIZE:-}" ]; then
  # Room for the gems, keys and doors: about eight free cells per gem.
  side=9
  while [ $((side * side)) -lt $((GEMS * 8 + 40)) ] && [ "$side" -lt 30 ]; do side=$((side + 1)); done
  SIZE="${side}x${side}"
fi
mkdir -p "$OUT"
"$BUILD_DIR/clips" generate --size "$SIZE" --gems "$GEMS" --keys "${KEYS:-2}" --doors "${DOORS:-2}" \
  --problems "${PROBLEMS:-6}" --plans "${PLANS:-2}" --seed "${SEED:-21}" --out "$OUT/dataset" --force -q
"$BUILD_DIR/clips" bench particles --dataset "$OUT/dataset" --particles "${PARTICLES:-64,128,256}" \
  --seeds "${SEEDS:-3}" --out "$OUT/eval.json" | tee "$OUT/eval.txt"
