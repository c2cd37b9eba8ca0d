#!/usr/bin/env bash
# Renders the pictures of docs/classic-shadow-map.md: one per step of the tutorial, with the same settings as
# the golden-image tests (tests/shading/techniques/golden_test.cpp), at 400×225 with a 1024² d16 map.
#   docs/scripts/tutorial_pictures.sh [path/to/shadowlab]   (default: build/cli/shadowlab)
set -euo pipefail
bin=${1:-build/cli/shadowlab}
out=docs/images/tutorial
mkdir -p "$out"
common=(--size 400x225 --shadow-size 1024 --threads 2)
step() {  # name scene args...
  local name=$1 scene=$2
  shift 2
  "$bin" render "$scene" "${common[@]}" "$@" --out "$out/$name.png"
}
step 01-no-bias tutorial --filter hard --bias none --no-cull-front
step 02-constant tutorial --filter hard --bias constant --no-cull-front
step 03-slope tutorial --filter hard --bias slope --no-cull-front
step 04-back-faces tutorial --filter hard --bias slope --cull-front
step 05-offset tutorial --filter hard --bias offset --no-cull-front
step 06-normal tutorial --filter hard --bias normal --no-cull-front
step 07-pcf tutorial --filter pcf --bias slope --cull-front
step 08-poisson4 tutorial --filter poisson --poisson-taps 4 --bias slope --cull-front
step 09-poisson16 tutorial --filter poisson --poisson-taps 16 --bias slope --cull-front
step 10-stratified tutorial --filter stratified --poisson-taps 4 --pcf-taps --bias slope --cull-front
step 11-rotated tutorial --filter rotated --poisson-taps 16 --pcf-taps --bias slope --cull-front
step 12-early-bail tutorial --filter early-bail --bias slope --cull-front
step 13-spot tutorial-spot --filter pcf --bias slope --cull-front
# The tutorial's own Poisson arithmetic (--poisson-variant tutorial) beside shadowlab's mean of the taps.
step 14-stratified-tutorial tutorial --filter stratified --poisson-taps 4 --pcf-taps --bias slope --cull-front \
  --poisson-variant tutorial
step 15-poisson16-tutorial tutorial --filter poisson --poisson-taps 16 --bias slope --cull-front \
  --poisson-variant tutorial
step 16-rotated-tutorial tutorial --filter rotated --poisson-taps 16 --pcf-taps --bias slope --cull-front \
  --poisson-variant tutorial
# The directional light's box: fitted to the view frustum's part of the scene box (auto), the tutorial's fixed
# box, and the tutorial's automatic light frustum, on the `duel` scene (a long street under a low sun).
step 17-duel-fit-auto duel --technique shadowmap --filter pcf --fit auto
step 18-duel-fit-fixed duel --technique shadowmap --filter pcf --fit fixed
step 19-duel-fit-tutorial duel --technique shadowmap --filter pcf --fit tutorial
# A close-up of the sphere's shadow at 1600x900: stratified 4 taps and Poisson 16 taps, shadowlab's mean and the
# tutorial's arithmetic side by side (oiiotool, from OpenImageIO).
for v in shadowlab tutorial; do
  "$bin" render tutorial --size 1600x900 --shadow-size 1024 --threads 2 --filter stratified --poisson-taps 4 \
    --pcf-taps --bias slope --cull-front --poisson-variant $v --out "$out/.strat-$v.png"
  "$bin" render tutorial --size 1600x900 --shadow-size 1024 --threads 2 --filter poisson --poisson-taps 16 \
    --bias slope --cull-front --poisson-variant $v --out "$out/.p16-$v.png"
done
oiiotool "$out/.strat-shadowlab.png" --cut 300x200+800+400 "$out/.strat-tutorial.png" --cut 300x200+800+400 \
  "$out/.p16-shadowlab.png" --cut 300x200+800+400 "$out/.p16-tutorial.png" --cut 300x200+800+400 \
  --mosaic 4x1 -o "$out/poisson-variants-zoom.png"
rm -f "$out"/.strat-*.png "$out"/.p16-*.png
