#!/usr/bin/env python3
"""Markers and regions end to end, read back with the tools users use.

afmesh_2 meshes a multi-region input made by our own afm_make_input
(tagged-regions: three regions, segment and vertex markers, area limits)
and Triangle's la.poly from the shared data (its markers and regions),
writing .node/.ele/.edge, .msh, .vtu and the boundary .poly, in memory and
streamed (--stream), the VTU binary and ASCII. Every mesh is checked by the
independent validity checker; the markers and regions are read back with
our own parser of Triangle's files, with meshio (.msh and .vtu) and with
Gmsh's own Python API (.msh), and must agree with each other, between the
in-memory and the streamed run, and with the input.

usage: check_markers_and_regions.py AFMESH MAKE_INPUT CHECK WORK_DIR [SHARED_DATA_DIR]
"""
import math
import os
import sys

import meshio
import numpy as np

from cli_checks import check, finish, run
from tagged_files import check_formats_agree, numbers, read_triangle, tagged_geometry

AFMESH, MAKE_INPUT, CHECK, WORK = sys.argv[1:5]
SHARED = sys.argv[5] if len(sys.argv) > 5 else ""
os.makedirs(WORK, exist_ok=True)


def check_streamed_like_in_memory(input_file, base, extra_args):
    """--stream writes the same mesh with the same tags as the in-memory run on one thread (streaming meshes on
    one), in every format, binary and ASCII VTU alike."""
    serial = base + "_serial"
    run(AFMESH, input_file, *extra_args, "--threads", "1", "-o", serial + ".node")
    st = base + "_st"
    run(AFMESH, input_file, *extra_args, "--stream", "-o", st + ".node", "-o", st + ".msh", "-o", st + ".vtu",
        "-o", st + ".off")
    run(CHECK, input_file, st + ".off")
    streamed = read_triangle(st)
    check_formats_agree(st, *streamed)
    a, b = tagged_geometry(*read_triangle(serial)), tagged_geometry(*streamed)
    check(a[0] == b[0], base + ": streamed triangles and region attributes = in memory")
    check(a[1] == b[1], base + ": streamed segments and markers = in memory")
    check(a[2] == b[2], base + ": streamed vertex markers = in memory")
    # ASCII VTU on request, the same arrays as the binary default
    run(AFMESH, input_file, *extra_args, "--vtu-ascii", "-o", base + "_ascii.vtu")
    with open(base + ".vtu", "rb") as f:
        check(b'<AppendedData encoding="raw">' in f.read(), base + ".vtu is binary (raw appended) by default")
    with open(base + "_ascii.vtu", "rb") as f:
        text = f.read()
        check(b"AppendedData" not in text and b'format="ascii"' in text, base + "_ascii.vtu is ASCII")
    x, y = meshio.read(base + ".vtu"), meshio.read(base + "_ascii.vtu")
    check(np.array_equal(x.points, y.points) and all(np.array_equal(x.cells_dict[k], y.cells_dict[k])
                                                     for k in x.cells_dict), base + ": ASCII VTU = binary VTU")
    check(all(np.array_equal(x.point_data[k], y.point_data[k]) for k in x.point_data) and
          all(np.array_equal(u, v) for k in x.cell_data for u, v in zip(x.cell_data[k], y.cell_data[k])),
          base + ": ASCII VTU data = binary VTU data")


def inside(p, polygon):
    """Even-odd rule, for points off the polygon's boundary."""
    x, y = p
    c = False
    for i in range(len(polygon)):
        (x1, y1), (x2, y2) = polygon[i], polygon[i - 1]
        if (y1 > y) != (y2 > y) and x < x1 + (y - y1) * (x2 - x1) / (y2 - y1):
            c = not c
    return c


