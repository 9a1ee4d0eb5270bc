#!/usr/bin/env bash
# Whole-problem timings that are not micro-benchmarks: solving every visible
# mDKG problem x 4 gems x 4 cost profiles optimally from the initial state.
set -euo pipefail
BUILD_DIR=${1:-build}
DATASET=${2:-../shared/dataset}
DKG="$DATASET/doors-keys-gems"
if [ ! -f "$DKG/domain.pddl" ]; then
  echo "bench-report: $DKG not found, skipping the whole-dataset planning timing"
  exit 0
fi
start=$(date +%s.%N)
n=0
ok=0
unreachable=0
for p in "$DKG"/problems/*.pddl; do
  id=$(basename "$p" .pddl)
  for g in 1 2 3 4; do
    for c in 1 2 3 4; do
      out=$("$BUILD_DIR/clips" plan --dataset "$DKG" --problem "$id" --goal "(has human gem$g)" --costs "$c" --json || true)
      case "$out" in
        *'"status":"success"'*) ok=$((ok + 1)) ;;
        *'"status":"failure"'*) unreachable=$((unreachable + 1)) ;;
      esac
      n=$((n + 1))
    done
  done
done
end=$(date +%s.%N)
echo "bench-report: $n (problem, gem, cost profile) tasks from the initial state with the admissible default heuristic:"
echo "bench-report:   $ok solved optimally, $unreachable proved unreachable, $((n - ok - unreachable)) out of budget; $(awk "BEGIN {printf \"%.2f\", $end - $start}") s in all"
