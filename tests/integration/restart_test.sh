#!/usr/bin/env bash
# Checkpoint and restart of both programs together (docs/reliability.md), fluid NF : DEM ND:
#   1. the whole run straight (79 steps);
#   2. the first half (time.end cut to step 40, checkpoint every 10 steps, keep 2), then
#      --restart from the checkpoint folder to the original end: the body trace and the
#      momentum audit must equal the straight run's byte for byte, and only 2 checkpoints
#      may remain;
#   3. the same checkpoint continued on NF + 1 fluid ranks: equal within round-off;
#   4. SIGTERM to one fluid rank mid-run: both programs write a checkpoint, end with status 0
#      and print the restart command; the restart reproduces the straight run byte for byte;
#   5. refusals: a flipped byte in the populations, a truncated fluid half, a missing DEM
#      half, a missing DEM journal part, another scene (viscosity changed), another DEM rank
#      count.
# With a fifth argument `quick`, parts 1 to 4 only; with `overlap`, parts 1 to 4 with
# coupling.overlap (the fluid one step behind; it waits for the states at agreement steps,
# so checkpoints hold one step of both programs and the restart is still byte for byte); with
# `control`, parts 1 to 4 under fluid.mean_velocity_control without feed-forward (the
# controller alone finds the force, so its integral must cross the restart); with `rebalance`,
# parts 1 and 2 with fluid.decomposition: balanced and the restart keeping the checkpoint's cuts
# (fluid.rebalance_above: 100, byte for byte), then the same checkpoint continued on NF ranks
# cut anew by the work measured at the checkpoint (rebalance_above: 1): another layout, equal
# within round-off; then the straight run checked at step 40 while it runs
# (fluid.rebalance_interval): cut anew, it must continue exactly as that restart did, byte for
# byte; where the new cuts would not lower the blocks' imbalance, it keeps its cuts and equals
# the straight run byte for byte.
# Usage: restart_test.sh BUILD_DIR SOURCE_DIR NF ND [quick|overlap|control|rebalance]
set -euo pipefail
build=$1 src=$2 nf=$3 nd=$4 mode=${5:-}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
work=$(mktemp -d)
mpirun_pid=""
cleanup() {
  [ -n "$mpirun_pid" ] && kill "$mpirun_pid" 2> /dev/null || true
  rm -rf "$work"
}
trap cleanup EXIT
cd "$work"
started=$(date +%s.%N)
fluid=$build/fluid_app/fluid_app dem=$build/dem_app/dem_app
run() {  # run LOG NF ND [fluid/dem options...] : scene is scene.yaml
  local log=$1 a=$2 b=$3
  shift 3
  mpirun -np "$a" "$fluid" "$@" scene.yaml : -np "$b" "$dem" "$@" scene.yaml > "$log" 2>&1
}
fail() { echo "FAIL: $*"; exit 1; }
rebalance_above=100 rebalance_interval=""
scene() {  # scene END [extra coupling lines]
  sed "s/end: 2.0e-2/end: $1/" "$src/tests/integration/restart_scene.yaml" > scene.yaml
  [ "$mode" = control ] && sed -i 's/^  tau: 0.6$/  tau: 0.6\n  mean_velocity_control: {target: [0, 0, 0], gain: 0.3, integral_gain: 0.05, feed_forward: false}/' scene.yaml
  [ "$mode" = rebalance ] \
    && sed -i "s/^fluid:$/fluid:\n  decomposition: balanced\n  rebalance_above: $rebalance_above${rebalance_interval:+\\n  rebalance_interval: $rebalance_interval}/" scene.yaml
  shift
  [ "$mode" = overlap ] && set -- "$@" "overlap: true"
  for line in "$@"; do printf '  %s\n' "$line" >> scene.yaml; done
}
ckdir=restart_sphere_checkpoints

# 1. straight
scene 2.0e-2
run straight.log "$nf" "$nd" || { cat straight.log; fail "straight run"; }
cp restart_sphere_bodies.csv straight_bodies.csv
cp restart_sphere_momentum.csv straight_momentum.csv
rm -rf "$ckdir"

