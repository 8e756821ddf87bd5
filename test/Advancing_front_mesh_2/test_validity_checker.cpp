// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

// Self-tests of afm_validity_checker.h on hand-made meshes: a checker that
// accepts everything would make every mesher test meaningless, so each defect
// it is meant to catch is planted once and must be reported with its kind.

#include "afm_test_harness.h"
#include "afm_split_segments.h"
#include "afm_validity_checker.h"

#include <cmath>
#include <limits>

#include <string>

namespace {

using afm_check::Mesh;
using afm_check::Pslg;
using afm_check::Report;
namespace kind = afm_check::error_kind;

std::string explain(const Report& r)
{
  std::string s = r.summary();
  for(const std::string& e : r.errors) s += "\n  " + e;
  return s;
}

bool has_message(const Report& r, const std::string& part)
{
  for(const std::string& e : r.errors)
    if(e.find(part) != std::string::npos) return true;
  return false;
}

Pslg unit_square()
{
  Pslg in;
  in.points = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  in.segments = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
  return in;
}

Mesh unit_square_mesh()
{
  Mesh m;
  m.vertices = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  return m;
}

// Outer square [0,3]^2 (points 0-3), inner square [1,2]^2 (points 4-7) with a
// hole seed in its middle.
Pslg square_with_hole()
{
  Pslg in;
  in.points = {{0, 0}, {3, 0}, {3, 3}, {0, 3}, {1, 1}, {2, 1}, {2, 2}, {1, 2}};
  in.segments = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6}, {6, 7}, {7, 4}};
  in.holes = {{1.5, 1.5}};
  return in;
}

// Each of the four trapezoids O_k O_k+1 I_k+1 I_k split into two triangles;
// the diagonals across the corners were checked by hand to be Delaunay.
Mesh square_with_hole_mesh()
{
  Mesh m;
  m.vertices = {{0, 0}, {3, 0}, {3, 3}, {0, 3}, {1, 1}, {2, 1}, {2, 2}, {1, 2}};
  for(std::size_t k = 0; k < 4; ++k) {
    const std::size_t o0 = k, o1 = (k + 1) % 4, i0 = 4 + k, i1 = 4 + (k + 1) % 4;
    m.triangles.push_back({o0, o1, i1});
    m.triangles.push_back({o0, i1, i0});
  }
  return m;
}

} // namespace

AFM_TEST_CASE(test_checker_unit_square_accepted)
{
  const Report r = afm_check::check_mesh(unit_square(), unit_square_mesh());
  AFM_CHECK_MSG(r.ok, explain(r));
  AFM_CHECK(r.n_vertices == 4 && r.n_triangles == 2);
  AFM_CHECK(r.n_components == 1);
  AFM_CHECK(r.mesh_area == 1.0 && r.domain_area == 1.0);
  AFM_CHECK_MSG(r.min_angle_deg > 44.999 && r.max_angle_deg < 90.001, explain(r));
  AFM_CHECK(r.summary().rfind("ok", 0) == 0);
}

// Coordinates near 1e+300 and 1e-300 are checked scaled by a power of two:
// the verdicts stay, the areas come back in the input's units.
AFM_TEST_CASE(test_checker_extreme_magnitudes)
{
  for(int e : {996, -996}) {
    Pslg in = unit_square();
    Mesh m = unit_square_mesh();
    for(auto& p : in.points) p = {{std::ldexp(p[0], e), std::ldexp(p[1], e)}};
    for(auto& p : m.vertices) p = {{std::ldexp(p[0], e), std::ldexp(p[1], e)}};
    const Report r = afm_check::check_mesh(in, m);
    AFM_CHECK_MSG(r.ok, "2^" << e << ": " << explain(r));
    AFM_CHECK_MSG(r.domain_area == std::ldexp(1.0, 2 * e), r.domain_area);
    m.triangles.pop_back(); // half the square uncovered
    const Report bad = afm_check::check_mesh(in, m);
    AFM_CHECK_MSG(!bad.ok, "2^" << e << ": a half-covered square was accepted");
  }
}

