#!/usr/bin/env bash
# Runs every libFuzzer target of a fuzz build for a bounded time each.
#   fuzz/run.sh BUILD_DIR SECONDS_PER_TARGET
# Each target starts from its seed corpus (fuzz/corpus/<target>/, copied to BUILD_DIR so the
# inputs it adds stay out of the source tree). An input that crashes, hangs (> 10 s) or leaks is
# written to fuzz/regressions/<target>/, where the replay test (ctest fuzz_replay_<target>) picks
# it up: commit it with the fix. Exit status 1 if any target found something.
set -uo pipefail
cd "$(dirname "$0")/.."
build=${1:-build-fuzz}
seconds=${2:-60}
status=0
for exe in "$build"/fuzz/fuzz_*; do
  [ -x "$exe" ] || continue
  name=${exe##*/fuzz_}
  case $name in replay_*) continue ;; esac
  corpus="$build/fuzz-corpus/$name"
  mkdir -p "$corpus" "fuzz/regressions/$name"
  echo "fuzz: $name for $seconds s (seed corpus fuzz/corpus/$name, working corpus $corpus)"
  before=$(ls "fuzz/regressions/$name" | wc -l)
  "$exe" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=4096 -max_len=16384 \
    -print_final_stats=1 -artifact_prefix="fuzz/regressions/$name/" \
    "$corpus" "fuzz/corpus/$name" > "$build/fuzz-$name.log" 2>&1
  rc=$?
  after=$(ls "fuzz/regressions/$name" | wc -l)
  grep -E "^stat::number_of_executed_units|^stat::new_units_added|^#[0-9]+.*DONE" "$build/fuzz-$name.log" | sed 's/^/  /'
  if [ $rc -ne 0 ] || [ "$after" -ne "$before" ]; then
    echo "fuzz: $name FOUND a failing input (exit $rc): see $build/fuzz-$name.log and fuzz/regressions/$name/"
    status=1
  else
    echo "fuzz: $name: no finding"
  fi
done
exit $status
