#!/usr/bin/env python3
"""Polygons from GIS formats: GeoJSON and WKT inputs of afmesh_2.

A real coastline (MESH2D's Lake Superior from the shared data: a shoreline
and six islands) is written as a GeoJSON FeatureCollection and as a WKT
POLYGON by this script, meshed from both, and checked: the independent
validity checker on the mesh and the boundary afmesh_2 writes, the same
triangles from both formats, and the meshed area equal to the shoreline's
minus the islands' (shoelace formula here, independent of the mesher). A
MULTIPOLYGON with an island inside a hole, and malformed files (each
refused with exit code 1 and a message naming the file), complete it.

usage: check_polygon_inputs.py AFMESH CHECK WORK_DIR SHARED_DATA_DIR
"""
import json
import os
import sys

from cli_checks import check, finish, run

AFMESH, CHECK, WORK, SHARED = sys.argv[1:5]
os.makedirs(WORK, exist_ok=True)


def shoelace(ring):
    return 0.5 * sum(ring[i - 1][0] * ring[i][1] - ring[i][0] * ring[i - 1][1] for i in range(len(ring)))


def mesh_area(off):
    lines = [l.split() for l in open(off) if l.split()]
    nv, nt = int(lines[1][0]), int(lines[1][1])
    p = [(float(l[0]), float(l[1])) for l in lines[2:2 + nv]]
    area = 0.0
    for l in lines[2 + nv:2 + nv + nt]:
        a, b, c = (p[int(i)] for i in l[1:4])
        area += 0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]))
    return area, nt


def jigsaw_loops(path):
    """The closed loops of a JIGSAW .msh file (points x;y;tag, edges i;j;tag)."""
    rows = [l.strip() for l in open(path) if l.strip() and not l.startswith("#")]
    i = next(k for k, r in enumerate(rows) if r.lower().startswith("point="))
    n = int(rows[i].split("=")[1])
    pts = [tuple(float(x) for x in r.split(";")[:2]) for r in rows[i + 1:i + 1 + n]]
    j = next(k for k, r in enumerate(rows) if r.lower().startswith("edge2="))
    m = int(rows[j].split("=")[1])
    nxt = {}
    for r in rows[j + 1:j + 1 + m]:
        a, b = (int(x) for x in r.split(";")[:2])
        nxt[a] = b
    loops, seen = [], set()
    for start in nxt:
        if start in seen:
            continue
        loop, v = [], start
        while v not in seen:
            seen.add(v)
            loop.append(pts[v])
            v = nxt[v]
        loops.append(loop)
    return loops


def wkt_ring(ring):
    return "(" + ",".join("%.17g %.17g" % p for p in ring + [ring[0]]) + ")"


def node_text(base):
    return open(base + ".node").read(), open(base + ".ele").read()


# --- Lake Superior: one polygon, six holes --------------------------------------------------------------
lake = os.path.join(SHARED, "mesh2d", "lake.msh")
if os.path.exists(lake):
    loops = sorted(jigsaw_loops(lake), key=lambda l: -abs(shoelace(l)))
    check(len(loops) == 7, "lake: 7 loops (got %d)" % len(loops))
    rings = [l + [l[0]] for l in loops]
    g = os.path.join(WORK, "lake.geojson")
    json.dump({"type": "FeatureCollection", "features": [
        {"type": "Feature", "properties": {"name": "Lake Superior"},
         "geometry": {"type": "Polygon", "coordinates": [[list(p) for p in r] for r in rings]}}]}, open(g, "w"))
    w = os.path.join(WORK, "lake.wkt")
    open(w, "w").write("# Lake Superior, from MESH2D\nPOLYGON(" + ",".join(wkt_ring(l) for l in loops) + ")\n")
    expected_area = abs(shoelace(loops[0])) - sum(abs(shoelace(l)) for l in loops[1:])
    for src, name in ((g, "lake_geojson"), (w, "lake_wkt")):
        base = os.path.join(WORK, name)
        run(AFMESH, src, "--size", "0.1", "-o", base + ".off", "-o", base + ".poly", "-o", base + ".node")
        run(CHECK, base + ".poly", base + ".off")
        area, nt = mesh_area(base + ".off")
        check(abs(area - expected_area) < 1e-9 * expected_area,
              "%s: meshed area %.12g, the polygon's %.12g" % (name, area, expected_area))
        check(nt > 1000, "%s: %d triangles" % (name, nt))
        rows = [l.split() for l in open(base + ".poly") if l.split()]
        n = int(rows[0][0])
        ns = int(rows[n + 1][0])
        check(n == 303 and ns == 303, "%s: the boundary has the 303 points and segments (%d, %d)" % (name, n, ns))
        check(int(rows[n + 2 + ns][0]) == 6, "%s: six holes, the islands (%s)" % (name, rows[n + 2 + ns][0]))
    check(node_text(os.path.join(WORK, "lake_geojson")) == node_text(os.path.join(WORK, "lake_wkt")),
          "lake: the same mesh from GeoJSON and from WKT")
