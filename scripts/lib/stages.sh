# shellcheck shell=bash
# shellcheck disable=SC2154 # $jobs and $logs are set by scripts/test.sh, which sources this file
# What scripts/test.sh's stages run (sourced by it, after scripts/lib/schedule.sh): the builds, the checks
# and the suites, each a function, in the order the stages call them.

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
    -DSHADELAB_SANITIZE=ON -DSHADELAB_WERROR=ON -DSHADELAB_UNITY_BUILD=ON -DCMAKE_EXE_LINKER_FLAGS=-fuse-ld=lld \
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


# -O2 as the program's own build, without its debug information (a third of the compile time); warnings are
# errors. The tests' own sources at -O1 (tests/CMakeLists.txt): 206 CPU-s instead of 296, the suite as fast.
# Linked with gold (binutils, as ld): a third less time than ld.bfd for the large test executables.
release_build() {
  SHADELAB_BUILD_TYPE=Release scripts/setup.sh --build -- -DSHADELAB_WERROR=ON \
    -DCMAKE_EXE_LINKER_FLAGS=-fuse-ld=gold -DCMAKE_SHARED_LINKER_FLAGS=-fuse-ld=gold \
    "-DCMAKE_CXX_FLAGS_RELEASE=-O2 -DNDEBUG" "-DCMAKE_C_FLAGS_RELEASE=-O2 -DNDEBUG" -DSHADELAB_TEST_OPTIMIZATION=-O1
}

clang_tidy() {
  git ls-files 'src/*.cpp' | xargs -P"$jobs" -n1 clang-tidy -p build --quiet
}

format_check() {
  git ls-files 'src/*.cpp' 'src/*.h' 'include/*.h' 'tests/*.cpp' 'tests/*.h' 'web/*.cpp' 'web/*.h' 'fuzz/*.cpp' |
    xargs clang-format --dry-run --Werror
  git ls-files '*.sh' .ci/run | xargs shellcheck -x
}

# The window and page tests first: they wait on Xvfb and Chromium, so -j overlaps them with the rest.
release_tests() {
  ctest --test-dir build --output-on-failure -j"$jobs" -L 'web|window' "$@"
  ctest --test-dir build --output-on-failure -j"$jobs" -LE 'web|window' "$@"
}

permission_tests() {
  if [ "$(id -u)" -ne 0 ]; then
    echo "skipped: not root (the tests switch to uid 65534, which needs root)"
    return 0
  fi
  # mktemp -d makes the folder 0700, as /root is: nobody cannot reach anything beneath it.
  local private
  private=$(mktemp -d)
  cp build/shadelab "$private/"
  SHADELAB_TEST_EXE="$private/shadelab" build/tests/output_safety_test --gtest_brief=1
  rm -rf "$private"
}

# The installed program alone (its shaders, font and scenes are compiled in) and the example's installed
# copy, run from outside the checkout with the arguments examples/ci/gitlab-ci.yml and github-actions.yml
# give it, as docs/ci-engineers.md "Screenshot regression in your CI" describes; the JUnit must be written.
ci_example() {
  local prefix
  prefix=$(mktemp -d)
  cmake --install build --component program --prefix "$prefix" >/dev/null
  (cd "$prefix" && PATH="$prefix/bin:$PATH" share/doc/shadelab/examples/ci/screenshot-regression.sh \
    --artifacts screenshot-artifacts --junit screenshot-artifacts/junit.xml &&
    test -s screenshot-artifacts/junit.xml)
  rm -rf "$prefix"
}

# The independent implementations the image metrics are held to (tests/compare/independent/): pixelmatch at
# its pinned version, by npm ci, before the suite that runs them.
independent_comparisons() {
  local install=tests/compare/independent/install.sh
  if [ ! -x "$install" ]; then
    echo "skipped: no $install yet"
    return 0
  fi
  "$install"
}

# The light install's Debian package (cpack -G DEB) installed in a fresh Debian 12 root and run there; the
# root is made by debootstrap and entered by chroot, which need root, as the permission tests do.
deb_install() {
  if [ "$(id -u)" -ne 0 ]; then
    echo "skipped: not root (debootstrap and chroot need root)"
    return 0
  fi
  scripts/test-deb.sh build
}

sanitizer_tests() {
  export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:strict_string_checks=1
  export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
  # The suppressions from a file every user can read: the permission-dropping tests run the program as
  # nobody, whose sanitizer runtime reads them as it starts and stops there if it cannot (a clone in /root
  # is 0700).
  local suppressions slow skipped
  suppressions=$(mktemp /tmp/shadelab-lsan.XXXXXX)
  cleanup+=("$suppressions")
  cp tests/sanitizers/lsan.supp "$suppressions"
  chmod 644 "$suppressions"
  export LSAN_OPTIONS="suppressions=$suppressions:print_suppressions=0"
  # The window tests and the longest ones first (a report interrupted four times, a 1500x1500 reference
  # three times), so the last minutes are not one long test on one core. These run one ctest test per test;
  # every other executable runs whole, one process for all of its tests (SHADELAB_TESTS_PER_EXECUTABLE,
  # tests/CMakeLists.txt): a quarter less CPU time under the sanitizers (284 CPU-s instead of 375 here, 152 s
  # instead of 209).
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
}
