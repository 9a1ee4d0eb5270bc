#!/usr/bin/env bash
# Times `clips plan` (optimal A*, the pack's default heuristic) on every
# (problem, gem) task of the paper's doors-keys-gems dataset: the goal
# (has human gemN) for each gem of each problem. This is the per-call check
# docs/results.md compares against Fast Downward (on the same tasks exported
# with `clips export-strips`).
#
#   scripts/dkg-plan-times.sh [--clips BIN] [--dataset DIR] [--out FILE]
#
# The TSV (problem, gem, status, cost, expanded, search seconds, wall and
# CPU seconds of the whole call) goes to --out (default stdout); the totals
# to stderr.
set -uo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
clips="$here/build/clips"
dataset="${CLIPS_DATASET:-$here/../shared/dataset}/doors-keys-gems"
out=/dev/stdout
while [ $# -gt 0 ]; do
  case "$1" in
    --clips) clips="$2"; shift 2 ;;
    --dataset) dataset="$2"; shift 2 ;;
    --out) out="$2"; shift 2 ;;
    -h|--help) sed -n 2,12p "$0"; exit 0 ;;
    *) echo "dkg-plan-times: unknown option '$1' (see --help)" >&2; exit 2 ;;
  esac
done
[ -d "$dataset/problems" ] || { echo "dkg-plan-times: no $dataset/problems (give --dataset DIR)" >&2; exit 2; }
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
printf 'problem\tgem\tstatus\tcost\texpanded\tsearch_seconds\twall\tcpu\n' >"$out"
n=0 wall_sum=0 cpu_sum=0
for f in "$dataset"/problems/*.pddl; do
  p="$(basename "$f" .pddl)"
  for g in $(grep -o 'gem[0-9]\+' "$f" | sort -u); do
    t0=$(date +%s.%N)
    /usr/bin/time -f "%U %S" -o "$tmp/cpu" "$clips" plan --dataset "$dataset" --problem "$p" \
      --goal "(has human $g)" --json >"$tmp/out" 2>/dev/null
    t1=$(date +%s.%N)
    wall=$(python3 -c "print('%.3f' % ($t1 - $t0))")
    cpu=$(awk 'NF == 2 && $1 ~ /^[0-9.]+$/ { printf "%.3f", $1 + $2 }' "$tmp/cpu")
    fields=$(python3 -c '
import json, sys
try:
    j = json.loads(open(sys.argv[1]).read().strip().splitlines()[-1])
    print("%s\t%g\t%s\t%.4f" % (j["status"], j["cost"], j["expanded"], j["seconds"]))
except Exception:
    print("error\t\t\t")' "$tmp/out")
    printf '%s\t%s\t%s\t%s\t%s\n' "$p" "$g" "$fields" "$wall" "$cpu" >>"$out"
    n=$((n + 1))
    wall_sum=$(python3 -c "print($wall_sum + $wall)")
    cpu_sum=$(python3 -c "print($cpu_sum + ${cpu:-0})")
  done
done
echo "dkg-plan-times: $n tasks, ${wall_sum}s wall, ${cpu_sum}s cpu in all" >&2
