#!/usr/bin/env bash
# Runs `clips plan` on problem 1 of every folder of an IPC benchmark
# collection (default ../shared/ipc, see its README) and compares each answer
# with Fast Downward's in its reference.tsv: status, optimal cost, seconds.
#
#   scripts/ipc-bench.sh [--clips BIN] [--ipc DIR] [--seconds S] [--only REGEX] [--ground] [--out FILE]
#
# --ground: parse and ground problems 1 and 2 of each folder only
# (`clips plan --ground-only`), no search. Seconds are wall-clock per run,
# parsing and grounding included (cpu: user + system time, which says more
# on a machine others load). The TSV goes to --out (default stdout), a
# summary to stderr. Exit status 0 when every problem Fast Downward solves is
# solved with its cost (or, with --ground, every problem grounds), else 1.
set -uo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
clips="$here/build/clips"
ipc="${CLIPS_IPC:-$here/../shared/ipc}"
seconds=20
only=""
ground=0
out=/dev/stdout
while [ $# -gt 0 ]; do
  case "$1" in
    --clips) clips="$2"; shift 2 ;;
    --ipc) ipc="$2"; shift 2 ;;
    --seconds) seconds="$2"; shift 2 ;;
    --only) only="$2"; shift 2 ;;
    --ground) ground=1; shift ;;
    --out) out="$2"; shift 2 ;;
    -h|--help) sed -n 2,13p "$0"; exit 0 ;;
    *) echo "ipc-bench: unknown option '$1' (see --help)" >&2; exit 2 ;;
  esac
done
ref="$ipc/reference.tsv"
[ -f "$ref" ] || { echo "ipc-bench: no $ref (give --ipc DIR)" >&2; exit 2; }
[ -x "$clips" ] || { echo "ipc-bench: no clips binary at $clips (build it, or give --clips BIN)" >&2; exit 2; }
command -v python3 >/dev/null || { echo "ipc-bench: needs python3 to read the JSON answers" >&2; exit 2; }

# The domain file of problem file P in folder D: domain.pddl, or one of the
# per-problem spellings the collection uses.
domain_of() {
  local d="$1" stem="${2%.pddl}"
  for f in "$d/domain.pddl" "$d/$stem-domain.pddl" "$d/domain_$stem.pddl" "$d/domain-$stem.pddl"; do
    [ -f "$f" ] && { echo "$f"; return; }
  done
}

# Fields of one `clips plan --json` answer: status, cost, expanded.
fields() {
  python3 -c '
import json, sys
try:
    j = json.loads(sys.stdin.read().strip().splitlines()[-1])
except Exception:
    print("\t\t"); sys.exit(0)
if "actions" in j:
    print("%s\t%s\t%s" % (j.get("status", ""), j.get("actions", ""), j.get("atoms", "")))
else:
    print("%s\t%g\t%s" % (j.get("status", ""), j.get("cost", 0), j.get("expanded", "")))'
}

tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
if [ "$ground" = 1 ]; then
  printf 'domain\tproblem\tstatus\tactions\tatoms\tseconds\tcpu\tmessage\n' >"$out"
else
  printf 'domain\tproblem\tstatus\tcost\texpanded\tseconds\tcpu\tfd_status\tfd_cost\tfd_seconds\tverdict\tmessage\n' >"$out"
fi
total=0 ok=0 fd_solved=0 both=0 ours_t=0 fd_t=0 missed=""
# Tabs are whitespace to read, which would merge an empty fd_cost with the
# next field: read the table with the unit separator instead.
while IFS=$'\037' read -r dom prob search fd_status fd_cost fd_secs; do
  [ "$dom" = domain ] && continue
  [ -n "$only" ] && ! [[ "$dom" =~ $only ]] && continue
  dir="$ipc/$dom"
  probs=("$prob")
  if [ "$ground" = 1 ]; then
    second="$(cd "$dir" && ls *.pddl | grep -v -i domain | grep -v -x "$prob" | sort | head -1)"
    [ -n "$second" ] && probs+=("$second")
  fi
  for p in "${probs[@]}"; do
    dfile="$(domain_of "$dir" "$p")"
    total=$((total + 1))
    t0=$(date +%s.%N)
    extra=()
    [ "$ground" = 1 ] && extra=(--ground-only)
    /usr/bin/time -f "%U %S" -o "$tmp/cpu" timeout $((seconds + 10)) "$clips" plan --domain "$dfile" \
      --problem "$dir/$p" --json --max-seconds "$seconds" "${extra[@]}" >"$tmp/out" 2>"$tmp/err"
    rc=$?
    t1=$(date +%s.%N)
    secs=$(python3 -c "print('%.2f' % ($t1 - $t0))")
    cpu=$(awk 'NF == 2 && $1 ~ /^[0-9.]+$/ { printf "%.2f", $1 + $2 }' "$tmp/cpu")
    IFS=$'\t' read -r status cost expanded < <(fields <"$tmp/out")
    [ -z "$status" ] && status="exit$rc"
    msg="$(grep -v '^$' "$tmp/err" | tail -1 | cut -c1-160 | tr '\t' ' ')"
    if [ "$ground" = 1 ]; then
      [ "$status" = grounded ] && ok=$((ok + 1)) || missed="$missed $dom/$p"
      printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$dom" "$p" "$status" "$cost" "$expanded" "$secs" "$cpu" "$msg" >>"$out"
      continue
    fi
    verdict=""
    if [ "$fd_status" = solved ]; then
      fd_solved=$((fd_solved + 1))
      if [ "$status" = success ] && python3 -c "import sys; sys.exit(abs($cost - $fd_cost) > 1e-6)"; then
        verdict=same; both=$((both + 1)); ok=$((ok + 1))
        ours_t=$(python3 -c "print($ours_t + $secs)"); fd_t=$(python3 -c "print($fd_t + $fd_secs)")
      elif [ "$status" = success ]; then
        verdict=WRONG-COST; missed="$missed $dom"
      else
        verdict=MISSED; missed="$missed $dom"
      fi
    elif [ "$status" = success ]; then
      verdict=only-clips; ok=$((ok + 1))
    fi
    printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$dom" "$p" "$status" "$cost" "$expanded" "$secs" \
      "$cpu" "$fd_status" "$fd_cost" "$fd_secs" "$verdict" "$msg" >>"$out"
  done
done < <(tr '\t' '\037' <"$ref")
if [ "$ground" = 1 ]; then
  echo "ipc-bench: $ok of $total problems parsed and grounded${missed:+; not:$missed}" >&2
  [ "$ok" = "$total" ]
else
  echo "ipc-bench: clips solved $ok of $total first problems; Fast Downward $fd_solved (reference.tsv);" \
       "both with the same cost: $both, clips ${ours_t}s vs Fast Downward ${fd_t}s on them${missed:+; missed:$missed}" >&2
  [ "$both" = "$fd_solved" ]
fi
