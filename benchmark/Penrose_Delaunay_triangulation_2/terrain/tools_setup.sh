# Sourced by terrain_benchmark.sh and image_benchmark.sh, after they set
# `here` (their folder), `build` (the build folder) and `out` (the output
# folder): makes `out` absolute,
# builds penrose_mesh in `build` if it is missing, and installs delatin and
# @mapbox/martini from the npm registry into `out`, beside greedy_meshes.mjs.
python=/usr/bin/python3
mkdir -p "$out"
out=$(cd "$out" && pwd)

[ -x "$build/tools/penrose_mesh" ] || cmake --build "$build" --target penrose_mesh
if [ ! -d "$out/node_modules/delatin" ] || [ ! -d "$out/node_modules/@mapbox/martini" ]; then
  (cd "$out" && npm install --no-save --no-audit --no-fund --silent delatin @mapbox/martini)
fi
cp "$here/greedy_meshes.mjs" "$out/"
