#!/usr/bin/env python3
"""A channel with a circular inclusion, meshed from NumPy arrays for a solver.

The channel [0, 4] x [0, 1] has its inlet (marker 1), outlet (2) and walls (3);
the inclusion, a circle of radius 0.2 at (1, 0.5), is its own region (its
boundary, marker 4, is an interior segment) with an area limit, and a size
function refines the mesh toward the inclusion. The mesh goes to a VTU file
through meshio, with the markers and regions a solver reads back.

usage: channel_with_inclusion.py [OUTPUT.vtu]
(PYTHONPATH must hold build/release/examples/Advancing_front_mesh_2/python)
"""
import sys

import numpy as np

import afmesh_2

out = sys.argv[1] if len(sys.argv) > 1 else "channel.vtu"

# The mesher splits input segments longer than the local size to the size
# (the boundary discretisation), so the channel is given by its four corners;
# the circle, a curve, by 64 chords. Segment i goes from corner i to corner
# i + 1: the lower wall, the outlet, the upper wall, the inlet.
outer = np.array([[0.0, 0.0], [4.0, 0.0], [4.0, 1.0], [0.0, 1.0]])
outer_markers = np.array([3, 2, 3, 1])
angles = np.linspace(0, 2 * np.pi, 64, endpoint=False)
circle = np.column_stack([1 + 0.2 * np.cos(angles), 0.5 + 0.2 * np.sin(angles)])
vertices = np.vstack([outer, circle])

n = len(outer)
segments = np.array([[i, (i + 1) % n] for i in range(n)] + [[n + i, n + (i + 1) % 64] for i in range(64)])
segment_markers = np.concatenate([outer_markers, [4] * 64])

# region rows as in a .poly file: x, y, attribute, area limit (<= 0: none)
regions = np.array([[3.0, 0.5, 1, 0], [1.0, 0.5, 2, 2e-4]])


def size(points):
    """Called with an (n, 2) array a few times, not once per point."""
    distance = np.hypot(points[:, 0] - 1, points[:, 1] - 0.5)
    return np.clip(0.01 + 0.05 * (distance - 0.2), 0.01, 0.06)


m = afmesh_2.mesh(vertices, segments, regions=regions, segment_markers=segment_markers, size=size, smooth=5)
print(m)
for attribute in (1, 2):
    print("region %d: %d triangles" % (attribute, np.count_nonzero(m.regions == attribute)))
for marker, name in ((1, "inlet"), (2, "outlet"), (3, "walls"), (4, "inclusion")):
    print("%-9s (marker %d): %d boundary edges" % (name, marker, np.count_nonzero(m.segment_markers == marker)))

m.to_meshio().write(out)
print("wrote", out)
