#!/usr/bin/env bash
# Sets up and builds shadelab, then runs everything CI runs, and prints how long each stage took (wall and
# CPU time):
#   1. setup: the Debian packages the build needs that are missing, then the release build (-O2 as the
#      program's own build, without debug information; warnings are errors). Beside it, at lower CPU
#      priorities, with the cores it leaves idle: the packages only the checks need (X, clang's tools,
#      emscripten, Chromium), then the browser build (scripts/web.sh build) and the sanitizer tree's build
#      (clang; -O1, the tests' own sources -O0)
#   2. from the release build on, beside the rest at the lowest priority: clang-tidy (.clang-tidy) on src/,
#      the fuzzers' build
#   3. formatting (.clang-format) of src/, include/, tests/, web/, fuzz/; every shell script put through
#      the shellcheck linter
#   4. the whole test suite on the release build: CPU tests, GL tests on every headless backend (EGL with
#      OpenGL and with OpenGL ES, OSMesa), the command line end to end, the demo window under Xvfb, the page
#      in headless Chromium
#   5. the permission-dropping tests again with the binary in a folder only root can enter, as a clone in
#      /root is; the program installed into an empty prefix runs the CI example (examples/ci/)
#   6. the suite under AddressSanitizer + UndefinedBehaviorSanitizer (+ LeakSanitizer; only Mesa's and the
#      system GL stack's own allocations are suppressed), built by clang at -O1 (the tests' own sources at
#      -O0, tests/CMakeLists.txt): the CPU, command-line, window and EGL + OpenGL tests whole, and of the
#      OpenGL ES and OSMesa copies of the GL tests the ones that exercise those contexts' own code (the rest
#      is the same renderer code on the same driver). The page's tests are left out: the page is
#      WebAssembly, not built with the sanitizers.
#   7. the fuzzers for a fixed budget (scripts/fuzz.sh)
# Extra arguments go to every ctest run (e.g. -R cpu.). SHADELAB_QUICK=1 builds no sanitizer tree, runs no
# clang-tidy, and stops after step 4.
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=$(nproc)
logs=$(mktemp -d "${TMPDIR:-/tmp}/shadelab-test-logs.XXXXXX")

declare -A pids starts # the background stages: process and start time, by name
cleanup=()             # files of the run's own, removed as it ends
# ---- stage timing: a table of every stage's duration, printed at the end, whether it passed or not ----
names=()
seconds=()
cpus=() # each stage's CPU seconds: its own processes' (a foreground stage's without the background stages')
began=$(date +%s)
stage_began=$began
stage_name=""
# Sets cpu_now to the CPU seconds (user + system) of the processes this shell has waited for: `times`' second
# line, through the file $1. `times` runs in this shell, never in a pipeline or $(...): a subshell's `times`
# counts only the subshell's own children.
children_cpu() {
  times >"$1"
  cpu_now=$(tail -n 1 "$1" | awk '{ split($1, a, /[ms]/); split($2, b, /[ms]/)
    printf "%d", a[1] * 60 + a[2] + b[1] * 60 + b[2] }')
}
stage_cpu_began=0
background_cpu=0 # the CPU seconds of background stages waited for during the current stage
stage() {
  local now cpu
  now=$(date +%s)
  children_cpu "$logs/times"
  cpu=$cpu_now
  if [ -n "$stage_name" ]; then
    names+=("$stage_name")
    seconds+=($((now - stage_began)))
    cpus+=($((cpu - stage_cpu_began - background_cpu)))
  fi
  stage_name=$1
  stage_began=$now
  stage_cpu_began=$cpu
  background_cpu=0
  [ -n "$1" ] && printf '\n=== %s\n' "$1"
  return 0
}
# A stage that ran beside others: its own start and end, and its CPU seconds.
background_stage() {
  names+=("$1 (beside the others)")
  seconds+=($(($3 - $2)))
  cpus+=("$4")
  background_cpu=$((background_cpu + $4))
}
# A background stage still running when the script ends (a failure elsewhere) ends with it, children first.
kill_tree() {
  local child
  for child in $(ps -o pid= --ppid "$1" 2>/dev/null); do kill_tree "$child"; done
  kill "$1" 2>/dev/null || true
}
print_table() {
  local status=$?
  local pid
  for pid in "${pids[@]}"; do kill_tree "$pid"; done
  rm -f "${cleanup[@]}"
  stage ""
  printf '\n=== stage durations (%s, %s cores)\n' "$(date -u +%Y-%m-%dT%H:%MZ)" "$jobs"
  printf '%-72s %7s %7s\n' "" "wall" "CPU"
  for i in "${!names[@]}"; do
    printf '%-72s %4d:%02d %4d:%02d\n' "${names[$i]}" $((seconds[i] / 60)) $((seconds[i] % 60)) \
      $((cpus[i] / 60)) $((cpus[i] % 60))
  done
  # The processes' CPU time (user + system, the background stages' too), against the wall time of all cores.
  local total=$(($(date +%s) - began)) cpu
  children_cpu "$logs/times"
  cpu=$cpu_now
  printf '%-72s %4d:%02d %4d:%02d\n' "total ($jobs cores: the CPU time is at most $jobs× the wall time)" \
    $((total / 60)) $((total % 60)) $((cpu / 60)) $((cpu % 60))
  [ "$status" -eq 0 ] || printf 'FAILED (exit %d) in: %s\n' "$status" "${names[-1]:-setup}"
}
trap print_table EXIT

