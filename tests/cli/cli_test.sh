#!/usr/bin/env bash
# End-to-end tests of floorcover-cli from the user's entry point: exit codes, outputs and
# files. Needs FC_CLI and FC_PLANS_DIR; test data next to this script in ../data.
set -u
cli="${FC_CLI:?}"
plans="${FC_PLANS_DIR:?}"
data="$(cd "$(dirname "$0")/../data" && pwd)"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
passed=0
failed=0

check() { # name, then a command that must succeed
  local name="$1"; shift
  if "$@" >"$work/out" 2>"$work/err"; then
    passed=$((passed + 1))
  else
    failed=$((failed + 1))
    echo "FAIL: $name"; sed 's/^/  stdout: /' "$work/out" | head -5; sed 's/^/  stderr: /' "$work/err" | head -5
  fi
}

expect_bad_input() { # name, file, extra args: exit 2, one line naming the file
  local name="$1" file="$2"; shift 2
  "$cli" plan "$file" "$@" >"$work/out" 2>"$work/err"
  local rc=$?
  local lines; lines=$(wc -l <"$work/err")
  if [ "$rc" -eq 2 ] && [ "$lines" -eq 1 ] && grep -q "$(basename "$file")" "$work/err"; then
    passed=$((passed + 1))
  else
    failed=$((failed + 1))
    echo "FAIL: $name (exit $rc, $lines stderr lines)"; sed 's/^/  stderr: /' "$work/err" | head -5
  fi
}

cli() { # runs the CLI, keeping its stdout for metrics_ok
  "$cli" "$@" >"$work/last"
  local rc=$?
  cat "$work/last"
  return $rc
}

metrics_ok() { # the last CLI JSON line has every SPEC key and coverage >= 0.99
  python3 - "$work/last" <<'PY'
import json, sys
line = open(sys.argv[1]).read().strip().splitlines()[-1]
m = json.loads(line)
keys = ["solver","length","ideal","extra","turns","coverage","uncovered_area","unreachable_area",
        "time","cells","graph_cost","seconds"]
assert list(m.keys())[:len(keys)] == keys, m.keys()
assert m["coverage"] >= 0.99, m
PY
}

for plan in simple simple-diamond room-obstacle room-notches office ward; do
  for solver in heuristic greedy; do
    check "plan $plan $solver" cli plan "$plans/$plan.geojson" --solver "$solver" --out "$work/$plan-$solver.geojson"
    check "metrics $plan $solver" metrics_ok
  done
done
for plan in simple simple-diamond room-obstacle room-notches; do
  check "plan $plan exact" cli plan "$plans/$plan.geojson" --solver exact
  check "metrics $plan exact" metrics_ok
done

# Output formats by extension.
for ext in geojson csv json yaml; do
  check "format $ext" "$cli" plan "$plans/simple.geojson" --out "$work/path.$ext"
  check "format $ext written" test -s "$work/path.$ext"
done
check "csv header" grep -q '^x,y,heading' "$work/path.csv"
check "yaml parses" python3 -c "import yaml,sys; d=yaml.safe_load(open('$work/path.yaml')); assert d['poses']"
if command -v ogrinfo >/dev/null; then
  check "geojson passes ogrinfo" ogrinfo -ro -al -so "$work/path.geojson"
fi

# Options: rooms, start/end, angle, seed determinism.
check "rooms subset" cli plan "$plans/office.geojson" --rooms S01,Corridor,N03 --start 1,1 --end 29,19
check "metrics rooms subset" metrics_ok
check "auto angle" "$cli" plan "$plans/room-notches.geojson" --angle auto
check "no wall loop" "$cli" plan "$plans/simple.geojson" --no-wall-loop
# A corridor on a 120-degree arc (UTM coordinates) plans as loops along its walls, with a note;
# --no-rings plans it without them.
"$cli" plan "$data/curved-corridor.geojson" >"$work/curved.out" 2>"$work/curved.err"
check "curved corridor plans" test $? -eq 0
check "curved corridor planned as rings" grep -q "note: .*planned as loops along the walls" "$work/curved.err"
"$cli" plan "$data/curved-corridor.geojson" --no-rings >"$work/stripes.out" 2>"$work/stripes.err"
check "no rings plans" test $? -eq 0
check "no rings, no rings note" bash -c "! grep -q 'planned as loops' '$work/stripes.err'"
check "slanted sweep" cli plan "$plans/simple.geojson" --angle 30
check "metrics slanted" metrics_ok
a=$("$cli" plan "$plans/office.geojson" --seed 7 --out "$work/a.csv" | python3 -c "import json,sys; d=json.load(sys.stdin); print(d['graph_cost'])")
b=$("$cli" plan "$plans/office.geojson" --seed 7 --out "$work/b.csv" | python3 -c "import json,sys; d=json.load(sys.stdin); print(d['graph_cost'])")
check "deterministic per seed" test "$a" = "$b"