AFM_TEST_CASE(test_checker_equilateral_quality)
{
  Pslg in;
  const double h = 0.8660254037844386;
  in.points = {{0, 0}, {1, 0}, {0.5, h}};
  in.segments = {{0, 1}, {1, 2}, {2, 0}};
  Mesh m;
  m.vertices = in.points;
  m.triangles = {{0, 1, 2}};
  const Report r = afm_check::check_mesh(in, m);
  AFM_CHECK_MSG(r.ok, explain(r));
  AFM_CHECK_MSG(r.min_radius_ratio > 0.999999 && r.min_radius_ratio < 1.000001, explain(r));
  AFM_CHECK_MSG(r.min_angle_deg > 59.9999 && r.max_angle_deg < 60.0001, explain(r));
}

AFM_TEST_CASE(test_checker_square_with_hole_accepted)
{
  const Report r = afm_check::check_mesh(square_with_hole(), square_with_hole_mesh());
  AFM_CHECK_MSG(r.ok, explain(r));
  AFM_CHECK(r.n_triangles == 8);
  AFM_CHECK(r.mesh_area == 8.0 && r.domain_area == 8.0);
}

AFM_TEST_CASE(test_checker_vertex_order_independent)
{
  // The same annulus with vertices listed in another order than the input.
  Mesh m = square_with_hole_mesh();
  const std::size_t n = m.vertices.size();
  Mesh shuffled;
  shuffled.vertices.resize(n);
  for(std::size_t v = 0; v < n; ++v) shuffled.vertices[(v * 3) % n] = m.vertices[v];
  for(const auto& t : m.triangles)
    shuffled.triangles.push_back({(t[1] * 3) % n, (t[2] * 3) % n, (t[0] * 3) % n});
  const Report r = afm_check::check_mesh(square_with_hole(), shuffled);
  AFM_CHECK_MSG(r.ok, explain(r));
}

AFM_TEST_CASE(test_checker_flipped_triangle_rejected)
{
  Mesh m = unit_square_mesh();
  m.triangles[0] = {0, 2, 1};
  const Report r = afm_check::check_mesh(unit_square(), m);
  AFM_CHECK(!r.ok);
  AFM_CHECK_MSG(r.count(kind::orientation) == 1, explain(r));
  AFM_CHECK(r.summary().rfind("FAILED", 0) == 0);
}

AFM_TEST_CASE(test_checker_flat_triangle_rejected)
{
  Mesh m = unit_square_mesh();
  m.vertices.push_back({0.5, 0.5});
  m.triangles.push_back({0, 4, 2}); // on the diagonal: zero area
  const Report r = afm_check::check_mesh(unit_square(), m);
  AFM_CHECK(!r.ok);
  AFM_CHECK_MSG(r.count(kind::orientation) == 1, explain(r));
}

AFM_TEST_CASE(test_checker_missing_triangle_rejected)
{
  Mesh m = unit_square_mesh();
  m.triangles.pop_back();
  const Report r = afm_check::check_mesh(unit_square(), m);
  AFM_CHECK(!r.ok);
  AFM_CHECK_MSG(r.count(kind::area) == 1, explain(r));
  AFM_CHECK_MSG(r.count(kind::boundary_edge) == 1, explain(r));
  AFM_CHECK(r.mesh_area == 0.5 && r.domain_area == 1.0);
}

AFM_TEST_CASE(test_checker_duplicate_triangle_rejected)
{
  Mesh m = unit_square_mesh();
  m.triangles.push_back(m.triangles[0]);
  const Report r = afm_check::check_mesh(unit_square(), m);
  AFM_CHECK(!r.ok);
  AFM_CHECK_MSG(r.count(kind::non_manifold) >= 1, explain(r));
  AFM_CHECK_MSG(r.count(kind::area) == 1, explain(r));
}

