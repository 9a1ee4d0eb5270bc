#!/usr/bin/env bash
# A few seconds of libFuzzer per target, for the normal test suite (CTest
# FuzzSmoke). Exits 77 (skipped) when clang-14/libFuzzer are not installed or
# the targets are not built (`make fuzz-build` builds them; `make test` does
# so when clang-14 is installed). New inputs go to a temporary folder, never
# into the seeds. TARGET... (default: every fuzz/*_fuzz.cpp) are the targets
# run; CTest passes the ones `make fuzz-build` builds.
#   fuzz/smoke.sh BUILD_FUZZ_DIR FUZZ_DIR [SECONDS [TARGET...]]
set -uo pipefail
bin_dir=$1 fuzz_dir=$2 seconds=${3:-2}
shift $(( $# >= 3 ? 3 : $# ))
if ! command -v clang++-14 >/dev/null || ! ls /usr/lib/llvm-14/lib/clang/*/lib/linux/libclang_rt.fuzzer-x86_64.a >/dev/null 2>&1; then
  echo "FuzzSmoke: clang-14 / libFuzzer not installed; skipped"; exit 77
fi
if [ $# -gt 0 ]; then
  targets="$*"
else
  targets=$(ls "$fuzz_dir"/*_fuzz.cpp | xargs -n1 basename | sed 's/_fuzz\.cpp$//')
fi
for t in $targets; do
  if [ ! -x "$bin_dir/${t}_fuzz" ]; then
    echo "FuzzSmoke: $bin_dir/${t}_fuzz not built (make fuzz-build); skipped"; exit 77
  fi
done
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
status=0
for t in $targets; do
  mkdir -p "$scratch/$t"
  dict=()
  case $t in
    pddl|sexpr|plan|quantified_goals) dict=(-dict="$fuzz_dir/dict/pddl.dict") ;;
    pack|pack_roles|cost_profiles) dict=(-dict="$fuzz_dir/dict/pack.dict") ;;
  esac
  [ "$t" = goalset ] && dict=(-dict="$fuzz_dir/dict/goalset.dict")
  if ! "$bin_dir/${t}_fuzz" "$scratch/$t" "$fuzz_dir/corpus/$t" "${dict[@]}" -max_total_time="$seconds" \
      -rss_limit_mb=2048 -timeout=1 -artifact_prefix="$scratch/$t/" -print_final_stats=1 \
      >"$scratch/$t.log" 2>&1; then
    echo "FuzzSmoke: $t FAILED"; tail -40 "$scratch/$t.log"; status=1
  else
    echo "FuzzSmoke: $t ok ($(grep -o 'stat::number_of_executed_units: *[0-9]*' "$scratch/$t.log" | grep -o '[0-9]*$') runs)"
  fi
done
exit $status
