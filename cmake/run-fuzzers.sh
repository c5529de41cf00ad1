#!/usr/bin/env bash
# Runs the readers' fuzz targets (tests/fuzz, built by `make fuzz` in BUILD) from the committed
# corpus, with the sanitizers' options; new inputs go to BUILD/scratch/, failures to
# BUILD/findings/ (and the script exits non-zero).
#   run-fuzzers.sh BUILD SECONDS   explore: each target for SECONDS (make fuzz)
#   run-fuzzers.sh BUILD ci        a fixed seed and a fixed number of inputs per target (make
#                                  test): the same inputs on every machine, so a CI failure is a
#                                  regression that reproduces, never bad luck
set -euo pipefail
build=$1
mode=$2
root="$(cd "$(dirname "$0")/.." && pwd)"
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
export LSAN_OPTIONS=suppressions=$root/tests/fuzz/lsan.supp
# Inputs per target in ci mode: ~30 s each on one core (12,900 scenes or ~200 snapshot files
# a second, each snapshot input being a file written and read).
declare -A ci_runs=([scene_reader]=400000 [snapshot_reader]=6000)
for reader in scene_reader snapshot_reader; do
  scratch="$build/scratch/$reader"
  rm -rf "$scratch"
  mkdir -p "$scratch" "$build/findings"
  if [ "$mode" = ci ]; then
    limit=(-seed=24 "-runs=${ci_runs[$reader]}")
  else
    limit=("-max_total_time=$mode")
  fi
  echo "ejecta: fuzzing the $reader (${limit[*]})"
  "$build/tests/fuzz/fuzz_$reader" "${limit[@]}" -timeout=10 -rss_limit_mb=2048 \
    -malloc_limit_mb=1024 -print_final_stats=1 -artifact_prefix="$build/findings/$reader-" \
    "$scratch" "$root/tests/fuzz/corpus/$reader" 2>"$build/fuzz_$reader.log" ||
    { tail -60 "$build/fuzz_$reader.log"; echo "ejecta: the $reader fuzzer failed; input in $build/findings/" >&2; exit 1; }
  grep -E "^Done|stat::number_of_executed_units|stat::new_units_added" "$build/fuzz_$reader.log" || true
done
