#!/usr/bin/env bash
# Sets up and builds shadelab, then runs the whole test suite: CPU tests, GL tests on both headless
# backends (EGL and OSMesa), the command line end to end.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
ctest --test-dir build --output-on-failure -j"$(nproc)" "$@"