# Runs a command in the background at a lower CPU priority (the nice value NICE, 19 for the lowest), its
# output to $logs/NAME.log; `finish NAME` waits for it, prints its log if it failed, and records its duration.
#   in_background NAME NICE COMMAND...
in_background() {
  local name=$1 niceness=$2
  shift 2
  starts[$name]=$(date +%s)
  # A subshell that lowers its own priority, so that it can run this script's functions (nice cannot).
  # Its CPU seconds go to $logs/NAME.cpu (`times` in the subshell counts the subshell's children).
  (
    renice -n "$niceness" -p "$BASHPID" >/dev/null
    status=0
    "$@" || status=$?
    children_cpu "$logs/$name.times"
    echo "$cpu_now" >"$logs/$name.cpu"
    exit "$status"
  ) >"$logs/$name.log" 2>&1 &
  pids[$name]=$!
}
finish() {
  local name=$1 status=0
  wait "${pids[$name]}" || status=$?
  unset "pids[$name]"
  background_stage "$name" "${starts[$name]}" "$(date +%s)" "$(cat "$logs/$name.cpu" 2>/dev/null || echo 0)"
  if [ "$status" -ne 0 ]; then
    echo "shadelab: $name failed (exit $status); its log ($logs/$name.log):"
    tail -n 200 "$logs/$name.log"
    exit "$status"
  fi
}

