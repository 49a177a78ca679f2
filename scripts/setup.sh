#!/usr/bin/env bash
# Installs whatever shadelab needs that this Debian 12 machine lacks (as root, or through sudo), then
# configures and builds into build/. Used by scripts/run.sh and scripts/test.sh; safe to run again.
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(
  # toolchain
  g++ cmake make pkg-config ca-certificates
  # libraries, all found by find_package / pkg-config
  libglfw3-dev libglm-dev libegl-dev libegl-mesa0 libgl1-mesa-dri libosmesa6-dev libpng-dev
  nlohmann-json3-dev libcli11-dev libgtest-dev libbenchmark-dev python3-glad libimgui-dev libstb-dev
  fonts-dejavu-core
  # the demo under a virtual display, and driving it in tests
  xvfb xauth xdotool libx11-dev
  # CI's checks: formatting, static analysis, fuzzing (clang's libFuzzer), the report's plot
  clang-format clang-tidy clang libclang-rt-14-dev gnuplot-nox git
)

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
cmake -S . -B build -DCMAKE_BUILD_TYPE="$build_type" ${SHADELAB_CMAKE_ARGS:-}
cmake --build build -j"$(nproc)"