else:
    print("lake.msh not found under", SHARED, "- the coastline part is skipped")

# --- a MULTIPOLYGON: a square with a hole holding an island, and a triangle beside it ----------------------
square = [(0, 0), (4, 0), (4, 4), (0, 4)]
hole = [(1, 1), (1, 3), (3, 3), (3, 1)]
island = [(1.5, 1.5), (2.5, 1.5), (2.5, 2.5), (1.5, 2.5)]
triangle = [(5, 0), (7, 0), (6, 2)]
m = os.path.join(WORK, "multi.wkt")
open(m, "w").write("MULTIPOLYGON((%s,%s),(%s))\nPOLYGON(%s)\n" % (wkt_ring(square), wkt_ring(hole), wkt_ring(triangle),
                                                                   wkt_ring(island)))
base = os.path.join(WORK, "multi")
run(AFMESH, m, "--size", "0.2", "-o", base + ".off", "-o", base + ".poly")
run(CHECK, base + ".poly", base + ".off")
area, _ = mesh_area(base + ".off")
check(abs(area - (16 - 4 + 1 + 2)) < 1e-12, "multi: meshed area %.15g, expected 15" % area)

# --- malformed files: exit 1, one line naming the file (and the line where there is one) ------------------
def refused(name, content, pattern):
    path = os.path.join(WORK, name)
    open(path, "w").write(content)
    r = run(AFMESH, path, "--size", "0.1", "--no-output", code=1)
    ok = r.stderr.startswith("afmesh_2: error: " + path + pattern) and r.stderr.count("\n") == 1
    check(ok, "%s: unexpected message: %s" % (name, r.stderr))


refused("line.geojson", '{"type": "LineString", "coordinates": [[0, 0], [1, 1]]}',
        ": the geometry: a LineString is not a polygon")
refused("open.geojson", '{"type": "Polygon", "coordinates": [[[0, 0], [1, 0], [1, 1], [0, 1]]]}',
        ": the geometry, ring 1: a linear ring must have at least 4 positions, the last equal to the first")
refused("syntax.geojson", '{"type": "Polygon",\n "coordinates": [[[0, 0], [1, 0],, [0, 0]]]}', ":2: not valid JSON")
refused("empty.geojson", '{"type": "FeatureCollection", "features": []}', ": no Polygon or MultiPolygon")
refused("point.wkt", "POINT(1 2)\n", ":1: expected a WKT POLYGON or MULTIPOLYGON, found 'POINT'")
refused("broken.wkt", "\nPOLYGON((0 0,1 0,1 1,0 0)\n", ":2: not a valid WKT polygon")
refused("flat.wkt", "POLYGON((0 0,1 0,0 0))\n", ":1: polygon 1: ring 1 has fewer than 3 distinct points")
refused("crossing.wkt", "POLYGON((0 0,2 0,2 2,0 2,0 0))\nPOLYGON((1 1,3 1,3 3,1 3,1 1))\n", ":2: segment")

finish("polygon inputs")
