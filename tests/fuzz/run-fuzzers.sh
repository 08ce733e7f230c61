#!/usr/bin/env bash
# Builds the importers' libFuzzer targets with clang (ASan + UBSan, its own build folder) and
# runs each for a bounded time on a seed corpus made from the test fixtures.
#   tests/fuzz/run-fuzzers.sh [SECONDS_PER_TARGET=30] [BUILD_DIR=build-fuzz]
# Exits non-zero when a target finds a crash, a leak, a timeout (> 10 s on one input) or
# an out-of-memory; the reproducer is left in BUILD_DIR/fuzz-findings/.
set -euo pipefail
seconds="${1:-30}"
root="$(cd "$(dirname "$0")/../.." && pwd)"
build="$(realpath -m "${2:-$root/build-fuzz}")"
sanitize="-fsanitize=address,undefined,fuzzer-no-link -fno-omit-frame-pointer"

cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_CXX_FLAGS="$sanitize" -DFC_BUILD_FUZZERS=ON \
  -DFC_BUILD_TESTS=OFF -DFC_BUILD_BENCH=OFF >/dev/null
ninja -C "$build" -j"${FC_JOBS:-1}" fuzz_dxf fuzz_wkt fuzz_rosmap

seeds="$build/fuzz-seeds"
rm -rf "$seeds"
mkdir -p "$seeds/dxf" "$seeds/wkt" "$seeds/rosmap" "$build/fuzz-findings"
/usr/bin/python3 "$root/tests/data/import/make_dxf_fixtures.py" "$seeds/dxf" >/dev/null
rm -f "$seeds/dxf/expected.txt"
for f in /usr/share/openscad/testdata/dxf/*.dxf; do
  [ "$(stat -c %s "$f")" -lt 65536 ] && cp "$f" "$seeds/dxf/"
done
printf 'POLYGON ((0 0, 20 0, 20 10, 0 10, 0 0), (5 5, 6 5, 6 6, 5 6, 5 5))' >"$seeds/wkt/polygon"
printf 'SRID=25832;MULTIPOLYGON (((0 0, 9 0, 9 9, 0 9, 0 0)), ((1 1, 4 1, 4 4, 1 4, 1 1)))' \
  >"$seeds/wkt/multi"
printf 'CURVEPOLYGON (CIRCULARSTRING (0 0, 4 0, 4 4, 0 4, 0 0))' >"$seeds/wkt/curve"
# a 12 x 10 room with a pillar, as binary and ASCII PGM, with and without a start pose
/usr/bin/python3 - "$seeds/rosmap" <<'PY'
import sys
w, h = 12, 10
px = [[0 if x in (0, w - 1) or y in (0, h - 1) or (4 <= x < 6 and 4 <= y < 6) else 254
       for x in range(w)] for y in range(h)]
yaml = b"image: map.pgm\nresolution: 0.5\norigin: [1.0, -2.0, 0.0]\nnegate: 0\n" \
       b"occupied_thresh: 0.65\nfree_thresh: 0.196\n"
p5 = b"P5\n%d %d\n255\n" % (w, h) + bytes(v for row in px for v in row)
p2 = (b"P2\n%d %d\n255\n" % (w, h)) + b"\n".join(b" ".join(b"%d" % v for v in row) for row in px)
open(sys.argv[1] + "/p5", "wb").write(yaml + b"%%\n" + p5)
open(sys.argv[1] + "/p2", "wb").write(yaml + b"start_pose: [2, -1, 0]\nmode: scale\n%%\n" + p2)
open(sys.argv[1] + "/png", "wb").write(yaml.replace(b"map.pgm", b"map.png") + b"%%\n\x89PNG\r\n")
PY

status=0
for target in dxf wkt rosmap; do
  corpus="$build/fuzz-corpus/$target"
  mkdir -p "$corpus"
  echo "== fuzz_$target: ${seconds}s"
  if ! (cd "$build/fuzz-findings" &&
        "$build/tests/fuzz/fuzz_$target" "$corpus" "$seeds/$target" -max_total_time="$seconds" \
          -timeout=10 -rss_limit_mb=2048 -max_len=200000 -print_final_stats=1 \
          2>"$build/fuzz-$target.log"); then
    status=1
    echo "fuzz_$target: FINDING (see $build/fuzz-$target.log and fuzz-findings/)"
  fi
  grep -E "stat::number_of_executed_units|stat::peak_rss_mb|Done [0-9]+ runs" \
    "$build/fuzz-$target.log" || true
done
exit "$status"
