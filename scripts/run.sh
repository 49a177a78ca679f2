#!/usr/bin/env bash
# Sets up and builds shadelab, then runs the demo window — or, with no display, renders the showcase
# (every shading mode × lighting model) headless to shadelab-showcase.png. Arguments go to shadelab.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
exec build/shadelab "$@"
