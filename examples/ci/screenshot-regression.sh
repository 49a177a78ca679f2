#!/usr/bin/env bash
# Screenshot regression as a CI job runs it (docs/ci-engineers.md "Screenshot regression in your CI"): renders every
# scene in scenes/ headless, compares each with its reference for the GL driver that drew it, and on a
# failure leaves the render, the difference image and the comparison's JSON in the artifacts folder.
#
#   examples/ci/screenshot-regression.sh [--shadelab PATH] [--artifacts DIR] [--bless]
#
#   --shadelab PATH   the program (default: shadelab on PATH, else build/shadelab of this checkout)
#   --artifacts DIR   where a failure's files go (default: screenshot-artifacts/ in the current folder),
#                     made if missing; of what is in it, only files named after a failing scene are replaced
#   --bless           write the renders as the references of this driver instead of comparing (look at them
#                     first: a reference is only as right as the picture you accepted)
#
# References live in references/DRIVER/, DRIVER being the renderer's first word as `render --verbose`
# names it (llvmpipe, softpipe, a vendor's driver...): each driver rasterizes its own way, so each has its
# own pictures. A scene may have a mask, masks/SCENE.png (black: not compared). The tolerances are the
# TOLERANCE array below. Exit: 0 every scene within tolerance, 1 one or more not, 2 a missing reference or
# bad arguments.
set -euo pipefail
# The folder of the script itself, links resolved: a job may run it through a link in another folder, and the
# scenes, references and masks are beside the file. No cd: with CDPATH exported, bash's cd prints the folder
# it found, and `$(cd ... && pwd)` would hold it twice; CDPATH is unset for any later cd too.
unset CDPATH
here=$(dirname -- "$(readlink -f -- "$0")")

# Per channel on 0..255: at most 2 apart, a mean under 0.05 over the compared pixels, and up to 8 pixels
# beyond the 2 (an edge pixel a driver covers differently). The same driver gives the same pixels, so these
# only absorb what a driver update may move.
TOLERANCE=(--max 2 --mean 0.05 --outliers 8)

shadelab=""
artifacts=$PWD/screenshot-artifacts
bless=0
while (($#)); do
  case $1 in
    --shadelab)
      shadelab=${2:?--shadelab needs the program\'s path}
      shift 2
      ;;
    --artifacts)
      artifacts=${2:?--artifacts needs a folder}
      shift 2
      ;;
    --bless)
      bless=1
      shift
      ;;
    *)
      echo "screenshot-regression.sh: unknown argument '$1' (see the comment at the top of this script)" >&2
      exit 2
      ;;
  esac
done
if [ -z "$shadelab" ]; then
  shadelab=$(command -v shadelab || echo "$here/../../build/shadelab")
fi
[ -x "$shadelab" ] || {
  echo "screenshot-regression.sh: no shadelab program at '$shadelab' (give --shadelab PATH)" >&2
  exit 2
}

work=$(mktemp -d)
trap 'rm -rf -- "$work"' EXIT

# The driver: the renderer's first word in `render --verbose`'s line, "... context: llvmpipe (LLVM ...".
"$shadelab" render --size 8x8 --verbose --out "$work/probe.png" 2>"$work/verbose.txt"
driver=$(sed -n 's/.*context: \([A-Za-z0-9_.-]*\).*/\1/p' "$work/verbose.txt" | head -n 1)
[ -n "$driver" ] || {
  echo "screenshot-regression.sh: could not read the driver from: $(cat "$work/verbose.txt")" >&2
  exit 1
}
references=$here/references/$driver
echo "driver: $driver (references: ${references#"$here"/})"

mkdir -p -- "$artifacts"
failed=0
missing=0
for scene in "$here"/scenes/*.json; do
  name=$(basename -- "$scene" .json)
  actual=$work/$name.png
  "$shadelab" render "$scene" --out "$actual"
  if ((bless)); then
    mkdir -p -- "$references"
    cp -- "$actual" "$references/$name.png"
    echo "blessed: $name"
    continue
  fi
  if [ ! -f "$references/$name.png" ]; then
    echo "MISSING: $name has no reference for $driver (look at a render, then run with --bless)"
    missing=1
    continue
  fi
  mask=()
  [ -f "$here/masks/$name.png" ] && mask=(--mask "$here/masks/$name.png")
  status=0
  "$shadelab" compare "$actual" "$references/$name.png" "${TOLERANCE[@]}" "${mask[@]}" \
    --diff "$work/$name.diff.png" --json >"$work/$name.json" || status=$?
  case $status in
    0) echo "pass: $name" ;;
    1)
      echo "FAIL: $name (render, difference x8 and figures in ${artifacts}/)"
      cp -- "$actual" "$artifacts/$name.png"
      cp -- "$work/$name.json" "$artifacts/$name.json"
      [ -f "$work/$name.diff.png" ] && cp -- "$work/$name.diff.png" "$artifacts/$name.diff.png"
      failed=1
      ;;
    *) exit "$status" ;;
  esac
done
((missing)) && exit 2
((failed)) && exit 1
exit 0
