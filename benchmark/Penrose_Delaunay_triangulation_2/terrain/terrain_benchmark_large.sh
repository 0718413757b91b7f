#!/usr/bin/env bash
# The whole process of penrose_mesh --terrain against delatin (greedy
# insertion in JavaScript) on a large grid: by default 10^6 vertices on the
# 4096 x 4096 synthetic terrain of penrose_data_generator, read as an ESRI
# ASCII grid, meshes written as OFF.
#
#   benchmark/Penrose_Delaunay_triangulation_2/terrain/terrain_benchmark_large.sh
#
# SIZE (default 4096), POINTS (default 1000000), ROUNDS (default 5): the
# tools run alternately, ROUNDS times each, and the medians of their wall
# times are compared (other work on the machine slows both alike). Needs
# build/tools/penrose_mesh and penrose_data_generator (built if missing),
# node and npm (delatin is installed from the npm registry into the output
# folder), Debian's python3-numpy and python3-matplotlib. Writes $OUT
# (default build/terrain_benchmark_large)/times.csv (round,tool,seconds) and
# prints the medians, their ratio, penrose_mesh's own breakdown (read:
# reading and density; sample, triangulate: the Penrose sample; refine:
# greedy insertion) and, with QUALITY=1, both meshes' RMS and maximum errors
# over every cell (minutes of Python).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../../.." && pwd)
build=${BUILD:-$root/build}
out=${OUT:-$build/terrain_benchmark_large}
size=${SIZE:-4096}
points=${POINTS:-1000000}
rounds=${ROUNDS:-5}
python=/usr/bin/python3
mkdir -p "$out/dems"
out=$(cd "$out" && pwd)

for t in penrose_mesh penrose_data_generator; do
  [ -x "$build/tools/$t" ] || cmake --build "$build" --target "$t"
done
[ -d "$out/node_modules/delatin" ] || (cd "$out" && npm install --no-save --no-audit --no-fund --silent delatin @mapbox/martini)
cp "$here/greedy_meshes.mjs" "$out/"

name=terrain$size
dem="$out/dems/$name"
if [ ! -f "$dem.asc" ]; then
  "$build/tools/penrose_data_generator" --terrain "$dem.png" --size "$size"
  "$python" "$here/make_dems.py" "$out/dems" --png "$dem.png" >/dev/null
fi

seconds() {
  local s t
  s=$(date +%s.%N); "$@" > /dev/null 2> "$out/last.log"; t=$(date +%s.%N)
  echo "$t - $s" | bc -l
}
median() { sort -n | awk '{v[NR] = $1} END {print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}'; }

csv="$out/times.csv"
echo "round,tool,seconds" > "$csv"
for ((r = 1; r <= rounds; ++r)); do
  t=$(seconds "$build/tools/penrose_mesh" --terrain "$dem.asc" --points "$points" --out-mesh "$out/${name}_penrose.off")
  echo "$r,penrose_mesh,$t" >> "$csv"
  grep -o "in [0-9.]* s (.*" "$out/last.log" | sed "s/^/penrose_mesh round $r: /"
  t=$(seconds node "$out/greedy_meshes.mjs" delatin "$dem.f64" "$size" "$size" "$out/$name" vertices "$points")
  echo "$r,delatin,$t" >> "$csv"
done
p=$(grep ',penrose_mesh,' "$csv" | cut -d, -f3 | median)
d=$(grep ',delatin,' "$csv" | cut -d, -f3 | median)
echo "$size x $size, $points vertices, medians of $rounds alternating runs (load average: $(cut -d' ' -f1-3 /proc/loadavg)):"
echo "penrose_mesh $p s, delatin $d s, ratio $(echo "$p / $d" | bc -l | cut -c1-5)"
if [ "${QUALITY:-0}" = 1 ]; then
  echo "penrose_mesh vertices,triangles,rms,max,uncovered: $("$python" "$here/mesh_error.py" "$dem.f64" "$size" "$size" "$out/${name}_penrose.off" --cells)"
  echo "delatin      vertices,triangles,rms,max,uncovered: $("$python" "$here/mesh_error.py" "$dem.f64" "$size" "$size" "$out/${name}_delatin_$points.off")"
fi
