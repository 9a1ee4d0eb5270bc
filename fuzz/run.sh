#!/usr/bin/env bash
# Runs libFuzzer targets one after the other (one process each: -jobs/-workers
# are left at 1), each for SECONDS (and at most RUNS executions when set).
# New inputs are merged into the scratch corpus BUILD/corpus/<name>/ (the seeds
# in fuzz/corpus/ are only read); crashers land in BUILD/artifacts/<name>/,
# logs in BUILD/logs/<name>.log. Exits non-zero if any target failed.
# FUZZ_TIMEOUT (default 1) is libFuzzer's -timeout: wall-clock seconds per
# input, so on a machine busy with other work raise it, then replay the
# corpus with the default to check.
#   fuzz/run.sh BUILD SECONDS [RUNS] [TARGET...]
set -uo pipefail
build=$1 seconds=$2 runs=${3:-0}
shift $(( $# >= 3 ? 3 : $# ))
fuzz_dir=$(cd "$(dirname "$0")" && pwd)
targets=("$@")
if [ ${#targets[@]} -eq 0 ]; then
  # The fast targets first; serve (built by `make fuzz` only) last.
  targets=(sexpr chat completions dataset goalset pack pack_roles cost_profiles quantified_goals plan utterance pddl serve
           stdio bench_merge)
fi
mkdir -p "$build/logs"
status=0
for t in "${targets[@]}"; do
  mkdir -p "$build/corpus/$t" "$build/artifacts/$t"
  args=("$build/corpus/$t" "$fuzz_dir/corpus/$t" -max_total_time="$seconds" -rss_limit_mb=2048 -timeout="${FUZZ_TIMEOUT:-1}"
        -artifact_prefix="$build/artifacts/$t/" -print_final_stats=1)
  [ "$runs" -gt 0 ] && args+=(-runs="$runs")
  case $t in
    sexpr|pddl|plan|quantified_goals) args+=(-dict="$fuzz_dir/dict/pddl.dict") ;;
    serve) args+=(-dict="$fuzz_dir/dict/serve.dict") ;;
    stdio) args+=(-dict="$fuzz_dir/dict/stdio.dict") ;;
    goalset) args+=(-dict="$fuzz_dir/dict/goalset.dict") ;;
    pack|pack_roles|cost_profiles) args+=(-dict="$fuzz_dir/dict/pack.dict") ;;
    bench_merge) args+=(-dict="$fuzz_dir/dict/bench_merge.dict") ;;
  esac
  echo "fuzz: $build/${t}_fuzz ${args[*]}" | tee "$build/logs/$t.log"
  if "$build/${t}_fuzz" "${args[@]}" >>"$build/logs/$t.log" 2>&1; then
    result=ok
  else
    result=FAILED status=1
  fi
  execs=$(grep -o 'number_of_executed_units: *[0-9]*' "$build/logs/$t.log" | grep -o '[0-9]*$')
  speed=$(grep -o 'average_exec_per_sec: *[0-9]*' "$build/logs/$t.log" | grep -o '[0-9]*$')
  cov=$(grep -o 'cov: [0-9]*' "$build/logs/$t.log" | tail -1 | grep -o '[0-9]*$')
  echo "fuzz: $t $result: ${execs:-?} execs, ${speed:-?} exec/s, cov ${cov:-?} edges (log $build/logs/$t.log)"
done
exit $status
