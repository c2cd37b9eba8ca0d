#!/usr/bin/env bash
# Runs the sweeps behind docs/ground-truth-report.md: `shadowlab eval` on each built-in scene at 1280×720 with
# shimmer (half a pixel, half a degree), one report folder per scene (eval.csv, eval.json, eval.html, contact
# sheets).
#   docs/scripts/ground_truth_report.sh [path/to/shadowlab] [output folder]
#   (defaults: build/cli/shadowlab, ground-truth-report)
set -euo pipefail
bin=${1:-build/cli/shadowlab}
out=${2:-ground-truth-report}
mkdir -p "$out"
common=(--shimmer-pixels 0.5 --shimmer-degrees 0.5)
directional=(--techniques shadowmap,cascades,lispsm,frustum-faces --filters hard,pcf --biases slope,normal
             --sizes 1024,2048)
omni=(--filters hard,pcf --biases slope,normal --sizes 512,1024)
"$bin" eval tutorial "${directional[@]}" "${common[@]}" --out "$out/tutorial"
"$bin" eval duel "${directional[@]}" "${common[@]}" --out "$out/duel"
"$bin" eval tutorial-spot --techniques shadowmap --filters hard,pcf,poisson --biases constant,slope,offset,normal \
    --sizes 512,1024,2048 "${common[@]}" --out "$out/tutorial-spot"
"$bin" eval pyramid --techniques cube,paraboloid,pyramid "${omni[@]}" "${common[@]}" --out "$out/pyramid"
"$bin" eval paraboloid --techniques cube,paraboloid "${omni[@]}" "${common[@]}" --out "$out/paraboloid"
"$bin" eval projective --techniques projective,shadowmap --filters pcf --biases slope --sizes 256,1024,2048 \
    "${common[@]}" --out "$out/projective"
# Issue 19: the filterable maps and PCSS beside the classic map with PCF and Poisson (each light's own size).
for scene in tutorial duel; do
  "$bin" eval "$scene" --techniques shadowmap --filters pcf,poisson --out "$out/$scene-classic"
  "$bin" eval "$scene" --techniques esm,vsm,evsm2,evsm4,pcss --out "$out/$scene-filtered"
done
# Issue 21: the irregular z-buffer (exact, no bias) beside the classic map, cascades and the face-split maps (PCF,
# normal offset, 2048²), on tutorial, duel and two large shared glTF models staged with a sun and a ground
# (assets folder: SHADOWLAB_ASSETS, default ../shared/assets). The irregular rows run on their own so that no
# map size is forced on them (for irregular --map-size is the grid's largest side, default 4096).
assets=${SHADOWLAB_ASSETS:-../shared/assets}
for scene in tutorial duel "$assets/stanford_dragon/dragon_vrip.glb" "$assets/flight_helmet/FlightHelmet.gltf"; do
  name=$(basename "$scene"); name=${name%.*}
  "$bin" eval "$scene" --techniques irregular --out "$out/$name-irregular"
  "$bin" eval "$scene" --techniques shadowmap,cascades,frustum-faces --filters pcf --biases normal --sizes 2048 \
      --out "$out/$name-maps"
done
