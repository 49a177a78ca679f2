#!/usr/bin/env bash
# Installs the independent implementations' npm packages at the versions package-lock.json pins, into
# node_modules/ beside this script (tests/compare/perceptual_test.cpp runs pixelmatch from there). Idempotent:
# npm ci starts from the lock file each time. Needs node and npm and the npm registry.
set -euo pipefail
here=$(dirname -- "$(readlink -f -- "$0")")
command -v npm >/dev/null || {
  echo "install.sh: npm is missing (apt-get install nodejs npm)" >&2
  exit 1
}
cd -- "$here"
npm ci --no-audit --no-fund --loglevel=error
