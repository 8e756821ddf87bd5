"""afmesh_2_mpi on 1, 2, 3 and 4 ranks of this machine (mpirun --oversubscribe):
every mesh is checked by the independent validity checker (afm_check_mesh:
valid and constrained Delaunay, so also across the ranks' interfaces) and
compared with afmesh_2's on as many threads, which cuts the domain the same
way: the same vertex and triangle counts, and a share of radius ratios above
0.9 within half a point (the seams are smoothed in a band instead of in the
whole mesh); the counts within 1% of the serial mesh. The pieces of a .pvtu
are read back with meshio: their global vertex numbers must agree with the
points and, put together, give the --merge mesh. Each part streamed
(--stream) gives pieces that are valid put together, and close to the mesh
made in memory (the same on one rank). Bad usage and invalid input stop
every rank with one message and afmesh_2's exit codes.

Usage: mpi_checks.py MPIEXEC AFMESH_2_MPI AFMESH_2 AFM_MAKE_INPUT AFM_CHECK_MESH WORK_DIR [LAKE.msh]
"""
import json
import os
import subprocess
import sys

import meshio
import numpy as np

from cli_checks import check, finish, run

mpiexec, tool, serial, make_input, checker, work = sys.argv[1:7]
lake = sys.argv[7] if len(sys.argv) > 7 else ""
os.makedirs(work, exist_ok=True)
os.chdir(work)
os.makedirs("streamed", exist_ok=True)

# OpenMPI keeps some of its start-up allocations to the end: LeakSanitizer
# (in the sanitizer build) is told about its libraries only, so that a leak
# of ours still fails the run. ASan's fast unwinder stops at the first frame
# inside OpenMPI (built without frame pointers), which names no library:
# the ranks unwind fully (only they: it slows every allocation)
with open("lsan.supp", "w") as f:
    f.write("".join("leak:%s\n" % lib for lib in ("libmpi", "libopen-pal", "libopen-rte", "libpmix", "libhwloc",
                                                     "libevent", "mca_")))
os.environ["LSAN_OPTIONS"] = "suppressions=" + os.path.abspath("lsan.supp")
asan_options = os.environ.get("ASAN_OPTIONS", "")
rank_asan_options = (asan_options + ":" if asan_options else "") + "fast_unwind_on_malloc=0"
# no cross-memory attach between the ranks (not allowed in every container)
os.environ["OMPI_MCA_btl_vader_single_copy_mechanism"] = "none"
# OpenMPI unloads its components at the end: kept loaded, their frames in
# the leak reports are named (mca_*)
os.environ["OMPI_MCA_mca_base_component_disable_dlclose"] = "1"


def mpi(n, *args, code=0):
    launcher = [mpiexec, "--oversubscribe", "-np", str(n)]
    if os.geteuid() == 0:
        launcher.insert(1, "--allow-run-as-root")
    os.environ["ASAN_OPTIONS"] = rank_asan_options
    try:
        return run(*launcher, tool, *args, code=code)
    finally:
        os.environ["ASAN_OPTIONS"] = asan_options


def read_off(path):
    with open(path) as f:
        assert f.readline().strip() == "OFF"
        nv, nt, _ = map(int, f.readline().split())
        points = np.array([list(map(float, f.readline().split()[:2])) for _ in range(nv)])
        triangles = np.array([list(map(int, f.readline().split()[1:4])) for _ in range(nt)], dtype=np.int64)
    return points, triangles


def share_above_0_9(points, triangles):
    p = points[triangles]
    a = np.linalg.norm(p[:, 1] - p[:, 2], axis=1)
    b = np.linalg.norm(p[:, 2] - p[:, 0], axis=1)
    c = np.linalg.norm(p[:, 0] - p[:, 1], axis=1)
    s = (a + b + c) / 2
    area = np.sqrt(np.maximum(s * (s - a) * (s - b) * (s - c), 0))
    ratio = 2 * (area / s) / (a * b * c / (4 * area))
    return 100 * np.mean(ratio > 0.9)


def triangle_set(points, triangles):
    return {tuple(sorted(tuple(points[v]) for v in t)) for t in triangles}


def valid(poly, mesh, label):
    r = subprocess.run([checker, poly, mesh], capture_output=True, text=True)
    check(r.returncode == 0, "%s: the checker rejects %s: %s" % (label, mesh, r.stdout.strip()))


