"""The Python module afmesh_2, run by pytest from ctest (test python_module).

The environment names the tools: AFMESH (the command-line tool), MAKE_INPUT
(afm_make_input), CHECK (the independent validity checker), WORK (a scratch
directory) and SHARED (../shared/data, may be empty).
"""
import os
import subprocess
import sys

import meshio
import numpy as np
import pytest

import afmesh_2

AFMESH = os.environ["AFMESH"]
MAKE_INPUT = os.environ["MAKE_INPUT"]
CHECK = os.environ["CHECK"]
WORK = os.environ["WORK"]
os.makedirs(WORK, exist_ok=True)


def run(*args):
    r = subprocess.run([str(a) for a in args], capture_output=True, text=True)
    assert r.returncode == 0, "%s\n%s%s" % (" ".join(map(str, args)), r.stdout, r.stderr)
    return r


def read_poly(path):
    """Our own .poly files (no comments, 1-based): vertices, segments, holes, regions, markers."""
    rows = [line.split() for line in open(path) if line.split()]
    n, _, _, nm = map(int, rows[0])
    vertices = np.array([[float(r[1]), float(r[2])] for r in rows[1:n + 1]])
    vmark = np.array([int(r[3]) for r in rows[1:n + 1]]) if nm else None
    k = n + 1
    ns, sm = map(int, rows[k])
    segments = np.array([[int(r[1]) - 1, int(r[2]) - 1] for r in rows[k + 1:k + 1 + ns]])
    smark = np.array([int(r[3]) for r in rows[k + 1:k + 1 + ns]]) if sm else None
    k += 1 + ns
    nh = int(rows[k][0])
    holes = np.array([[float(r[1]), float(r[2])] for r in rows[k + 1:k + 1 + nh]]).reshape(-1, 2)
    k += 1 + nh
    regions = None
    if k < len(rows):
        nr = int(rows[k][0])
        regions = np.array([[float(x) for x in r[1:5]] for r in rows[k + 1:k + 1 + nr]])
    return vertices, segments, holes, regions, vmark, smark


def read_node_ele(base):
    node = [l.split() for l in open(base + ".node") if l.split()]
    ele = [l.split() for l in open(base + ".ele") if l.split()]
    points = np.array([[float(r[1]), float(r[2])] for r in node[1:]])
    triangles = np.array([[int(r[1]) - 1, int(r[2]) - 1, int(r[3]) - 1] for r in ele[1:]])
    return points, triangles


def write_off(path, m):
    with open(path, "w") as f:
        f.write("OFF\n%d %d 0\n" % (len(m.points), len(m.triangles)))
        for p in m.points:
            f.write("%.17g %.17g 0\n" % (p[0], p[1]))
        for t in m.triangles:
            f.write("3 %d %d %d\n" % tuple(t))


def check_valid(poly, m, name):
    off = os.path.join(WORK, name + ".off")
    write_off(off, m)
    run(CHECK, poly, off)


@pytest.fixture(scope="module")
def airfoil():
    path = os.path.join(WORK, "airfoil.poly")
    run(MAKE_INPUT, "multi-element-airfoil", path)
    return path


@pytest.mark.parametrize("options", [["--size", "0.05"], [], ["--size", "0.05", "--smooth", "3"]])
def test_same_triangles_as_the_cli(airfoil, options):
    v, s, h, _, _, _ = read_poly(airfoil)
    base = os.path.join(WORK, "cli_%d" % len(options))
    run(AFMESH, airfoil, *options, "-o", base + ".node")
    kwargs = {}
    if "--size" in options:
        kwargs["size"] = float(options[options.index("--size") + 1])
    if "--smooth" in options:
        kwargs["smooth"] = int(options[options.index("--smooth") + 1])
    m = afmesh_2.mesh(v, s, h, **kwargs)
    points, triangles = read_node_ele(base)
    assert np.array_equal(m.points, points)
    assert np.array_equal(m.triangles, triangles)
    check_valid(airfoil, m, "airfoil_%d" % len(options))


