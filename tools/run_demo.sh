#!/usr/bin/env bash
# The main job: installs the dependencies (Debian 12, as root), builds, and runs the small
# hindered-settling study (configs/study/small.yaml: 27 spheres and 27 volume-equivalent cubes
# at phi = 0.1, 0.2, 0.3 in a triply periodic box, plus one single-body run per shape for u_T;
# fluid 1 rank : DEM 1 rank per run; resumable). Output: runs/study/small/ (summary.csv,
# settling.png, rdf.png, correlation.png, vacf.png; per run the ParaView files). docs/study.md.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/setup_debian.sh
# Tests stay on so that tools/run_tests.sh can reuse this build directory in either order.
cmake -S . -B build -DLBDEM_TESTS=ON
cmake --build build -j"$(nproc)" --target fluid_app dem_app
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
/usr/bin/python3 tools/study.py configs/study/small.yaml --build build "$@"
