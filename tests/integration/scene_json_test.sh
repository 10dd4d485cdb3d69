#!/bin/bash
# fluid_app --check --json and dem_app --check --json print the same resolved scene, valid JSON
# with the derived numbers, for a coupled, a fluid-only and a DEM-only scene
# (coupler_lib/app/scene_json.hpp).
# usage: scene_json_test.sh BUILD SOURCE
set -euo pipefail
build=$1
src=$2
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
n=0
for scene in configs/demo/settling_cubes.yaml configs/fluid/periodic_box.yaml \
  configs/dem/cubes_pour.yaml tests/tools/spin_viscosity_yaml11.yaml; do
  "$build/fluid_app/fluid_app" --check --json "$src/$scene" > "$out/fluid.json"
  "$build/dem_app/dem_app" --check --json "$src/$scene" > "$out/dem.json"
  if ! cmp -s "$out/fluid.json" "$out/dem.json"; then
    echo "FAILED: $scene: fluid_app and dem_app print different JSON"
    diff "$out/fluid.json" "$out/dem.json" | head -20
    exit 1
  fi
  /usr/bin/python3 - "$out/fluid.json" "$scene" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
assert r["format"] == "lbdem-resolved-scene" and r["version"] == 1, r["format"]
for key in ("scene", "derived", "shapes", "bodies"):
    assert key in r, key
schedule = r["derived"]["schedule"]
assert schedule["steps"] >= 1, schedule
assert r["derived"]["fluid"] is not None or r["derived"]["dem"] is not None
print(f"{sys.argv[2]}: {len(r['bodies'])} bodies, {schedule['steps']} steps, "
      f"{schedule['dem_substeps']} DEM substeps")
PY
  n=$((n + 1))
done
echo "scene_json: $n scenes, the same JSON from both programs"
