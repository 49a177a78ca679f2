#!/usr/bin/env bash
# Sets up and builds the program (only the `shadelab` target: no tests), then runs the demo window — or,
# with no display, renders the showcase (every shading mode × lighting model) headless to
# shadelab-showcase.png. Without arguments it opens scenes/showcase.json; arguments go to shadelab as they are.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh --program
if (($#)); then exec build/shadelab "$@"; fi
exec build/shadelab scenes/showcase.json
