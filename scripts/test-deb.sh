#!/usr/bin/env bash
# The light install tested as a user gets it: the Debian package of the `compare` component (cpack -G DEB,
# Depends computed by dpkg-shlibdeps) installed with apt into a fresh Debian 12 root, where
# `shadelab-compare compare` and `review` run on two PNGs and the installed README's relative links resolve.
#   scripts/test-deb.sh [BUILD_DIR]     (default build/; shadelab-compare must be built there; run as root)
# The root made by `debootstrap --variant=minbase bookworm` is kept under BUILD_DIR/deb-test/bookworm and
# copied for each run, so a rerun downloads nothing but the package lists once a day. Needs the packages
# debootstrap and dpkg-dev (scripts/setup.sh's tools) and the network to deb.debian.org the first time.
set -euo pipefail
cd "$(dirname "$0")/.."

build=${1:-build}
mirror=${SHADELAB_DEBIAN_MIRROR:-http://deb.debian.org/debian}
work="$build/deb-test"
pristine="$work/bookworm"
root="$work/run"

die() {
  echo "test-deb.sh: $*" >&2
  exit 1
}

[ "$(id -u)" -eq 0 ] || die "run as root: debootstrap and chroot need it"
[ -x "$build/shadelab-compare" ] || die "no $build/shadelab-compare: cmake --build $build --target shadelab-compare"
command -v debootstrap >/dev/null || die "debootstrap is missing: apt-get install debootstrap"
command -v dpkg-shlibdeps >/dev/null || die "dpkg-shlibdeps is missing: apt-get install dpkg-dev"

mounted=()
cleanup() {
  local m
  for m in "${mounted[@]}"; do umount "$m" 2>/dev/null || true; done
}
trap cleanup EXIT

# ---- the package ----
rm -rf "$work/packages"
(cd "$build" && cpack -G DEB -D CPACK_COMPONENTS_ALL=compare -B "$PWD/deb-test/packages" >/dev/null)
deb=$(find "$work/packages" -maxdepth 1 -name 'shadelab-compare_*.deb' | head -n 1)
[ -n "$deb" ] || die "cpack made no shadelab-compare_*.deb in $work/packages"
echo "package: $deb ($(stat -c %s "$deb") bytes)"
dpkg-deb --field "$deb" Package Version Depends Maintainer

# ---- the root: made once, its package lists refreshed once a day, copied for each run ----
if [ ! -e "$pristine/.complete" ]; then
  rm -rf "$pristine"
  echo "making a Debian 12 root in $pristine (debootstrap --variant=minbase bookworm)"
  debootstrap --variant=minbase bookworm "$pristine" "$mirror" >"$work/debootstrap.log" 2>&1 ||
    die "debootstrap failed; see $work/debootstrap.log"
  touch "$pristine/.complete"
fi
cp /etc/resolv.conf "$pristine/etc/resolv.conf"
if [ -z "$(find "$pristine/var/lib/apt/lists" -maxdepth 1 -name '*_Packages' -mmin -1440 | head -n 1)" ]; then
  chroot "$pristine" apt-get update -qq
fi
rm -rf "$root"
cp -a "$pristine" "$root"
mount -t proc proc "$root/proc"
mounted+=("$root/proc")

in_root() {
  chroot "$root" env -i PATH=/usr/sbin:/usr/bin:/sbin:/bin HOME=/root "$@"
}

# ---- installed by apt, so that Depends are resolved from the archive ----
cp "$deb" "$root/tmp/shadelab-compare.deb"
in_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends \
  /tmp/shadelab-compare.deb >"$work/apt.log" 2>&1 || die "apt-get install failed; see $work/apt.log"
# shellcheck disable=SC2016 # dpkg-query's own format, not the shell's
echo "installed: $(in_root dpkg-query -W -f='${Package} ${Version}' shadelab-compare)"

# No GL stack: nothing of GL, EGL, GLFW, X11, LLVM or Google Benchmark among what it loads.
libraries=$(in_root ldd /usr/bin/shadelab-compare)
echo "$libraries"
if grep -Ei 'lib(GL|EGL|glfw|X11|LLVM|benchmark)' <<<"$libraries"; then
  die "shadelab-compare loads part of the GL stack (above)"
fi

# ---- the two commands on two PNGs ----
mkdir -p "$root/tmp/check/actual" "$root/tmp/check/expected"
cp tests/references/phong_phong.png "$root/tmp/check/actual/sphere.png"
cp tests/references/phong_phong.png "$root/tmp/check/expected/sphere.png"
cp tests/references/flat_phong.png "$root/tmp/check/flat.png"
in_root shadelab-compare compare /tmp/check/actual/sphere.png /tmp/check/expected/sphere.png ||
  die "compare of a file with itself did not pass"
status=0
in_root shadelab-compare compare /tmp/check/actual/sphere.png /tmp/check/flat.png --json \
  --diff /tmp/check/diff.png >"$work/compare.json" || status=$?
[ "$status" -eq 1 ] || die "compare of two different pictures exited $status, not 1"
grep -q '"passed": false' "$work/compare.json" || die "compare --json did not say passed: false"
[ -s "$root/tmp/check/diff.png" ] || die "compare --diff wrote nothing"
in_root shadelab-compare review /tmp/check/actual /tmp/check/expected --out /tmp/check/review \
  --json /tmp/check/review.json --junit /tmp/check/junit.xml || die "review of identical folders did not pass"
for f in review/index.html review.json junit.xml; do
  [ -s "$root/tmp/check/$f" ] || die "review wrote no $f"
done
cp tests/references/flat_phong.png "$root/tmp/check/actual/sphere.png"
status=0
in_root shadelab-compare review /tmp/check/actual /tmp/check/expected --quiet || status=$?
[ "$status" -eq 1 ] || die "review of a changed picture exited $status, not 1"

# ---- the relative links of the pages a CI engineer reads (the README, the CI guide, the example's README)
# resolve inside the root; the other guides' links to source files point into a clone ----
docs="$root/usr/share/doc/shadelab-compare"
[ -s "$docs/README.md" ] || die "no README.md in /usr/share/doc/shadelab-compare"
broken=0
while IFS= read -r -d '' page; do
  while IFS= read -r link; do
    target=${link%%#*}
    case "$target" in "" | http://* | https://* | mailto:*) continue ;; esac
    if [ ! -e "$(dirname "$page")/$target" ]; then
      echo "broken link in ${page#"$root"}: $link"
      broken=1
    fi
  done < <(grep -o '](\([^)[:space:]]*\))' "$page" | sed 's/^](//; s/)$//')
done < <(printf '%s\0' "$docs/README.md" "$docs/docs/ci-engineers.md" "$docs/examples/ci/README.md")
[ "$broken" -eq 0 ] || die "the installed documents link to files that are not installed (above)"
echo "test-deb.sh: shadelab-compare installed, ran and documented in a fresh Debian 12 root"
