#!/usr/bin/env bash
# Runs every benchmark that docs/performance.md quotes, once each, one after the other, so that
# the page's tables come from one run on one machine in the same minutes:
#   bash tools/performance_reference.sh [build-dir] [out-dir]
# Each program's output goes to out-dir/<benchmark>.txt (and to the terminal). Run it on a quiet
# machine: the figures are wall and CPU times.
set -euo pipefail
cd "$(dirname "$0")/.."
build=$(realpath "${1:-build}")
out=${2:-runs/performance}
mkdir -p "$out"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
mpirun=(mpirun --oversubscribe --bind-to none)
scene=configs/bench/cubes64_c100_particle_dt.yaml

step() {  # step NAME COMMAND...: runs it, keeps its output, says the load before it
  local name=$1
  shift
  echo "## $name ($(cut -d' ' -f1-3 /proc/loadavg) load before): $*" | tee "$out/$name.txt"
  "$@" 2>&1 | tee -a "$out/$name.txt"
}

step fluid_bench_np1 "${mpirun[@]}" -np 1 "$build/tools/fluid_bench" --porous
step fluid_bench_np2 "${mpirun[@]}" -np 2 "$build/tools/fluid_bench" --porous
step dem_bench "${mpirun[@]}" -np 1 "$build/tools/dem_bench" --cubes 1000 --phi 0.3 --steps 1000 \
  --substeps 10
step porosity_bench "$build/tools/porosity_bench" "$scene" --updates 200 --lookup both
step lattice_bench "$build/tools/lattice_bench" "$scene" --force --steps 20 --repeat 8
step lattice_bench_spheres "$build/tools/lattice_bench" configs/bench/spheres967.yaml --force \
  --steps 10 --repeat 4
step coupled_bench /usr/bin/python3 tools/coupled_bench.py --build "$build" \
  --only cubes64_c100_particle_dt,fluid58,spheres967,fluid135
echo "outputs in $out"