# Issue 13: a 0.9 m door (W = 1 m, L = 0.6 m) is passed; a 0.5 m door is not, and the
# loss is said on stderr; --strict turns it into exit code 3 (the path is still written).
check "0.9 m door: both rooms" cli plan "$data/door-0.9m.geojson" --start 1,1 --strict
check "metrics 0.9 m door" metrics_ok
"$cli" plan "$data/door-0.5m.geojson" --start 1,1 --out "$work/narrow.geojson" >"$work/out" 2>"$work/err"
rc=$?
if [ "$rc" -eq 0 ] && grep -q "does not cover" "$work/err" && [ -s "$work/narrow.geojson" ]; then
  passed=$((passed + 1))
else
  failed=$((failed + 1)); echo "FAIL: 0.5 m door warns (exit $rc)"; head -3 "$work/err"
fi
"$cli" plan "$data/door-0.5m.geojson" --start 1,1 --strict --out "$work/strict.geojson" >"$work/out" 2>"$work/err"
rc=$?
if [ "$rc" -eq 3 ] && grep -q -- "--strict" "$work/err" && [ -s "$work/strict.geojson" ]; then
  passed=$((passed + 1))
else
  failed=$((failed + 1)); echo "FAIL: --strict exits 3 on a loss (exit $rc)"; head -3 "$work/err"
fi
check "per-room angle" cli plan "$plans/office.geojson" --angle per-room
check "metrics per-room" metrics_ok

check "same path per seed" cmp -s "$work/a.csv" "$work/b.csv"

# Graph export.
check "graph export" "$cli" graph "$plans/simple.geojson" --out "$work/graph.json"
check "graph shape" python3 -c "
import json; g=json.load(open('$work/graph.json'))
assert len(g['nodes']) == 20 and all(k in g for k in ('nodes','cells','edges'))
assert {e['kind'] for e in g['edges']} == {'coverage','contour','inter'}"

# Compare.
check "compare" cli compare "$plans/simple.geojson"
check "compare lists solvers" grep -q heuristic "$work/last"
check "compare lists the baselines" grep -q '^adjacency-ga ' "$work/last"
check "compare prints the paper's ratios" grep -q 'vs reeb-cpp .*extra .*turns' "$work/last"
check "compare --json" cli compare "$plans/simple.geojson" --json
check "compare --json lines parse" python3 -c "
import json; lines = [json.loads(l) for l in open('$work/last')]
assert {l['solver'] for l in lines[:-1]} >= {'heuristic', 'reeb-cpp', 'adjacency-ga'}
assert {r['baseline'] for r in lines[-1]['ratios']} == {'reeb-cpp', 'adjacency-ga', 'adjacency-ga-centres'}"

# The paper's baselines plan like any solver.
for plan in simple room-obstacle office; do
  for solver in reeb-cpp adjacency-ga adjacency-ga-centres; do
    check "plan $plan $solver" cli plan "$plans/$plan.geojson" --solver "$solver" --out "$work/$plan-$solver.csv"
    check "metrics $plan $solver" metrics_ok
  done
done

# Bad input: exit code 2 and one line naming the file.
# Every fixture listed as refused in tests/data/README.md.
for name in $(sed -n 's/^| `\([^`]*\)` |.*/\1/p' "$data/README.md"); do
  expect_bad_input "bad input $name" "$data/$name"
