#!/usr/bin/env bash
# The main job on the bundled default mesh: installs what is missing, builds, then on
# Data/dino.off (or the mesh given as $1; $2 the pictures' up axis, auto|x|y|z - the bundled
# dinosaur's file is Z-up):
#   1. detects the symmetry plane and symmetric region  -> results/<stem>_symmetry.{vtp,png}
#   2. folds the mesh into a folding tree                -> results/<stem>_tree.vtm, segmentation
#   3. unfolds the tree back into a mesh                 -> results/<stem>_unfolded.{vtp,png}
#   4. writes the compact folding tree                   -> results/<stem>.fmz
# and writes results/summary.json with the four summaries. Safe to run twice.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
BUILD_DIR="${FOLDINGMESHES_BUILD_DIR:-build}"
MESH="${1:-Data/dino.off}"
UP="${2:-$([ -z "${1:-}" ] && echo z || echo auto)}"
STEM="$(basename "${MESH%.*}")"
mkdir -p results
run() { xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" "$BUILD_DIR/bin/foldingmeshes" "$@"; }
run detect "$MESH" --up "$UP" --outdir results --json > results/detect.json
run fold "$MESH" --up "$UP" --outdir results --json > results/fold.json
run unfold "results/${STEM}_tree.vtm" --original "$MESH" --up "$UP" --outdir results --json \
  > results/unfold.json
run compress "$MESH" --outdir results --json --quiet > results/compress.json
{
  echo "{"
  echo "\"detect\": $(cat results/detect.json),"
  echo "\"fold\": $(cat results/fold.json),"
  echo "\"unfold\": $(cat results/unfold.json),"
  echo "\"compress\": $(cat results/compress.json)"
  echo "}"
} > results/summary.json
rm -f results/detect.json results/fold.json results/unfold.json results/compress.json
cat results/summary.json
echo "results written to $(pwd)/results"
