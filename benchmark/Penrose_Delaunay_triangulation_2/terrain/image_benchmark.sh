#!/usr/bin/env bash
# Meshes of an image for its reconstruction: penrose_mesh against greedy
# insertion (delatin, on the image's luminance) and the regular grid of as
# many vertices, at 2% and 5% of the pixels, measured by an evaluator of
# their own (mesh_error.py) at every pixel of the luminance.
#
#   benchmark/Penrose_Delaunay_triangulation_2/terrain/image_benchmark.sh [IMAGE.png ...]
#
# Without arguments: the bundled data/test_image.png (512 x 512, flat shapes
# and gradients) and a photograph, SciPy's face.png of make_images.py
# (1024 x 768). Needs build/tools/penrose_mesh (built if missing), node and
# npm (delatin is installed from the npm registry into the output folder),
# Debian's python3-numpy, python3-scipy and python3-matplotlib. Writes $OUT
# (default build/image_benchmark)/image.csv
# (image,tool,fraction,vertices,triangles,seconds,rms,max,psnr; seconds: the
# whole process; rms and max: of the luminance, from 0 to 1; psnr: -20
# log10(rms)) and image_psnr.png, PSNR against vertices for each tool.
# FRACTIONS (default "0.02 0.05") sets the vertex counts as fractions of the
# pixels. Tools: "penrose_mesh" (--reconstruct, no density option: a sample
# then greedy insertion), "penrose_mesh --fit-heights" (the same, the
# luminance at the vertices fitted by least squares: no longer interpolating
# the image), "penrose_mesh --gradient" (importance sampling of
# the edges, for comparison), "triangulate_height_grid" (the library
# function, through the example mesh_height_grid, built if missing: a uniform
# sample, no border points, then greedy insertion), delatin at penrose_mesh's
# vertex count, and "grid", a regular grid of about as many vertices
# (grid_mesh.py).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../../.." && pwd)
build=${BUILD:-$root/build}
out=${OUT:-$build/image_benchmark}
fractions=${FRACTIONS:-0.02 0.05}
source "$here/tools_setup.sh"
example=$build/examples/Penrose_Delaunay_triangulation_2/mesh_height_grid
[ -x "$example" ] || cmake --build "$build" --target mesh_height_grid

images=("$@")
if [ $# -eq 0 ]; then
  "$python" "$here/make_images.py" "$out/images"
  images=("$root/data/test_image.png" "$out/images/face.png")
fi

seconds() {
  local s
  s=$(date +%s.%N); "$@" > /dev/null 2>&1; echo "$(date +%s.%N) - $s" | bc -l
}

# appends a row for the mesh $5 of tool $2 on image $1 at fraction $3, made in $4 seconds
row() {
  local r
  r=$("$python" "$here/mesh_error.py" "$f64" "$width" "$height" "$5" ${6:-})  # $6 unquoted: options
  psnr=$("$python" -c "import math, sys; print(f'{-20 * math.log10(float(sys.argv[1])):.4f}')" "$(echo "$r" | cut -d, -f3)")
  echo "$1,$2,$3,${r%%,*},$(echo "$r" | cut -d, -f2),$4,$(echo "$r" | cut -d, -f3,4),$psnr" >> "$csv"
}

csv="$out/image.csv"
echo "image,tool,fraction,vertices,triangles,seconds,rms,max,psnr" > "$csv"
for image in "${images[@]}"; do
  name=$(basename "${image%.*}")
  f64="$out/$name.f64"
  # the Rec. 709 luminance of the 8-bit colours, as penrose_mesh reads it
  read -r width height < <("$python" -c "
import sys, numpy as np, matplotlib.image as mi
c = mi.imread(sys.argv[1])[:, :, :3].astype(np.float64)
(0.2126 * c[:, :, 0] + 0.7152 * c[:, :, 1] + 0.0722 * c[:, :, 2]).astype('<f8').tofile(sys.argv[2])
print(c.shape[1], c.shape[0])" "$image" "$f64")
  for fraction in $fractions; do
    n=$("$python" -c "import sys; print(round(float(sys.argv[1]) * int(sys.argv[2]) * int(sys.argv[3])))" "$fraction" "$width" "$height")
    for option in "" --fit-heights --gradient; do
      mesh="$out/${name}_penrose${option}_$n.off"
      t=$(seconds "$build/tools/penrose_mesh" --density "image:$image" $option --points "$n" \
            --reconstruct "$out/${name}_penrose${option}_$n.png" --out-mesh "$mesh")
      sample=
      [ "$option" = --gradient ] && sample=" --sample"
      row "$name" "penrose_mesh${option:+ $option}" "$fraction" "$t" "$mesh" "--cells$sample"
    done
    mesh="$out/${name}_library_$n.off"
    t=$(seconds "$example" image "$image" "$n" "$mesh")
    row "$name" triangulate_height_grid "$fraction" "$t" "$mesh" --cells
    vertices=$(sed -n 2p "$out/${name}_penrose_$n.off" | cut -d' ' -f1)
    t=$(seconds node "$out/greedy_meshes.mjs" delatin "$f64" "$width" "$height" "$out/$name" vertices "$vertices")
    row "$name" delatin "$fraction" "$t" "$out/${name}_delatin_$vertices.off"
    "$python" "$here/grid_mesh.py" "$f64" "$width" "$height" "$vertices" "$out/${name}_grid_$vertices.off"
    row "$name" grid "$fraction" 0 "$out/${name}_grid_$vertices.off"
  done
done
"$python" "$here/plot_image_benchmark.py" "$csv" "$out"
cat "$csv"
