#!/usr/bin/env bash
# Builds the libFuzzer targets of fuzz/ with clang and runs each for a fixed budget, all four at once on the
# two cores (60 s: the 2 CPU-minutes two fuzzers took, now 30 CPU-seconds each), printing how many inputs each
# executed. Exits non-zero if any found a crash, a leak, a timeout or a sanitizer report, after printing the
# report and the file that reproduces it.
#   scripts/fuzz.sh [seconds per fuzzer]      (default 60; SHADELAB_FUZZ_SECONDS also sets it)
# Needs the Debian packages clang and libclang-rt-14-dev (scripts/setup.sh installs them).
set -euo pipefail
cd "$(dirname "$0")/.."

seconds=${1:-${SHADELAB_FUZZ_SECONDS:-60}}
build=${SHADELAB_FUZZ_BUILD:-build-fuzz}
work=$build/run # grown corpora, logs and crash artifacts; kept between local runs

if ! command -v clang++ >/dev/null; then
  echo "fuzz: clang++ not found; install the Debian packages clang and libclang-rt-14-dev" >&2
  exit 1
fi
cmake -S fuzz -B "$build" -DCMAKE_CXX_COMPILER=clang++ >/dev/null
cmake --build "$build" -j"$(nproc)"

# name, extra seed folders, extra flags. The bundled scenes seed the scene fuzzer in place, the bundled
# lessons the lesson fuzzer (never copied,
# so a new bundled scene is a new seed). The command line gets long inputs from the start (-len_control=0):
# an argument longer than NAME_MAX (255) is what found the exists() bug of the mistyped subcommand.
run_fuzzer() {
  local name=$1 seeds=$2 flags=$3
  mkdir -p "$work/$name-corpus" "$work/artifacts"
  # shellcheck disable=SC2086 # seeds and flags are word lists
  "$build/${name}_fuzzer" -max_total_time="$seconds" -rss_limit_mb=2048 -timeout=10 -print_final_stats=1 \
    -dict="fuzz/$name.dict" -artifact_prefix="$work/artifacts/$name-" $flags \
    "$work/$name-corpus" "fuzz/corpus/$name" $seeds >"$work/$name.log" 2>&1
}

pids=()
run_fuzzer scene "scenes" "" &
pids+=($!)
run_fuzzer cli "" "-max_len=4096 -len_control=0" &
pids+=($!)
run_fuzzer lesson "lessons" "" &
pids+=($!)
run_fuzzer model "" "" &
pids+=($!)

status=0
names=(scene cli lesson model)
for i in "${!names[@]}"; do
  name=${names[$i]}
  if wait "${pids[$i]}"; then
    runs=$(sed -n 's/^stat::number_of_executed_units: //p' "$work/$name.log")
    corpus=$(find "$work/$name-corpus" -type f | wc -l)
    echo "fuzz: ${name}_fuzzer: ${runs:-?} executions in ${seconds} s, no crash (corpus: $corpus inputs)"
  else
    status=1
    echo "fuzz: ${name}_fuzzer FAILED; the end of its log ($work/$name.log):"
    tail -n 60 "$work/$name.log"
    artifact=$(sed -n 's/.*Test unit written to //p' "$work/$name.log" | tail -n 1)
    echo "fuzz: reproduce with: $build/${name}_fuzzer ${artifact:-<the artifact in $work/artifacts>}"
  fi
done
exit $status