def test_size_function_in_bulk(airfoil):
    v, s, h, _, _, _ = read_poly(airfoil)
    calls = []

    def size(points):
        calls.append(len(points))
        return 0.01 + 0.2 * np.hypot(points[:, 0] - 0.5, points[:, 1])

    m = afmesh_2.mesh(v, s, h, size=size)
    check_valid(airfoil, m, "airfoil_function")
    # a few calls on arrays, not one per point
    assert 0 < len(calls) < 40 and max(calls) > 100
    assert sum(calls) < len(m.triangles)
    # the size follows the function: triangles near (0.5, 0) are smaller than far away
    centre = m.points[m.triangles].mean(axis=1)
    d = np.hypot(centre[:, 0] - 0.5, centre[:, 1])
    edge = np.linalg.norm(m.points[m.triangles[:, 0]] - m.points[m.triangles[:, 1]], axis=1)
    assert edge[(d > 3) & (d < 5)].mean() > 5 * edge[(d > 0.6) & (d < 0.8)].mean()


def test_size_grid(airfoil):
    """A NumPy grid of sizes: the same mesh as the function it samples where that function is bilinear in each
    cell (here linear), and bad grids refused."""
    v, s, h, _, _, _ = read_poly(airfoil)
    xs, ys = np.linspace(-20, 21, 42), np.linspace(-20, 20, 9)
    grid = 0.02 + 0.01 * np.abs(xs)[None, :] + 0.0 * ys[:, None]
    linear = lambda p: 0.02 + 0.01 * np.abs(np.clip(p[:, 0], -20, 21))
    m = afmesh_2.mesh(v, s, h, size=(xs, ys, grid))
    check_valid(airfoil, m, "airfoil_grid")
    # |x| is linear on each cell, the grid's nodes at integers
    f = afmesh_2.mesh(v, s, h, size=linear)
    assert len(m.triangles) > 1000
    assert abs(len(m.triangles) - len(f.triangles)) <= 0.01 * len(f.triangles)
    p = np.array([[0.25, 0.3], [-7.5, 1.0], [30.0, 0.0]])
    assert np.allclose(afmesh_2.grid_size(xs, ys, grid)(p), linear(p))
    for bad in ((xs[::-1], ys, grid), (xs, ys, grid[:, :-1]), (xs, ys, -grid), (xs, [0.0], grid[:1]), (xs, ys)):
        with pytest.raises(ValueError):
            afmesh_2.mesh(v, s, h, size=bad)


def test_markers_regions_and_meshio():
    path = os.path.join(WORK, "tagged.poly")
    run(MAKE_INPUT, "tagged-regions", path)
    v, s, h, regions, vmark, smark = read_poly(path)
    m = afmesh_2.mesh(v, s, h, regions=regions, vertex_markers=vmark, segment_markers=smark, size=0.05)
    check_valid(path, m, "tagged")
    assert sorted(set(m.regions.tolist())) == [1.0, 2.0, 3.0]
    assert sorted(set(m.segment_markers.tolist())) == [1, 2, 3, 4, 5, 6, 7]
    corners = [i for i, p in enumerate(m.points) if p[0] in (0, 2) and p[1] in (0, 1)]
    assert len(corners) == 4 and all(m.vertex_markers[i] == 9 for i in corners)
    # the same as the tool writes
    base = os.path.join(WORK, "tagged_cli")
    run(AFMESH, path, "--size", "0.05", "-o", base + ".node")
    points, triangles = read_node_ele(base)
    assert np.array_equal(m.points, points) and np.array_equal(m.triangles, triangles)
    attributes = np.array([float(l.split()[4]) for l in open(base + ".ele").readlines()[1:]])
    assert np.array_equal(m.regions, attributes)
    # through meshio and back
    out = os.path.join(WORK, "tagged_python.vtu")
    m.to_meshio().write(out)
    back = meshio.read(out)
    assert np.array_equal(back.cells_dict["triangle"], m.triangles)
    assert np.array_equal(back.cell_data_dict["region"]["triangle"], m.regions)
    assert np.array_equal(back.cell_data_dict["marker"]["line"], m.segment_markers)
    assert np.array_equal(back.point_data["marker"], m.vertex_markers)


