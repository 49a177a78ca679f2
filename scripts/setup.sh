#!/usr/bin/env bash
# Installs whatever shadelab needs that this Debian 12 machine lacks (as root, or through sudo), then
# configures and builds into build/. Safe to run again.
#   scripts/setup.sh             everything: the program, the tests and CI's tools (scripts/test.sh)
#   scripts/setup.sh --program   only what the program needs, and only the `shadelab` target (scripts/run.sh)
set -euo pipefail
cd "$(dirname "$0")/.."

program_packages=(
  # toolchain
  g++ cmake make pkg-config ca-certificates
  # libraries, all found by find_package / pkg-config
  libglfw3-dev libglm-dev libegl-dev libegl-mesa0 libgl1-mesa-dri libosmesa6-dev libpng-dev
  nlohmann-json3-dev libcli11-dev libbenchmark-dev python3-glad libimgui-dev libstb-dev fonts-dejavu-core
  # `shadelab report`'s plot
  gnuplot-nox
)
check_packages=(
  libgtest-dev
  # the demo under a virtual display, and driving it in tests
  xvfb xauth xdotool libx11-dev
  # CI's checks: formatting, static analysis, fuzzing (clang's libFuzzer)
  clang-format clang-tidy clang libclang-rt-14-dev git
  # the page's build and its tests (scripts/web.sh installs them too; here they share one apt transaction)
  emscripten chromium chromium-driver python3-selenium
)

packages=("${program_packages[@]}")
build_args=()
configure_args=()
if [ "${1:-}" = --program ]; then
  build_args=(--target shadelab)
  # A first configure leaves the tests out, so GoogleTest need not be installed; a tree that has them keeps them.
  [ -f build/CMakeCache.txt ] || configure_args=(-DSHADELAB_BUILD_TESTS=OFF)
else
  packages+=("${check_packages[@]}")
  configure_args=(-DSHADELAB_BUILD_TESTS=ON)
fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "shadelab: installing ${missing[*]}"
  sudo=()
  [ "$(id -u)" -eq 0 ] || sudo=(sudo)
  "${sudo[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

build_type=${SHADELAB_BUILD_TYPE:-RelWithDebInfo}
# shellcheck disable=SC2086 # SHADELAB_CMAKE_ARGS is a list of arguments
cmake -S . -B build -DCMAKE_BUILD_TYPE="$build_type" "${configure_args[@]}" ${SHADELAB_CMAKE_ARGS:-}
cmake --build build -j"$(nproc)" "${build_args[@]}"
