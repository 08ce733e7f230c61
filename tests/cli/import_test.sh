#!/usr/bin/env bash
# floorcover-cli import end to end: the ezdxf office drawing (FC_IMPORT_FIXTURES_DIR, made by
# the import_make_dxf_fixtures test), a generated occupancy map, WKT, and bad input.
set -u
cli="${FC_CLI:?}"
fixtures="${FC_IMPORT_FIXTURES_DIR:?}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
failed=0
fail() { echo "FAIL: $*"; failed=$((failed + 1)); }

# The DXF: summary line, warning on stderr, a plan the planner accepts.
"$cli" import "$fixtures/office.dxf" --out "$work/office.geojson" >"$work/out" 2>"$work/err" ||
  fail "office.dxf exit $?"
grep -q '"format":"dxf"' "$work/out" && grep -q '"obstacles":6,"rooms":2' "$work/out" ||
  fail "office.dxf summary: $(cat "$work/out")"
expected=$(awk '$1 == "office.dxf" {print $2}' "$fixtures/expected.txt")
python3 - "$work/out" "$expected" <<'PY' || fail "office.dxf free area"
import json, sys
free = json.load(open(sys.argv[1]))["free_area"]
sys.exit(0 if abs(free - float(sys.argv[2])) <= 0.01 * float(sys.argv[2]) else 1)
PY
grep -q 'warning: .*office.dxf: layer "NOTES": 2 open segments' "$work/err" || fail "stray warning"
"$cli" plan "$work/office.geojson" >/dev/null 2>&1 || fail "imported plan does not plan"

# Explicit layers and units.
"$cli" import "$fixtures/office.dxf" --boundary-layers WALLS --obstacle-layers COLUMNS \
  --units 0.001 --out "$work/walls.fcproj" >"$work/out" 2>/dev/null || fail "layers exit $?"
grep -q '"obstacles":2,"rooms":0' "$work/out" || fail "layers summary: $(cat "$work/out")"

# An occupancy map with a start pose ends up as the project's start.
printf 'P2\n8 6\n255\n' >"$work/map.pgm"
for row in 1 2 3 4 5 6; do
  if [ "$row" = 1 ] || [ "$row" = 6 ]; then echo "0 0 0 0 0 0 0 0"; else echo "0 254 254 254 254 254 254 0"; fi
done >>"$work/map.pgm"
printf 'image: map.pgm\nresolution: 0.5\norigin: [10, 20, 0]\nstart_pose: [11, 21, 0]\n' >"$work/map.yaml"
"$cli" import "$work/map.yaml" --out "$work/map.fcproj" >"$work/out" 2>"$work/err" ||
  fail "map exit $? $(cat "$work/err")"
python3 -c 'import json, sys; s = json.load(open(sys.argv[1]))
sys.exit(0 if s["format"] == "ros-map" and abs(s["free_area"] - 6) < 0.06 and s["start"] == [11, 21] else 1)' \
  "$work/out" || fail "map summary: $(cat "$work/out")"
grep -q '"hasStart": *true' "$work/map.fcproj" || grep -q '"start"' "$work/map.fcproj" ||
  fail "map project has no start"

# Every cleaning switch the help lists is accepted (--smooth was listed but refused).
"$cli" import "$work/map.yaml" --out "$work/map-switches.fcproj" --smooth off --straighten off \
  --unknown free --unknown-gap 0.1 --speckle 0.2 --fragment 0.5 --opening 0.2 --closing 0 \
  --robot-diameter 0.6 --wall-band 1 --notch 0.1 --segment-rooms none --min-room 1 \
  --max-door 1.6 >"$work/out" 2>"$work/err" || fail "cleaning switches: $(cat "$work/err")"
"$cli" --help | grep -o -- '\[--[a-z-]*' | sed 's/\[//' | sort -u >"$work/listed"
for option in --smooth --straighten --unknown --unknown-gap --speckle --fragment --opening \
  --closing --wall-band --notch --segment-rooms --min-room --max-door --no-cleaning; do
  grep -qx -- "$option" "$work/listed" || fail "help does not list $option"
done

