#!/usr/bin/env bash
# Re-blesses the reference images in tests/references/ from the EGL backend. Look at every changed PNG
# (git diff --stat tests/references; open them) and say in the commit message why its pixels moved.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake --build build --target gl_references_test -j"$(nproc)"
SHADELAB_BLESS=1 SHADELAB_TEST_BACKEND=egl build/tests/gl_references_test
git status --short tests/references
