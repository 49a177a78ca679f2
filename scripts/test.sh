#!/usr/bin/env bash
# Sets up and builds shadelab, then runs everything CI runs, in this order:
#   1. formatting (.clang-format) of src/, include/ and tests/
#   2. the browser build (scripts/web.sh build), the release build (warnings are errors) and the whole
#      test suite: CPU tests, GL tests on every headless backend (EGL with OpenGL and with OpenGL ES,
#      OSMesa), the command line end to end, the demo window under Xvfb, the page in headless Chromium
#   3. clang-tidy (.clang-tidy) on src/
#   4. a Debug build with AddressSanitizer + UndefinedBehaviorSanitizer running the whole suite again
#      (LeakSanitizer on; only Mesa's and the system GL stack's own allocations are suppressed)
#   5. the fuzzers for a fixed budget (scripts/fuzz.sh), when present
# Extra arguments go to every ctest run (e.g. -R cpu.). SHADELAB_QUICK=1 stops after step 2.
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=$(nproc)
SHADELAB_CMAKE_ARGS="-DSHADELAB_WERROR=ON" scripts/setup.sh
stage() { printf '\n=== %s\n' "$*"; }

stage "browser build (WebGL 2, emscripten)"
scripts/web.sh build

stage "format check (clang-format)"
git ls-files 'src/*.cpp' 'src/*.h' 'include/*.h' 'tests/*.cpp' 'tests/*.h' 'web/*.cpp' | xargs clang-format --dry-run --Werror

stage "tests (release build)"
ctest --test-dir build --output-on-failure -j"$jobs" "$@"
[ "${SHADELAB_QUICK:-}" = 1 ] && exit 0

stage "clang-tidy"
git ls-files 'src/*.cpp' | xargs -P"$jobs" -n1 clang-tidy -p build --quiet

stage "tests under AddressSanitizer + UndefinedBehaviorSanitizer (debug build)"
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=Debug -DSHADELAB_SANITIZE=ON -DSHADELAB_WERROR=ON >/dev/null
cmake --build build-asan -j"$jobs"
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:strict_string_checks=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
export LSAN_OPTIONS="suppressions=$PWD/tests/sanitizers/lsan.supp:print_suppressions=0"
ctest --test-dir build-asan --output-on-failure -j"$jobs" "$@"

if [ -x scripts/fuzz.sh ]; then
  stage "fuzzing"
  scripts/fuzz.sh
fi
stage "all stages passed"
