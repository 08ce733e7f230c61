#!/usr/bin/env bash
# Third-party validators on `floorcover-cli export` output (issue 5): GeoJSON through GDAL's
# ogrinfo, YAML through python3-yaml, SVG through xmllint, PDF through qpdf --check, VDA 5050
# through its JSON schema (python3-jsonschema), CSV parsed back; plus the command's errors.
# Usage: validate_exports.sh CHECK   (geojson|yaml|svg|pdf|vda5050|csv|errors)
# Needs FC_CLI, FC_PLANS_DIR and FC_TEST_DATA_DIR. Exits 77 (CTest SKIP_RETURN_CODE) when
# the validator the check needs is not installed.
set -u
cli="${FC_CLI:?}"
plans="${FC_PLANS_DIR:?}"
data="${FC_TEST_DATA_DIR:?}"
check="${1:?usage: validate_exports.sh CHECK}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
failed=0

fail() { echo "FAIL: $*"; failed=$((failed + 1)); }
need() { command -v "$1" >/dev/null || { echo "SKIP: $1 is not installed"; exit 77; }; }
need_python() { python3 -c "import $1" 2>/dev/null || { echo "SKIP: python3-$1 is not installed"; exit 77; }; }
export_to() { # FILE, then export options; the plan is office unless --plan-file is first
  local out="$1"; shift
  local plan="$plans/office.geojson"
  if [ "${1:-}" = "--plan-file" ]; then plan="$2"; shift 2; fi
  "$cli" export "$plan" --out "$work/$out" "$@" >"$work/stdout" 2>"$work/stderr" \
    || { fail "export $out $*: $(cat "$work/stderr")"; return 1; }
}

case "$check" in
geojson)
  need ogrinfo
  export_to path.geojson
  export_to zones.geojson --what zones
  export_to plan.geojson --what plan
  export_to wgs84.geojson --plan-file "$data/utm-offset.geojson" --format wgs84-geojson
  export_to wgs84-path.geojson --plan-file "$data/utm-offset.geojson" --format wgs84-geojson \
    --what path --width 1
  for f in path zones plan wgs84 wgs84-path; do
    ogrinfo -ro -al -so "$work/$f.geojson" >"$work/$f.info" 2>&1 || fail "ogrinfo $f: $(head -3 "$work/$f.info")"
  done
  grep -q "Geometry: Line String" "$work/path.info" || fail "path is not a LineString"
  grep -q "Feature Count: 13" "$work/zones.info" || fail "office has 13 rooms: $(grep Count "$work/zones.info")"
  grep -q '"floorcover:crs": "local metres"' "$work/plan.geojson" || fail "local plan not marked"
  # RFC 7946: lon/lat near 9 E, 45.15 N for the UTM 32N plan at E 500000, N 5000000
  grep -Eq "Extent: \(9\.0+, 45\.153" "$work/wgs84.info" || fail "WGS84 extent: $(grep Extent "$work/wgs84.info")"
  grep -q '"crs"' "$work/wgs84.geojson" && fail "WGS84 GeoJSON keeps a crs member"
  grep -q "Geometry: Line String" "$work/wgs84-path.info" || fail "WGS84 path"
  ;;
yaml)
  need python3; need_python yaml
  export_to path.yaml
  export_to nav2.yaml --format nav2 --frame-id odom
  python3 - "$work/path.yaml" "$work/nav2.yaml" <<'PY' || fail "YAML content"
import math, sys, yaml
for name in sys.argv[1:]:
    doc = yaml.safe_load(open(name))
    poses = doc["poses"]
    assert len(poses) > 100, (name, len(poses))
    for p in poses:
        q = p["pose"]["orientation"]
        assert abs(math.hypot(q["x"], q["y"], q["z"], q["w"]) - 1) < 1e-6, q
        pos = p["pose"]["position"]
        assert 0 <= pos["x"] <= 30 and 0 <= pos["y"] <= 20, pos
    if "nav2" in name:
        assert "header" not in doc and poses[0]["header"]["frame_id"] == "odom", doc.keys()
    else:
        assert doc["header"]["frame_id"] == "map"
    assert "metres" in open(name).read()
PY
  ;;