# Built by clang (the fuzzers' compiler, installed with the checks' packages) and linked by lld, at -O1 (what
# AddressSanitizer's own documentation asks for): the suite under the sanitizers takes about 3 minutes instead
# of 6:57 with everything at -O0. The tests' own sources are built at -O0 all the same (tests/CMakeLists.txt:
# a third of their -O1 compile time, the suite as long), and clang compiles this tree in half gcc's time.
# A second compiler's warnings are errors here too, beside the release tree's gcc (and clang's
# -Wreserved-identifier, CMakeLists.txt). Line tables only (-g1): the sanitizers' reports name file and line.
build_asan() {
  # A tree configured by another compiler is made anew: CMake keeps a tree's compiler.
  local cache=build-asan/CMakeCache.txt
  if [ -f "$cache" ] && ! grep -q '^CMAKE_CXX_COMPILER:.*clang++' "$cache"; then rm -rf build-asan; fi
  cmake -S . -B build-asan -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=Debug \
    -DSHADELAB_SANITIZE=ON -DSHADELAB_WERROR=ON -DCMAKE_EXE_LINKER_FLAGS=-fuse-ld=lld \
    -DCMAKE_SHARED_LINKER_FLAGS=-fuse-ld=lld "-DCMAKE_CXX_FLAGS_DEBUG=-O1 -g1" \
    "-DCMAKE_C_FLAGS_DEBUG=-O1 -g1" &&
    cmake --build build-asan -j"$jobs"
}
build_fuzzers() {
  cmake -S fuzz -B build-fuzz -DCMAKE_CXX_COMPILER=clang++ && cmake --build build-fuzz -j"$jobs"
}
# The checks' packages install beside the release build; what needs them waits for them (their exit status
# in $logs/packages.status), then runs.
install_tools() {
  local status=0
  scripts/setup.sh --install tools || status=$?
  echo "$status" >"$logs/packages.status"
  return "$status"
}
after_packages() {
  until [ -e "$logs/packages.status" ]; do sleep 1; done
  if [ "$(cat "$logs/packages.status")" != 0 ]; then
    echo "the checks' packages did not install (their log: checks' packages)"
    return 1
  fi
  "$@"
}

stage "setup: the build's packages, then the release build (the checks' packages, the browser build and the sanitizer build beside it)"
scripts/setup.sh --install program,tests
# The whole run is CPU-bound: what fills an idle core shortens it. The release build leaves cores idle
# (configuring, a precompiled header or a large link that the rest waits for), and these fill them at lower
# priorities: the packages, then the browser build (the page's tests need it with the release suite), then
# the sanitizer tree (its suite runs after the release suite).
in_background "checks' packages" 10 install_tools
in_background "browser build" 5 after_packages scripts/web.sh build
[ "${SHADELAB_QUICK:-}" = 1 ] || in_background "sanitizer build" 10 after_packages build_asan
# -O2 as the program's own build, without its debug information (a third of the compile time); warnings are
# errors. The tests' own sources at -O1 (tests/CMakeLists.txt): 206 CPU-s instead of 296, the suite as fast.
# Linked with gold (binutils, as ld): a third less time than ld.bfd for the large test executables.
SHADELAB_BUILD_TYPE=Release scripts/setup.sh --build -- -DSHADELAB_WERROR=ON \
  -DCMAKE_EXE_LINKER_FLAGS=-fuse-ld=gold -DCMAKE_SHARED_LINKER_FLAGS=-fuse-ld=gold \
  "-DCMAKE_CXX_FLAGS_RELEASE=-O2 -DNDEBUG" "-DCMAKE_C_FLAGS_RELEASE=-O2 -DNDEBUG" -DSHADELAB_TEST_OPTIMIZATION=-O1
finish "checks' packages"

# clang-tidy (on the release tree's compile database) and the fuzzers' build need nothing else: they take
# what the release suite and the sanitizer build leave idle.
if [ "${SHADELAB_QUICK:-}" != 1 ]; then
  in_background "clang-tidy" 19 bash -c "git ls-files 'src/*.cpp' | xargs -P$jobs -n1 clang-tidy -p build --quiet"
  in_background "fuzzers' build" 19 build_fuzzers
fi

stage "browser build (what the release build left)"
finish "browser build"

stage "format check (clang-format) and the shell scripts' check (shellcheck)"
git ls-files 'src/*.cpp' 'src/*.h' 'include/*.h' 'tests/*.cpp' 'tests/*.h' 'web/*.cpp' 'web/*.h' 'fuzz/*.cpp' |
  xargs clang-format --dry-run --Werror
git ls-files '*.sh' .ci/run | xargs shellcheck

