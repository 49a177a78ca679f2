#!/usr/bin/env bash
# Re-blesses the reference images in tests/references/ (all, or those whose case name contains FILTER)
# from one backend (default egl; osmesa and gles give the same pixels on llvmpipe). Look at every changed
# PNG (git diff --stat tests/references; open them) and say in the commit message why its pixels moved.
#   scripts/bless.sh [FILTER] [--backend egl|osmesa|gles]
set -euo pipefail
cd "$(dirname "$0")/.."
filter="" backend="egl"
while (($#)); do
  case "$1" in
  --backend)
    [ $# -ge 2 ] || { echo "bless.sh: --backend needs egl, osmesa or gles" >&2; exit 2; }
    backend="$2"
    shift 2
    ;;
  -*) echo "bless.sh: unknown option $1; usage: scripts/bless.sh [FILTER] [--backend egl|osmesa|gles]" >&2; exit 2 ;;
  *) filter="$1"; shift ;;
  esac
done
case "$backend" in egl | osmesa | gles) ;; *) echo "bless.sh: --backend $backend: expected egl, osmesa or gles" >&2; exit 2 ;; esac
[[ "$filter" =~ ^[A-Za-z0-9_]*$ ]] || { echo "bless.sh: FILTER is a case name or part of one ([A-Za-z0-9_]), got '$filter'" >&2; exit 2; }
cmake --build build --target gl_references_test -j"$(nproc)"
SHADELAB_BLESS=1 SHADELAB_TEST_BACKEND="$backend" build/tests/gl_references_test --gtest_filter="*${filter}*"
git status --short tests/references