def read_pieces(pvtu, ranks):
    """The mesh of a .pvtu's pieces put together by their global vertex
    numbers, which must run from 0 without gaps, each with one position;
    every piece must be named by the collection and hold its rank's
    triangles only. Returns (points, triangles) or None."""
    directory = os.path.dirname(pvtu)
    stem = os.path.basename(pvtu)[:-len(".pvtu")]
    collection = open(pvtu).read()
    by_id = {}
    triangles = []
    for rank in range(ranks):
        piece = "%s_%d.vtu" % (stem, rank)
        named = 'Source="%s"' % piece in collection
        check(named, "%s does not name %s" % (pvtu, piece))
        if not named:
            return None
        m = meshio.read(os.path.join(directory, piece))
        ids = m.point_data["GlobalNodeId"]
        check(len(set(ids.tolist())) == len(ids), "%s: a vertex number is given twice" % piece)
        for i, p in zip(ids, m.points[:, :2]):
            seen = by_id.setdefault(int(i), tuple(p))
            check(seen == tuple(p), "%s: vertex %d has two positions in the pieces" % (pvtu, i))
        cells = m.cells_dict.get("triangle", np.zeros((0, 3), dtype=np.int64))
        check(len(np.unique(cells)) == len(m.points), "%s: a point of the piece is in no triangle" % piece)
        part = m.cell_data_dict["partition"]["triangle"] if len(cells) else []
        check(all(int(k) == rank for k in part), "a triangle of %s is not in partition %d" % (piece, rank))
        triangles.extend(ids[cells].tolist())
    gapless = sorted(by_id) == list(range(len(by_id)))
    check(gapless, "%s: the vertex numbers are not 0 to %d" % (pvtu, len(by_id) - 1))
    if not gapless:
        return None
    return np.array([by_id[i] for i in range(len(by_id))]), np.array(triangles)


def write_off(path, points, triangles):
    with open(path, "w") as f:
        f.write("OFF\n%d %d 0\n" % (len(points), len(triangles)))
        f.writelines("%.17g %.17g 0\n" % (x, y) for x, y in points)
        f.writelines("3 %d %d %d\n" % tuple(t) for t in triangles)


run(make_input, "square-with-hole", "square.poly", "0.005")
run(make_input, "multi-element-airfoil", "airfoil.poly")

# the square on 1, 2 and 4 ranks against afmesh_2 on as many threads
run(serial, "square.poly", "--size", "0.005", "--threads", "1", "-o", "serial.off")
serial_points, serial_triangles = read_off("serial.off")
for n in (1, 2, 4):
    label = "square, %d ranks" % n
    stats = json.loads(mpi(n, "square.poly", "--size", "0.005", "--merge", "-o", "mpi.off", "--stats").stdout)
    valid("square.poly", "mpi.off", label)
    check(stats["parts"] == n, "%s: %d parts" % (label, stats["parts"]))
    m_points, m_triangles = read_off("mpi.off")
    check(sum(r["triangles"] for r in stats["per_rank"]) == len(m_triangles) and
          sum(r["owned_vertices"] for r in stats["per_rank"]) == len(m_points),
          "%s: the ranks' triangles and vertices do not add up to the merged mesh's" % label)
    # --stream: each part streamed to scratch files, the triangles near the
    # cuts held back for the merge; the same mesh but for the seams (the
    # frontal mesher of a part streamed may close the front near a cut
    # differently), valid and constrained Delaunay
    streamed = json.loads(mpi(n, "square.poly", "--size", "0.005", "--stream", "-o", "streamed/s.pvtu",
                              "--stats").stdout)
    check(n == 1 or all(r["held_triangles"] > 0 for r in streamed["per_rank"]),
          "%s, streamed: a rank held back no triangle" % label)
    check(not [f for f in os.listdir("streamed") if f.endswith(".tmp")],
          "%s, streamed: scratch files are left: %s" % (label, os.listdir("streamed")))
    pieces = read_pieces("streamed/s.pvtu", n)
    if pieces is not None:
        s_points, s_triangles = pieces
        write_off("streamed.off", s_points, s_triangles)
        valid("square.poly", "streamed.off", label + ", streamed")
        m_points, m_triangles = read_off("mpi.off")
        check(len(s_triangles) == streamed["number_of_faces"] and len(s_points) == streamed["number_of_vertices"],
              "%s, streamed: --stats says %d triangles and %d vertices, the pieces hold %d and %d" %
              (label, streamed["number_of_faces"], streamed["number_of_vertices"], len(s_triangles),
               len(s_points)))
        if n == 1:
            check(triangle_set(s_points, s_triangles) == triangle_set(m_points, m_triangles),
                  "%s, streamed: not the mesh made in memory" % label)
        check(abs(len(s_triangles) - len(m_triangles)) <= 0.001 * len(m_triangles),
              "%s, streamed: %d triangles, in memory %d" % (label, len(s_triangles), len(m_triangles)))
        mine, theirs = share_above_0_9(s_points, s_triangles), share_above_0_9(m_points, m_triangles)
        check(abs(mine - theirs) <= 0.2, "%s, streamed: share above 0.9 %.2f%%, in memory %.2f%%" %
              (label, mine, theirs))
    run(serial, "square.poly", "--size", "0.005", "--threads", str(n), "-o", "threads.off")
    points, triangles = read_off("mpi.off")
    t_points, t_triangles = read_off("threads.off")
    check(len(points) == len(t_points) and len(triangles) == len(t_triangles),
          "%s: %d vertices and %d triangles, on %d threads %d and %d" %
          (label, len(points), len(triangles), n, len(t_points), len(t_triangles)))
    mine, theirs = share_above_0_9(points, triangles), share_above_0_9(t_points, t_triangles)
    check(abs(mine - theirs) <= 0.5, "%s: share above 0.9 %.2f%%, on threads %.2f%%" % (label, mine, theirs))
    check(abs(len(triangles) - len(serial_triangles)) <= 0.01 * len(serial_triangles),
          "%s: %d triangles, serially %d" % (label, len(triangles), len(serial_triangles)))

