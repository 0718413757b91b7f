#!/usr/bin/env bash
# On a fresh Debian 12 machine: installs the packages that building needs
# (.ci/install-dependencies, which does nothing when they are all there),
# builds penrose_mesh in Release, and samples and triangulates the bundled
# default input, the gradient ramp of the paper's Figure 7: 20,000 points,
# drawn into ramp.svg, with the statistics of the run in ramp.json.
set -euo pipefail
cd "$(dirname "$0")/.."

if [ "$(id -u)" -ne 0 ] && command -v sudo >/dev/null; then
  sudo bash .ci/install-dependencies
else
  bash .ci/install-dependencies
fi
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$(nproc)" --target penrose_mesh
build/tools/penrose_mesh --density ramp --points 20000 --svg ramp.svg --stats-json ramp.json
echo "wrote ramp.svg and ramp.json"
