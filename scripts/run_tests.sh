#!/usr/bin/env bash
# The whole test suite: installs what is missing, builds, runs every CTest test
# (unit, accuracy, image, Python, pvpython). Safe to run twice.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
BUILD_DIR="${FOLDINGMESHES_BUILD_DIR:-build}"
cd "$BUILD_DIR"
ctest --output-on-failure --timeout 900 "$@"