AFM_TEST_CASE(test_checker_bad_indices_rejected)
{
  Mesh m = unit_square_mesh();
  m.triangles.push_back({0, 1, 7});
  m.triangles.push_back({1, 1, 2});
  m.vertices.push_back({0, 0}); // same point as vertex 0
  const Report r = afm_check::check_mesh(unit_square(), m);
  AFM_CHECK(!r.ok);
  AFM_CHECK_MSG(r.count(kind::index) == 1, explain(r));
  AFM_CHECK_MSG(r.count(kind::degenerate_triangle) == 1, explain(r));
  AFM_CHECK_MSG(r.count(kind::duplicate_vertex) == 1, explain(r));
}

AFM_TEST_CASE(test_checker_split_segment_rejected)
{
  Mesh m;
  m.vertices = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0.5, 0}};
  m.triangles = {{0, 4, 3}, {4, 1, 2}, {4, 2, 3}};
  const Report r = afm_check::check_mesh(unit_square(), m);
  AFM_CHECK(!r.ok);
  AFM_CHECK_MSG(r.count(kind::missing_segment) == 1, explain(r));
  AFM_CHECK_MSG(has_message(r, "split by mesh vertex 4"), explain(r));
  // The covered area is right: only the segment rule catches this.
  AFM_CHECK_MSG(r.count(kind::area) == 0, explain(r));
}

AFM_TEST_CASE(test_checker_non_delaunay_edge_rejected)
{
  // Convex quad A B C D that is not cocircular: D is inside the circle
  // through A, B, C, so diagonal AC is wrong and BD is right.
  Pslg in;
  in.points = {{0, 0}, {2, 0}, {2, 2}, {0, 1}};
  in.segments = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
  Mesh good;
  good.vertices = in.points;
  good.triangles = {{0, 1, 3}, {1, 2, 3}};
  const Report ok = afm_check::check_mesh(in, good);
  AFM_CHECK_MSG(ok.ok, explain(ok));

  Mesh bad = good;
  bad.triangles = {{0, 1, 2}, {0, 2, 3}};
  const Report r = afm_check::check_mesh(in, bad);
  AFM_CHECK(!r.ok);
  AFM_CHECK_MSG(r.n_non_delaunay_edges == 1 && r.count(kind::non_delaunay) == 1, explain(r));
  AFM_CHECK_MSG(r.n_errors() == 1, explain(r));
}

AFM_TEST_CASE(test_checker_constrained_edge_may_be_non_delaunay)
{
  // The same wrong diagonal is fine once it is an input segment.
  Pslg in;
  in.points = {{0, 0}, {2, 0}, {2, 2}, {0, 1}};
  in.segments = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 2}};
  Mesh m;
  m.vertices = in.points;
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  const Report r = afm_check::check_mesh(in, m);
  AFM_CHECK_MSG(r.ok, explain(r));
  AFM_CHECK(r.n_components == 2);
}

AFM_TEST_CASE(test_checker_triangles_in_hole_rejected)
{
  Mesh m = square_with_hole_mesh();
  m.triangles.push_back({4, 5, 6});
  m.triangles.push_back({4, 6, 7});
  const Report r = afm_check::check_mesh(square_with_hole(), m);
  AFM_CHECK(!r.ok);
  AFM_CHECK_MSG(r.count(kind::outside_domain) == 1, explain(r));
  AFM_CHECK_MSG(has_message(r, "lies in a hole"), explain(r));
  AFM_CHECK_MSG(r.count(kind::area) == 1, explain(r));
  AFM_CHECK_MSG(r.count(kind::boundary_edge) == 0, explain(r));
}

AFM_TEST_CASE(test_checker_missing_hole_seed_changes_domain)
{
  // Without the seed the inner square is domain, so the annulus alone is
  // incomplete.
  Pslg in = square_with_hole();
  in.holes.clear();
  const Report r = afm_check::check_mesh(in, square_with_hole_mesh());
  AFM_CHECK(!r.ok);
  AFM_CHECK_MSG(r.count(kind::coverage) == 4, explain(r));
  AFM_CHECK_MSG(r.count(kind::area) == 1, explain(r));
}

