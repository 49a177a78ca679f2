#!/usr/bin/env bash
# Installs whatever shadelab needs that this Debian 12 machine lacks (as root, or through sudo), then
# configures and builds into build/. Safe to run again.
#   scripts/setup.sh               everything: the program, the tests and CI's tools (scripts/test.sh)
#   scripts/setup.sh --program     only what the program needs, and only the `shadelab` target (scripts/run.sh)
#   scripts/setup.sh --install SET[,SET...]
#                                  only installs the missing packages of these sets (program, tests, tools)
#   scripts/setup.sh --build [-- CMAKE_ARGS...]
#                                  only configures and builds everything (the packages must be there)
# After `--` (with no option, or --build), the rest goes to CMake's configure step, e.g.
# `scripts/setup.sh --build -- -DSHADELAB_WERROR=ON`.
set -euo pipefail
cd "$(dirname "$0")/.."

# The program: what `scripts/run.sh` installs.
program_packages=(
  # toolchain
  g++ cmake make ninja-build pkg-config ca-certificates
  # libraries, all found by find_package / pkg-config
  libglfw3-dev libglm-dev libegl-dev libegl-mesa0 libgl1-mesa-dri libosmesa6-dev libpng-dev
  nlohmann-json3-dev libcli11-dev libbenchmark-dev python3-glad libimgui-dev libstb-dev fonts-dejavu-core
  # the model readers (OBJ/MTL, glTF); their headers are also what the page compiles
  libtinyobjloader-dev libtinygltf-dev
  # `shadelab report`'s plot
  gnuplot-nox
)
# What building the tests needs on top.
tests_packages=(libgtest-dev libx11-dev git libxml2-utils python3-skimage python3-pil nodejs) # libxml2-utils: xmllint, the JUnit schema check; python3-skimage: the SSIM check; nodejs: pixelmatch, the perceptual check
# npm installs pixelmatch (tests/compare/independent/install.sh); NodeSource's nodejs bundles it and conflicts
# with Debian's npm package, so that is only asked for when no npm is there.
command -v npm >/dev/null || tests_packages+=(npm)
# What running the checks needs, none of it for the build: scripts/test.sh installs these beside the build.
tools_packages=(
  # the demo under a virtual display, and driving it in tests
  xvfb xauth xdotool
  # CI's checks: formatting, static analysis, the sanitizer tree (clang, its runtimes, lld) and fuzzing
  # (clang's libFuzzer)
  clang-format clang-tidy clang libclang-rt-14-dev lld-14 shellcheck
  # the page's build and its tests (scripts/web.sh installs them too)
  emscripten chromium chromium-driver python3-selenium
  # the Debian packages (cpack -G DEB computes Depends with dpkg-shlibdeps) and their install in a fresh
  # Debian 12 root (scripts/test-deb.sh)
  dpkg-dev debootstrap
)

die() {
  echo "setup.sh: $*" >&2
  exit 2
}

# Installs the packages named that are missing, in one apt transaction.
install_missing() {
  local missing=() p
  for p in "$@"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  ((${#missing[@]})) || return 0
  echo "shadelab: installing ${missing[*]}"
  local sudo=()
  [ "$(id -u)" -eq 0 ] || sudo=(sudo)
  # The package lists are read again unless this machine did so in the last hour (a second set installed
  # right after the first needs no second download of them).
  if [ -z "$(find /var/lib/apt/lists -maxdepth 1 -name '*_Packages*' -mmin -60 2>/dev/null | head -n 1)" ]; then
    "${sudo[@]}" apt-get update -qq
  fi
  DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
}

# The packages of the sets named (e.g. "program,tests"), into the array `packages`.
packages_of() {
  local set
  local -a sets
  IFS=, read -r -a sets <<<"$1"
  ((${#sets[@]})) || die "--install: no set named (the sets are program, tests and tools)"
  packages=()
  for set in "${sets[@]}"; do
    case $set in
      program) packages+=("${program_packages[@]}") ;;
      tests) packages+=("${tests_packages[@]}") ;;
      tools) packages+=("${tools_packages[@]}") ;;
      *) die "--install: unknown set '$set' (the sets are program, tests and tools)" ;;
    esac
  done
}

mode=all
case ${1:-} in
  --program | --build)
    mode=${1#--}
    shift
    ;;
  --install)
    [ $# -eq 2 ] || die "--install takes one argument, the sets (e.g. --install program,tests)"
    packages_of "$2"
    install_missing "${packages[@]}"
    exit 0
    ;;
  --) ;;
  "") ;;
  *) die "unknown option '$1' (the options are --program, --install SET[,SET...] and --build)" ;;
esac
[ "${1:-}" != -- ] || shift
[ "$mode" != program ] || [ $# -eq 0 ] || die "--program takes no CMake arguments"

build_args=()
configure_args=()
case $mode in
  program)
    install_missing "${program_packages[@]}"
    build_args=(--target shadelab)
    # Eight files to a compile (CMakeLists.txt: SHADELAB_UNITY_BUILD): the first window in half the time.
    configure_args=(-DSHADELAB_UNITY_BUILD=ON)
    # A first configure leaves the tests out, so GoogleTest need not be installed; a tree that has them keeps them.
    # It is Ninja's: it compiles a target's files while the libraries it links are still being built (make
    # waits for each library), and it does not run make's and CMake's dependency scans at every step.
    [ -f build/CMakeCache.txt ] || configure_args+=(-G Ninja -DSHADELAB_BUILD_TESTS=OFF)
    ;;
  all)
    install_missing "${program_packages[@]}" "${tests_packages[@]}" "${tools_packages[@]}"
    configure_args=(-DSHADELAB_BUILD_TESTS=ON -DSHADELAB_UNITY_BUILD=OFF)
    ;;
  build) configure_args=(-DSHADELAB_BUILD_TESTS=ON -DSHADELAB_UNITY_BUILD=OFF) ;; # clang-tidy reads each file
esac

build_type=${SHADELAB_BUILD_TYPE:-RelWithDebInfo}
cmake -S . -B build -DCMAKE_BUILD_TYPE="$build_type" "${configure_args[@]}" "$@"
cmake --build build -j"$(nproc)" "${build_args[@]}"