# the pieces of a .pvtu on 3 ranks, read back, against the merged file
os.makedirs("pieces", exist_ok=True)
mpi(3, "airfoil.poly", "--size", "0.02", "-o", "pieces/airfoil.pvtu")
mpi(3, "airfoil.poly", "--size", "0.02", "--merge", "-o", "merged.off")
valid("airfoil.poly", "merged.off", "airfoil, 3 ranks")


merged_points, merged_triangles = read_off("merged.off")
pieces = read_pieces("pieces/airfoil.pvtu", 3)
if pieces is not None:
    points, triangles = pieces
    check(len(points) == len(merged_points), "the pieces have %d vertices, the merged mesh %d" %
          (len(points), len(merged_points)))
    check(triangle_set(points, triangles) == triangle_set(merged_points, merged_triangles),
          "the pieces put together are not the merged mesh")
    write_off("from_pieces.off", points, triangles)
    valid("airfoil.poly", "from_pieces.off", "airfoil pieces")

# the same pieces in ASCII (--vtu-ascii): the same mesh
mpi(3, "airfoil.poly", "--size", "0.02", "--vtu-ascii", "-o", "pieces/ascii.pvtu")
ascii_pieces = read_pieces("pieces/ascii.pvtu", 3)
if pieces is not None and ascii_pieces is not None:
    check(triangle_set(*ascii_pieces) == triangle_set(*pieces), "the ASCII pieces are not the binary pieces' mesh")

# the input's free points near a cut are vertices of the mesh where the
# input puts them: the seam smoothing leaves them
free = [(x, y) for x in (0.47, 0.49, 0.51, 0.53) for y in (0.2, 0.4, 0.6, 0.8)]
with open("free.poly", "w") as f:
    corners = [(0, 0), (1, 0), (1, 1), (0, 1)]
    f.write("%d 2 0 0\n" % (4 + len(free)))
    f.writelines("%d %r %r\n" % (i + 1, x, y) for i, (x, y) in enumerate(corners + free))
    f.write("4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n0\n")
mpi(2, "free.poly", "--size", "0.02", "--merge", "-o", "free.off")
valid("free.poly", "free.off", "free points, 2 ranks")
f_points, _ = read_off("free.off")
at = {tuple(p) for p in f_points}
moved = [p for p in free if p not in at]
check(not moved, "free points near the cut moved: %s" % moved)

# a streamed rank keeps its part once meshed: --stop-after-meshing stops
# there; --resume meshes only the parts not kept (rank 1's, deleted here)
# and gives the uninterrupted run's pieces, byte for byte
os.makedirs("kept", exist_ok=True)
mpi(2, "square.poly", "--size", "0.005", "--stream", "-o", "kept/full.pvtu")
mpi(2, "square.poly", "--size", "0.005", "--stream", "--stop-after-meshing", "-o", "kept/s.pvtu")
kept = sorted(os.listdir("kept"))
check("s_0.vtu.part" in kept and "s_1.vtu.part" in kept and "s_0.vtu" not in kept and "s.pvtu" not in kept,
      "--stop-after-meshing: %s" % kept)
os.remove("kept/s_1.vtu.part")
stats = json.loads(mpi(2, "square.poly", "--size", "0.005", "--stream", "--resume", "-o", "kept/s.pvtu",
                       "--stats").stdout)
check([r["resumed_part"] for r in stats["per_rank"]] == [True, False],
      "--resume: parts taken %s" % [r["resumed_part"] for r in stats["per_rank"]])
for rank in range(2):
    same = open("kept/s_%d.vtu" % rank, "rb").read() == open("kept/full_%d.vtu" % rank, "rb").read()
    check(same, "--resume: piece %d is not the uninterrupted run's" % rank)
