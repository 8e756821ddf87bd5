"""Readers of the tagged outputs (markers and regions) that the checks of
afmesh_2 (check_markers_and_regions.py) and afmesh_2_mpi (mpi_checks.py)
share: Triangle's .node/.ele/.edge by our own parser, and a check that the
.msh (meshio and Gmsh's own reader) and the .vtu (meshio) beside them hold
the same."""
import gmsh
import meshio
import numpy as np

from cli_checks import check


def numbers(path):
    """The lines of a Triangle file without comments, as lists of tokens."""
    rows = []
    with open(path) as f:
        for line in f:
            line = line.split("#")[0].split()
            if line:
                rows.append(line)
    return rows


def read_triangle(base):
    """.node/.ele/.edge: points, point markers, triangles (0-based), attributes, segments, segment markers."""
    node = numbers(base + ".node")
    n, dim, nattr, nmark = map(int, node[0])
    check(dim == 2 and nattr == 0 and nmark == 1, base + ".node header has one marker per vertex")
    pts = np.array([[float(r[1]), float(r[2])] for r in node[1:n + 1]])
    pmark = np.array([int(r[3]) for r in node[1:n + 1]])
    ele = numbers(base + ".ele")
    m, per, ea = map(int, ele[0])
    tri = np.array([[int(r[1]) - 1, int(r[2]) - 1, int(r[3]) - 1] for r in ele[1:m + 1]])
    attr = np.array([float(r[4]) for r in ele[1:m + 1]]) if ea == 1 else None
    edge = numbers(base + ".edge")
    k, em = map(int, edge[0])
    check(em == 1, base + ".edge has one marker per segment")
    seg = np.array([[int(r[1]) - 1, int(r[2]) - 1] for r in edge[1:k + 1]])
    smark = np.array([int(r[3]) for r in edge[1:k + 1]])
    return pts, pmark, tri, attr, seg, smark


def check_formats_agree(base, pts, pmark, tri, attr, seg, smark):
    """The .msh (meshio and Gmsh) and the .vtu (meshio) hold what the Triangle files hold."""
    # VTU through meshio
    v = meshio.read(base + ".vtu")
    check(np.array_equal(v.points[:, :2], pts), base + ".vtu: the points of the .node, in its order")
    check(np.array_equal(v.cells_dict["triangle"], tri), base + ".vtu: the triangles of the .ele")
    check(np.array_equal(v.cells_dict["line"], seg), base + ".vtu: the segments of the .edge as lines")
    check(np.array_equal(v.point_data["marker"], pmark), base + ".vtu: point data 'marker' = .node markers")
    check(np.array_equal(v.cell_data_dict["marker"]["line"], smark), base + ".vtu: cell data 'marker' = .edge markers")
    if attr is not None:
        check(np.array_equal(v.cell_data_dict["region"]["triangle"], attr),
              base + ".vtu: cell data 'region' = .ele attributes")

    # MSH through meshio: physical tags and names
    g = meshio.read(base + ".msh")
    check(np.array_equal(g.points[:, :2], pts), base + ".msh: the points of the .node")
    phys = g.cell_data_dict["gmsh:physical"]
    # meshio merges the blocks of one cell type in file order: compare as sets of cells with their tags
    msh_tri = {tuple(sorted(t)): int(p) for t, p in zip(g.cells_dict["triangle"], phys["triangle"])}
    msh_seg = {tuple(sorted(s)): int(p) for s, p in zip(g.cells_dict["line"], phys["line"])}
    check(len(msh_tri) == len(tri) and len(msh_seg) == len(seg), base + ".msh: as many triangles and lines")
    names = {tuple(val)[::-1]: key for key, val in g.field_data.items()}  # (dim, tag) -> name
    for s, k in zip(seg, smark):
        tag = msh_seg.get(tuple(sorted(s)))
        if names.get((1, tag)) != "marker_%d" % k:
            check(False, base + ".msh: segment %s in physical group %s, expected marker_%d" % (s, names.get((1, tag)), k))
            break
    if attr is not None:
        for t, a in zip(tri, attr):
            tag = msh_tri.get(tuple(sorted(t)))
            expected = "region_%s" % ("%g" % a if a != int(a) else "%d" % a)
            if names.get((2, tag)) != expected:
                check(False, base + ".msh: triangle %s in group %s, expected %s" % (t, names.get((2, tag)), expected))
                break

    # MSH through Gmsh's own reader
    gmsh.initialize(["", "-v", "0"])
    try:
        gmsh.open(base + ".msh")
        groups = gmsh.model.getPhysicalGroups()
        gnames = {(d, t): gmsh.model.getPhysicalName(d, t) for d, t in groups}
        counts = {}
        for (d, t), name in gnames.items():
            n = 0
            for e in gmsh.model.getEntitiesForPhysicalGroup(d, t):
                types, tags, _ = gmsh.model.mesh.getElements(d, e)
                n += sum(len(x) for x in tags)
            counts[name] = n
        for k in set(smark.tolist()):
            check(counts.get("marker_%d" % k) == int((smark == k).sum()),
                  base + ".msh (Gmsh): group marker_%d holds its %d segments" % (k, (smark == k).sum()))
        if attr is not None:
            for a in set(attr.tolist()):
                name = "region_%s" % ("%g" % a if a != int(a) else "%d" % a)
                check(counts.get(name) == int((attr == a).sum()),
                      base + ".msh (Gmsh): group %s holds its %d triangles (got %s)" % (name, (attr == a).sum(),
                                                                                       counts.get(name)))
        node_tags, coords, _ = gmsh.model.mesh.getNodes()
        check(len(node_tags) == len(pts), base + ".msh (Gmsh): %d nodes" % len(pts))
    finally:
        gmsh.finalize()


def tagged_geometry(pts, pmark, tri, attr, seg, smark):
    """The tags keyed by coordinates, independent of the numbering."""
    t = {tuple(sorted(map(tuple, pts[x]))): (None if attr is None else float(a))
         for x, a in zip(tri, attr if attr is not None else [None] * len(tri))}
    s = {frozenset(map(tuple, pts[x])): int(k) for x, k in zip(seg, smark)}
    p = {tuple(q): int(k) for q, k in zip(pts, pmark)}
    return t, s, p
