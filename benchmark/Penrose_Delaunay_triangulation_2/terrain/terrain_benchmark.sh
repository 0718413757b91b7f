#!/usr/bin/env bash
# Terrain meshes of penrose_mesh against greedy insertion (delatin) and RTIN
# (@mapbox/martini) at equal vertex counts, measured by an evaluator of
# their own (mesh_error.py) at every node of the height grid.
#
#   benchmark/Penrose_Delaunay_triangulation_2/terrain/terrain_benchmark.sh [DEM.asc|DEM.png ...]
#
# Without arguments: the bundled data/terrain.png and two synthetic DEMs of
# make_dems.py (volcano, hills). Needs build/tools/penrose_mesh (built if
# missing), node and npm (delatin and @mapbox/martini are installed from the
# npm registry into the output folder), Debian's python3-numpy and
# python3-matplotlib. Writes $OUT (default build/terrain_benchmark)/terrain.csv
# (dem,tool,target,vertices,triangles,seconds,rms,max,uncovered; seconds: the
# whole process, the best of RUNS runs, default 1) and one plot of RMS and maximum error against vertices a DEM.
# POINTS (default "5000 20000 80000") sets the penrose_mesh vertex counts; the
# other tools are given the vertex count that penrose_mesh reached. Then, for
# the maximum error E of delatin's mesh at each count, penrose_mesh --max-error E
# and delatin refined to E (tools "penrose_mesh --max-error" and "delatin
# --max-error", target E) compare the vertices and the time that E takes.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../../.." && pwd)
build=${BUILD:-$root/build}
out=${OUT:-$build/terrain_benchmark}
points=${POINTS:-5000 20000 80000}
source "$here/tools_setup.sh"

dems=()
if [ $# -eq 0 ]; then
  "$python" "$here/make_dems.py" "$out/dems" --png "$root/data/terrain.png" >/dev/null
  "$python" "$here/make_dems.py" "$out/dems" >/dev/null
  dems=("$out/dems/terrain.asc" "$out/dems/volcano.asc" "$out/dems/hills.asc")
else
  for f in "$@"; do
    case "$f" in
      *.png) "$python" "$here/make_dems.py" "$out/dems" --png "$f" >/dev/null
             dems+=("$out/dems/$(basename "${f%.*}").asc") ;;
      *.asc) dems+=("$f") ;;
      *) echo "terrain_benchmark.sh: $f: a DEM is a 16-bit PNG or an .asc with cellsize 1 and its corner at the origin" >&2; exit 2 ;;
    esac
  done
fi

# the best time: other work on the machine only ever slows a run down
seconds() {
  local best= s t
  for ((r = 0; r < ${RUNS:-1}; ++r)); do
    s=$(date +%s.%N); "$@" > /dev/null; t=$(echo "$(date +%s.%N) - $s" | bc -l)
    if [ -z "$best" ] || [ "$(echo "$t < $best" | bc -l)" = 1 ]; then best=$t; fi
  done
  echo "$best"
}

csv="$out/terrain.csv"
echo "dem,tool,target,vertices,triangles,seconds,rms,max,uncovered" > "$csv"
for asc in "${dems[@]}"; do
  name=$(basename "${asc%.asc}")
  f64="$out/dems/$name.f64"
  if [ ! -f "$f64" ]; then
    "$python" -c "import numpy as np, sys; np.loadtxt(sys.argv[1], skiprows=5).astype('<f8').tofile(sys.argv[2])" "$asc" "$f64"
  fi
  read -r width height < <(awk '/^ncols/{w=$2} /^nrows/{h=$2} END{print w, h}' "$asc")
  for n in $points; do
    mesh="$out/${name}_penrose_$n.off"
    t=$(seconds "$build/tools/penrose_mesh" --terrain "$asc" --points "$n" --boundary --out-mesh "$mesh")
    row=$("$python" "$here/mesh_error.py" "$f64" "$width" "$height" "$mesh" --cells)
    echo "$name,penrose_mesh,$n,${row%%,*},$(echo "$row" | cut -d, -f2),$t,$(echo "$row" | cut -d, -f3-)" >> "$csv"
    vertices=${row%%,*}
    for tool in delatin martini; do
      t=$(seconds node "$out/greedy_meshes.mjs" "$tool" "$f64" "$width" "$height" "$out/$name" vertices "$vertices")
      row=$("$python" "$here/mesh_error.py" "$f64" "$width" "$height" "$out/${name}_${tool}_$vertices.off")
      echo "$name,$tool,$vertices,${row%%,*},$(echo "$row" | cut -d, -f2),$t,$(echo "$row" | cut -d, -f3-)" >> "$csv"
      [ "$tool" = delatin ] && e=$(echo "$row" | cut -d, -f4)
    done
    mesh="$out/${name}_penrose_e$e.off"
    t=$(seconds "$build/tools/penrose_mesh" --terrain "$asc" --max-error "$e" --out-mesh "$mesh")
    row=$("$python" "$here/mesh_error.py" "$f64" "$width" "$height" "$mesh" --cells)
    echo "$name,penrose_mesh --max-error,$e,${row%%,*},$(echo "$row" | cut -d, -f2),$t,$(echo "$row" | cut -d, -f3-)" >> "$csv"
    t=$(seconds node "$out/greedy_meshes.mjs" delatin "$f64" "$width" "$height" "$out/$name" error "$e")
    row=$("$python" "$here/mesh_error.py" "$f64" "$width" "$height" "$out/${name}_delatin_$e.off")
    echo "$name,delatin --max-error,$e,${row%%,*},$(echo "$row" | cut -d, -f2),$t,$(echo "$row" | cut -d, -f3-)" >> "$csv"
  done
done
"$python" "$here/plot_terrain_benchmark.py" "$csv" "$out"
cat "$csv"
