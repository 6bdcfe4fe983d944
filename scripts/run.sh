#!/usr/bin/env bash
# The README's main job: renders BEAMS, LANDSCAPE and SPHERES in stereo and hybrid at the HTC
# Vive's per-eye resolution, then runs a study session of the demo protocol on the simulated
# OpenXR headset (simxr) with a simulated observer at the controls, exports its decision log, and
# analyses it (report.html, summary.json, tables, figures; docs/analysis.md). Says where
# everything is.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh --target monoplane
out="${OUT_DIR:-out}"
for scene in beams landscape spheres; do
  echo "== $scene: stereo, and hybrid at m = 8 compared with it"
  build/monoplane render --scene "$scene" --mode stereo --hmd vive --detail low --out "$out/stereo/$scene"
  build/monoplane render --scene "$scene" --mode hybrid --mono-plane 8 --hmd vive --detail low \
    --compare-stereo --out "$out/hybrid-m8/$scene"
done

echo "== study session: protocols/demo.toml on the simulated OpenXR headset, simulated observer"
mkdir -p "$out/study"
participant="demo-$(date -u +%Y%m%dT%H%M%S)"
# A fifth of the Vive's resolution and a 15 Hz virtual display keep it to minutes on a CPU
# rasterizer; every frame goes through the same OpenXR path as a real headset's.
build/monoplane study run --protocol protocols/demo.toml --participant "$participant" \
  --db "$out/study/demo.sqlite" --headset simulated --observer default --hmd vive \
  --resolution-scale 0.2 --sim-rate 15 --detail low
build/monoplane study export --db "$out/study/demo.sqlite" --format csv --out "$out/study/demo.csv"

echo "== analysis of the study database (every session in it)"
build/monoplane analyze --db "$out/study/demo.sqlite" --out "$out/analysis"

echo
echo "Stereo pairs (left.png, right.png, stats.json):   $(realpath "$out/stereo")/<scene>"
echo "Hybrid at m = 8 (also mono.png, SSIM heat maps):  $(realpath "$out/hybrid-m8")/<scene>"
echo "Study database and decision log:                  $(realpath "$out/study")/demo.sqlite, demo.csv"
echo "Analysis report (open in a browser):              $(realpath "$out/analysis")/report.html"
