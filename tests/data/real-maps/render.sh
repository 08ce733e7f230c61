#!/usr/bin/env bash
# Reproduces the real occupancy-grid maps in this folder from Debian's MRPT
# packages. NOT run by the build; it only documents how the files were made.
#
# Needs (Debian 12 "bookworm"):
#   apt-get install -y --no-install-recommends mrpt-apps mrpt-common python3
# Rendered with mrpt-apps / mrpt-common 1:2.5.8+ds-2.
#
# Usage: ./render.sh [OUTPUT_DIR]   (default: the folder holding this script)
set -euo pipefail

OUT=$(realpath "${1:-$(dirname "$0")}")
DS=/usr/share/mrpt/datasets
CFG=/usr/share/mrpt/config_files
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
cd "$WORK"

# ---------------------------------------------------------------------------
# 1. Occupancy-grid builder config for observations2map (5 cm cells).
#    Each laser ray adds log-odds p2l(0.65) of "free" to the cells it crosses
#    and 3x that of "occupied" to the cell it hits; rays are used up to 15 m.
# ---------------------------------------------------------------------------
cat > grid.ini <<'INI'
[MappingApplication]
occupancyGrid_count=1
gasGrid_count=0
landmarksMap_count=0
beaconMap_count=0
pointsMap_count=0
likelihoodMapSelection=-1

[MappingApplication_occupancyGrid_00_creationOpts]
resolution=0.05
disableSaveAs3DObject=0

[MappingApplication_occupancyGrid_00_insertOpts]
mapAltitude=0
useMapAltitude=0
maxDistanceInsertion=15
maxOccupancyUpdateCertainty=0.65
maxFreenessUpdateCertainty=0
considerInvalidRangesAsFreeSpace=0
wideningBeamsWithDistance=1
INI

# ---------------------------------------------------------------------------
# 2. MRPT gridmap -> ROS map_server PNG + YAML (python3 standard library only)
# ---------------------------------------------------------------------------
cat > gridmap2ros.py <<'PY'
#!/usr/bin/env python3
"""Convert an MRPT COccupancyGridMap2D file (*.gridmap or *.gridmap.gz, as
written by observations2map or shipped in mrpt-common) into a ROS map_server
map: an 8-bit greyscale PNG (254 free, 0 occupied, 205 unknown) plus a YAML.

Only the python3 standard library is used.

MRPT binary layout (checked against MRPT 2.5.8 files, serial versions 3 and 6):
  u8 0x80|len(class name), class name, u8 version, u8 bitsPerCell (8),
  u32 size_x, u32 size_y, f32 x_min, x_max, y_min, y_max, resolution,
  size_x*size_y int8 cells (row 0 = y_min), then options we ignore.
A cell holds the log-odds of the cell being FREE, scaled by 16:
  p_free = 1 / (1 + exp(-cell / 16))     (0 = never observed, p = 0.5).
Classification uses ROS map_server's defaults on p_occ = 1 - p_free:
  occupied if p_occ > 0.65, free if p_occ < 0.196, otherwise unknown.

Usage: gridmap2ros.py IN.gridmap[.gz] OUT_PREFIX [--margin 20]
           [--bbox XMIN XMAX YMIN YMAX]   (metres; ignore cells outside)
Writes OUT_PREFIX.png and OUT_PREFIX.yaml and prints statistics.
"""
import argparse
import gzip
import math
import os
import struct
import zlib

FREE, OCC, UNKNOWN = 254, 0, 205
OCC_THRESH, FREE_THRESH = 0.65, 0.196


def read_gridmap(path):
    with open(path, 'rb') as f:
        data = f.read()
    if data[:2] == b'\x1f\x8b':
        data = gzip.decompress(data)
    n = data[0] & 0x7F
    name = data[1:1 + n].decode()
    if not name.endswith('COccupancyGridMap2D'):
        raise SystemExit('not an occupancy grid: %s' % name)
    p = 1 + n
    version, bits = data[p], data[p + 1]
    p += 2
    if bits != 8:
        raise SystemExit('only 8-bit cells supported (got %d)' % bits)
    sx, sy = struct.unpack_from('<II', data, p)
    p += 8
    xmin, xmax, ymin, ymax, res = struct.unpack_from('<5f', data, p)
    p += 20
    cells = struct.unpack_from('<%db' % (sx * sy), data, p)
    return dict(name=name, version=version, sx=sx, sy=sy, xmin=xmin,
                xmax=xmax, ymin=ymin, ymax=ymax, res=res, cells=cells)