stage "tests (release build)"
# The window and page tests first: they wait on Xvfb and Chromium, so -j overlaps them with the rest.
ctest --test-dir build --output-on-failure -j"$jobs" -L 'web|window' "$@"
ctest --test-dir build --output-on-failure -j"$jobs" -LE 'web|window' "$@"
[ "${SHADELAB_QUICK:-}" = 1 ] && exit 0

stage "permission-dropping tests, the binary in a folder only root can enter"
if [ "$(id -u)" -eq 0 ]; then
  # mktemp -d makes the folder 0700, as /root is: nobody cannot reach anything beneath it.
  private=$(mktemp -d)
  cp build/shadelab "$private/"
  SHADELAB_TEST_EXE="$private/shadelab" build/tests/output_safety_test --gtest_brief=1
  rm -rf "$private"
else
  echo "skipped: not root (the tests switch to uid 65534, which needs root)"
fi

stage "the CI example (examples/ci/) run by the program installed into an empty prefix"
# The installed program alone (its shaders, font and scenes are compiled in) and the example's installed
# copy, run from outside the checkout, as README "Screenshot regression in your CI" describes.
prefix=$(mktemp -d)
cmake --install build --prefix "$prefix" >/dev/null
(cd "$prefix" && PATH="$prefix/bin:$PATH" share/doc/shadelab/examples/ci/screenshot-regression.sh \
  --artifacts "$prefix/artifacts")
rm -rf "$prefix"

stage "sanitizer build (what the release tests left)"
finish "sanitizer build"
stage "tests under AddressSanitizer + UndefinedBehaviorSanitizer (clang; -O1, the tests' code -O0)"
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:strict_string_checks=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
# The suppressions from a file every user can read: the permission-dropping tests run the program as nobody,
# whose sanitizer runtime reads them as it starts and stops there if it cannot (a clone in /root is 0700).
suppressions=$(mktemp /tmp/shadelab-lsan.XXXXXX)
cleanup+=("$suppressions")
cp tests/sanitizers/lsan.supp "$suppressions"
chmod 644 "$suppressions"
export LSAN_OPTIONS="suppressions=$suppressions:print_suppressions=0"
# The window tests and the longest ones first (a report interrupted four times, a 1500x1500 reference three
# times), so the last minutes are not one long test on one core. These run one ctest test per test; every
# other executable runs whole, one process for all of its tests (SHADELAB_TESTS_PER_EXECUTABLE,
# tests/CMakeLists.txt): a quarter less CPU time under the sanitizers (284 CPU-s instead of 375 here, 152 s instead of 209).
slow='^(window\.|cli\.report\.ReportCli\.InterruptedRun|cli\.output\..*SignalDuringWrite)'
ctest --test-dir build-asan --output-on-failure -j"$jobs" -R "$slow" "$@"
# The CPU, command-line and EGL + OpenGL executables whole; of the OpenGL ES and OSMesa copies of the GL
# tests, the references, the specialized programs and depth precision: those contexts' own code and the ES
# shader path, once each under the sanitizers.
ctest --test-dir build-asan --output-on-failure -j"$jobs" -E "$slow" \
  -R '^((cpu|cli|egl|gl)\..*|(gles|osmesa)\.gl_(references|specialization|depth_precision)_test)$' "$@"
# A test skipped inside an executable run whole leaves the executable passed: every skipped test of this
# run, each after its reason, is named here.
skipped=$(grep -h -B2 '^\[  SKIPPED \] [A-Za-z].* ([0-9]* ms)$' build-asan/Testing/Temporary/LastTest.log |
  grep -v '^--$' || true)
if [ -n "$skipped" ]; then
  echo "skipped (each after its reason):"
  echo "$skipped"
fi
unset ASAN_OPTIONS UBSAN_OPTIONS LSAN_OPTIONS

stage "clang-tidy (what the sanitizer tests left)"
finish "clang-tidy"
finish "fuzzers' build"

stage "fuzzing"
scripts/fuzz.sh

stage "all stages passed"
