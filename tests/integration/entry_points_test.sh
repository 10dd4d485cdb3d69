#!/usr/bin/env bash
# The real binaries fail cleanly on misuse (each case must end within the timeout CTest sets):
#   1. a coupled scene launched with fluid_app alone: one message giving the mpirun line;
#   2. a bad scene launched MPMD (fluid 2 : DEM 1): the message names file, line and key,
#      is printed once, and the exit status is non-zero;
#   3. --check on both binaries validates without running and prints derived numbers.
# Usage: entry_points_test.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build=$1 src=$2
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
cp "$src/tests/integration/replay_scene.yaml" scene.yaml

if mpirun --oversubscribe -np 1 "$build/fluid_app/fluid_app" scene.yaml > alone.log 2>&1; then
  cat alone.log; echo "FAIL: a coupled scene ran without dem_app"; exit 1
fi
grep -q "mpirun -np" alone.log || { cat alone.log; echo "FAIL: no launch line in the message"; exit 1; }

sed 's/tau: 0.6/tau: 0.45/' scene.yaml > bad.yaml
if mpirun --oversubscribe -np 2 "$build/fluid_app/fluid_app" bad.yaml : -np 1 "$build/dem_app/dem_app" bad.yaml > bad.log 2>&1; then
  cat bad.log; echo "FAIL: a bad scene ran"; exit 1
fi
n=$(grep -c "bad.yaml:11: fluid.tau: expected a value > 0.5, got 0.45" bad.log || true)
[ "$n" = 1 ] || { cat bad.log; echo "FAIL: expected the tau message exactly once, got $n"; exit 1; }

mpirun --oversubscribe -np 1 "$build/fluid_app/fluid_app" --check scene.yaml > check_fluid.log 2>&1 \
  || { cat check_fluid.log; echo "FAIL: fluid_app --check"; exit 1; }
grep -q "dt = " check_fluid.log || { cat check_fluid.log; echo "FAIL: no derived numbers"; exit 1; }
mpirun --oversubscribe -np 1 "$build/dem_app/dem_app" --check scene.yaml > check_dem.log 2>&1 \
  || { cat check_dem.log; echo "FAIL: dem_app --check"; exit 1; }
grep -q "Rayleigh time" check_dem.log || { cat check_dem.log; echo "FAIL: no DEM numbers"; exit 1; }
echo "PASS: missing partner, bad scene (printed once), --check on both binaries"