def classify(cell):
    p_occ = 1.0 - 1.0 / (1.0 + math.exp(-cell / 16.0))
    if p_occ > OCC_THRESH:
        return OCC
    if p_occ < FREE_THRESH:
        return FREE
    return UNKNOWN


def write_png(path, width, height, rows):
    def chunk(tag, body):
        c = tag + body
        return struct.pack('>I', len(body)) + c + struct.pack('>I', zlib.crc32(c) & 0xFFFFFFFF)
    raw = bytearray()
    prev = bytes(width)
    for row in rows:  # PNG filter 2 ("Up") compresses these maps well
        raw.append(2)
        raw.extend((a - b) & 0xFF for a, b in zip(row, prev))
        prev = row
    png = b'\x89PNG\r\n\x1a\n'
    png += chunk(b'IHDR', struct.pack('>IIBBBBB', width, height, 8, 0, 0, 0, 0))
    png += chunk(b'IDAT', zlib.compress(bytes(raw), 9))
    png += chunk(b'IEND', b'')
    with open(path, 'wb') as f:
        f.write(png)


def count_specks(grid, w, h):
    """8-connected components of occupied cells, and how many are <= 4 cells."""
    seen = bytearray(w * h)
    comps = []
    for start in range(w * h):
        if grid[start] != OCC or seen[start]:
            continue
        seen[start] = 1
        stack, size = [start], 0
        while stack:
            i = stack.pop()
            size += 1
            y, x = divmod(i, w)
            for dy in (-1, 0, 1):
                for dx in (-1, 0, 1):
                    yy, xx = y + dy, x + dx
                    if 0 <= yy < h and 0 <= xx < w:
                        j = yy * w + xx
                        if grid[j] == OCC and not seen[j]:
                            seen[j] = 1
                            stack.append(j)
        comps.append(size)
    return len(comps), sum(1 for s in comps if s <= 4)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('gridmap')
    ap.add_argument('prefix')
    ap.add_argument('--margin', type=int, default=20)
    ap.add_argument('--bbox', type=float, nargs=4, metavar=('XMIN', 'XMAX', 'YMIN', 'YMAX'))
    a = ap.parse_args()
    g = read_gridmap(a.gridmap)
    sx, sy, res = g['sx'], g['sy'], g['res']
    res_r = round(res, 6)
    lut = {v: classify(v) for v in range(-128, 128)}
    cls = bytearray(lut[c] for c in g['cells'])  # row 0 = bottom (y_min)
    if a.bbox:
        bx0, bx1, by0, by1 = a.bbox
        for r in range(sy):
            yc = g['ymin'] + (r + 0.5) * res
            for c in range(sx):
                xc = g['xmin'] + (c + 0.5) * res
                if not (bx0 <= xc <= bx1 and by0 <= yc <= by1):
                    cls[r * sx + c] = UNKNOWN
    known_rows = [r for r in range(sy) if any(v != UNKNOWN for v in cls[r * sx:(r + 1) * sx])]
    known_cols = [c for c in range(sx) if any(cls[r * sx + c] != UNKNOWN for r in known_rows)]
    m = a.margin
    r0, r1 = known_rows[0] - m, known_rows[-1] + m
    c0, c1 = known_cols[0] - m, known_cols[-1] + m
    w, h = c1 - c0 + 1, r1 - r0 + 1
    grid = bytearray([UNKNOWN]) * (w * h)  # row 0 = bottom
    for r in range(max(r0, 0), min(r1, sy - 1) + 1):
        cs, ce = max(c0, 0), min(c1, sx - 1)
        off = (r - r0) * w + (cs - c0)
        grid[off:off + ce - cs + 1] = cls[r * sx + cs:r * sx + ce + 1]
    rows = [bytes(grid[(h - 1 - i) * w:(h - i) * w]) for i in range(h)]  # top row first
    write_png(a.prefix + '.png', w, h, rows)
    ox = g['xmin'] + c0 * res
    oy = g['ymin'] + r0 * res
    with open(a.prefix + '.yaml', 'w') as f:
        f.write('image: %s.png\n' % os.path.basename(a.prefix))
        f.write('mode: trinary\n')
        f.write('resolution: %g\n' % res_r)
        f.write('origin: [%.3f, %.3f, 0.0]\n' % (ox, oy))
        f.write('negate: 0\n')
        f.write('occupied_thresh: 0.65\n')
        f.write('free_thresh: 0.196\n')
    nfree, nocc = grid.count(FREE), grid.count(OCC)
    ncomp, nsmall = count_specks(grid, w, h)
    print('source %s (%s v%d): %dx%d cells, res %g m, x[%g,%g] y[%g,%g]' % (
        a.gridmap, g['name'], g['version'], sx, sy, res_r, g['xmin'], g['xmax'], g['ymin'], g['ymax']))
    print('output %s.png: %dx%d cells, origin [%.3f, %.3f], %d bytes' % (
        a.prefix, w, h, ox, oy, os.path.getsize(a.prefix + '.png')))
    print('free cells %d (%.1f m^2), occupied cells %d, unknown %d' % (
        nfree, nfree * res_r * res_r, nocc, w * h - nfree - nocc))
    print('occupied 8-connected components: %d (of which <=4 cells: %d)' % (ncomp, nsmall))