AFM_TEST_CASE(test_checker_triangle_outside_rejected)
{
  Mesh m = unit_square_mesh();
  m.vertices.push_back({2, 0});
  m.triangles.push_back({1, 4, 2});
  const Report r = afm_check::check_mesh(unit_square(), m);
  AFM_CHECK(!r.ok);
  AFM_CHECK_MSG(r.count(kind::outside_domain) == 1, explain(r));
  AFM_CHECK_MSG(has_message(r, "outside the outer boundary"), explain(r));
  AFM_CHECK_MSG(r.count(kind::area) == 1, explain(r));
}

AFM_TEST_CASE(test_checker_free_point)
{
  Pslg in = unit_square();
  in.points.push_back({0.5, 0.5}); // free point inside: must be meshed
  in.points.push_back({5, 5});     // free point outside: must not be
  Mesh with_point;
  with_point.vertices = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0.5, 0.5}};
  with_point.triangles = {{0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}};
  const Report good = afm_check::check_mesh(in, with_point);
  AFM_CHECK_MSG(good.ok, explain(good));

  const Report r = afm_check::check_mesh(in, unit_square_mesh());
  AFM_CHECK(!r.ok);
  AFM_CHECK_MSG(r.count(kind::missing_input_point) == 1, explain(r));
  AFM_CHECK_MSG(r.n_errors() == 1, explain(r));

  Mesh with_outside_vertex = with_point;
  with_outside_vertex.vertices.push_back({5, 5});
  const Report r2 = afm_check::check_mesh(in, with_outside_vertex);
  AFM_CHECK_MSG(r2.count(kind::outside_domain) == 1, explain(r2));
  AFM_CHECK_MSG(r2.count(kind::unused_vertex) == 1, explain(r2));
}

AFM_TEST_CASE(test_checker_dangling_segment)
{
  Pslg in = unit_square();
  in.points.push_back({0.25, 0.5});
  in.points.push_back({0.75, 0.5});
  in.segments.push_back({4, 5});
  Mesh m;
  m.vertices = in.points;
  m.triangles = {{0, 1, 5}, {0, 5, 4}, {3, 4, 5}, {3, 5, 2}, {0, 4, 3}, {1, 2, 5}};
  const Report good = afm_check::check_mesh(in, m);
  AFM_CHECK_MSG(good.ok, explain(good));
  AFM_CHECK(good.domain_area == 1.0);
  AFM_CHECK(good.n_components == 1); // the dangling segment separates nothing

  const Report missing = afm_check::check_mesh(in, unit_square_mesh());
  AFM_CHECK(!missing.ok);
  AFM_CHECK_MSG(missing.count(kind::missing_segment) == 1, explain(missing));
  AFM_CHECK_MSG(missing.count(kind::missing_input_point) == 2, explain(missing));
}

AFM_TEST_CASE(test_checker_one_sided_dangling_segment_rejected)
{
  // A slit: the triangle above the dangling segment is missing, the one
  // below is there, so the mesh is one-sided along the segment.
  Pslg in;
  in.points = {{0, 0}, {2, 0}, {1, 1}, {1, 0.5}};
  in.segments = {{0, 1}, {1, 2}, {2, 0}, {0, 3}};
  Mesh m;
  m.vertices = in.points;
  m.triangles = {{0, 1, 3}, {1, 2, 3}};
  const Report r = afm_check::check_mesh(in, m);
  AFM_CHECK(!r.ok);
  AFM_CHECK_MSG(r.count(kind::coverage) == 1, explain(r));
  AFM_CHECK_MSG(has_message(r, "the domain is on both sides but mesh triangles are on its"),
                explain(r));
  AFM_CHECK_MSG(r.count(kind::area) == 1, explain(r));
}

AFM_TEST_CASE(test_checker_crossing_input_reported)
{
  Pslg in = unit_square();
  in.segments.push_back({0, 2});
  in.segments.push_back({1, 3});
  const Report r = afm_check::check_mesh(in, unit_square_mesh());
  AFM_CHECK(!r.ok);
  AFM_CHECK_MSG(r.count(kind::input) >= 1, explain(r));
}