done
# A site of two buildings: plan plans each, graph needs one (--building K).
check "plan a site" cli plan "$data/two-boundaries.geojson" --out "$work/site.csv"
check "a path per building" test -s "$work/site-building-1.csv" -a -s "$work/site-building-2.csv"
"$cli" graph "$data/two-boundaries.geojson" --out "$work/site-graph.json" >/dev/null 2>"$work/site.err"
check "graph of a site is bad input" test $? -eq 2
check "graph of a site names --building" grep -q -- "--building K" "$work/site.err"
# export writes every building of a site, a file each, as plan does; --building K one.
check "export a site" cli export "$data/two-boundaries.geojson" --out "$work/site.json"
check "an export per building" test -s "$work/site-building-1.json" -a \
  -s "$work/site-building-2.json"
"$cli" export "$data/two-boundaries.geojson" --format vda5050 --out "$work/site.yaml" \
  >"$work/site.out" 2>/dev/null
check "the site's export lists its buildings" grep -q '"files":2,"buildings":\[{"building":1,' \
  "$work/site.out"
check "a VDA 5050 order per building" grep -q '"two-boundaries-building-2-coverage"' \
  "$work/site-building-2.yaml"
check "export one building of a site" cli export "$data/two-boundaries.geojson" --building 2 \
  --out "$work/b2.csv"
# A plan whose own rings are wrong names the repair in its one line, and the repair it names
# gives a plan that plans.
cp "$data/overlapping-holes.geojson" "$work/overlapping.geojson"
"$cli" plan "$work/overlapping.geojson" >"$work/out" 2>"$work/repair.err"
check "repairable plan is bad input" test $? -eq 2
check "its error is one line" test "$(wc -l <"$work/repair.err")" -eq 1
check "its error names the repair" grep -q "to repair it: floorcover-cli import $work/overlapping.geojson --repair --out $work/overlapping-repaired.fcproj" "$work/repair.err"
check "the named repair works" "$cli" import "$work/overlapping.geojson" --repair --out "$work/overlapping-repaired.fcproj"
check "the repaired plan plans" cli plan "$work/overlapping-repaired.fcproj"
check "metrics of the repaired plan" metrics_ok
"$cli" plan "$plans/office.geojson" --rooms Kitchen >"$work/out" 2>"$work/other.err"
check "other bad input names no repair" test "$(grep -c 'to repair it' "$work/other.err")" -eq 0
# The valid fixtures plan.
for name in simple.fcproj utm-offset.geojson rooms-with-hole.geojson; do
  check "valid fixture $name" cli plan "$data/$name"
  check "metrics $name" metrics_ok
done
check "utm path keeps its crs" cli plan "$data/utm-offset.geojson" --out "$work/utm.geojson"
check "utm geojson names epsg" grep -q 32632 "$work/utm.geojson"
# A plan in longitude/latitude (RFC 7946, as GIS tools write GeoJSON) plans in metres, in its
# UTM zone, with a note; its path is the UTM plan's.
check "plan exported to wgs84" "$cli" export "$data/utm-offset.geojson" --format wgs84-geojson \
  --what plan --out "$work/lonlat.geojson"
"$cli" plan "$work/lonlat.geojson" >"$work/lonlat.out" 2>"$work/lonlat.err"
check "lon/lat plan plans" test $? -eq 0
check "lon/lat note names the zone" grep -q "note: .*reprojected to metres in WGS84 / UTM zone 32N (EPSG:32632)" "$work/lonlat.err"
"$cli" plan "$data/utm-offset.geojson" >"$work/utm.out" 2>/dev/null
check "lon/lat plan is the utm plan" python3 -c "
import json
a=json.loads(open('$work/lonlat.out').read().splitlines()[-1])
b=json.loads(open('$work/utm.out').read().splitlines()[-1])
assert abs(a['ideal']-b['ideal']) < 1e-3 and abs(a['length']-b['length']) < 0.01 * b['length'], (a, b)"
check "lon/lat path keeps the utm crs" "$cli" plan "$work/lonlat.geojson" --out "$work/lonlat-path.geojson"
check "lon/lat path names epsg" grep -q 32632 "$work/lonlat-path.geojson"
expect_bad_input "missing file" "$work/does-not-exist.geojson"
expect_bad_input "robot wider than W" "$plans/simple.geojson" --robot-diameter 2 --width 1
expect_bad_input "negative width" "$plans/simple.geojson" --width -1
# A width of 0 also lowers L to it: the message names W, the option given.
expect_bad_input "zero width" "$plans/simple.geojson" --width 0
if grep -q "coverage width W must be a positive number (got 0)" "$work/err"; then
  passed=$((passed + 1))