left = [f for f in os.listdir("kept") if f.endswith(".part") or f.endswith(".tmp")]
check(not left, "files left after a complete run: %s" % left)
r = mpi(2, "square.poly", "--size", "0.005", "--resume", "-o", "kept/m.pvtu", code=2)
check("add --stream" in r.stderr, "--resume without --stream: " + r.stderr)

# fewer parts than ranks: a domain too small for 3 parts of 2,000 triangles
run(make_input, "square-with-hole", "small.poly", "0.05")
stats = json.loads(mpi(3, "small.poly", "--size", "0.05", "--merge", "-o", "small.off", "--stats").stdout)
valid("small.poly", "small.off", "small square, 3 ranks")
check(stats["parts"] == 1 and stats["per_rank"][1]["triangles"] == 0,
      "small square: %d parts, rank 1 has %d triangles" % (stats["parts"], stats["per_rank"][1]["triangles"]))
mpi(3, "small.poly", "--size", "0.05", "-o", "small.pvtu")
check(not os.path.exists("small_1.vtu") and "small_1.vtu" not in open("small.pvtu").read(),
      "small square: rank 1, which has no triangles, has a piece")
check(len(meshio.read("small_0.vtu").cells_dict["triangle"]) == stats["number_of_faces"],
      "small square: rank 0's piece does not hold every triangle")

# a real geometry no one here wrote
if lake and os.path.exists(lake):
    run(make_input, "from-jigsaw", "lake.poly", lake)
    mpi(2, "lake.poly", "--size", "0.05", "--merge", "-o", "lake.vtu")
    m = meshio.read("lake.vtu")
    with open("lake.off", "w") as f:
        f.write("OFF\n%d %d 0\n" % (len(m.points), len(m.cells_dict["triangle"])))
        f.writelines("%.17g %.17g 0\n" % (x, y) for x, y in m.points[:, :2])
        f.writelines("3 %d %d %d\n" % tuple(t) for t in m.cells_dict["triangle"])
    valid("lake.poly", "lake.off", "lake, 2 ranks")

# more ranks than the domain has room for strips wider than their bands:
# fewer parts, the ranks beyond them mesh nothing
run(make_input, "square-with-hole", "narrow.poly", "0.01")
stats = json.loads(mpi(6, "narrow.poly", "--size", "0.01", "--merge", "-o", "narrow.off", "--stats").stdout)
valid("narrow.poly", "narrow.off", "narrow strips, 6 ranks")
check(1 < stats["parts"] < 6 and "narrower than its interface bands" in stats.get("fewer_parts_reason", ""),
      "narrow strips: %d parts, %s" % (stats["parts"], stats.get("fewer_parts_reason")))

# --help and --version: printed once, exit 0
r = mpi(2, "--help")
check(r.stdout.count("Usage: mpirun") == 1, "--help: " + r.stdout)
r = mpi(2, "--version")
check(len(r.stdout.strip().splitlines()) == 1, "--version: " + r.stdout)

# bad usage and invalid input: afmesh_2's codes, one message (rank 0's)
r = mpi(2, "square.poly", "--size", "0.01", "--smooth", "3", "-o", "x.pvtu", code=2)
check("does not support --smooth" in r.stderr, "--smooth: " + r.stderr)
r = mpi(2, "square.poly", "--size", "0.01", "--stream", "--merge", "-o", "x.off", code=2)
check("--stream writes pieces" in r.stderr, "--stream with --merge: " + r.stderr)
r = mpi(2, "square.poly", "--size", "0.01", "--stream", "--no-output", code=2)
check("--stream writes pieces" in r.stderr, "--stream with --no-output: " + r.stderr)
r = mpi(2, "square.poly", "--size", "0.01", "-o", "x.off", code=2)
check("collection of pieces" in r.stderr, "-o x.off without --merge: " + r.stderr)
r = mpi(2, "missing.poly", "--size", "0.01", "-o", "x.pvtu", code=1)
check(r.stderr.count("missing.poly") == 1, "a missing input is named once: " + r.stderr)
with open("broken.poly", "w") as f:
    f.write("4 2 0 0\n1 0 0\n2 1 0\n3 1 x\n")
r = mpi(2, "broken.poly", "--size", "0.01", "-o", "x.pvtu", code=1)
check("broken.poly:4" in r.stderr and r.stderr.count("error") == 1, "a malformed input: " + r.stderr)

r = mpi(2, "square.poly", "--size", "0.01", "-o", "no_such_directory/x.pvtu", code=3)
check("cannot write no_such_directory/x_0.vtu" in r.stderr, "an output that cannot be written: " + r.stderr)

finish("afmesh_2_mpi")
