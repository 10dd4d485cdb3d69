#!/usr/bin/env bash
# Record/replay through the real entry points (ranks: fluid 2 : DEM 1 recorded and replayed;
# then fluid 3 : DEM 2):
#   1. a coupled run records every packet (coupling.record: one part per DEM rank);
#   2. `fluid_app --replay` alone reproduces the recorded loads bit for bit;
#   3. `dem_app --replay` alone reproduces the recorded states bit for bit;
#   4. a recording with one bit flipped in one load is detected, naming the step.
# With a fifth argument `overlap`, the same with coupling.overlap: true; with `rebalance`, with
# the fluid cut anew every 10 steps while it runs (fluid.rebalance_interval, rebalance_above: 1),
# which the replayed fluid repeats at the same steps.
# Usage: replay_test.sh BUILD_DIR SOURCE_DIR FLUID_RANKS DEM_RANKS [overlap]
set -euo pipefail
build=$1 src=$2 nf=$3 nd=$4 mode=${5:-}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
mpirun=(mpirun --oversubscribe)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cp "$src/tests/integration/replay_scene.yaml" "$work/scene.yaml"
printf '  record: rec.h5\n' >> "$work/scene.yaml"
if [ "$mode" = overlap ]; then printf '  overlap: true\n' >> "$work/scene.yaml"; fi
if [ "$mode" = rebalance ]; then
  sed -i 's/^fluid:$/fluid:\n  decomposition: balanced\n  rebalance_above: 1\n  rebalance_interval: 2.5e-3/' "$work/scene.yaml"
fi
cd "$work"

"${mpirun[@]}" -np "$nf" "$build/fluid_app/fluid_app" scene.yaml : -np "$nd" "$build/dem_app/dem_app" scene.yaml > run.log 2>&1 \
  || { cat run.log; echo "FAIL: the recorded coupled run failed"; exit 1; }

"${mpirun[@]}" -np "$nf" "$build/fluid_app/fluid_app" --replay rec.h5 scene.yaml > fluid.log 2>&1 \
  || { cat fluid.log; echo "FAIL: fluid replay"; exit 1; }
grep -q "loads of all 40 steps match the recording bit for bit" fluid.log \
  || { cat fluid.log; echo "FAIL: fluid replay did not confirm a bit-for-bit match"; exit 1; }
if [ "$mode" = rebalance ]; then
  grep -q "the fluid cut its lattice anew" run.log || { cat run.log; echo "FAIL: no in-run cut"; exit 1; }
  [ "$(grep -c "rebalanced at step" fluid.log)" = "$(grep -c "rebalanced at step" run.log)" ] \
    || { cat fluid.log; echo "FAIL: the replay did not cut where the recorded run did"; exit 1; }
fi

"${mpirun[@]}" -np "$nd" "$build/dem_app/dem_app" --replay rec.h5 scene.yaml > dem.log 2>&1 \
  || { cat dem.log; echo "FAIL: DEM replay"; exit 1; }
grep -q "states of all 40 steps match the recording bit for bit" dem.log \
  || { cat dem.log; echo "FAIL: DEM replay did not confirm a bit-for-bit match"; exit 1; }

# One part per DEM rank, nothing else under the recording's name.
parts=$(ls rec*.h5 | tr '\n' ' ')
expected=$(for ((r = 0; r < nd; r++)); do printf 'rec.rank%d.h5 ' "$r"; done)
[ "$parts" = "$expected" ] || { echo "FAIL: recording files '$parts', expected '$expected'"; exit 1; }

# Flip the lowest bit of one recorded force component: the fluid replay must notice.
/usr/bin/python3 - <<'PY'
import h5py, numpy as np
with h5py.File("rec.rank0.h5", "r+") as f:
    loads = f["loads"][...]
    k = len(loads) // 2
    fz = np.array([loads["f"][k][2]], dtype=np.float64)
    fz.view(np.uint64)[0] ^= np.uint64(1)
    loads["f"][k, 2] = fz[0]
    f["loads"][...] = loads
    print(f"flipped the lowest bit of loads[{k}].f[2] (step {loads['step'][k]})")
PY
if "${mpirun[@]}" -np "$nf" "$build/fluid_app/fluid_app" --replay rec.h5 scene.yaml > tampered.log 2>&1; then
  cat tampered.log; echo "FAIL: a tampered recording replayed without error"; exit 1
fi
grep -q "differ from the recording" tampered.log \
  || { cat tampered.log; echo "FAIL: the mismatch was not reported"; exit 1; }
grep "differ from the recording" tampered.log | head -1
echo "PASS: record ($nf:$nd${mode:+, $mode}), fluid replay and DEM replay bit for bit, tampering detected"