else
  failed=$((failed + 1)); echo "FAIL: --width 0 names W: $(cat "$work/err")"
fi
# An absurd start is named in short form, not in 300 digits.
expect_bad_input "absurd start" "$plans/simple.geojson" --start 1e300,1e300
if grep -q "start point (1e+300, 1e+300) lies outside the floor" "$work/err"; then
  passed=$((passed + 1))
else
  failed=$((failed + 1)); echo "FAIL: absurd start in short form: $(cat "$work/err")"
fi
expect_bad_input "unknown room" "$plans/office.geojson" --rooms Kitchen
expect_bad_input "unknown solver" "$plans/simple.geojson" --solver nonsense
expect_bad_input "exact above its limit" "$plans/ward.geojson" --solver exact
expect_bad_input "nan start" "$plans/simple.geojson" --start nan,1
expect_bad_input "start in the pillar" "$plans/simple.geojson" --start 6,4
expect_bad_input "end outside the floor" "$plans/simple.geojson" --end -5,4
# A start 0.15 m from the wall (the 0.6 m robot needs 0.3 m) moves to where it fits.
check "start beside a wall" cli plan "$plans/simple.geojson" --start 0.15,4.2
cp "$work/err" "$work/moved.err"
check "start beside a wall is moved with a note" grep -q "moved 0.1[0-9] m to" "$work/moved.err"

# The Double-DQN planner from the user's side: train, plan with the model, resume, Ctrl-C,
# and a clear refusal of another plan's, a broken or a missing model.
check "train a model" cli train "$plans/simple.geojson" --out "$work/simple.fcdqn" --episodes 30 --seed 3
check "train summary" grep -q '"episodes":30' "$work/last"
check "plan with dqn" cli plan "$plans/simple.geojson" --solver dqn --model "$work/simple.fcdqn" --out "$work/dqn.geojson"
check "dqn metrics" metrics_ok
check "dqn named in metrics" grep -q '"solver":"dqn"' "$work/last"
check "compare includes dqn with a model" cli compare "$plans/simple.geojson" --model "$work/simple.fcdqn"
check "compare lists dqn" grep -q '^dqn ' "$work/last"
check "resume training" cli train "$plans/simple.geojson" --out "$work/simple.fcdqn" --episodes 5 --resume
check "resumed episode count" grep -q '"episodes":35' "$work/last"
check "train with the graph state" cli train "$plans/room-obstacle.geojson" --out "$work/graph.fcdqn" --episodes 10 --setting graph
check "plan with a graph-state model" cli plan "$plans/room-obstacle.geojson" --solver dqn --model "$work/graph.fcdqn"
check "graph-state metrics" metrics_ok
"$cli" train "$plans/simple.geojson" --out "$work/x.fcdqn" --episodes 3 --setting voxel >"$work/out" 2>"$work/err"
check "unknown setting is bad input" test $? -eq 2
"$cli" train "$plans/simple.geojson" --out "$work/interrupted.fcdqn" --seconds 120 >"$work/int.out" 2>&1 &
trainer=$!
sleep 3
kill -INT "$trainer"
check "ctrl-c ends training cleanly" wait "$trainer"
check "ctrl-c reported" grep -q '"stopped_by":"interrupted"' "$work/int.out"
check "ctrl-c saved the model" cli plan "$plans/simple.geojson" --solver dqn --model "$work/interrupted.fcdqn"
expect_bad_input "model of another plan" "$plans/room-obstacle.geojson" --solver dqn --model "$work/simple.fcdqn"
cp "$work/err" "$work/refusal"
check "another plan named as such" grep -q "another floor plan" "$work/refusal"
head -c 3000 "$work/simple.fcdqn" >"$work/truncated.fcdqn"
expect_bad_input "truncated model" "$plans/simple.geojson" --solver dqn --model "$work/truncated.fcdqn"
cp "$work/err" "$work/refusal"
check "truncated named as such" grep -q "truncated" "$work/refusal"
expect_bad_input "plan file as model" "$plans/simple.geojson" --solver dqn --model "$plans/simple.geojson"
check "dqn without a model plans with the generalist" cli plan "$plans/room-obstacle.geojson" --solver dqn
check "generalist dqn metrics" metrics_ok
check "dqn-search plans with the generalist" cli plan "$plans/room-obstacle.geojson" --solver dqn-search
check "dqn-search metrics" metrics_ok
check "dqn-search named in metrics" grep -q '"solver":"dqn-search"' "$work/last"
check "compare includes dqn without a model" cli compare "$plans/simple.geojson"
check "compare lists dqn with the generalist" grep -q '^dqn ' "$work/last"
check "train from scratch" cli train "$plans/simple.geojson" --out "$work/scratch.fcdqn" --episodes 5 --from-scratch
expect_bad_input "missing model" "$plans/simple.geojson" --solver dqn --model "$work/none.fcdqn"
"$cli" train "$plans/simple.geojson" --episodes 3 >"$work/out" 2>"$work/err"
check "train without --out is bad input" test $? -eq 2
"$cli" train "$work/missing.geojson" --out "$work/x.fcdqn" >"$work/out" 2>"$work/err"
check "train on a missing plan is bad input" test $? -eq 2
check "no model written for a missing plan" test ! -e "$work/x.fcdqn"

