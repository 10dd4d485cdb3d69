#!/usr/bin/env bash
# Installs the dependencies (Debian 12, as root), builds, runs the default scene (27 cubes
# settling in a periodic box, fluid 1 rank : DEM 1 rank) and plots its settling velocity.
# Output: runs/demo/ (ParaView: settling_cubes_volume.xdmf, settling_cubes_bodies.xdmf;
# CSV: settling_cubes_bodies.csv, settling_cubes_series.csv; plot: settling_cubes_settling.png).
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/setup_debian.sh
cmake -S . -B build -DLBDEM_TESTS=OFF
cmake --build build -j"$(nproc)"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
scene=configs/demo/settling_cubes.yaml
mpirun --oversubscribe -np 1 build/fluid_app/fluid_app "$scene" : -np 1 build/dem_app/dem_app "$scene"
/usr/bin/python3 tools/plot_settling.py "$scene"