def test_boundary_discretisation():
    """A unit square by its corners: split to the size by default, kept on request."""
    path = os.path.join(WORK, "unit_square.poly")
    with open(path, "w") as f:
        f.write("4 2 0 0\n1 0 0\n2 1 0\n3 1 1\n4 0 1\n4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n0\n")
    v, s, h, _, _, _ = read_poly(path)
    # on one thread: a cut would split two more sides (test_threads meshes in parts)
    m = afmesh_2.mesh(v, s, h, size=0.02, threads=1)
    check_valid(path, m, "unit_square")
    assert 5000 < len(m.triangles) < 6500
    # 4 sides of 50 pieces: 200 boundary segments
    assert len(m.segments) == 200
    kept = afmesh_2.mesh(v, s, h, size=0.02, keep_segments=True)
    check_valid(path, kept, "unit_square_kept")
    assert len(kept.triangles) == 4 and len(kept.segments) == 4
    # the same as the tool writes
    base = os.path.join(WORK, "unit_square_cli")
    run(AFMESH, path, "--size", "0.02", "--threads", "1", "-o", base + ".node")
    points, triangles = read_node_ele(base)
    assert np.array_equal(m.points, points) and np.array_equal(m.triangles, triangles)


def test_min_angle():
    """min_angle=30 as afmesh_2 --min-angle 30: the same mesh, every angle of at least
    30 degrees but at the wedge's 16.7 degree corner; bad bounds are a ValueError."""
    path = os.path.join(WORK, "wedge.poly")
    with open(path, "w") as f:
        f.write("3 2 0 0\n1 0 0\n2 1 0\n3 1 0.3\n3 0\n1 1 2\n2 2 3\n3 3 1\n0\n")
    v, s, h, _, _, _ = read_poly(path)
    m = afmesh_2.mesh(v, s, h, size=0.05, min_angle=30)
    check_valid(path, m, "wedge_min_angle")
    p = m.points[m.triangles]
    smallest = []
    for i in range(3):
        a, b = p[:, (i + 1) % 3] - p[:, i], p[:, (i + 2) % 3] - p[:, i]
        cosine = (a * b).sum(1) / np.linalg.norm(a, axis=1) / np.linalg.norm(b, axis=1)
        smallest.append(np.degrees(np.arccos(np.clip(cosine, -1, 1))))
    smallest = np.min(smallest, axis=0)
    at_corner = np.linalg.norm(p, axis=2).min(1) < 0.1
    assert (smallest[~at_corner] >= 30 - 1e-6).all()
    base = os.path.join(WORK, "wedge_cli")
    run(AFMESH, path, "--size", "0.05", "--min-angle", "30", "-o", base + ".node")
    points, triangles = read_node_ele(base)
    assert np.array_equal(m.points, points) and np.array_equal(m.triangles, triangles)
    for bad in (-1, 31, float("nan")):
        with pytest.raises(ValueError):
            afmesh_2.mesh(v, s, h, size=0.05, min_angle=bad)


def test_sources_and_kernels(airfoil):
    v, s, h, _, _, _ = read_poly(airfoil)
    sources = np.array([[0.0, 0.0, 0.02], [1.0, 0.0, 0.04]])
    for kernel in ("epick", "epeck"):
        m = afmesh_2.mesh(v, s, h, sources=sources, max_size=0.5, kernel=kernel)
        check_valid(airfoil, m, "airfoil_sources_" + kernel)
        assert len(m.triangles) > 1000
        # the sources refine the field: finer than the boundary-spacing field alone
        assert len(m.triangles) > len(afmesh_2.mesh(v, s, h, max_size=0.5, kernel=kernel).triangles)


def test_errors():
    square = np.array([[0, 0], [1, 0], [1, 1], [0, 1]], float)
    sides = [[0, 1], [1, 2], [2, 3], [3, 0]]
    with pytest.raises(ValueError, match="segment 1 crosses segment 0"):
        afmesh_2.mesh(square, [[0, 2], [1, 3]], size=0.1)
    with pytest.raises(afmesh_2.InputError):
        afmesh_2.mesh(square, [[0, 2], [1, 3]], size=0.1)
    with pytest.raises(ValueError, match="out of range"):
        afmesh_2.mesh(square, [[0, 7]], size=0.1)
    with pytest.raises(ValueError, match="shape"):
        afmesh_2.mesh(np.zeros((4, 3)), sides, size=0.1)
    with pytest.raises(ValueError, match="positive"):
        afmesh_2.mesh(square, sides, size=-1)
    with pytest.raises(ValueError, match="returned -1"):
        afmesh_2.mesh(square, sides, size=lambda p: -np.ones(len(p)))
    with pytest.raises(ValueError, match="one size per point"):
        afmesh_2.mesh(square, sides, size=lambda p: np.ones(3))
    with pytest.raises(ZeroDivisionError):
        afmesh_2.mesh(square, sides, size=lambda p: 1 / 0)
    with pytest.raises(ValueError, match="hole 0 lies outside every closed boundary"):
        afmesh_2.mesh(square, sides, [[5, 5]], size=0.1)
    with pytest.raises(ValueError, match="kernel"):
        afmesh_2.mesh(square, sides, size=0.1, kernel="float")


