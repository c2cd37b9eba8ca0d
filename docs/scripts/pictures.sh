#!/usr/bin/env bash
# Regenerates every picture in README.md and docs/ from the current build: the README's frame and map, the
# tutorial steps (tutorial_pictures.sh), the directional contact sheets (bench/directional_report.sh), the
# filtered-shadow frames and contact sheets, the omnidirectional caster pictures and the projective variants. Needs oiiotool; the forest
# sheet needs ../shared/assets (skipped, said on stderr, without it). Run from the repository root:
#   docs/scripts/pictures.sh [path/to/shadowlab]   (default: build/cli/shadowlab)
set -euo pipefail
bin=$(realpath "${1:-build/cli/shadowlab}")
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
cd "$root"
img=docs/images
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$img/filtered" "$img/omni"

# README: the default tutorial frame and its shadow map in false colour.
"$bin" render tutorial --size 960x540 --threads 2 --out "$img/tutorial.png" --maps "$work/maps"
"$bin" inspect "$work/maps/light0-sun.exr" --png "$work/map.png" >/dev/null
oiiotool "$work/map.png" --resize 512x512 -o "$img/tutorial-map.png"

# docs/classic-shadow-map.md: one picture per step.
docs/scripts/tutorial_pictures.sh "$bin"

# docs/directional.md: frames and aliasing heat maps of every whole-scene technique.
bench/directional_report.sh duel "$work/duel" "$bin" >/dev/null
cp "$work/duel/contact-sheet.png" "$img/directional-duel.png"
if [ -e ../shared/assets/README.md ]; then
  bench/directional_report.sh bench/scenes/forest.json "$work/forest" "$bin" >/dev/null
  cp "$work/forest/contact-sheet.png" "$img/directional-forest.png"
else
  echo "pictures.sh: ../shared/assets is missing: $img/directional-forest.png left as it is" >&2
fi

# docs/filtered-shadows.md: the spot room with PCSS (10 cm light) and VSM; tutorial and duel with six readers.
"$bin" render docs/examples/spot-room.json --size 480x270 --light-radius 0.1 --out "$img/filtered/pcss-spot.png"
"$bin" render docs/examples/spot-room.json --size 480x270 --technique vsm --out "$img/filtered/vsm-spot.png"
for scene in tutorial duel; do
  shots=()
  for t in "shadowmap --filter pcf" "shadowmap --filter poisson" "esm" "vsm" "evsm4" "pcss"; do
    name=$(tr ' ' '_' <<<"$t")
    # shellcheck disable=SC2086
    "$bin" render "$scene" --size 386x200 --technique $t --out "$work/$scene-$name.png"
    shots+=("$work/$scene-$name.png")
  done
  oiiotool "${shots[@]}" --mosaic 3x2 -o "$img/filtered/contact-$scene.png"
done
# PCSS on the cube map (15 cm light) beside the cube with PCF, on the paraboloid scene's point light.
"$bin" render paraboloid --size 480x270 --technique cube --soft-shadows pcss --light-radius 0.15 --out "$work/cube-pcss.png"
"$bin" render paraboloid --size 480x270 --technique cube --out "$work/cube-pcf.png"
oiiotool "$work/cube-pcss.png" "$work/cube-pcf.png" --mosaic 2x1 -o "$img/filtered/cube-pcss.png"

# docs/omnidirectional.md: the square frame under the lamp with the pyramid and the paraboloid maps.
"$bin" render docs/examples/omni-caster.json --technique pyramid --size 480x320 --out "$work/pyr.png" --maps "$work/pyr"
"$bin" render docs/examples/omni-caster.json --technique paraboloid --size 480x320 --out "$work/par.png" --maps "$work/par"
oiiotool "$work/pyr/light0-lamp.exr" --ch Z --mulc 3 --clamp:min=0:max=1 --resize 256x256 -d uint8 -o "$work/pyr-map.png"
oiiotool "$work/par/light0-lamp.exr" --ch Z --mulc 3 --clamp:min=0:max=1 --resize 256x256 -d uint8 \
  -o "$work/par-map.png"
oiiotool "$work/pyr-map.png" "$work/par-map.png" --mosaic 2x1 -o "$img/omni/caster-maps.png"
oiiotool "$work/pyr.png" "$work/par.png" --mosaic 2x1 -o "$img/omni/caster-shadows.png"
# docs/projective.md: caster selection from close up, and the article's blur and fade beside today's choices
# (the blur row at 64² maps so the texels show, the fade row over 1.8 … 3 m behind each caster).
mkdir -p "$img/projective"
"$bin" render projective --camera orbit:180,10,3 --caster-reach 10 --size 400x225 --out "$img/projective-caster-reach.png"
view=(projective --camera orbit:200,45,1.8 --size 320x180)
"$bin" render "${view[@]}" --shadow-size 64 --out "$img/projective/blur-none.png"
"$bin" render "${view[@]}" --shadow-size 64 --lod-bias 2 --out "$img/projective/blur-lod-bias.png"
"$bin" render "${view[@]}" --shadow-size 64 --blur-passes 3 --out "$img/projective/blur-offset.png"
"$bin" render "${view[@]}" --out "$img/projective/fade-none.png"
fade=(--fade-start 1.8 --fade-end 3)
"$bin" render "${view[@]}" "${fade[@]}" --out "$img/projective/fade-formula.png"
"$bin" render "${view[@]}" "${fade[@]}" --fade-lookup texture --fade-table smoothstep --out "$img/projective/fade-smoothstep.png"
"$bin" render "${view[@]}" "${fade[@]}" --fade-lookup texture --fade-table 1,1,0.25,0.25 --out "$img/projective/fade-table.png"
echo "pictures.sh: regenerated the pictures under $img"