# 2. half, stop, restart
scene 1.0e-2 "checkpoint_interval: 2.5e-3"
run half.log "$nf" "$nd" || { cat half.log; fail "first half"; }
n=$(ls "$ckdir"/*.fluid.h5 | wc -l)
[ "$n" = 2 ] || { ls "$ckdir"; fail "checkpoint_keep 2 left $n fluid halves"; }
[ -f "$ckdir/restart_sphere_step0000000040.dem.h5" ] || { ls "$ckdir"; fail "no step-40 DEM half"; }
# The DEM half's journal: one part per DEM rank, pruned with its half.
n=$(ls "$ckdir"/*.dem.rank*.h5 | wc -l)
[ "$n" = $((2 * nd)) ] || { ls "$ckdir"; fail "$n DEM journal parts, expected 2 x $nd"; }
cp -r "$ckdir" saved_checkpoints
cp restart_sphere_bodies.csv half_bodies.csv
cp restart_sphere_momentum.csv half_momentum.csv
scene 2.0e-2
run restarted.log "$nf" "$nd" --restart "$ckdir" || { cat restarted.log; fail "restart"; }
grep -q "restart from .*step0000000040 at step 40" restarted.log || { cat restarted.log; fail "no restart line"; }
cmp restart_sphere_bodies.csv straight_bodies.csv || fail "body trace after restart differs from the straight run"
cmp restart_sphere_momentum.csv straight_momentum.csv || fail "momentum audit after restart differs"
echo "restart at step 40 of 79 ($nf:$nd): body trace and momentum audit identical byte for byte"
if [ "$mode" = rebalance ]; then
  grep -q "kept from the checkpoint" restarted.log || { cat restarted.log; fail "layout not kept"; }
  grep -m1 "decomposition" restarted.log
fi

# 3. another fluid rank count (rebalance: the same count, cut by the measured work)
rm -rf "$ckdir" && cp -r saved_checkpoints "$ckdir"
cp half_bodies.csv restart_sphere_bodies.csv && cp half_momentum.csv restart_sphere_momentum.csv
nf2=$((nf + 1))
if [ "$mode" = rebalance ]; then
  nf2=$nf rebalance_above=1
  scene 2.0e-2
fi
run ranks.log "$nf2" "$nd" --restart "$ckdir" || { cat ranks.log; fail "restart on $nf2 fluid ranks"; }
if [ "$mode" = rebalance ]; then
  grep -q "rebalanced by the work measured at the checkpoint" ranks.log \
    || { cat ranks.log; fail "no rebalance at the restart"; }
  # New cuts regroup the partial loads: identical bits would mean the layout did not change.
  ! cmp -s restart_sphere_bodies.csv straight_bodies.csv || fail "the new cuts changed nothing"
  grep -m1 "decomposition" ranks.log
  [ "$(grep -m1 -o 'imbalance of the weighted work [0-9.]*' half.log)" ] || fail "no imbalance line"
fi
/usr/bin/python3 - straight_bodies.csv restart_sphere_bodies.csv <<'PY'
import csv, sys
a = list(csv.reader(open(sys.argv[1]))); b = list(csv.reader(open(sys.argv[2])))
assert len(a) == len(b), f"{len(a)} rows against {len(b)}"
worst = 0.0
for ra, rb in zip(a[1:], b[1:]):
    for x, y in zip(ra, rb):
        x, y = float(x), float(y)
        worst = max(worst, abs(x - y) / max(abs(x), abs(y), 1e-30) if abs(x - y) > 1e-300 else 0.0)
# Positions, velocities and loads: summation order only (a few ulps growing over 40 steps);
# near-zero components make the relative figure large, so the test bounds it loosely.
print(f"restart on another fluid layout: largest relative difference {worst:.3e}")
assert worst < 1e-6, worst
PY
if [ "$mode" = rebalance ]; then
  # 4. The straight run again, cut anew at step 40 while it runs (no checkpoint, no restart).
  cp restart_sphere_bodies.csv restarted_bodies.csv && cp restart_sphere_momentum.csv restarted_momentum.csv
  rm -rf "$ckdir" restart_sphere_bodies.csv restart_sphere_momentum.csv
  rebalance_interval=1.02e-2  # 40 steps of 2.552e-4 s
  scene 2.0e-2
  run inrun.log "$nf" "$nd" || { cat inrun.log; fail "run rebalanced during the run"; }
  grep -m1 "step 40: load imbalance of the weighted work" inrun.log \
    || { cat inrun.log; fail "no in-run check at step 40"; }
  if grep -q "step 40: .*(new cuts by the measured work would give [0-9.]*): cuts kept" inrun.log; then
    # New slabs would not lower the blocks' imbalance (one small body on a grid of 2 x 2 x 2
    # blocks): the run keeps its cuts and goes on as the straight run, byte for byte.
    cmp restart_sphere_bodies.csv straight_bodies.csv || fail "the body trace changed where the cuts were kept"
    cmp restart_sphere_momentum.csv straight_momentum.csv || fail "the momentum audit changed where the cuts were kept"
    echo "in-run check at step 40 ($nf:$nd): new cuts would not help, cuts kept, identical byte for byte to the straight run"
  else
    grep -q "step 40: load imbalance of the weighted work [0-9.]* -> [0-9.]*" inrun.log \
      || { cat inrun.log; fail "no in-run rebalancing at step 40"; }
    grep -q "the fluid cut its lattice anew" inrun.log || { cat inrun.log; fail "the DEM kept the old boxes"; }
    cmp restart_sphere_bodies.csv restarted_bodies.csv \
      || fail "the body trace of the in-run rebalancing differs from the restart cut at step 40"
    cmp restart_sphere_momentum.csv restarted_momentum.csv \
      || fail "the momentum audit of the in-run rebalancing differs from the restart cut at step 40"
    echo "in-run rebalancing at step 40 ($nf:$nd): identical byte for byte to the restart cut there"
  fi
  echo "PASS: restart with rebalancing ($nf:$nd) in $(echo "$(date +%s.%N) - $started" | bc) s"
  exit 0
fi

# 4. SIGTERM mid-run
rm -rf "$ckdir" restart_sphere_bodies.csv restart_sphere_momentum.csv
scene 2.0e-2
mpirun -np "$nf" "$fluid" scene.yaml : -np "$nd" "$dem" scene.yaml > term.log 2>&1 &
mpirun_pid=$!
for _ in $(seq 600); do
  [ -f restart_sphere_bodies.csv ] && [ "$(wc -l < restart_sphere_bodies.csv)" -ge 6 ] && break
  kill -0 "$mpirun_pid" 2> /dev/null || break
  sleep 0.05
done
fluid_pid=$(pgrep -P "$mpirun_pid" -x fluid_app | head -1 || true)
[ -n "$fluid_pid" ] || { cat term.log; fail "no fluid_app child to signal (the run ended too early)"; }
kill -TERM "$fluid_pid"
rc=0
wait "$mpirun_pid" || rc=$?
mpirun_pid=""
[ "$rc" = 0 ] || { cat term.log; fail "exit status $rc after SIGTERM"; }
grep -q "stopped on request" term.log || { cat term.log; fail "no stop message"; }
grep -q "continue with: mpirun" term.log || { cat term.log; fail "no restart command"; }
grep "stopped on request" term.log | head -2
run term_restart.log "$nf" "$nd" --restart "$ckdir" || { cat term_restart.log; fail "restart after SIGTERM"; }
cmp restart_sphere_bodies.csv straight_bodies.csv || fail "trace after SIGTERM + restart differs"
cmp restart_sphere_momentum.csv straight_momentum.csv || fail "audit after SIGTERM + restart differs"
echo "SIGTERM: checkpoint written, restart identical byte for byte"

if [ "$mode" = quick ] || [ "$mode" = overlap ] || [ "$mode" = control ]; then
  echo "PASS: restart ($nf:$nd) in $(echo "$(date +%s.%N) - $started" | bc) s"
  exit 0
fi

# 5. refusals, each must end with status != 0 and name the problem
refuse() {  # refuse NAME REGEX NF ND [RESTART_ARG]
  local name=$1 regex=$2
  if run "$name.log" "$3" "$4" --restart "${5:-bad}"; then cat "$name.log"; fail "$name: accepted"; fi
  grep -q -- "$regex" "$name.log" || { cat "$name.log"; fail "$name: no message matching '$regex'"; }
  grep -m1 -o -- "$regex.*" "$name.log" | cut -c1-160
}
prefix=bad/restart_sphere_step0000000040
fresh() { rm -rf bad && mkdir bad && cp saved_checkpoints/restart_sphere_step0000000040.* bad/; }
fresh
/usr/bin/python3 - "$prefix.fluid.h5" <<'PY'
import h5py, sys
with h5py.File(sys.argv[1], "r+") as f:
    f["populations"][3, 2, 2, 2] = f["populations"][3, 2, 2, 2] * (1 + 1e-15) + 1e-12
PY
refuse corrupted "do not match their checksum" "$nf" "$nd"
fresh && truncate -s 2000 "$prefix.fluid.h5"
refuse truncated "not a readable checkpoint" "$nf" "$nd"
fresh && rm "$prefix.dem.h5"
refuse missing_half "is missing; a restart needs both halves" "$nf" "$nd" "$prefix.fluid.h5"
fresh && rm "$prefix.dem.rank0.h5"
refuse missing_part "journal part .* of DEM rank 0 is missing" "$nf" "$nd"
fresh && sed -i 's/viscosity: 1.0e-6/viscosity: 1.1e-6/' scene.yaml
refuse other_scene "written for another scene" "$nf" "$nd"
scene 2.0e-2
fresh
refuse dem_ranks "dem_app ranks, this run has" "$nf" "$((nd + 1))"
echo "PASS: restart ($nf:$nd) in $(echo "$(date +%s.%N) - $started" | bc) s"