# The tiling robot: one JSON line of metrics per solver, waypoint export, refusals.
tile_metrics_ok() { # the last tile JSON line: the issue's keys first, every tile visited
  python3 - "$work/last" <<'PY'
import json, sys
m = json.loads(open(sys.argv[1]).read().strip().splitlines()[-1])
keys = ["energy", "length", "shape_changes", "waypoints", "seconds"]
assert list(m.keys())[:len(keys)] == keys, m.keys()
assert m["waypoints"] > 100 and m["energy"] > 0 and m["length"] > 0, m
PY
}
for solver in zigzag spiral greedy aco aco+2opt ga; do
  check "tile simple $solver" cli tile "$plans/simple.geojson" --solver "$solver"
  check "tile metrics $solver" tile_metrics_ok
done
check "tile ppo trains and saves" cli tile "$plans/simple.geojson" --solver ppo --train-seconds 3 \
  --save-model "$work/ppo.pt"
check "tile metrics ppo" tile_metrics_ok
check "tile ppo-policy loads the model" cli tile "$plans/simple.geojson" --solver ppo-policy \
  --model "$work/ppo.pt"
check "tile metrics ppo-policy" tile_metrics_ok
check "tile waypoints csv" "$cli" tile "$plans/simple-diamond.geojson" --solver greedy --out "$work/tiles.csv"
check "tile csv header" grep -q '^x,y,shape,heading$' "$work/tiles.csv"
check "tile waypoints json" "$cli" tile "$plans/simple-diamond.geojson" --out "$work/tiles.json"
check "tile json lists shapes and left cells" python3 -c "
import json; d=json.load(open('$work/tiles.json'))
assert {w['shape'] for w in d['waypoints']} <= {'rectangle','triangle','parallelogram','curve','square'}
assert len(d['waypoints']) > 100 and len(d['untiled_cells']) >= 2 and 'unreachable_cells' in d"
a=$("$cli" tile "$plans/simple.geojson" --solver aco --seed 4 | python3 -c "import json,sys; print(json.load(sys.stdin)['energy'])")
b=$("$cli" tile "$plans/simple.geojson" --solver aco --seed 4 | python3 -c "import json,sys; print(json.load(sys.stdin)['energy'])")
check "tile aco deterministic per seed" test "$a" = "$b"
for bad in "--solver nonsense" "--solver exact" "--block-leg -1" "--block-masses 1,2,3" "--out $work/tiles.txt" \
  "--solver ppo --model $work/tiles.csv" "--solver ppo --train-seconds 0"; do
  # shellcheck disable=SC2086
  "$cli" tile "$plans/simple.geojson" $bad >"$work/out" 2>"$work/err"
  rc=$?
  check "tile refuses $bad" test "$rc" -eq 2 -a "$(wc -l <"$work/err")" -eq 1