if __name__ == '__main__':
    main()
PY

# ---------------------------------------------------------------------------
# Map 1: telecom-faculty -- ICP-SLAM over the one-loop laser rawlog.
#   Config = shipped icp-slam_demo_classic.ini with: absolute rawlog path,
#   no 3D window / scene files, and keyframes every 0.5 m / 20 deg
#   (shipped: 1.2 m / 45 deg) so the grid gets 110 scans instead of 54.
# ---------------------------------------------------------------------------
sed -e "s|^rawlog_file=.*|rawlog_file=$DS/2006-01ENE-21-SENA_Telecom Faculty_one_loop_only.rawlog|" \
    -e 's|^SAVE_3D_SCENE=1|SAVE_3D_SCENE=0|' \
    -e 's|^SHOW_PROGRESS_3D_REAL_TIME=1|SHOW_PROGRESS_3D_REAL_TIME=0|' \
    -e 's|^insertionLinDistance.*|insertionLinDistance\t= 0.5\t// (shipped: 1.2)|' \
    -e 's|^insertionAngDistance.*|insertionAngDistance\t= 20.0\t// (shipped: 45.0)|' \
    "$CFG/icp-slam/icp-slam_demo_classic.ini" > icp.ini
icp-slam icp.ini </dev/null > icp-slam.log 2>&1
observations2map grid.ini LOG_ICP-SLAM/_finalmap_.simplemap telecom </dev/null > o2m-telecom.log 2>&1
python3 gridmap2ros.py telecom_gridmap_no00.gridmap "$OUT/telecom-faculty"

# ---------------------------------------------------------------------------
# Map 2: localization-demo -- the shipped keyframe map (poses + laser scans)
#   used by MRPT's pf-localization demo: a long corridor with side rooms.
# ---------------------------------------------------------------------------
observations2map grid.ini "$DS/localization_demo.simplemap.gz" locdemo </dev/null > o2m-locdemo.log 2>&1
python3 gridmap2ros.py locdemo_gridmap_no00.gridmap "$OUT/localization-demo"

# ---------------------------------------------------------------------------
# Map 3: uwb-localization-demo -- the shipped 4 cm occupancy grid used by the
#   UWB range-only localization demo, converted as is (no re-mapping).
# ---------------------------------------------------------------------------
python3 gridmap2ros.py "$DS/uwb_ro-localization_demo_map.gridmap.gz" "$OUT/uwb-localization-demo"
