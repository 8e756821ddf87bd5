#!/usr/bin/env python3
"""Polygons from GIS formats, GeoJSON and WKT, and boundaries from Gmsh: inputs of afmesh_2.

A real coastline (MESH2D's Lake Superior from the shared data: a shoreline
and six islands) is written as a GeoJSON FeatureCollection and as a WKT
POLYGON by this script (and, when afmesh_2 was built with GDAL, as a
Shapefile and a GeoPackage by GDAL's ogr2ogr), meshed from each, and
checked: the independent
validity checker on the mesh and the boundary afmesh_2 writes, the same
triangles from GeoJSON, WKT and the GeoPackage (the Shapefile's rings
are stored in another order: as many triangles), and the meshed area equal to the shoreline's
minus the islands' (shoelace formula here, independent of the mesher). A
MULTIPOLYGON with an island inside a hole, a square with a hole drawn with
Gmsh's Python API and saved as a 1D mesh in MSH 4.1 and 2.2 (when
python3-gmsh is installed), and malformed files (each refused with exit
code 1 and a message naming the file), complete it.

usage: check_polygon_inputs.py AFMESH CHECK WORK_DIR SHARED_DATA_DIR
"""
import json
import os
import shutil
import subprocess
import sys

from cli_checks import check, finish, run

AFMESH, CHECK, WORK, SHARED = sys.argv[1:5]
# built with GDAL (afmesh_2 --version says so): OGR sources are read, made here with GDAL's ogr2ogr
HAS_GDAL = "without GDAL" not in subprocess.run([AFMESH, "--version"], capture_output=True, text=True).stdout
OGR2OGR = shutil.which("ogr2ogr") or "ogr2ogr (gdal-bin) is needed with GDAL"
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
    sources = [(g, "lake_geojson"), (w, "lake_wkt")]
    if HAS_GDAL:
        # the same polygon as a Shapefile and a GeoPackage, written by GDAL's ogr2ogr, read through GDAL
        for ext, driver in (("shp", "ESRI Shapefile"), ("gpkg", "GPKG")):
            out = os.path.join(WORK, "lake." + ext)
            if os.path.exists(out):
                os.remove(out)
            run(OGR2OGR, "-f", driver, out, g)
            sources.append((out, "lake_" + ext))
    for src, name in sources:
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
        # the 303 points of the polygon are all on the boundary written, with
        # the cuts of the boundary discretisation between them (closed loops:
        # as many segments as points)
        written = set((float(r[1]), float(r[2])) for r in rows[1:n + 1])
        given = set(tuple(p) for l in loops for p in l)
        check(len(given) == 303 and given <= written and ns == n,
              "%s: the boundary has the 303 points of the polygon (%d of them written; %d points, %d segments)"
              % (name, len(given & written), n, ns))
        check(int(rows[n + 2 + ns][0]) == 6, "%s: six holes, the islands (%s)" % (name, rows[n + 2 + ns][0]))
    check(node_text(os.path.join(WORK, "lake_geojson")) == node_text(os.path.join(WORK, "lake_wkt")),
          "lake: the same mesh from GeoJSON and from WKT")
    if HAS_GDAL:
        # a GeoPackage keeps the rings as given; a Shapefile stores the outer ring clockwise, so its points
        # come in another order, and the mesh, of the same domain (area and boundary checked above), differs
        check(node_text(os.path.join(WORK, "lake_gpkg")) == node_text(os.path.join(WORK, "lake_geojson")),
              "lake: the same mesh from the GeoPackage as from GeoJSON")
        nt_shp, nt_json = mesh_area(os.path.join(WORK, "lake_shp.off"))[1], mesh_area(os.path.join(WORK, "lake_geojson.off"))[1]
        check(abs(nt_shp - nt_json) <= 0.01 * nt_json, "lake: as many triangles from the Shapefile (%d, %d)" %
              (nt_shp, nt_json))
        # GDAL is in a module loaded only for such inputs: afmesh_2 runs without it (a .poly file), and
        # refuses an OGR source naming the module when it is not beside the executable
        alone = os.path.join(WORK, "without_module")
        os.makedirs(alone, exist_ok=True)
        shutil.copy(AFMESH, alone)
        lone = os.path.join(alone, os.path.basename(AFMESH))
        run(lone, os.path.join(WORK, "lake_geojson.poly"), "--size", "0.1", "-o", os.path.join(alone, "lake.off"))
        r = run(lone, os.path.join(WORK, "lake.gpkg"), "--size", "0.1", "-o", os.path.join(alone, "x.off"), code=1)
        check("lake.gpkg" in r.stderr and "afmesh_2_ogr.so" in r.stderr and r.stderr.count("\n") == 1,
              "without the GDAL module: %s" % r.stderr)
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

# --- a Gmsh 1D mesh: a square with a hole, its sides in the physical groups 3 (outer) and 7 (hole), ---------
# meshed along its curves at the size then asked of afmesh_2, saved in MSH 4.1 (Gmsh's default) and 2.2
try:
    import gmsh
except ImportError:
    gmsh = None
