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
# One Python process starts every call and times it (wall: from the fork to
# the exit; CPU: the child's user + system time from wait4), so that the
# figures are the calls' own, not the shell's around them.
exec /usr/bin/python3 - "$clips" "$dataset" "$out" <<'PY'
import json, os, re, subprocess, sys, time
clips, dataset, out = sys.argv[1:4]
rows = ["problem\tgem\tstatus\tcost\texpanded\tsearch_seconds\twall\tcpu"]
n = wall_sum = cpu_sum = 0
for f in sorted(os.listdir(os.path.join(dataset, "problems"))):
    if not f.endswith(".pddl"):
        continue
    p = f[:-5]
    text = open(os.path.join(dataset, "problems", f)).read()
    for g in sorted(set(re.findall(r"gem[0-9]+", text))):
        t0 = time.perf_counter()
        proc = subprocess.Popen([clips, "plan", "--dataset", dataset, "--problem", p, "--goal", "(has human %s)" % g,
                                 "--json"], stdout=subprocess.PIPE, stderr=subprocess.DEVNULL)
        stdout = proc.stdout.read()
        _, _, usage = os.wait4(proc.pid, 0)
        wall = time.perf_counter() - t0
        cpu = usage.ru_utime + usage.ru_stime
        try:
            j = json.loads(stdout.decode().strip().splitlines()[-1])
            fields = "%s\t%g\t%s\t%.4f" % (j["status"], j["cost"], j["expanded"], j["seconds"])
        except Exception:
            fields = "error\t\t\t"
        rows.append("%s\t%s\t%s\t%.4f\t%.4f" % (p, g, fields, wall, cpu))
        n += 1
        wall_sum += wall
        cpu_sum += cpu
with open(out, "w") as o:
    o.write("\n".join(rows) + "\n")
print("dkg-plan-times: %d tasks, %.3f s wall, %.3f s cpu in all" % (n, wall_sum, cpu_sum), file=sys.stderr)
PY