svg)
  need xmllint
  export_to drawing.svg
  export_to plan.svg --what plan
  for f in drawing plan; do
    xmllint --noout "$work/$f.svg" 2>"$work/xml.err" || fail "xmllint $f: $(head -3 "$work/xml.err")"
  done
  grep -q 'viewBox="-1.5 -21.5 33.0 23.0"' "$work/drawing.svg" || fail "viewBox: $(grep -o 'viewBox="[^"]*"' "$work/drawing.svg")"
  ;;
pdf)
  need qpdf
  export_to drawing.pdf
  export_to plan.pdf --what plan
  for f in drawing plan; do
    qpdf --check "$work/$f.pdf" >"$work/qpdf.out" 2>&1 || fail "qpdf $f: $(tail -3 "$work/qpdf.out")"
  done
  ;;
vda5050)
  need python3; need_python jsonschema
  schemas="$data/schemas"
  export_to order.json --format vda5050 --serial-number S-42 --map-id floor-2
  for schema in "$schemas/vda5050-order.schema.json" "$schemas/vda5050-order.published.schema.json"; do
    [ -f "$schema" ] || continue
    python3 - "$schema" "$work/order.json" <<'PY' || fail "VDA 5050 schema $(basename "$schema")"
import json, sys, jsonschema
schema, order = (json.load(open(f)) for f in sys.argv[1:])
jsonschema.validators.validator_for(schema)(schema).validate(order)
assert order["serialNumber"] == "S-42" and order["nodes"][0]["nodePosition"]["mapId"] == "floor-2"
# a broken order must fail: the validator really checks
del order["edges"][0]["startNodeId"]
try:
    jsonschema.validators.validator_for(schema)(schema).validate(order)
    sys.exit("the schema accepted an edge without startNodeId")
except jsonschema.ValidationError:
    pass
PY
  done
  ;;
csv)
  need python3
  export_to path.csv
  export_to path.json
  export_to path.f2c --format fields2cover
  python3 - "$work/path.csv" "$work/path.json" "$work/path.f2c" <<'PY' || fail "CSV/Fields2Cover parse-back"
import csv, json, math, sys
rows = list(csv.DictReader(line for line in open(sys.argv[1]) if not line.startswith("#")))
waypoints = json.load(open(sys.argv[2]))["waypoints"]
assert len(rows) == len(waypoints) > 100
for row, wp in zip(rows, waypoints):
    assert abs(float(row["x"]) - wp["x"]) < 1e-6 and abs(float(row["y"]) - wp["y"]) < 1e-6
    assert row["kind"] == wp["kind"]
# Fields2Cover: eight numbers per state, the states chain end to end
states = []
for line in open(sys.argv[3]):
    parts = line.split()
    if len(parts) != 8:
        break
    states.append([float(v) for v in parts])
for a, b in zip(states, states[1:]):
    x = a[0] + a[5] * math.cos(a[3]); y = a[1] + a[5] * math.sin(a[3])
    assert abs(x - b[0]) < 1e-5 and abs(y - b[1]) < 1e-5, (a, b)
PY
  ;;
errors)
  expect_error() { # name, file the message must name, then the export arguments
    local name="$1" file="$2"; shift 2
    "$cli" export "$@" >"$work/out" 2>"$work/err"
    local rc=$?
    if [ "$rc" -ne 2 ] || [ "$(wc -l <"$work/err")" -ne 1 ] || ! grep -q "$file" "$work/err"; then
      fail "$name (exit $rc): $(cat "$work/err")"
    fi
  }
  expect_error "unknown format" x.dwg "$plans/office.geojson" --format dwg --out "$work/x.dwg"
  expect_error "no format from .txt" x.txt "$plans/office.geojson" --out "$work/x.txt"
  expect_error "bad plan" truncated.geojson "$data/truncated.geojson" --format nav2 --out "$work/x.yaml"
  expect_error "vda zones" zones "$plans/office.geojson" --format vda5050 --what zones --out "$work/x.json"
  expect_error "bad width" office.geojson "$plans/office.geojson" --width -1 --out "$work/x.csv"
  expect_error "unwritable" no-such-dir "$plans/office.geojson" --what zones --format zones --out "/no-such-dir/x.json"
  ;;
*)
  echo "unknown check $check"; exit 2 ;;
esac
[ "$failed" -eq 0 ] && echo "export $check: ok"
exit $((failed > 0))