if gmsh is not None:
    msh41, msh22, msh_binary = (os.path.join(WORK, n) for n in ("square41.msh", "square22.msh", "binary.msh"))
    gmsh.initialize(["", "-v", "0"])
    try:
        geo = gmsh.model.geo

        def gmsh_square(x0, y0, x1, y1, lc):
            p = [geo.addPoint(x, y, 0, lc) for x, y in ((x0, y0), (x1, y0), (x1, y1), (x0, y1))]
            return [geo.addLine(p[i], p[(i + 1) % 4]) for i in range(4)]

        outer, inner = gmsh_square(0, 0, 1, 1, 0.05), gmsh_square(0.4, 0.4, 0.6, 0.6, 0.05)
        geo.addPlaneSurface([geo.addCurveLoop(outer), geo.addCurveLoop(inner)])
        geo.synchronize()
        gmsh.model.addPhysicalGroup(1, outer, 3)
        gmsh.model.addPhysicalGroup(1, inner, 7)
        gmsh.model.mesh.generate(1)
        gmsh.write(msh41)
        gmsh.option.setNumber("Mesh.MshFileVersion", 2.2)
        gmsh.write(msh22)
        gmsh.option.setNumber("Mesh.Binary", 1)
        gmsh.write(msh_binary)
    finally:
        gmsh.finalize()
    shutil.copyfile(msh41, os.path.join(WORK, "SQUARE.MSH"))
    for src, name in ((msh41, "gmsh41"), (msh22, "gmsh22"), (os.path.join(WORK, "SQUARE.MSH"), "gmsh_upper")):
        base = os.path.join(WORK, name)
        r = run(AFMESH, src, "--size", "0.05", "-o", base + ".off", "-o", base + ".poly")
        check(r.stderr == "", "%s: unexpected message: %s" % (name, r.stderr))
        run(CHECK, base + ".poly", base + ".off")
        area, nt = mesh_area(base + ".off")
        check(abs(area - 0.96) < 1e-12, "%s: meshed area %.15g, expected 0.96" % (name, area))
        # the boundary written back: 96 segments, the physical groups as their markers
        rows = [l.split() for l in open(base + ".poly") if l.split()]
        n = int(rows[0][0])
        pts = {int(r[0]): (float(r[1]), float(r[2])) for r in rows[1:1 + n]}
        ns = int(rows[n + 1][0])
        check(ns == 96 and rows[n + 1][1] == "1", "%s: %s segments with markers, expected 96" % (name, rows[n + 1]))
        for r in rows[n + 2:n + 2 + ns]:
            a, b = pts[int(r[1])], pts[int(r[2])]
            in_hole = all(0.4 <= c <= 0.6 for c in a + b)
            check(int(r[3]) == (7 if in_hole else 3), "%s: segment %s: marker %s" % (name, r[0], r[3]))
    check(open(os.path.join(WORK, "gmsh41.off")).read() == open(os.path.join(WORK, "gmsh22.off")).read() ==
          open(os.path.join(WORK, "gmsh_upper.off")).read(), "gmsh: the same mesh from MSH 4.1 and 2.2")
    r = run(AFMESH, msh_binary, "--size", "0.1", "--no-output", code=1)
    check(r.stderr == "afmesh_2: error: " + msh_binary + ":2: binary .msh is not supported: save it as ASCII "
          "(Gmsh's default: option Mesh.Binary = 0, or no -bin on the command line)\n", "binary .msh: " + r.stderr)
else:
    print("gmsh (python3-gmsh) not found - the Gmsh part is skipped")

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
refused("points.msh", "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n1\n1 0 0 0\n$EndNodes\n$Elements\n1\n"
        "1 15 2 0 1 1\n$EndElements\n", ": no line elements (type 1 or 8")
refused("undefined.msh", "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n2\n1 0 0 0\n2 1 0 0\n$EndNodes\n$Elements\n"
        "1\n7 1 2 0 1 1 9\n$EndElements\n", ":11: element 7 refers to node 9, which $Nodes does not define")
refused("crossing.msh", "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n4\n1 0 0 0\n2 1 1 0\n3 1 0 0\n4 0 1 0\n"
        "$EndNodes\n$Elements\n2\n5 1 0 1 2\n6 1 0 3 4\n$EndElements\n", ":14: segment 6 crosses segment 5 (line 13)")

# --- GIS vector sources through GDAL (Shapefile, GeoPackage, ...), or a clear refusal without it ----------
if HAS_GDAL:
    line = os.path.join(WORK, "line.geojson")
    open(line, "w").write('{"type": "LineString", "coordinates": [[0, 0], [1, 1]]}')
    for f in ("line.gpkg",):
        if os.path.exists(os.path.join(WORK, f)):
            os.remove(os.path.join(WORK, f))
    run(OGR2OGR, "-f", "GPKG", os.path.join(WORK, "line.gpkg"), line)
    r = run(AFMESH, os.path.join(WORK, "line.gpkg"), "--size", "0.1", "--no-output", code=1)
    check(r.stderr == "afmesh_2: error: %s: layer 'line', feature 1: a LINESTRING is not a polygon or a "
          "multipolygon\n" % os.path.join(WORK, "line.gpkg"), "line.gpkg: unexpected message: " + r.stderr)
    refused("garbage.shp", "not a shapefile\n", ": cannot open as vector data")
    r = run(AFMESH, os.path.join(WORK, "missing.gpkg"), "--size", "0.1", "--no-output", code=1)
    check(r.stderr.startswith("afmesh_2: error: %s: cannot open (no such file)" % os.path.join(WORK, "missing.gpkg")),
          "missing.gpkg: unexpected message: " + r.stderr)
else:
    refused("any.shp", "", ": this afmesh_2 was built without GDAL")

finish("polygon inputs")
