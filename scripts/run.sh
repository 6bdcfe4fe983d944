#!/usr/bin/env bash
# The README's main job. Until the study runner exists: renders BEAMS, LANDSCAPE and SPHERES in
# stereo at the HTC Vive's per-eye resolution and says where the PNGs are.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh --target monoplane
out="${OUT_DIR:-out/stereo}"
for scene in beams landscape spheres; do
  echo "== $scene"
  build/monoplane render --scene "$scene" --mode stereo --hmd vive --detail low --out "$out/$scene"
done
echo
echo "Stereo pairs (left.png, right.png, stats.json) are in:"
for scene in beams landscape spheres; do echo "  $(realpath "$out/$scene")"; done
