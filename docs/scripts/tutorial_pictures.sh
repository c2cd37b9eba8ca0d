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
