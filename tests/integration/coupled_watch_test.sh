#!/usr/bin/env bash
# The coupled stability watch (docs/stability.md): one scene per trigger (fluid 1 : DEM 1),
#   fluid_mach  a lattice Mach number over fluid.stability.max_mach (found by fluid_app),
#   body_speed  a body faster than that limit allows (found by dem_app),
#   overlap     two bodies' clump spheres deeper than dem.max_overlap (found by dem_app).
# Both programs must stop with exit status 3, one diagnosis (what, where, when, likely cause,
# what to change) from the program that found it, a line from the other pointing at it, and
# the last good checkpoint; restarting from that checkpoint must reach the same diagnosis at
# the same step (the checkpoint restarts), and with the limit relaxed (a key a restart may
# change) it must get past that step.
# Usage: coupled_watch_test.sh BUILD_DIR SOURCE_DIR CASE
set -euo pipefail
build=$1 src=$2 case=$3
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
cp "$src/tests/integration/watch/$case.yaml" scene.yaml
started=$(date +%s.%N)
run() {  # run LOG [options]
  local log=$1
  shift
  local rc=0
  mpirun -np 1 "$build/fluid_app/fluid_app" "$@" scene.yaml : -np 1 "$build/dem_app/dem_app" "$@" scene.yaml > "$log" 2>&1 || rc=$?
  echo "$rc"
}
fail() { echo "FAIL: $*"; exit 1; }
case $case in
  fluid_mach) what="fluid is unstable: Mach" other="fluid_app found the fluid unstable" ;;
  body_speed) what="the bodies are unstable: body 0 .* moves at" other="dem_app found the bodies unstable" ;;
  overlap) what="the bodies are unstable: bodies 0 and 1 overlap by" other="dem_app found the bodies unstable" ;;
  *) fail "unknown case $case" ;;
esac
rc=$(run first.log)
[ "$rc" = 3 ] || { cat first.log; fail "exit status $rc, expected 3"; }
grep -q -- "$what" first.log || { cat first.log; fail "no diagnosis '$what'"; }
grep -q "likely cause\|Likely cause\|raise\|refine\|lower" first.log || { cat first.log; fail "no advice"; }
grep -q -- "$other" first.log || { cat first.log; fail "the other program did not say why it stopped"; }
[ "$(grep -c "last good checkpoint: .*_step" first.log)" = 2 ] \
  || { cat first.log; fail "both programs must name the last good checkpoint"; }
grep -m1 -o -- "$what.*" first.log | cut -c1-300
grep -m1 -o "last good checkpoint: [^;]*" first.log
first_step=$(grep -m1 -o "stopped at step [0-9]*" first.log | grep -o "[0-9]*$")
if [ "$case" = fluid_mach ]; then
  # The fluid's last good state is on disk from the last passing check (interval 1: the step
  # before), whole, with no candidate of the failing check left.
  said=$(grep -m1 -o "last good state (step [0-9]*, .*) written to [^ ]*" first.log) \
    || { cat first.log; fail "the fluid names no last good state"; }
  file=${said##* } good=$(echo "$said" | grep -o "step [0-9]*" | grep -o "[0-9]*")
  [ ! -e "$file.tmp" ] || fail "the failing check's candidate $file.tmp was left"
  /usr/bin/python3 - "$file" "$good" "$((first_step - 1))" <<'PY' || fail "last good state file"
import sys, h5py, numpy as np
with h5py.File(sys.argv[1], "r") as f:
    step, rho = int(f.attrs["step"]), f["volume/density"][...]
    ok = np.all(np.isfinite(f["volume/velocity"][...])) and np.all(rho > 0)
if not (ok and step == int(sys.argv[2]) == int(sys.argv[3])):
    sys.exit(f"{sys.argv[1]}: step {step} (said {sys.argv[2]}, expected {sys.argv[3]}), good {ok}")
print(f"last good state {sys.argv[1]}: step {step}, {rho.size} nodes, finite, density > 0")
PY
fi
folder=$(ls -d ./*_checkpoints)
rc=$(run again.log --restart "$folder")
[ "$rc" = 3 ] || { cat again.log; fail "restart from the last good checkpoint: exit $rc, expected 3"; }
grep -q "restart from" again.log || { cat again.log; fail "did not restart"; }
grep -q -- "$what" again.log || { cat again.log; fail "the restart did not reach the same diagnosis"; }
echo "restart from $(basename "$(grep -m1 -o "restart from [^ ]*" again.log | cut -d' ' -f3)"): same diagnosis again"
# Relax the limit: the run must get past the step it stopped at (it may stop later).
case $case in
  overlap) sed -i 's/max_overlap: 0.1/max_overlap: 0/' scene.yaml ;;
  fluid_mach) sed -i 's/  stability: {interval: 1}/  stability: {interval: 1, max_mach: 0.9}/' scene.yaml ;;
  body_speed) sed -i 's/^  tau: 0.6$/  tau: 0.6\n  stability: {max_mach: 0.9}/' scene.yaml ;;
esac
rc=$(run relaxed.log --restart "$folder")
grep -q "restart from" relaxed.log || { cat relaxed.log; fail "relaxed restart did not restart"; }
if [ "$rc" != 0 ]; then
  later=$(grep -m1 -o "stopped at step [0-9]*" relaxed.log | grep -o "[0-9]*$" || echo 0)
  [ "$rc" = 3 ] && [ "$later" -gt "$first_step" ] || { cat relaxed.log; fail "relaxed limit: exit $rc at step $later"; }
fi
echo "relaxed limit: exit $rc, past step $first_step"
echo "PASS: coupled watch '$case' in $(echo "$(date +%s.%N) - $started" | bc) s"
