#!/usr/bin/env bash
# The main job on the bundled default mesh: installs what is missing, builds, finds the
# symmetry plane and symmetric region of Data/dino.off, writes results/ (labelled mesh,
# plane glyph, picture, JSON summary) and prints the summary. Safe to run twice.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
BUILD_DIR="${FOLDINGMESHES_BUILD_DIR:-build}"
MESH="${1:-Data/dino.off}"
mkdir -p results
xvfb-run -a "$BUILD_DIR/bin/foldingmeshes" detect "$MESH" --outdir results --json \
  > results/summary.json
cat results/summary.json
echo "results written to $(pwd)/results"
