#!/usr/bin/env bash
# Screenshot regression as a CI job runs it (docs/ci-engineers.md "Screenshot regression in your CI"): renders
# every scene in scenes/ headless into a fresh folder, then `shadelab review` holds each render to the
# references of the GL driver that drew it and writes the page, the JSON and the JUnit a CI shows.
#
#   examples/ci/screenshot-regression.sh [--shadelab PATH] [--artifacts DIR] [--junit FILE]
#                                        [--bless NAME]... [--bless-failed]
#
#   --shadelab PATH  the program (default: shadelab on PATH, else build/shadelab of this checkout)
#   --artifacts DIR  made if missing (default: screenshot-artifacts/ in the current folder). The job owns
#                    DIR/renders/ (every render of this run: what a bless would write), DIR/review/ (the page,
#                    index.html, with each case's actual, expected, difference and heatmap images) and
#                    DIR/review.json (every case's figures and the paths of its images); it replaces those
#                    and nothing else in DIR
#   --junit FILE     JUnit XML, one testcase a scene, for the CI's test report
#   --bless NAME     write scene NAME's render as this driver's reference (repeatable); look at it first
#   --bless-failed   write the render of every scene that FAILed or is NEW, and print each one written
#
# References live in references/DRIVER/, DRIVER being the renderer's first word as `render --verbose` names
# it (llvmpipe, softpipe, a vendor's driver...): each driver rasterizes its own way, so each has its own
# pictures; NAME.1.png, NAME.2.png... beside NAME.png are further approved images (any one passing passes).
# masks/NAME.png (black: not compared) masks a scene. expectations.txt marks known failures per driver.
# A reference whose scene is gone is reported STALE (delete it). Exit as review's: 0 every scene passes,
# 1 one or more fail (or are NEW or STALE), 2 bad arguments or bad input.
set -euo pipefail
# The folder of the script itself, links resolved: a job may run it through a link in another folder, and the
# scenes, references and masks are beside the file. No cd: with CDPATH exported, bash's cd prints the folder
# it found, and `$(cd ... && pwd)` would hold it twice; CDPATH is unset for any later cd too.
unset CDPATH
here=$(dirname -- "$(readlink -f -- "$0")")

# Per channel on 0..255: at most 2 apart, a mean under 0.05 over the compared pixels, and up to 8 pixels
# beyond the 2 (an edge pixel a driver covers differently); and at most 8 pixels pixelmatch calls visibly
# different (the same edge allowance, for when --max is loosened for another driver). The same driver gives
# the same pixels, so these only absorb what a driver update may move (docs/ci-engineers.md "Which metric").
TOLERANCE=(--max 2 --mean 0.05 --outliers 8 --perceptual-max-pixels 8)

usage() {
  echo "screenshot-regression.sh: $1 (see the comment at the top of this script)" >&2
  exit 2
}
shadelab=""
artifacts=$PWD/screenshot-artifacts
review_args=()
blessing=0
while (($#)); do
  case $1 in
    --shadelab | --artifacts | --junit | --bless)
      (($# >= 2)) || usage "$1 needs a value"
      case $1 in
        --shadelab) shadelab=$2 ;;
        --artifacts) artifacts=$2 ;;
        --junit) review_args+=("--junit=$2") ;;
        --bless) review_args+=("--bless=$2") && blessing=1 ;;
      esac
      shift 2
      ;;
    --bless-failed)
      review_args+=(--bless-failed)
      blessing=1
      shift
      ;;
    *) usage "unknown argument '$1'" ;;
  esac
done
if [ -z "$shadelab" ]; then
  shadelab=$(command -v shadelab || echo "$here/../../build/shadelab")
fi
[ -x "$shadelab" ] || usage "no shadelab program at '$shadelab' (give --shadelab PATH)"

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
# A driver with no references yet: every scene is NEW. Held to an empty folder, unless blessing, which makes
# the driver's folder to write into.
if [ ! -d "$references" ]; then
  if ((blessing)); then mkdir -p -- "$references"; else references=$work/none && mkdir "$references"; fi
fi

mkdir -p -- "$artifacts"
renders=$artifacts/renders
rm -rf -- "$renders" "$artifacts/review" "$artifacts/review.json"
mkdir -- "$renders"
for scene in "$here"/scenes/*.json; do
  "$shadelab" render "$scene" --out "$renders/$(basename -- "$scene" .json).png"
done

[ -d "$here/masks" ] && review_args+=("--masks=$here/masks")
status=0
"$shadelab" review "$renders" "$references" --out "$artifacts/review" --json "$artifacts/review.json" \
  --expectations "$here/expectations.txt" --driver "$driver" "${TOLERANCE[@]}" "${review_args[@]}" || status=$?
if ((status == 1)); then
  echo "the page: $artifacts/review/index.html; this run's renders: $renders/ (look, then --bless NAME or --bless-failed)"
fi
exit "$status"
