#!/usr/bin/env bash
# Runs every libFuzzer target in BUILD_DIR (or those FUZZ_TARGETS names, e.g. "nome obj") for SECONDS
# each and prints its execution count; FUZZ_JOBS targets at a time (default 1).
# Seeds: the example files in assets/, the bad-input catalogue, tests/data/fuzz/seeds/<format>/ and the
# checked-in regressions in tests/data/fuzz/<target>/. The corpus grows in BUILD_DIR/corpus/<target>;
# crashes, hangs (-timeout, default 1 s) and leaks land in BUILD_DIR/artifacts/<target>/.
set -uo pipefail
build=${1:?usage: run_fuzzers.sh BUILD_DIR SECONDS}
seconds=${2:-60}
timeout=${FUZZ_TIMEOUT:-1}
jobs=${FUZZ_JOBS:-1}
root=$(cd "$(dirname "$0")/../.." && pwd)

# Prints one line for the target (and the first lines of any report); exit status: the fuzzer's.
run_one() {
  local fuzzer=$1 name format corpus seeds artifacts max_len log status runs
  name=$(basename "$fuzzer")
  format=${name%_fuzzer}
  corpus=$build/corpus/$name
  seeds=$build/seeds/$name
  artifacts=$build/artifacts/$name
  mkdir -p "$corpus" "$seeds" "$artifacts"
  case $format in
    polygon_soup | pick | pipeline | zipper) max_len=1024 ;;
    save_reload) max_len=16384; cp "$root"/assets/*.nome "$seeds"/ ;;
    anom_scene) max_len=16384; cp "$root"/tests/data/bad/*.anom "$seeds"/ ;;
    *) max_len=16384
       cp "$root"/assets/*."$format" "$root"/tests/data/bad/*."$format" "$seeds"/ 2>/dev/null
       ;;
  esac
  cp "$root"/tests/data/fuzz/seeds/"$format"/* "$seeds"/ 2>/dev/null
  cp "$root"/tests/data/fuzz/"$name"/* "$seeds"/ 2>/dev/null
  log=$build/$name.log
  "$fuzzer" -max_total_time="$seconds" -timeout="$timeout" -rss_limit_mb=2048 -max_len="$max_len" \
    -print_final_stats=1 -artifact_prefix="$artifacts"/ "$corpus" "$seeds" >"$log" 2>&1
  status=$?
  runs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$')
  echo "$name: ${runs:-?} executions in ${seconds} s, corpus $(ls "$corpus" | wc -l) files, exit $status"
  [ "$status" -eq 0 ] || grep -m3 -E 'ERROR|SUMMARY|Test unit written' "$log"
  return "$status"
}

failed_mark=$build/.fuzz_failed
rm -f "$failed_mark"
targets=()
if [ -n "${FUZZ_TARGETS:-}" ]; then
  for t in $FUZZ_TARGETS; do targets+=("$build/tests/fuzz/${t}_fuzzer"); done
else
  targets=("$build"/tests/fuzz/*_fuzzer)
fi
for fuzzer in "${targets[@]}"; do
  [ -x "$fuzzer" ] || { echo "no fuzz target $fuzzer"; touch "$failed_mark"; continue; }
  while [ "$(jobs -rp | wc -l)" -ge "$jobs" ]; do wait -n; done
  { run_one "$fuzzer" || touch "$failed_mark"; } &
done
wait
[ ! -e "$failed_mark" ]
