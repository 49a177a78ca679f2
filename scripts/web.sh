#!/usr/bin/env bash
# The browser build of shadelab (WebGL 2, Debian's emscripten):
#   scripts/web.sh build                 installs what is missing, builds into build-web/
#   scripts/web.sh serve [PORT] [--lessons DIR]
#                                        serves the page (build-web/site/) on 127.0.0.1 (default port 8000,
#                                        1..65535), prints the URL; --lessons adds DIR's lessons (and the
#                                        files they name inside DIR) to the page's picker, no rebuild
#   scripts/web.sh render [--shading S] [--lighting L] [--subdivisions N] [--size WxH] [--depth D]
#                         [--tolerance-px T] < SCENE.json > FILE.png
#                                        draws the scene read from standard input in headless Chromium
#                                        through the WebGL 2 build and writes the canvas's pixels as a PNG to
#                                        standard output: the browser's `shadelab render - --out -` (files
#                                        are the command line's, whose rules live once, in src/io/)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"

install_missing() {
  local packages=(emscripten chromium chromium-driver python3-selenium python3-glad libglm-dev
    nlohmann-json3-dev libtinyobjloader-dev libtinygltf-dev cmake make)
  local missing=()
  for p in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  ((${#missing[@]})) || return 0
  echo "shadelab: installing ${missing[*]}"
  local sudo=()
  [ "$(id -u)" -eq 0 ] || sudo=(sudo)
  "${sudo[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
}

case "${1:-}" in
build)
  install_missing
  # Emscripten's JS optimizer loads Debian's node modules; a node from elsewhere on PATH needs the path.
  export NODE_PATH=/usr/share/nodejs
  # Debian's emscripten ships its system libraries prebuilt; a user who cannot write that cache gets a
  # copy of their own instead of a failed build.
  if [ ! -w /usr/share/emscripten/cache ] && [ -z "${EM_CACHE:-}" ]; then
    export EM_CACHE="${XDG_CACHE_HOME:-$HOME/.cache}/shadelab-emscripten"
    [ -d "$EM_CACHE" ] || cp -r /usr/share/emscripten/cache "$EM_CACHE"
  fi
  emcmake cmake -S "$root/web" -B "$root/build-web" -DCMAKE_BUILD_TYPE=Release >/dev/null
  cmake --build "$root/build-web" -j"$(nproc)"
  echo "shadelab: built $root/build-web (scripts/web.sh serve to open it)"
  ;;
serve)
  [ -f "$root/build-web/site/shadelab.wasm" ] || { echo "shadelab: no browser build: run scripts/web.sh build" >&2; exit 1; }
  shift
  port=8000 lessons=()
  while (($#)); do
    case "$1" in
    --lessons)
      (($# >= 2)) || { echo "shadelab: serve: --lessons needs a value: the folder that holds your lessons" >&2; exit 2; }
      lessons=(--lessons "$2")
      shift 2
      ;;
    --lessons=*) lessons=(--lessons "${1#--lessons=}"); shift ;;
    -?*) echo "shadelab: serve: unknown option '$1'; serve takes [PORT] [--lessons DIR]" >&2; exit 2 ;;
    *) port="$1"; shift ;;
    esac
  done
  # Only the page's own files (build-web/site/) and DIR's: no listings, no links out; the port and DIR are
  # checked there.
  exec /usr/bin/python3 "$root/web/serve.py" "$root/build-web/site" "$port" "${lessons[@]}"
  ;;
render)
  shift
  # Debian's python3 (with python3-selenium), not whichever python3 comes first on PATH.
  exec /usr/bin/python3 "$root/web/driver.py" render "$@"
  ;;
*)
  echo "usage: scripts/web.sh build | serve [PORT] [--lessons DIR] | render [flags] < SCENE.json > FILE.png" >&2
  exit 2
  ;;
esac