def triangle_areas(pts, tri):
    a, b, c = pts[tri[:, 0]], pts[tri[:, 1]], pts[tri[:, 2]]
    return 0.5 * np.abs((b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (c[:, 0] - a[:, 0]) * (b[:, 1] - a[:, 1]))


# --- our multi-region input --------------------------------------------------------------------------------
tr = os.path.join(WORK, "tr")
run(MAKE_INPUT, "tagged-regions", tr + ".poly")
run(AFMESH, tr + ".poly", "--size", "0.05", "-o", tr + ".node", "-o", tr + ".msh", "-o", tr + ".vtu",
    "-o", tr + ".off", "-o", tr + "_boundary.poly")
run(CHECK, tr + ".poly", tr + ".off")
pts, pmark, tri, attr, seg, smark = read_triangle(tr)
check(attr is not None, "tr.ele has the region attribute")
check_formats_agree(tr, pts, pmark, tri, attr, seg, smark)
check_streamed_like_in_memory(tr + ".poly", tr, ["--size", "0.05"])

# the region of each triangle, from the geometry: left of x = 1 is region 1,
# inside the inclusion (the polygon of the marker-6 segments) region 3, else 2
inclusion = sorted({tuple(pts[v]) for s, k in zip(seg, smark) if k == 6 for v in s},
                   key=lambda p: np.arctan2(p[1] - 0.5, p[0] - 1.5))
centre = pts[tri].mean(axis=1)
expected = np.array([1 if c[0] < 1 else (3 if inside(c, inclusion) else 2) for c in centre])
check(np.array_equal(attr, expected), "tr: every triangle has the attribute of the region it lies in")

# segment markers from the geometry, vertex markers by Triangle's rules
def segment_marker(a, b):
    if a[1] == 0 and b[1] == 0: return 1
    if a[0] == 2 and b[0] == 2: return 2
    if a[1] == 1 and b[1] == 1: return 3
    if a[0] == 0 and b[0] == 0: return 4
    if a[0] == 1 and b[0] == 1: return 5
    if abs(np.hypot(*(a - (1.5, 0.5))) - 0.2) < 1e-9: return 6
    return 7
expected_smark = np.array([segment_marker(pts[s[0]], pts[s[1]]) for s in seg])
check(np.array_equal(smark, expected_smark), "tr: every segment has its marker")
check(len(seg) == 906, "tr: all 906 input segments are segments of the mesh (got %d)" % len(seg))
on_segment = {}
for s, k in zip(seg, smark):
    for v in s:
        on_segment.setdefault(v, []).append(k)
corners = {(0., 0.), (2., 0.), (2., 1.), (0., 1.)}
for i, p in enumerate(pts):
    want = 9 if tuple(p) in corners else (min(on_segment[i]) if i in on_segment else 0)
    if pmark[i] != want:
        check(False, "tr: vertex %d at %s has marker %d, expected %d" % (i, p, pmark[i], want))
        break

# the area limits change the mesh: region 1 (limit 2e-4) and 3 (5e-5) are
# finer than region 2 (no limit, size 0.05), and mostly within their limits
area = triangle_areas(pts, tri)
for r, limit in ((1, 2e-4), (3, 5e-5)):
    sel = attr == r
    check(area[sel].mean() < limit, "tr: region %d's mean area %.3g below its limit %.3g" % (r, area[sel].mean(), limit))
    check((area[sel] > limit).mean() < 0.05, "tr: region %d: %.1f%% of the triangles above the limit" %
          (r, 100 * (area[sel] > limit).mean(), ))
check(area[attr == 2].mean() > 3 * area[attr == 1].mean(), "tr: region 2, without a limit, is coarser")

# the boundary .poly meshes again, to the same regions
run(AFMESH, tr + "_boundary.poly", "--size", "0.05", "-o", tr + "_again.node", "-o", tr + "_again.off")
run(CHECK, tr + "_boundary.poly", tr + "_again.off")
pts2, pmark2, tri2, attr2, seg2, smark2 = read_triangle(tr + "_again")
check(sorted(set(attr2.tolist())) == [1.0, 2.0, 3.0], "tr_boundary.poly keeps the regions")
check(sorted(smark2.tolist()) == sorted(smark.tolist()), "tr_boundary.poly keeps the segment markers")
check(abs(len(tri2) - len(tri)) <= 0.02 * len(tri), "tr_boundary.poly meshes to as many triangles (%d, %d)" %
      (len(tri2), len(tri)))

# --- Triangle's la.poly ------------------------------------------------------------------------------------
la_in = os.path.join(SHARED, "triangle_drufat", "la.poly")
if SHARED and os.path.exists(la_in):
    la = os.path.join(WORK, "la")
    run(AFMESH, la_in, "-o", la + ".node", "-o", la + ".msh", "-o", la + ".vtu", "-o", la + ".off")
    run(CHECK, la_in, la + ".off")
    pts, pmark, tri, attr, seg, smark = read_triangle(la)
    check_formats_agree(la, pts, pmark, tri, attr, seg, smark)
    check_streamed_like_in_memory(la_in, la, [])
    rows = numbers(la_in)
    n = int(rows[0][0])
    in_pts = {(float(r[1]), float(r[2])): int(r[3]) for r in rows[1:n + 1]}
    index = {tuple(p): i for i, p in enumerate(pts)}
    wrong = [p for p, k in in_pts.items() if k != 0 and pmark[index[p]] != k]
    check(not wrong, "la: every input vertex keeps its nonzero marker (%d do not)" % len(wrong))
    ns = int(rows[n + 1][0])
    in_seg = {}
    for r in rows[n + 2:n + 2 + ns]:
        a, b = (float(rows[int(r[1])][1]), float(rows[int(r[1])][2])), (float(rows[int(r[2])][1]), float(rows[int(r[2])][2]))
        in_seg[frozenset((a, b))] = int(r[3])
    # an input segment is one mesh segment, or a chain of them when the
    # boundary discretisation split it: the pieces lying on it cover it, and
    # each has its marker (a nonzero one as given)
    def on(a, b, p):
        dx, dy = b[0] - a[0], b[1] - a[1]
        l2 = dx * dx + dy * dy
        t = ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / l2
        return -1e-12 <= t <= 1 + 1e-12 and abs(dx * (p[1] - a[1]) - dy * (p[0] - a[0])) <= 1e-12 * l2
    mesh_segs = [(tuple(pts[s[0]]), tuple(pts[s[1]]), k) for s, k in zip(seg, smark)]
    wrong = []
    for ends, k in in_seg.items():
        a, b = tuple(ends)
        pieces = [(p, q, m) for p, q, m in mesh_segs if on(a, b, p) and on(a, b, q)]
        covered = sum(math.dist(p, q) for p, q, _ in pieces)
        if abs(covered - math.dist(a, b)) > 1e-9 * math.dist(a, b) or \
                len(set(m for _, _, m in pieces)) != 1 or (k != 0 and pieces[0][2] != k):
            wrong.append(ends)
    check(not wrong, "la: every input segment keeps its marker (%d do not)" % len(wrong))
    # its six regions have five attributes (two are 0.05)
    check(set(attr.tolist()) - {0.0} == {0.05, 0.2, 0.4, 0.8, 3.0}, "la: the regions are found")
else:
    print("la.poly not found under", SHARED, "- skipped")

finish("markers and regions")
