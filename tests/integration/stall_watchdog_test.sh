#!/usr/bin/env bash
# The stall watchdog: a coupled run (fluid 1 : DEM 1) whose DEM rank is stopped with SIGSTOP, as
# a hung node would be, must end the whole job within coupling.stall_timeout (3 s) plus a margin,
# with one message naming the silent side, the last completed exchange and the last checkpoint.
# With "automatic" the scene sets no stall_timeout: the automatic limit (60 s once the run is
# stepping, docs/reliability.md) must end the job, within 60 s plus the same margin.
# Prints the time from SIGSTOP to the end of the job.
# Usage: stall_watchdog_test.sh BUILD_DIR SOURCE_DIR [automatic]
set -euo pipefail
build=$1 src=$2 mode=${3:-fixed}
limit=3
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
work=$(mktemp -d)
mpirun_pid=""
cleanup() {
  # Only what this test started: the stopped rank is resumed so that nothing stays behind.
  [ -n "${dem_pid:-}" ] && kill -CONT "$dem_pid" 2> /dev/null || true
  [ -n "$mpirun_pid" ] && kill "$mpirun_pid" 2> /dev/null || true
  rm -rf "$work"
}
trap cleanup EXIT
cd "$work"
cp "$src/tests/integration/stall_scene.yaml" scene.yaml
if [ "$mode" = automatic ]; then
  sed -i '/stall_timeout/d' scene.yaml
  limit=60
fi
mpirun --oversubscribe -np 1 "$build/fluid_app/fluid_app" scene.yaml : \
  -np 1 "$build/dem_app/dem_app" scene.yaml > run.log 2>&1 &
mpirun_pid=$!

# Wait until the coupled run is stepping (a progress line), at most 60 s.
for _ in $(seq 600); do
  grep -q " t=" run.log 2> /dev/null && break
  kill -0 "$mpirun_pid" 2> /dev/null || { cat run.log; echo "FAIL: the run ended early"; exit 1; }
  sleep 0.1
done
grep -q " t=" run.log || { cat run.log; echo "FAIL: no progress within 60 s"; exit 1; }
dem_pid=$(pgrep -P "$mpirun_pid" -x dem_app || true)
[ -n "$dem_pid" ] || { ps -o pid,ppid,cmd --ppid "$mpirun_pid"; echo "FAIL: no dem_app child"; exit 1; }
kill -STOP "$dem_pid"
stopped=$(date +%s.%N)

# The job must end by itself: the limit + start of the abort, well within the limit + 27 s.
for _ in $(seq $(((limit + 27) * 10))); do
  kill -0 "$mpirun_pid" 2> /dev/null || break
  sleep 0.1
done
if kill -0 "$mpirun_pid" 2> /dev/null; then
  cat run.log; echo "FAIL: the job still runs $((limit + 27)) s after SIGSTOP of the DEM rank"; exit 1
fi
rc=0
wait "$mpirun_pid" || rc=$?
mpirun_pid=""
ended=$(date +%s.%N)
[ "$rc" != 0 ] || { cat run.log; echo "FAIL: exit status 0 after a stall"; exit 1; }
grep -q "dem_app (the dem side) has sent nothing for" run.log \
  || { cat run.log; echo "FAIL: no message naming the silent side"; exit 1; }
grep -q "last completed exchange: step [0-9]" run.log \
  || { cat run.log; echo "FAIL: no last completed step"; exit 1; }
grep -q "last checkpoint: " run.log || { cat run.log; echo "FAIL: no last checkpoint"; exit 1; }
if [ "$mode" = automatic ]; then
  grep -q "automatic: coupling.stall_timeout not set" run.log \
    || { cat run.log; echo "FAIL: not the automatic limit"; exit 1; }
fi
grep "has sent nothing" run.log
echo "the job ended $(echo "$ended - $stopped" | bc) s after SIGSTOP (limit $limit s), exit status $rc"