def test_example_channel_with_inclusion():
    """The example script runs and writes what it says: a valid mesh, the inclusion's triangles in region 2,
    every boundary edge with the marker of its side."""
    example = os.path.join(os.path.dirname(__file__), "..", "..", "..", "examples", "Advancing_front_mesh_2", "python",
                           "examples", "channel_with_inclusion.py")
    out = os.path.join(WORK, "channel.vtu")
    r = run(sys.executable, example, out)
    assert "region 2:" in r.stdout and "wrote" in r.stdout
    m = meshio.read(out)
    points, triangles, lines = m.points[:, :2], m.cells_dict["triangle"], m.cells_dict["line"]
    # valid under the checker, against the boundary the file holds
    poly = os.path.join(WORK, "channel.poly")
    with open(poly, "w") as f:
        f.write("%d 2 0 0\n" % len(points))
        for i, p in enumerate(points):
            f.write("%d %.17g %.17g\n" % (i + 1, p[0], p[1]))
        f.write("%d 0\n" % len(lines))
        for i, s in enumerate(lines):
            f.write("%d %d %d\n" % (i + 1, s[0] + 1, s[1] + 1))
        f.write("0\n")
    off = os.path.join(WORK, "channel.off")
    with open(off, "w") as f:
        f.write("OFF\n%d %d 0\n" % (len(points), len(triangles)))
        for p in points:
            f.write("%.17g %.17g 0\n" % (p[0], p[1]))
        for t in triangles:
            f.write("3 %d %d %d\n" % tuple(t))
    run(CHECK, poly, off)
    centre = points[triangles].mean(axis=1)
    in_circle = np.hypot(centre[:, 0] - 1, centre[:, 1] - 0.5) < 0.2
    assert np.array_equal(m.cell_data_dict["region"]["triangle"], np.where(in_circle, 2.0, 1.0))
    a, b = points[lines[:, 0]], points[lines[:, 1]]
    marker = m.cell_data_dict["marker"]["line"]
    # the chords of the circle, split or not, lie between the chord's and the
    # circle's distance from the centre
    def on_circle(p):
        r = np.hypot(p[:, 0] - 1, p[:, 1] - 0.5)
        return (r > 0.2 * np.cos(np.pi / 64) - 1e-9) & (r < 0.2 + 1e-9)
    expected = np.where((a[:, 0] == 0) & (b[:, 0] == 0), 1,
                        np.where((a[:, 0] == 4) & (b[:, 0] == 4), 2,
                                 np.where(on_circle(a) & on_circle(b), 4, 3)))
    assert np.array_equal(marker, expected)
    # the channel, given by its corners, is split to the size: about 0.06 on
    # the walls far from the inclusion
    assert np.count_nonzero(marker == 1) >= 15 and np.count_nonzero(marker == 3) >= 2 * 60


@pytest.mark.parametrize("threads", [1, 2, 3])
def test_threads(airfoil, threads):
    """threads=N as afmesh_2 --threads N: the same mesh, valid; bad counts and threads with
    keep_segments are a ValueError."""
    v, s, h, _, _, _ = read_poly(airfoil)
    m = afmesh_2.mesh(v, s, h, size=0.02, threads=threads)
    check_valid(airfoil, m, "airfoil_threads_%d" % threads)
    base = os.path.join(WORK, "cli_threads_%d" % threads)
    run(AFMESH, airfoil, "--size", "0.02", "--threads", str(threads), "-o", base + ".node")
    points, triangles = read_node_ele(base)
    assert np.array_equal(m.points, points)
    assert np.array_equal(m.triangles, triangles)
    for bad in (-1, 5000):
        with pytest.raises(ValueError):
            afmesh_2.mesh(v, s, h, size=0.02, threads=bad)
    with pytest.raises(ValueError):
        afmesh_2.mesh(v, s, h, size=0.02, threads=2, keep_segments=True)
