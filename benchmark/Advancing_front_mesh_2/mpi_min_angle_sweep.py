#!/usr/bin/env python3
"""afmesh_2_mpi --min-angle 30 on 2 to 6 ranks of this machine, against
afmesh_2 --threads 1 --min-angle 30 (the serial mesh) on the same inputs: the triangles
left below the bound (those beyond the serial mesh's, which are at input
angles below the bound, are the interfaces' doing), the smallest angle, the
triangle count against the serial mesh and the independent checker's verdict.
With a second tool (--before), the same runs of it side by side.

Usage: mpi_min_angle_sweep.py BIN_DIR CHECKER WORK_DIR OUT.md [LAKE.msh] [--before AFMESH_2_MPI NAME]
"""
import json
import os
import subprocess
import sys

args = sys.argv[1:]
before = None
if "--before" in args:
    i = args.index("--before")
    before, before_name = os.path.abspath(args[i + 1]), args[i + 2]
    del args[i:i + 3]
bin_dir, checker, work, out = (os.path.abspath(a) for a in args[:4])
lake = os.path.abspath(args[4]) if len(args) > 4 and args[4] else ""
tool, serial, make_input = (os.path.join(bin_dir, n) for n in ("afmesh_2_mpi", "afmesh_2", "afm_make_input"))
os.makedirs(work, exist_ok=True)
os.chdir(work)
launcher = ["mpiexec", "--oversubscribe"] + (["--allow-run-as-root"] if os.geteuid() == 0 else [])
os.environ["OMPI_MCA_btl_vader_single_copy_mechanism"] = "none"


def run(*command):
    r = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    if r.returncode != 0:
        sys.exit("failed (%d): %s\n%s" % (r.returncode, " ".join(command), r.stderr))
    return r.stdout


run(make_input, "multi-element-airfoil", "airfoil.poly")
run(make_input, "square-with-hole", "square.poly", "0.005")
run(make_input, "square-with-hole", "square_fine_boundary.poly", "0.01")
run(make_input, "tagged-regions", "tagged.poly")
cases = [("four-element airfoil", "airfoil.poly", h) for h in ("0.02", "0.03", "0.04")]
cases += [("square with a hole (boundary 0.005)", "square.poly", h) for h in ("0.005", "0.0035")]
cases += [("square with a hole (boundary 0.01)", "square_fine_boundary.poly", "0.01")]
if lake:
    run(make_input, "from-jigsaw", "lake.poly", lake)
    cases += [("MESH2D lake", "lake.poly", h) for h in ("0.05", "0.1")]
cases += [("three regions, markers", "tagged.poly", h) for h in ("0.01", "0.02")]


def figures(stats):
    return stats["triangles"], stats["min_angle"]["below_after"], stats["quality"]["min_angle_degrees"]


rows = []
totals = {"after": 0, "before": 0}
for label, poly, h in cases:
    reference = json.loads(run(serial, poly, "--size", h, "--min-angle", "30", "--threads", "1", "--no-output",
                               "--stats"))
    nt, below, smallest = figures(reference)
    for ranks in range(2, 7):
        cells = []
        for name, program in (("after", tool), ("before", before)):
            if program is None:
                continue
            mesh = "%s_%s_%d_%s.off" % (poly[:-5], h, ranks, name)
            stats = json.loads(run(*launcher, "-np", str(ranks), program, poly, "--size", h, "--min-angle", "30",
                                   "--merge", "-o", mesh, "--stats"))
            verdict = subprocess.run([checker, poly, mesh], stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                     text=True)
            t, b, s = figures(stats)
            excess = max(0, b - below)
            totals[name] += excess
            cells.append("%d (%.1f) | %+.2f%% | %s" % (excess, s, 100.0 * (t - nt) / nt,
                                                       "valid" if verdict.returncode == 0 else "REJECTED"))
            os.remove(mesh)
        rows.append("| %s | %s | %d | %d (%.1f) | %s |" % (label, h, ranks, below, smallest, " | ".join(cells)))
        print(rows[-1], flush=True)

with open(out, "w") as f:
    f.write("# afmesh_2_mpi --min-angle 30: triangles left below the bound\n\n")
    f.write("Written by scripts/benchmark_mpi_min_angle.sh on %d cores. Each input on 2 to 6 ranks "
            "(`mpirun --oversubscribe`), `--merge`, against `afmesh_2 --threads 1 --min-angle 30` (serial). "
            "*Below*: the triangles below 30 degrees beyond the serial mesh's (those are at input angles "
            "below the bound), with the smallest angle in degrees; *count*: triangles against the serial "
            "mesh; *checker*: the independent checker on the merged mesh.\n\n" % os.cpu_count())
    if before:
        f.write("*Before*: the same runs of afmesh_2_mpi at %s.\n\n" % before_name)
    head = "| input | size | ranks | serial: below (smallest) | below (smallest) | count | checker |"
    rule = "|---|---|--:|--:|--:|--:|---|"
    if before:
        head += " before: below (smallest) | count | checker |"
        rule += "--:|--:|---|"
    f.write(head + "\n" + rule + "\n" + "\n".join(rows) + "\n\n")
    f.write("Total below the bound beyond the serial meshes: %d" % totals["after"])
    if before:
        f.write(" (before: %d)" % totals["before"])
    f.write(".\n")
print("total beyond serial: %d%s" % (totals["after"], " (before: %d)" % totals["before"] if before else ""))
