#!/usr/bin/env bash
# Installs the independent implementations' npm packages at the versions package-lock.json pins, into
# node_modules/ beside this script (tests/compare/perceptual_test.cpp runs pixelmatch from there).
# Idempotent and offline-safe: when node_modules already holds every pinned version it downloads nothing;
# otherwise `npm ci` installs from the lock file. When that fails (no npm, no registry), it says so and, outside
# CI, exits 0: the perceptual check then skips naming what is missing. Under CI (env CI set) it fails, as the
# check itself would.
set -euo pipefail
here=$(dirname -- "$(readlink -f -- "$0")")
cd -- "$here"

unavailable() {
  echo "install.sh: $1; the perceptual delta cannot be held to pixelmatch" >&2
  if [ -n "${CI:-}" ]; then
    exit 1
  fi
  echo "install.sh: (not CI: perceptual_test will skip that check and name what is missing)" >&2
  exit 0
}

if ! command -v node >/dev/null || ! command -v npm >/dev/null; then
  unavailable "node or npm is missing (scripts/setup.sh --install tests)"
fi

# Every package the lock file pins, at its version, already under node_modules/?
pinned_versions_installed() {
  node -e '
    const packages = require("./package-lock.json").packages;
    for (const [path, entry] of Object.entries(packages)) {
      if (path === "") continue;
      if (require("./" + path + "/package.json").version !== entry.version) process.exit(1);
    }' 2>/dev/null
}

if pinned_versions_installed; then
  echo "install.sh: node_modules already holds the versions package-lock.json pins"
  exit 0
fi
npm ci --no-audit --no-fund --loglevel=error ||
  unavailable "npm ci failed (offline, or the npm registry unreachable?)"
