#!/usr/bin/env bash
# The main job on the bundled default mesh: installs what is missing, builds, then on
# Data/dino.off (or the mesh given as $1):
#   1. detects the symmetry plane and symmetric region  -> results/<stem>_symmetry.{vtp,png}
#   2. folds the mesh into a folding tree                -> results/<stem>_tree.vtm, segmentation
#   3. unfolds the tree back into a mesh                 -> results/<stem>_unfolded.{vtp,png}
# and writes results/summary.json with the three summaries. Safe to run twice.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
BUILD_DIR="${FOLDINGMESHES_BUILD_DIR:-build}"
MESH="${1:-Data/dino.off}"
STEM="$(basename "${MESH%.*}")"
mkdir -p results
run() { xvfb-run -a "$BUILD_DIR/bin/foldingmeshes" "$@"; }
run detect "$MESH" --outdir results --json > results/detect.json
run fold "$MESH" --outdir results --json > results/fold.json
run unfold "results/${STEM}_tree.vtm" --original "$MESH" --outdir results --json > results/unfold.json
{
  echo "{"
  echo "\"detect\": $(cat results/detect.json),"
  echo "\"fold\": $(cat results/fold.json),"
  echo "\"unfold\": $(cat results/unfold.json)"
  echo "}"
} > results/summary.json
rm -f results/detect.json results/fold.json results/unfold.json
cat results/summary.json
echo "results written to $(pwd)/results"
