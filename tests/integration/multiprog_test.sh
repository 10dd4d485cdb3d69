#!/usr/bin/env bash
# One launch of both programs as a single MPI application, as Slurm's `srun --multi-prog`
# does (every rank has MPI_APPNUM 0): tools/cluster_launch.py writes the rank table, and a
# wrapper started by one plain `mpirun -np 3` runs the program the table names for its rank.
# The programs must tell their sides apart by name (fluid 2 : DEM 1) and finish the quick
# 8-cube scene as under mpirun's MPMD syntax.
# Usage: multiprog_test.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build=$(cd "$1" && pwd) src=$(cd "$2" && pwd)
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
sed -e "s|\.\./shapes/|$src/configs/shapes/|" -e "s|\.\./\.\./runs/bench|out|" \
  "$src/configs/bench/quick_cubes8_c27.yaml" > quick.yaml
/usr/bin/python3 "$src/tools/cluster_launch.py" quick.yaml --fluid 2 --dem 1 --build "$build" > launch.txt
cat launch.txt
grep -q "^0-1 .*fluid_app .*quick.yaml$" quick.multiprog || { cat quick.multiprog; exit 1; }
grep -q "^2 .*dem_app .*quick.yaml$" quick.multiprog || { cat quick.multiprog; exit 1; }
grep -q "srun .*--multi-prog .*quick.multiprog" quick.sbatch || { cat quick.sbatch; exit 1; }
cat > rank.sh <<'SH'
#!/usr/bin/env bash
# What srun --multi-prog does: pick this rank's line of the table.
rank=$OMPI_COMM_WORLD_RANK
while read -r ranks exe scene; do
  lo=${ranks%-*} hi=${ranks#*-}
  if [ "$rank" -ge "$lo" ] && [ "$rank" -le "$hi" ]; then exec "$exe" "$scene"; fi
done < quick.multiprog
echo "no program for rank $rank" >&2; exit 1
SH
chmod +x rank.sh
mpirun --bind-to none -np 3 ./rank.sh > run.log 2>&1 || { cat run.log; exit 1; }
grep -q "coupled fluid run finished after 21 steps" run.log || { cat run.log; exit 1; }
grep -q "coupled DEM run finished after 21 steps" run.log || { cat run.log; exit 1; }
grep -q "per-rank work (fluid, 2 ranks)" run.log || { cat run.log; exit 1; }
echo "PASS: both programs as one application (srun --multi-prog style), fluid 2 : DEM 1"
