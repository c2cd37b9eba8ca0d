#!/usr/bin/env bash
# The aliasing table of issue 15 for one scene: every whole-scene directional technique at equal total map
# memory (2048² texels), at 1920x1080, with `shadowlab render --aliasing`; prints a Markdown table (max, p95 and
# mean pixels per texel over the lit-facing pixels, storage factor p95², maps and texels; the map-pass times
# come from bench/directional_bench.cpp, warm and repeated) and writes a contact
# sheet of the frames and heat maps (frame above heat map, one column per technique) with oiiotool.
#   bench/directional_report.sh SCENE OUT_DIR [SHADOWLAB]
# SCENE is a built-in name or a scene file (bench/scenes/forest.json needs ../shared/assets).
set -euo pipefail
scene=${1:?usage: directional_report.sh SCENE OUT_DIR [SHADOWLAB]}
out=${2:?usage: directional_report.sh SCENE OUT_DIR [SHADOWLAB]}
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
shadowlab=${3:-$root/build/cli/shadowlab}
size=1920x1080
mkdir -p "$out"

# The face-split maps come one per light-facing frustum face; at equal memory each gets 2048/sqrt(k) texels.
probe=$(mktemp -d)
trap 'rm -rf "$probe"' EXIT
"$shadowlab" render "$scene" --technique frustum-faces --map-layout separate --size 320x180 --out "$probe/p.png" \
  --maps "$probe" >/dev/null
faces=$(ls "$probe"/*.exr | wc -l)
face_size=$(awk -v k="$faces" 'BEGIN { printf "%d", 2048 / sqrt(k) }')

configs=(
  "uniform|1 x 2048²|--technique shadowmap --shadow-size 2048"
  "cascades-2|2 x 1448²|--technique cascades --cascades 2 --shadow-size 1448"
  "cascades-4|4 x 1024²|--technique cascades --cascades 4 --shadow-size 1024"
  "cascades-2-visible|2 x 1448²|--technique cascades --cascades 2 --shadow-size 1448 --view-range visible"
  "cascades-4-visible|4 x 1024²|--technique cascades --cascades 4 --shadow-size 1024 --view-range visible"
  "lispsm|1 x 2048²|--technique lispsm --shadow-size 2048"
  "cascades-4-lispsm|4 x 1024²|--technique cascades --cascades 4 --shadow-size 1024 --cascade-warp lispsm"
  "faces-exact|$faces x ${face_size}²|--technique frustum-faces --shadow-size $face_size"
  "faces-lispsm|$faces x ${face_size}²|--technique frustum-faces --shadow-size $face_size --face-warp lispsm"
)
echo "| technique | maps | max | p95 | mean | storage factor |"
echo "|---|---|---:|---:|---:|---:|"
frames=() heats=()
for c in "${configs[@]}"; do
  IFS='|' read -r name maps args <<<"$c"
  # shellcheck disable=SC2086
  line=$("$shadowlab" render "$scene" $args --size "$size" --out "$out/$name.png" --aliasing "$out/$name-aliasing.png")
  read -r max p95 mean factor < <(sed -E 's/.*max ([^,]+), p95 ([^,]+), mean ([^ ]+) .*storage factor (.*)/\1 \2 \3 \4/' <<<"$line")
  echo "| $name | $maps | $max | $p95 | $mean | $factor |"
  frames+=("$out/$name.png") heats+=("$out/$name-aliasing.png")
done
# Three techniques per row: their frames, then their heat maps beneath.
sheet=()
for ((i = 0; i < ${#frames[@]}; i += 3)); do
  sheet+=("${frames[@]:i:3}" "${heats[@]:i:3}")
done
rows=$(((${#frames[@]} + 2) / 3 * 2))
oiiotool "${sheet[@]}" --mosaic "3x$rows" --resize "960x$((rows * 180))" -o "$out/contact-sheet.png"
echo
echo "contact sheet: $out/contact-sheet.png (three techniques per row in the table's order: frames, heat maps beneath)"