# Map images written by GDAL, not by us: office and simple-diamond (a slanted obstacle)
# rasterized at 5 cm the way a map
# server stores a recorded map (free 254, walls and furniture 0, unknown 205 around it), as
# PGM with its YAML. The traced free area must be within 1% of the plan's.
if command -v gdal_rasterize >/dev/null && command -v gdal_translate >/dev/null; then
for name in office simple-diamond; do
  plan="${FC_PLANS_DIR:?}/$name.geojson"
  read -r xmin ymin xmax ymax < <(python3 -c 'import json, sys
pts = [p for f in json.load(open(sys.argv[1]))["features"] for r in f["geometry"]["coordinates"] for p in r]
xs = [p[0] for p in pts]; ys = [p[1] for p in pts]
print(min(xs) - 1, min(ys) - 1, max(xs) + 1, max(ys) + 1)' "$plan")
  gdal_rasterize -q -init 205 -burn 254 -where "role='boundary'" -tr 0.05 0.05 \
    -te "$xmin" "$ymin" "$xmax" "$ymax" -ot Byte -of GTiff "$plan" "$work/$name.tif" &&
    gdal_rasterize -q -b 1 -burn 0 -where "role='obstacle'" "$plan" "$work/$name.tif" &&
    gdal_translate -q -of PNM "$work/$name.tif" "$work/$name-map.pgm" || fail "gdal map"
  printf 'image: %s-map.pgm\nresolution: 0.05\norigin: [%s, %s, 0.0]\nnegate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\nmode: trinary\n' \
    "$name" "$xmin" "$ymin" >"$work/$name-map.yaml"
  "$cli" import "$plan" --out "$work/$name-reference.geojson" >"$work/$name-reference" 2>/dev/null ||
    fail "$name reference"
  "$cli" import "$work/$name-map.yaml" --out "$work/$name-map.geojson" >"$work/out" \
    2>"$work/err" || fail "gdal map exit: $(cat "$work/err")"
  python3 -c 'import json, sys
ref = json.load(open(sys.argv[1]))["free_area"]; got = json.load(open(sys.argv[2]))["free_area"]
print(sys.argv[3] + " map: free area %.2f m2 against the plan'"'"'s %.2f m2" % (got, ref))
sys.exit(0 if abs(got - ref) <= 0.01 * ref else 1)' "$work/$name-reference" "$work/out" "$name" ||
    fail "gdal map free area: $(cat "$work/out")"
  # The summary says how many doorway borders were laid along the walls.
  python3 -c 'import json, sys; c = json.load(open(sys.argv[1]))["cleaning"]
sys.exit(0 if isinstance(c.get("doorways_aligned"), int) and c["doorways_aligned"] >= 0 else 1)' \
    "$work/out" || fail "no doorways_aligned in the map summary: $(cat "$work/out")"
  "$cli" plan "$work/$name-map.geojson" >/dev/null 2>&1 || fail "the $name map's plan does not plan"
done
else
  echo "SKIP: gdal_rasterize not installed (gdal-bin)"
fi

# WKT.
echo 'POLYGON ((0 0, 10 0, 10 5, 0 5, 0 0), (2 2, 3 2, 3 3, 2 3, 2 2))' >"$work/hall.wkt"
"$cli" import "$work/hall.wkt" --out "$work/hall.geojson" >"$work/out" 2>/dev/null &&
  grep -q '"free_area":49.000,"obstacles":1' "$work/out" || fail "wkt: $(cat "$work/out")"

# Bad input: exit 2 and one stderr line naming the file.
bad() { # name, file, args...
  local name="$1" file="$2"; shift 2
  "$cli" import "$file" "$@" >"$work/out" 2>"$work/err"
  local rc=$? lines; lines=$(wc -l <"$work/err")
  if [ "$rc" -ne 2 ] || [ "$lines" -ne 1 ] || ! grep -q "$(basename "$file")" "$work/err"; then
    fail "$name (exit $rc, $lines lines: $(cat "$work/err"))"
  fi
}
head -c 3000 "$fixtures/office.dxf" >"$work/truncated.dxf"
bad "truncated dxf" "$work/truncated.dxf" --out "$work/x.geojson"
bad "missing file" "$work/none.dxf" --out "$work/x.geojson"
echo "LINESTRING (0 0, 1 1)" >"$work/line.wkt"
bad "wkt line" "$work/line.wkt" --out "$work/x.geojson"
echo "image: nowhere.pgm" >"$work/nomap.yaml"
bad "map without resolution" "$work/nomap.yaml" --out "$work/x.fcproj"
touch "$work/house.ifc"
bad "3D model" "$work/house.ifc" --out "$work/x.fcproj"
"$cli" import "$fixtures/office.dxf" --out "$work/x.csv" >/dev/null 2>&1
[ $? -eq 2 ] || fail "--out .csv accepted"
"$cli" import "$fixtures/office.dxf" --units -1 --out "$work/x.geojson" >/dev/null 2>&1
[ $? -eq 2 ] || fail "--units -1 accepted"

# A plan the planner refuses: refused as it is, made valid with --repair (issue 16, item 4).
cat >"$work/crossing.wkt" <<'WKT'
POLYGON ((0 0, 10 0, 10 8, 0 8, 0 0), (8 2, 12 2, 12 4, 8 4, 8 2))
WKT
bad "obstacle across the wall" "$work/crossing.wkt" --out "$work/x.geojson"
"$cli" import "$work/crossing.wkt" --repair --out "$work/repaired.geojson" >"$work/out" 2>"$work/err" &&
  grep -q "repaired:" "$work/err" && "$cli" plan "$work/repaired.geojson" >/dev/null 2>&1 ||
  fail "--repair: $(cat "$work/err")"

# A site of two buildings (a MultiPolygon boundary at UTM coordinates): graph refuses it and
# names the buildings, plan plans each; import and plan take one at a time with --building K.
cat >"$work/site.geojson" <<'JSON'
{"type":"FeatureCollection","features":[
{"type":"Feature","properties":{"role":"boundary"},"geometry":{"type":"MultiPolygon","coordinates":[
 [[[500000,5000000],[500020,5000000],[500020,5000012],[500000,5000012],[500000,5000000]]],
 [[[500040,5000000],[500050,5000000],[500050,5000008],[500040,5000008],[500040,5000000]]]]}},
{"type":"Feature","properties":{"role":"obstacle"},"geometry":{"type":"Polygon","coordinates":[[[500044,5000003],[500046,5000003],[500046,5000005],[500044,5000005],[500044,5000003]]]}},
{"type":"Feature","properties":{"role":"room","name":"Hall B"},"geometry":{"type":"Polygon","coordinates":[[[500040,5000000],[500050,5000000],[500050,5000008],[500040,5000008],[500040,5000000]]]}}
]}
JSON
"$cli" graph "$work/site.geojson" --out "$work/g.json" >/dev/null 2>"$work/err"
[ $? -eq 2 ] && grep -q "2 buildings (boundary polygons of 240, 80 m2" "$work/err" ||
  fail "site graphed as one plan: $(cat "$work/err")"
# plan without --building plans each building on its own, and says so.
"$cli" plan "$work/site.geojson" --out "$work/whole.geojson" >"$work/out" 2>"$work/err" &&
  grep -q "2 buildings, each planned on its own" "$work/err" &&
  [ -s "$work/whole-building-1.geojson" ] && [ -s "$work/whole-building-2.geojson" ] &&
  grep -q '"buildings":\[{"building":1,' "$work/out" ||
  fail "plan of a site: $(cat "$work/out" "$work/err")"
"$cli" import "$work/site.geojson" --building 2 --out "$work/b2.fcproj" >"$work/out" 2>/dev/null &&
  grep -q '"free_area":76.000,"obstacles":1,"rooms":1' "$work/out" &&
  "$cli" plan "$work/b2.fcproj" >"$work/out" 2>/dev/null && grep -q '"coverage":1.0' "$work/out" ||
  fail "building 2: $(cat "$work/out")"
"$cli" import "$work/site.geojson" --building 1 --out "$work/b1.geojson" >"$work/out" 2>/dev/null &&
  grep -q '"free_area":240.000,"obstacles":0,"rooms":0' "$work/out" || fail "building 1: $(cat "$work/out")"
# Every command that reads a plan takes --building K too: no import step needed.
"$cli" plan "$work/site.geojson" --building 2 --out "$work/b2.csv" >"$work/out" 2>"$work/err" &&
  grep -q '"coverage":1.0' "$work/out" && [ -s "$work/b2.csv" ] ||
  fail "plan --building 2: $(cat "$work/out" "$work/err")"
"$cli" graph "$work/site.geojson" --building 1 --out "$work/g1.json" >/dev/null 2>"$work/err" &&
  grep -q '"nodes"' "$work/g1.json" || fail "graph --building 1: $(cat "$work/err")"
"$cli" plan "$work/site.geojson" --building 3 >/dev/null 2>"$work/err"
[ $? -eq 2 ] && grep -q "building 3 does not exist: the file has 2 buildings" "$work/err" ||
  fail "plan --building 3 of 2: $(cat "$work/err")"
"$cli" plan "$work/site.geojson" --building 0 >/dev/null 2>"$work/err"
[ $? -eq 2 ] && grep -q "buildings are numbered from 1" "$work/err" ||
  fail "plan --building 0: $(cat "$work/err")"
# --building all: every building in one run, a path file each and the site's totals.
"$cli" plan "$work/site.geojson" --building all --out "$work/site.csv" >"$work/out" 2>"$work/err" &&
  [ -s "$work/site-building-1.csv" ] && [ -s "$work/site-building-2.csv" ] &&
  [ ! -e "$work/site.csv" ] && [ "$(wc -l <"$work/out")" -eq 1 ] &&
  grep -q '"ideal":316.0,' "$work/out" && grep -q '"buildings":\[{"building":1,' "$work/out" &&
  grep -q '},{"building":2,' "$work/out" ||
  fail "plan --building all: $(cat "$work/out" "$work/err")"
# Rooms and the start go to the building that holds them; one in no building is refused.
"$cli" plan "$work/site.geojson" --building all --rooms "Hall B" --start 500041,5000001 \
  >"$work/out" 2>"$work/err" && grep -q '"buildings":\[{"building":2,' "$work/out" &&
  ! grep -q '"building":1' "$work/out" || fail "--building all --rooms: $(cat "$work/out" "$work/err")"
"$cli" plan "$work/site.geojson" --building all --rooms "Hall C" >/dev/null 2>"$work/err"
[ $? -eq 2 ] && grep -q 'no building of the site has a room named "Hall C"' "$work/err" ||
  fail "--building all, unknown room: $(cat "$work/err")"
"$cli" plan "$work/site.geojson" --building all --start 500030,5000001 >/dev/null 2>"$work/err"
[ $? -eq 2 ] && grep -q -- '--start lies in no building of the site' "$work/err" ||
  fail "--building all, start outside: $(cat "$work/err")"
# A building that cannot be planned (a shed smaller than the robot, a self-crossing outline)
# is left out loudly, and the rest of the site is planned; --strict fails on it, and a start
# inside it is refused with its reason.
cat >"$work/shed.geojson" <<'JSON'
{"type":"FeatureCollection","features":[
{"type":"Feature","properties":{"role":"boundary"},"geometry":{"type":"Polygon","coordinates":[[[0,0],[20,0],[20,12],[0,12],[0,0]]]}},
{"type":"Feature","properties":{"role":"boundary"},"geometry":{"type":"Polygon","coordinates":[[[30,0],[30.4,0],[30.4,0.4],[30,0.4],[30,0]]]}},
{"type":"Feature","properties":{"role":"boundary"},"geometry":{"type":"Polygon","coordinates":[[[40,0],[50,0],[50,8],[40,8],[40,0]]]}},
{"type":"Feature","properties":{"role":"boundary"},"geometry":{"type":"Polygon","coordinates":[[[60,0],[66,6],[66,0],[60,6],[60,0]]]}}
]}
JSON
"$cli" plan "$work/shed.geojson" --out "$work/shed.csv" >"$work/out" 2>"$work/err" &&
  [ -s "$work/shed-building-1.csv" ] && [ -s "$work/shed-building-2.csv" ] &&
  [ ! -e "$work/shed-building-3.csv" ] && grep -q '"ideal":320.0,' "$work/out" &&
  grep -q '"skipped_buildings":2,' "$work/out" &&
  grep -q '{"building":3,"skipped":"free area 0.16 m^2' "$work/out" &&
  grep -q '{"building":4,"skipped":"boundary intersects itself' "$work/out" &&
  grep -q "building 3 (an outline of 0.16 m^2) not planned, left out" "$work/err" &&
  grep -q "building 4 not planned, left out" "$work/err" ||
  fail "site with an unplannable building: $(cat "$work/out" "$work/err")"
"$cli" plan "$work/shed.geojson" --strict >/dev/null 2>"$work/err"
[ $? -eq 3 ] && grep -q "a building was not planned (--strict)" "$work/err" ||
  fail "--strict on a skipped building: $(cat "$work/err")"
"$cli" plan "$work/shed.geojson" --start 30.2,0.2 >/dev/null 2>"$work/err"
[ $? -eq 2 ] && grep -q "(building 3): the robot (0.60 m across) does not fit" "$work/err" ||
  fail "start in a shed smaller than the robot: $(cat "$work/err")"
"$cli" graph "$work/site.geojson" --building all --out "$work/g.json" >/dev/null 2>"$work/err"
[ $? -eq 2 ] && grep -q "only \`plan\` plans every building" "$work/err" ||
  fail "graph --building all: $(cat "$work/err")"
bad "building 3 of 2" "$work/site.geojson" --building 3 --out "$work/x.fcproj"
"$cli" import "$work/site.geojson" --building 0 --out "$work/x.fcproj" >/dev/null 2>&1
[ $? -eq 2 ] || fail "--building 0 accepted"

# Found by fuzzing (session of 2026-12-07).
echo "POLYGON((0 0,10 0,10 8,0 8))" >"$work/unclosed.wkt"
"$cli" import "$work/unclosed.wkt" --out "$work/unclosed.geojson" >"$work/out" 2>"$work/err" &&
  grep -q '"boundary_area":80.000' "$work/out" || fail "an unclosed WKT ring keeps its last vertex: $(cat "$work/out" "$work/err")"
printf '\xEF\xBB\xBFPOLYGON((0 0,10 0,10 8,0 8,0 0))\n' >"$work/bom.wkt"
"$cli" import "$work/bom.wkt" --out "$work/bom.geojson" >"$work/out" 2>"$work/err" ||
  fail "WKT with a byte order mark: $(cat "$work/err")"
echo "SRID=-5;POLYGON((0 0,10 0,10 8,0 8,0 0))" >"$work/srid.wkt"
bad "negative SRID" "$work/srid.wkt" --out "$work/x.fcproj"
bad "units 1e9" "$work/unclosed.wkt" --units 1e9 --out "$work/x.fcproj"
python3 - "$work" <<'PY'
import sys
w = sys.argv[1]
with open(w + "/room.pgm", "wb") as f:
    f.write(b"P5 40 30 255\n" + bytes([0] * 40 + ([0] + [254] * 38 + [0]) * 28 + [0] * 40))
open(w + "/room.yaml", "w").write("image: room.pgm\nresolution: 0.05\norigin: [0, 0, 0]\n"
                                 "negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n")
open(w + "/bom.yaml", "wb").write(b"\xef\xbb\xbf" + open(w + "/room.yaml", "rb").read())
PY
"$cli" import "$work/bom.yaml" --out "$work/bom.fcproj" >"$work/out" 2>"$work/err" ||
  fail "map YAML with a byte order mark: $(cat "$work/err")"
for option in "--opening 1e9" "--closing 1000" "--opening 1e5"; do
  # shellcheck disable=SC2086
  "$cli" import "$work/room.yaml" $option --out "$work/x.fcproj" >"$work/out" 2>"$work/err"
  rc=$?
  [ "$rc" -eq 2 ] && grep -q "must be at most 5 m" "$work/err" || fail "$option: exit $rc, $(cat "$work/err")"
done

# --repair of obstacles touching the wall or each other at a point: shrunk by 1 mm, then valid.
printf '{"type":"FeatureCollection","features":[{"type":"Feature","properties":{"role":"boundary"},"geometry":{"type":"Polygon","coordinates":[[[0,0],[10,0],[10,8],[0,8],[0,0]]]}},{"type":"Feature","properties":{"role":"obstacle"},"geometry":{"type":"Polygon","coordinates":[[[5,0],[6,1],[5,2],[4,1],[5,0]]]}},{"type":"Feature","properties":{"role":"obstacle"},"geometry":{"type":"Polygon","coordinates":[[[2,4],[3,4],[3,5],[2,5],[2,4]]]}},{"type":"Feature","properties":{"role":"obstacle"},"geometry":{"type":"Polygon","coordinates":[[[3,5],[4,5],[4,6],[3,6],[3,5]]]}}]}' >"$work/touching.geojson"
"$cli" import "$work/touching.geojson" --repair --out "$work/touching.fcproj" >"$work/out" 2>"$work/err" &&
  grep -q "shrunk by 1 mm" "$work/err" && "$cli" plan "$work/touching.fcproj" >"$work/out" 2>"$work/err" ||
  fail "--repair of point touches: $(cat "$work/out" "$work/err")"

[ "$failed" -eq 0 ] && echo "import CLI: all checks passed"
exit "$failed"