AFM_TEST_CASE(test_checker_empty_input_and_mesh_accepted)
{
  const Report r = afm_check::check_mesh(Pslg(), Mesh());
  AFM_CHECK_MSG(r.ok, explain(r));
}

// afm_split_segments.h: the input of meshers that split segments, cut at
// the mesh vertices found on each segment.
namespace {
// the unit square with its bottom side split at (x, y)
Mesh square_split_at(double x, double y)
{
  Mesh m;
  m.vertices = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {x, y}};
  m.triangles = {{0, 4, 3}, {4, 1, 2}, {4, 2, 3}};
  return m;
}
} // namespace

AFM_TEST_CASE(test_checker_split_segment_accepted_as_a_chain)
{
  const Mesh m = square_split_at(0.5, 0);
  const Report r = afm_check::check_mesh(afm_check::split_at_mesh_vertices(unit_square(), m), m);
  AFM_CHECK_MSG(r.ok, explain(r));
}

// A cut rounded a few units in the last place off its segment is on it; one
// a thousand units off is not, and the mesh boundary then has edges that
// are no input segment.
AFM_TEST_CASE(test_checker_rounded_cut_within_tolerance)
{
  const double ulp = std::numeric_limits<double>::epsilon();
  for(double off : {-3 * ulp, 3 * ulp, -1000 * ulp}) {
    const Mesh m = square_split_at(0.5, off);
    const Report r = afm_check::check_mesh(afm_check::split_at_mesh_vertices(unit_square(), m), m);
    if(off > -100 * ulp)
      AFM_CHECK_MSG(r.ok, off << ": " << explain(r));
    else
      AFM_CHECK_MSG(!r.ok && r.count(kind::boundary_edge) > 0, off << ": " << explain(r));
  }
}

// A segment given twice, the second time the other way round: both copies
// get the chain (a fuzzer's find: the copy left whole overlapped the
// chain).
AFM_TEST_CASE(test_checker_duplicate_segment_split_once)
{
  Pslg in = unit_square();
  in.segments.push_back({1, 0});
  const Mesh m = square_split_at(0.5, 0);
  const Report r = afm_check::check_mesh(afm_check::split_at_mesh_vertices(in, m), m);
  AFM_CHECK_MSG(r.ok, explain(r));
}

// An input point exactly on a segment cuts it whether or not it is a mesh
// vertex: on the domain's boundary it must be one.
AFM_TEST_CASE(test_checker_input_point_on_a_segment)
{
  Pslg in = unit_square();
  in.points.push_back({0.5, 0});
  const Mesh split = square_split_at(0.5, 0);
  Report r = afm_check::check_mesh(afm_check::split_at_mesh_vertices(in, split), split);
  AFM_CHECK_MSG(r.ok, explain(r));
  const Mesh whole = unit_square_mesh();
  r = afm_check::check_mesh(afm_check::split_at_mesh_vertices(in, whole), whole);
  AFM_CHECK_MSG(!r.ok && r.count(kind::missing_input_point) == 1, explain(r));
}

// A vertex within rounding of two segments belongs to the nearer one.
AFM_TEST_CASE(test_checker_cut_belongs_to_the_nearer_segment)
{
  // the square's base split at (0.25, 0), and an inner segment from (0, 0)
  // to (1, 1e-15) that the cut is also within 16 units in the last place of
  Pslg in = unit_square();
  in.points.push_back({1, 1e-15});
  in.segments.push_back({0, 4});
  Mesh m;
  m.vertices = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {1, 1e-15}, {0.25, 0}};
  // the base's chain 0-5-1, the inner segment 0-4 (whole), the sliver
  // between them, and the rest of the square
  m.triangles = {{0, 5, 4}, {5, 1, 4}, {0, 4, 3}, {4, 2, 3}};
  const Report r = afm_check::check_mesh(afm_check::split_at_mesh_vertices(in, m), m);
  AFM_CHECK_MSG(r.ok, explain(r));
}
