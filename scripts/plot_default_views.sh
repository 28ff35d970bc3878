#!/usr/bin/env bash
# The first picture of the models a user would expect to open, each rendered by `strata render`
# with no option but the size and spp (the default camera, sky, backdrop and display), side by
# side: Debian's assimp-testmodels and Embree's Cornell box (embree-tools; left out when absent).
# Usage: [STRATA=path/to/strata] bash scripts/plot_default_views.sh [OUT.png]
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-assets/readme/default-views.png}
size=200
strata=${STRATA:-build/app/strata}  # another build: STRATA=build-dev/app/strata
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
models=/usr/share/assimp/models
scenes=(
  "$models/OBJ/concave_polygon.obj"
  "$models/OBJ/WusonOBJ.obj"
  "$models/OBJ/cube_usemtl.obj"
  "$models/OBJ/regr_3429812.obj"
  "$models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb"
  "$models/glTF2/ClearCoat-glTF/ClearCoatTest.gltf"
  /usr/share/doc/embree3/models/cornell_box.obj
  "$models/OBJ/regr01.obj"
  "$models/glTF/CesiumMilkTruck/CesiumMilkTruck.gltf"
  "$models/OBJ/spider.obj"
  "$models/glTF2/textureTransform/TextureTransformTest.gltf"
  "$models/OBJ/cube_with_vertexcolors.obj"
)
names=()
for scene in "${scenes[@]}"; do
  [ -f "$scene" ] || { echo "skipped: $scene is absent" >&2; continue; }
  name=$(basename "$scene")
  "$strata" render "$scene" --width $size --height $size --spp 192 --out "$work/$name.png" 2>/dev/null
  names+=("$name")
done
# Each picture drawn at its own size, one screen pixel a pixel, with its file's name above it.
columns=4
rows=$(((${#names[@]} + columns - 1) / columns))
cell_width=$((size + 10))
cell_height=$((size + 30))
width=$((columns * cell_width))
height=$((rows * cell_height))
mkdir -p "$(dirname "$out")"
{
  echo "set terminal pngcairo noenhanced size $width,$height font 'DejaVu Sans,10'"
  echo "set output '$out'"
  echo "set multiplot"
  echo "unset border; unset tics; unset key; set xrange [-0.5:$size-0.5]; set yrange [-0.5:$size-0.5]"
  for i in "${!names[@]}"; do
    left=$(((i % columns) * cell_width + 5))
    bottom=$(((rows - 1 - i / columns) * cell_height + 5))
    echo "set lmargin at screen $left.0/$width; set rmargin at screen ($left.0+$size)/$width"
    echo "set bmargin at screen $bottom.0/$height; set tmargin at screen ($bottom.0+$size)/$height"
    echo "set title '${names[$i]}' offset 0,-0.6"
    echo "plot '$work/${names[$i]}.png' binary filetype=png with rgbimage"
  done
  echo "unset multiplot"
} | gnuplot
echo "wrote $out"
