#!/usr/bin/env bash
# The malformed-input corpus: every scene under scenes/ is wrong on purpose (its first line says
# how). Each goes through fluid_app --check, dem_app --check and a real coupled launch
# (mpirun -np 1 fluid_app : -np 1 dem_app); each of the three must end within 10 s with a
# non-zero status and an error message, never a crash, a core dump, a hang or MPI's own noise.
# Both --check runs must refuse with the same message, and every case names the reason it must be
# refused for in a line "# expect: TEXT": the message must hold TEXT (so a case refused for
# another mistake than its own fails). base.yaml, the scene the cases depart
# from, must pass both --check runs (so a case fails for its own mistake only).
# Usage: run_corpus.sh BUILD_DIR CORPUS_DIR
set -uo pipefail
build=$1 corpus=$2
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
fluid=$build/fluid_app/fluid_app dem=$build/dem_app/dem_app
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
launch() {  # launch LOG ARGS...: run under a 10 s limit, print the exit status
  timeout -s KILL 10 mpirun --oversubscribe "${@:2}" > "$1" 2>&1
  echo $?
}
# The message without the program's name, for comparing the two --check runs.
message() { grep -a -m1 -E "^(fluid_app|dem_app): error: " "$1" | sed -E 's/^(fluid_app|dem_app): //'; }
noise='ORTE_ERROR_LOG|Segmentation fault|core dumped|Aborted|terminate called|bad_alloc|MPI_ABORT|exited on signal'

for prog in "$fluid" "$dem"; do
  if [ "$(launch "$work/base.log" -np 1 "$prog" --check "$corpus/base.yaml")" != 0 ]; then
    cat "$work/base.log"; echo "FAIL: base.yaml must pass $(basename "$prog") --check"; exit 1
  fi
done

failed=0 total=0
for scene in "$corpus"/scenes/*.yaml; do
  name=$(basename "$scene" .yaml) total=$((total + 1)) why=""
  rf=$(launch "$work/f.log" -np 1 "$fluid" --check "$scene")
  rd=$(launch "$work/d.log" -np 1 "$dem" --check "$scene")
  rr=$(launch "$work/r.log" -np 1 "$fluid" "$scene" : -np 1 "$dem" "$scene")
  for r in "f:$rf" "d:$rd" "r:$rr"; do
    log=$work/${r%%:*}.log rc=${r#*:}
    [ "$rc" = 0 ] && why+=" ${r%%:*}: accepted;"
    [ "$rc" = 137 ] && why+=" ${r%%:*}: no end within 10 s;"
    grep -aq "error" "$log" || why+=" ${r%%:*}: no error message;"
    grep -aqE "$noise" "$log" && why+=" ${r%%:*}: $(grep -a -m1 -oE "$noise" "$log");"
  done
  mf=$(message "$work/f.log") md=$(message "$work/d.log")
  [ "$mf" = "$md" ] || why+=" the two --check messages differ;"
  expect=$(sed -n 's/^# expect: //p' "$scene")
  if [ -z "$expect" ]; then
    why+=" no '# expect:' line;"
  elif [ -z "$mf" ] || [[ "$mf" != *"$expect"* ]]; then
    why+=" the message lacks '$expect';"
  fi
  if [ -n "$why" ]; then
    failed=$((failed + 1))
    echo "FAIL $name:$why"
    for l in f d r; do echo "--- $l"; tail -n 5 "$work/$l.log"; done
  else
    echo "ok   $name: ${mf:0:150}"
  fi
done
echo "corpus: $((total - failed)) of $total malformed scenes refused cleanly by both programs"
[ "$failed" = 0 ]
