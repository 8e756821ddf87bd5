"""Advancing_front_mesh_2 from Python: triangular meshes of planar domains.

The advancing-front Delaunay mesher of D. J. Mavriplis (1992), as in the
afmesh_2 command-line tool (the same input and options give the same
triangles): NumPy arrays in, NumPy arrays out, and a meshio.Mesh when meshio
is installed.

    import numpy as np, afmesh_2
    square = np.array([[0, 0], [1, 0], [1, 1], [0, 1]], float)
    m = afmesh_2.mesh(square, [[0, 1], [1, 2], [2, 3], [3, 0]], size=0.05)
    m.points, m.triangles                  # (n, 2) floats, (t, 3) 0-based, counter-clockwise
    m.to_meshio().write("square.vtu")
"""
from ._afmesh_2 import InputError, PolyReadError, __version__
from ._afmesh_2 import mesh as _mesh

__all__ = ["mesh", "grid_size", "Mesh", "InputError", "PolyReadError", "__version__"]


class Mesh:
    """A mesh: its points, triangles and segments, with their tags.

    points: (n, 2) float64; triangles: (t, 3) int64, 0-based, counter-clockwise;
    segments: (s, 2) int64, the constrained edges beside the domain (a boundary
    edge with the domain on its left); vertex_markers: (n,) and segment_markers:
    (s,) int32, by Triangle's rules (1 on the boundary, 0 inside, unless given);
    regions: (t,) float64, the region attribute of each triangle (0 outside every
    region), or None without regions; return_code: "MESH_COMPLETE".
    """

    def __init__(self, points, triangles, segments, vertex_markers, segment_markers, regions, return_code):
        self.points = points
        self.triangles = triangles
        self.segments = segments
        self.vertex_markers = vertex_markers
        self.segment_markers = segment_markers
        self.regions = regions
        self.return_code = return_code

    def __repr__(self):
        return "afmesh_2.Mesh(%d points, %d triangles, %d segments%s)" % (
            len(self.points), len(self.triangles), len(self.segments),
            "" if self.regions is None else ", regions")

    def to_meshio(self):
        """The mesh as a meshio.Mesh: triangles and the segments as lines, the
        markers as point and cell data 'marker', the regions as cell data 'region'."""
        import meshio
        import numpy as np
        cells = [("triangle", self.triangles), ("line", self.segments)]
        cell_data = {"marker": [np.zeros(len(self.triangles), dtype=np.int32), self.segment_markers]}
        if self.regions is not None:
            cell_data["region"] = [self.regions, np.zeros(len(self.segments))]
        # z = 0: the 3D points VTK and Gmsh files hold
        points = np.column_stack([self.points, np.zeros(len(self.points))])
        return meshio.Mesh(points, cells, point_data={"marker": self.vertex_markers}, cell_data=cell_data)


def grid_size(xs, ys, h):
    """A size function from a grid of sizes: h[j, i] at (xs[i], ys[j]),
    interpolated bilinearly (the nearest edge value outside the grid); for
    size=(xs, ys, h). xs and ys strictly increasing, at least 2 each; h of
    shape (len(ys), len(xs)), positive and finite. Raises ValueError."""
    import numpy as np
    xs, ys, h = (np.asarray(a, dtype=float) for a in (xs, ys, h))
    for name, a in (("xs", xs), ("ys", ys)):
        if a.ndim != 1 or len(a) < 2 or not np.all(np.isfinite(a)) or not np.all(np.diff(a) > 0):
            raise ValueError("grid size: %s must be at least 2 finite, strictly increasing values" % name)
    if h.shape != (len(ys), len(xs)):
        raise ValueError("grid size: h has shape %s, expected (len(ys), len(xs)) = (%d, %d)" %
                         (h.shape, len(ys), len(xs)))
    if not np.all(np.isfinite(h)) or not np.all(h > 0):
        raise ValueError("grid size: every value of h must be positive and finite")

    def size(points):
        x = np.clip(points[:, 0], xs[0], xs[-1])
        y = np.clip(points[:, 1], ys[0], ys[-1])
        i = np.clip(np.searchsorted(xs, x, side="right") - 1, 0, len(xs) - 2)
        j = np.clip(np.searchsorted(ys, y, side="right") - 1, 0, len(ys) - 2)
        tx = (x - xs[i]) / (xs[i + 1] - xs[i])
        ty = (y - ys[j]) / (ys[j + 1] - ys[j])
        return ((1 - ty) * ((1 - tx) * h[j, i] + tx * h[j, i + 1]) +
                ty * ((1 - tx) * h[j + 1, i] + tx * h[j + 1, i + 1]))
    return size


def mesh(vertices, segments=None, holes=None, *, regions=None, vertex_markers=None, segment_markers=None,
         size=None, sources=None, max_size=None, grading=0.2, boundary_spacing="grow", smooth=0,
         smoother="quality", kernel="epick", keep_segments=False, min_angle=0.0, threads=None):
    """Meshes the domain bounded by `segments`.

    vertices: (n, 2) coordinates; segments: (m, 2) 0-based indices into vertices;
    holes: (k, 2) points inside the holes; regions: (r, 4) rows (x, y, attribute,
    max_area) as in a .poly file (max_area <= 0: no limit); vertex_markers (n,)
    and segment_markers (m,): integer boundary markers.

    The size (target edge length h) is one of:
      size=H                 a uniform size;
      size=f                 a function of an (n, 2) array of points returning n
                             sizes, evaluated in bulk a few times on a quadtree
                             of samples (not once per point);
      size=(xs, ys, h)       a NumPy grid of sizes, h[j, i] at (xs[i], ys[j]),
                             interpolated bilinearly (see grid_size());
      sources=(s, 3) array   point sources (x, y, h) diffused by a Poisson solve,
                             with the boundary spacing grown at `grading`
                             (None: not limited) and bounded by max_size;
      nothing                the boundary spacing grown at `grading`.
    Regions with an area limit bound any of them. Segments longer than the
    local size are split to it first, unless keep_segments=True (every
    segment one mesh edge, as afmesh_2 --keep-segments). smooth=N runs N passes of
    the smoother ('quality' or 'laplacian'); min_angle=A (0 < A <= 30) then
    raises the smallest angle to A degrees by local Delaunay refinement, as
    afmesh_2 --min-angle; kernel: 'epick', 'epeck' or 'exact-rational'.
    threads=N meshes N strips of the domain at once and merges them, as
    afmesh_2 --threads N (1: the serial mesher; None: every core, or one
    with keep_segments); the mesh depends on N, and for a given N not on
    the machine.

    Invalid input raises ValueError (InputError for a graph that cannot be
    meshed, with the message of the afmesh_2 tool). The GIL is released while
    meshing.
    """
    if isinstance(size, tuple):
        if len(size) != 3:
            raise ValueError("size: a grid is given as (xs, ys, h)")
        size = grid_size(*size)
    return Mesh(**_mesh(vertices, segments, holes, regions, vertex_markers, segment_markers, size, sources,
                        max_size, grading, boundary_spacing, smooth, smoother, kernel,
                        keep_segments, float(min_angle), 0 if threads is None else int(threads)))
