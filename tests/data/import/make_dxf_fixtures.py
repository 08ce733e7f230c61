#!/usr/bin/env python3
"""Writes the DXF import fixtures with ezdxf (a CAD library nobody on the team wrote).

usage: make_dxf_fixtures.py OUTDIR

office.dxf (millimetres, $INSUNITS=4)
  WALLS      LWPOLYLINE 20 x 10 m with a bulge (semicircle, r = 5 m) on the east side
  COLUMNS    two CIRCLEs r = 0.3 m
  FURNITURE  block DESK (1.2 x 0.6 m) INSERTed rotated 30 degrees, and once scaled 0.5
  OBSTACLES  a HATCH 1 x 1 m; a 1 x 2 m cabinet drawn as four LINEs with a 20 mm gap
  ROOMS      two closed outlines, named by TEXT/MTEXT on layer ROOMTEXT
  NOTES      two stray LINEs that close nothing
free area = 200 + 12.5 pi - 2 (0.09 pi) - 0.72 - 0.18 - 1 - 2 m^2

rounded.dxf (DXF R12, which has no $INSUNITS: read as metres with a warning; everything on
layer 0): a 10 x 6 m outline with 1 m rounded corners chained from LINE and ARC pieces, and
an old-style closed POLYLINE (VERTEX entities) 2 x 1 m inside.
free area = 60 - (4 - pi) - 2 m^2

The expected areas are written next to the files (expected.txt) from these formulas.
"""
import math
import os
import sys

import ezdxf


def office(path):
    doc = ezdxf.new("R2010")
    doc.header["$INSUNITS"] = 4  # millimetres
    msp = doc.modelspace()
    for name in ("WALLS", "COLUMNS", "FURNITURE", "OBSTACLES", "ROOMS", "ROOMTEXT", "NOTES"):
        doc.layers.add(name)
    # (x, y, start_width, end_width, bulge): bulge 1 on the segment (20000,0)->(20000,10000)
    msp.add_lwpolyline(
        [(0, 0, 0, 0, 0), (20000, 0, 0, 0, 1), (20000, 10000, 0, 0, 0), (0, 10000, 0, 0, 0)],
        format="xyseb", close=True, dxfattribs={"layer": "WALLS"})
    for x in (5000, 15000):
        msp.add_circle((x, 5000), 300, dxfattribs={"layer": "COLUMNS"})
    desk = doc.blocks.new(name="DESK")
    desk.add_lwpolyline([(0, 0), (1200, 0), (1200, 600), (0, 600)], close=True)
    msp.add_blockref("DESK", (10000, 2500), dxfattribs={"layer": "FURNITURE", "rotation": 30})
    msp.add_blockref("DESK", (3000, 1500),
                     dxfattribs={"layer": "FURNITURE", "xscale": 0.5, "yscale": 0.5})
    hatch = msp.add_hatch(color=1, dxfattribs={"layer": "OBSTACLES"})
    hatch.paths.add_polyline_path([(2000, 7000), (3000, 7000), (3000, 8000), (2000, 8000)],
                                  is_closed=True)
    # the cabinet: four lines, the last one stops 20 mm short of the first corner
    cabinet = [(17000, 6000), (18000, 6000), (18000, 8000), (17000, 8000), (17000, 6020)]
    for a, b in zip(cabinet, cabinet[1:]):
        msp.add_line(a, b, dxfattribs={"layer": "OBSTACLES"})
    msp.add_lwpolyline([(500, 500), (7500, 500), (7500, 9500), (500, 9500)], close=True,
                       dxfattribs={"layer": "ROOMS"})
    msp.add_lwpolyline([(12000, 500), (19500, 500), (19500, 9500), (12000, 9500)], close=True,
                       dxfattribs={"layer": "ROOMS"})
    msp.add_text("Office A", dxfattribs={"layer": "ROOMTEXT", "height": 300}).set_placement(
        (3500, 5000))
    msp.add_mtext("Office B", dxfattribs={"layer": "ROOMTEXT", "char_height": 300,
                                          "insert": (16000, 4000)})
    msp.add_line((21000, 12000), (22000, 12500), dxfattribs={"layer": "NOTES"})
    msp.add_line((-3000, -2000), (-1000, -2000), dxfattribs={"layer": "NOTES"})
    doc.saveas(path)
    return 200 + 12.5 * math.pi - 2 * 0.09 * math.pi - 0.72 - 0.18 - 1 - 2


def rounded(path):
    doc = ezdxf.new("R12")
    msp = doc.modelspace()
    w, h, r = 10.0, 6.0, 1.0
    msp.add_line((r, 0), (w - r, 0))
    msp.add_arc((w - r, r), r, 270, 360)
    msp.add_line((w, r), (w, h - r))
    msp.add_arc((w - r, h - r), r, 0, 90)
    msp.add_line((w - r, h), (r, h))
    msp.add_arc((r, h - r), r, 90, 180)
    msp.add_line((0, h - r), (0, r))
    msp.add_arc((r, r), r, 180, 270)
    msp.add_polyline2d([(4, 2), (6, 2), (6, 3), (4, 3)], close=True)
    doc.saveas(path)
    return w * h - (4 - math.pi) * r * r - 2


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "."
    os.makedirs(out, exist_ok=True)
    with open(os.path.join(out, "expected.txt"), "w") as f:
        f.write("office.dxf %.6f\n" % office(os.path.join(out, "office.dxf")))
        f.write("rounded.dxf %.6f\n" % rounded(os.path.join(out, "rounded.dxf")))


if __name__ == "__main__":
    main()
