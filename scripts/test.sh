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
#   4. pixelmatch at its pinned version from npm (the metrics' independent check), then the whole test
#      suite on the release build: CPU tests, GL tests on every headless backend (EGL with
#      OpenGL and with OpenGL ES, OSMesa), the command line end to end, the demo window under Xvfb, the page
#      in headless Chromium
#   5. the permission-dropping tests again with the binary in a folder only root can enter, as a clone in
#      /root is; the program installed into an empty prefix runs the CI example (examples/ci/) as the
#      GitLab and GitHub jobs do; the Debian package installed in a fresh Debian 12 root
#   6. the suite under AddressSanitizer + UndefinedBehaviorSanitizer (+ LeakSanitizer; only Mesa's and the
#      system GL stack's own allocations are suppressed), built by clang at -O1 (the tests' own sources at
#      -O0, tests/CMakeLists.txt): the CPU, command-line, window and EGL + OpenGL tests whole, and of the
#      OpenGL ES and OSMesa copies of the GL tests the ones that exercise those contexts' own code (the rest
#      is the same renderer code on the same driver). The page's tests are left out: the page is
#      WebAssembly, not built with the sanitizers.
#   7. the fuzzers for a fixed budget (scripts/fuzz.sh)
# Extra arguments go to every ctest run (e.g. -R cpu.). SHADELAB_QUICK=1 builds no sanitizer tree, runs no
# clang-tidy, and stops after step 4. The stages' scheduling is scripts/lib/schedule.sh, what each runs
# scripts/lib/stages.sh.
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=$(nproc)
logs=$(mktemp -d "${TMPDIR:-/tmp}/shadelab-test-logs.XXXXXX")
quick=${SHADELAB_QUICK:-}
# shellcheck source=scripts/lib/schedule.sh
. scripts/lib/schedule.sh
# shellcheck source=scripts/lib/stages.sh
. scripts/lib/stages.sh
trap print_table EXIT

stage "setup: the build's packages, then the release build (the checks' packages, the browser build and the sanitizer build beside it)"
scripts/setup.sh --install program,tests
# The whole run is CPU-bound: what fills an idle core shortens it. The release build leaves cores idle
# (configuring, a precompiled header or a large link that the rest waits for), and these fill them at lower
# priorities: the packages, then the browser build (the page's tests need it with the release suite), then
# the sanitizer tree (its suite runs after the release suite).
in_background "checks' packages" 10 install_tools
in_background "browser build" 5 after_packages scripts/web.sh build
[ "$quick" = 1 ] || in_background "sanitizer build" 10 after_packages build_asan
release_build
finish "checks' packages"
# clang-tidy (on the release tree's compile database) and the fuzzers' build need nothing else: they take
# what the release suite and the sanitizer build leave idle.
if [ "$quick" != 1 ]; then
  in_background "clang-tidy" 19 clang_tidy
  in_background "fuzzers' build" 19 build_fuzzers
fi

stage "browser build (what the release build left)"
finish "browser build"

stage "format check (clang-format) and the shell scripts' check (shellcheck)"
format_check

stage "the independent comparisons' packages (pixelmatch from npm, at its pinned version)"
independent_comparisons

stage "tests (release build)"
release_tests "$@"
[ "$quick" = 1 ] && exit 0

stage "permission-dropping tests, the binary in a folder only root can enter"
permission_tests

stage "the CI example (examples/ci/) run by the program installed into an empty prefix"
ci_example

stage "the Debian package installed in a fresh Debian 12 root"
deb_install

stage "sanitizer build (what the release tests left)"
finish "sanitizer build"
stage "tests under AddressSanitizer + UndefinedBehaviorSanitizer (clang; -O1, the tests' code -O0)"
sanitizer_tests "$@"

stage "clang-tidy (what the sanitizer tests left)"
finish "clang-tidy"
finish "fuzzers' build"

stage "fuzzing"
scripts/fuzz.sh

stage "all stages passed"
