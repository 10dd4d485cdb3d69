#!/usr/bin/env bash
# The main job: installs the dependencies (Debian 12, as root), builds, and runs the small
# hindered-settling study (configs/study/small.yaml: 27 spheres and 27 volume-equivalent cubes
# at phi = 0.1, 0.2, 0.3 in a triply periodic box, plus one single-body run per shape for u_T;
# fluid 1 rank : DEM 1 rank per run; resumable). Output: runs/study/small/ (summary.csv,
# settling.png, rdf.png, correlation.png, vacf.png; per run the ParaView files, and a picture of
# the bodies and the fluid where ParaView is installed). docs/study.md.
# Usage: run_demo.sh [--with-paraview] [study.py options]
#   --with-paraview  installs ParaView too (tools/setup_debian.sh --with-paraview), so that the
#                    study draws its pictures
set -euo pipefail
cd "$(dirname "$0")/.."
setup=()
if [ "${1:-}" = --with-paraview ]; then
  setup=(--with-paraview)
  shift
fi
bash tools/setup_debian.sh "${setup[@]}"
# Tests stay on so that tools/run_tests.sh can reuse this build directory in either order.
cmake -S . -B build -DLBDEM_TESTS=ON
cmake --build build -j"$(nproc)" --target fluid_app dem_app
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
/usr/bin/python3 tools/study.py configs/study/small.yaml --build build "$@"
if command -v pvbatch > /dev/null && command -v xvfb-run > /dev/null; then
  echo "run_demo: pictures of each run: runs/study/small/*/<run name>.png (pvbatch)"
else
  echo "run_demo: no pictures of the runs: ParaView is not installed. For them:" \
    "bash tools/run_demo.sh --with-paraview (installs about 0.8 GB; the finished runs are" \
    "skipped, only the pictures are drawn)"
fi