done
"$cli" tile "$work/missing.geojson" >"$work/out" 2>"$work/err"
check "tile on a missing plan is bad input" test $? -eq 2

# Found by fuzzing (session of 2026-12-07): each is refused in one line naming the problem.
for bad in "--block-leg 0.004" "--block-masses 1,1,1,1e308"; do
  # shellcheck disable=SC2086
  "$cli" tile "$plans/simple.geojson" $bad >"$work/out" 2>"$work/tile-err"
  rc=$?
  check "tile refuses $bad" test "$rc" -eq 2 -a "$(wc -l <"$work/tile-err")" -eq 1
  check "tile names the problem of $bad" grep -q "block leg\|block masses" "$work/tile-err"
done
expect_bad_input "speed 1e-308" "$plans/simple.geojson" --speed 1e-308
expect_bad_input "turn time 1e308" "$plans/simple.geojson" --turn-time 1e308
"$cli" plan "$plans/simple.geojson" --bogus >"$work/out" 2>"$work/bogus-err"
check "a last unknown option is unknown" grep -q "unknown option --bogus" "$work/bogus-err"
"$cli" plan "$plans/simple.geojson" --out "$work/path.txt" >"$work/txt-out" 2>"$work/txt-err"
check "--out .txt refused before planning, naming the file" grep -q "path.txt: unsupported path format" "$work/txt-err"
check "--out .txt: no metrics line" test ! -s "$work/txt-out"
printf '\0{}' >"$work/nul.geojson"
expect_bad_input "a binary file" "$work/nul.geojson"
grep -q "NUL byte" "$work/err" || { failed=$((failed + 1)); echo "FAIL: NUL: $(cat "$work/err")"; }
printf '{"type":"FeatureCollection","features":[{"type":"Feature","properties":{"role":"boundary"},"geometry":{"type":"Polygon","coordinates":[[[0,0],[1e10,0],[1e10,8],[0,8],[0,0]]]}}]}' >"$work/wide.geojson"
expect_bad_input "a plan 1e10 m long" "$work/wide.geojson"
grep -q "is the plan in metres" "$work/err" || { failed=$((failed + 1)); echo "FAIL: wide: $(cat "$work/err")"; }
printf '{"type":"FeatureCollection","features":[{"type":"Feature","properties":{"role":"boundary"},"geometry":{"type":"Polygon","coordinates":[[[1e14,1e14],[100000000000010,1e14],[100000000000010,100000000000008],[1e14,100000000000008],[1e14,1e14]]]}}]}' >"$work/far.geojson"
expect_bad_input "a plan 1e14 m from its origin" "$work/far.geojson"
printf '{"type":"FeatureCollection","crs":{"type":"name","properties":{"name":"EPSG:3857"}},"features":[{"type":"Feature","properties":{"role":"boundary"},"geometry":{"type":"Polygon","coordinates":[[[0,6e9],[10,6e9],[10,6000000008],[0,6000000008],[0,6e9]]]}}]}' >"$work/mercator.geojson"
expect_bad_input "Web Mercator off the globe" "$work/mercator.geojson"
grep -q "is not on the globe" "$work/err" || { failed=$((failed + 1)); echo "FAIL: mercator: $(cat "$work/err")"; }
"$cli" train "$plans/simple.geojson" --out "$work/m.fcdqn" --episodes 0 >"$work/out" 2>"$work/err"
check "train --episodes 0 refused" test $? -eq 2

printf '{"type":"FeatureCollection","features":[{"type":"Feature","properties":{"role":"boundary"},"geometry":{"type":"Polygon","coordinates":[[[0,0],[10,0],[10,8],[0,8],[0,0]]]}},{"type":"Feature","properties":{"role":"boundary"},"geometry":{"type":"Polygon","coordinates":[[[5,0],[15,0],[15,8],[5,8],[5,0]]]}}]}' >"$work/overlap.geojson"
"$cli" plan "$work/overlap.geojson" >"$work/out" 2>"$work/overlap-err"
check "overlapping buildings are said to overlap" grep -q "building 1 overlaps building 2 by 40 m2" "$work/overlap-err"

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
