// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

// Independent validity checker for 2D constrained Delaunay meshes.
//
// It deliberately shares no code with the mesher under test: it only uses the
// standard library and stock CGAL (kernels, Exact_rational, Arrangement_2), so
// a bug in the mesher's own geometry cannot hide itself by also being in the
// checker.
//
// Every decision is exact on the double coordinates: predicates come from the
// filtered kernels (exact), areas are summed in Exact_rational, and the domain
// is the exact planar arrangement of the input segments. Doubles are only used
// for the quality figures, which are reported but never decide anything.
//
// Why the checks are sufficient (and not just plausible): let w(p) be the
// number of triangles covering a point p. w can only change across an edge
// whose triangles do not cancel, i.e. across mesh boundary edges. Once checks
// 2, 3 and 6 pass, those are all input segments, so w is constant on each
// face of the arrangement. The "coverage" check then compares, for every input
// segment, the jump of w across it with the jump of the domain indicator D.
// Since w = D = 0 on the unbounded face and the faces are connected through
// the segments, w = D everywhere: the triangles tile the domain exactly once.
// The per-component location (check 8) and the exact area (check 9) are
// implied by that, but are kept because their messages are easier to act on.

#ifndef AFM_VALIDITY_CHECKER_H
#define AFM_VALIDITY_CHECKER_H

#include <CGAL/Arr_batched_point_location.h>
#include <CGAL/Arr_extended_dcel.h>
#include <CGAL/Arr_point_location_result.h>
#include <CGAL/Arr_segment_traits_2.h>
#include <CGAL/Arrangement_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Exact_rational.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace afm_check {

struct Pslg
{
  std::vector<std::array<double, 2>> points;
  std::vector<std::array<std::size_t, 2>> segments; // 0-based into points
  std::vector<std::array<double, 2>> holes;         // hole seeds
};

struct Mesh
{
  std::vector<std::array<double, 2>> vertices;
  std::vector<std::array<std::size_t, 3>> triangles; // 0-based, CCW
};

// Error kinds: every message starts with "<kind>: " and Report::count(kind)
// counts all of them, including those beyond the stored messages, so tests
// can assert on the kind of a failure rather than on its wording.
namespace error_kind {
// The PSLG itself is unusable (crossing segments, bad indices, NaN, a hole
// seed on a segment...); the domain checks are then skipped.
inline constexpr const char* input = "input";
// Check 1: NaN/inf coordinates, out-of-range indices, coincident vertices,
// triangles repeating a vertex, vertices no triangle uses.
inline constexpr const char* bad_coordinate = "bad-coordinate";
inline constexpr const char* index = "index";
inline constexpr const char* duplicate_vertex = "duplicate-vertex";
inline constexpr const char* degenerate_triangle = "degenerate-triangle";
inline constexpr const char* unused_vertex = "unused-vertex";
inline constexpr const char* orientation = "orientation";                 // check 2
inline constexpr const char* non_manifold = "non-manifold";               // check 3
inline constexpr const char* missing_input_point = "missing-input-point"; // check 4
inline constexpr const char* missing_segment = "missing-segment";         // check 5
inline constexpr const char* boundary_edge = "boundary-edge";             // check 6
inline constexpr const char* non_delaunay = "non-delaunay";               // check 7
inline constexpr const char* outside_domain = "outside-domain";           // check 8
inline constexpr const char* area = "area";                               // check 9
// Mesh triangles on the wrong side(s) of an input segment; see the argument
// at the top of this file.
inline constexpr const char* coverage = "coverage";
} // namespace error_kind

struct Report
{
  bool ok = true;
  std::vector<std::string> errors;                 // the first max_stored_errors messages
  std::map<std::string, std::size_t> error_counts; // all errors, by kind
  std::size_t n_vertices = 0, n_triangles = 0;
  std::size_t n_components = 0; // triangles connected across non-segments
  std::size_t n_non_delaunay_edges = 0;
  double min_radius_ratio = 0, mean_radius_ratio = 0; // 2r/R, 1 = equilateral
  double min_angle_deg = 0, max_angle_deg = 0;
  double mesh_area = 0, domain_area = 0; // rounded from the exact values

  static constexpr std::size_t max_stored_errors = 20;

  std::size_t count(const std::string& kind) const
  {
    auto it = error_counts.find(kind);
    return it == error_counts.end() ? 0 : it->second;
  }

  std::size_t n_errors() const
  {
    std::size_t n = 0;
    for(const auto& kc : error_counts) n += kc.second;
    return n;
  }

  void add_error(const std::string& kind, const std::string& message)
  {
    ok = false;
    ++error_counts[kind];
    if(errors.size() < max_stored_errors) errors.push_back(kind + ": " + message);
  }

  // Lets callers skip building an expensive diagnostic nobody will read.
  bool stores_next_error() const { return errors.size() < max_stored_errors; }

  std::string summary() const
  {
    std::ostringstream os;
    os.precision(4);
    if(ok) {
      os << "ok: ";
    } else {
      os << "FAILED (" << n_errors() << " errors:";
      for(const auto& kc : error_counts) os << " " << kc.first << " x" << kc.second;
      os << "): ";
    }
    os << n_vertices << " vertices, " << n_triangles << " triangles, "
       << "radius ratio min " << min_radius_ratio << " mean " << mean_radius_ratio << ", angles "
       << min_angle_deg << ".." << max_angle_deg << " deg";
    if(!errors.empty()) os << "; first: " << errors.front();
    return os.str();
  }
};

namespace detail {

using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
using Epeck = CGAL::Exact_predicates_exact_constructions_kernel;
using Arr_traits = CGAL::Arr_segment_traits_2<Epeck>;
// Vertex data: canonical input point id. Face data: one of Face_kind.
using Arr_dcel = CGAL::Arr_extended_dcel<Arr_traits, std::size_t, char, char>;
using Arrangement = CGAL::Arrangement_2<Arr_traits, Arr_dcel>;
using Location = CGAL::Arr_point_location_result<Arrangement>::Type;

enum Face_kind : char { unbounded_face = 0, domain_face = 1, hole_face = 2 };

constexpr std::size_t none = std::numeric_limits<std::size_t>::max();
using Point2 = std::array<double, 2>;

inline std::string fmt(double x)
{
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", x); // round-trips the exact double
  return buf;
}

inline std::string fmt(const Point2& p)
{
  return "(" + fmt(p[0]) + ", " + fmt(p[1]) + ")";
}

inline std::uint64_t mix64(std::uint64_t z)
{
  z += 0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

// Exact coordinate identity: bit patterns, with -0.0 folded onto +0.0 since
// they are the same point.
struct Coord_key
{
  std::uint64_t x, y;
  bool operator==(const Coord_key& o) const { return x == o.x && y == o.y; }
};

inline Coord_key coord_key(const Point2& p)
{
  Coord_key k;
  const double x = (p[0] == 0.0) ? 0.0 : p[0];
  const double y = (p[1] == 0.0) ? 0.0 : p[1];
  std::memcpy(&k.x, &x, sizeof x);
  std::memcpy(&k.y, &y, sizeof y);
  return k;
}

struct Coord_hash
{
  std::size_t operator()(const Coord_key& k) const
  {
    return static_cast<std::size_t>(mix64(k.x ^ mix64(k.y)));
  }
};

struct Pair_key
{
  std::size_t a, b; // a < b
  bool operator==(const Pair_key& o) const { return a == o.a && b == o.b; }
};

inline Pair_key pair_key(std::size_t u, std::size_t v)
{
  return u < v ? Pair_key{u, v} : Pair_key{v, u};
}

struct Pair_hash
{
  std::size_t operator()(const Pair_key& k) const
  {
    return static_cast<std::size_t>(mix64(std::uint64_t(k.a) ^ mix64(std::uint64_t(k.b))));
  }
};

struct Less_xy
{
  bool operator()(const Epeck::Point_2& p, const Epeck::Point_2& q) const
  {
    return CGAL::compare_xy(p, q) == CGAL::SMALLER;
  }
};

// One undirected mesh edge {a, b}, a < b.
struct Edge
{
  std::size_t a, b;
  int uses = 0;
  // (#triangles traversing a->b) - (#traversing b->a). A CCW triangle lies to
  // the left of its directed edges, so this is the jump of the coverage
  // count from the right of a->b to its left.
  int net = 0;
  std::size_t tri[2] = {none, none};
  int opposite[2] = {-1, -1}; // local index of the vertex opposite the edge
  bool is_segment = false;
};

class Checker
{
public:
  Checker(const Pslg& input, const Mesh& mesh, Report& report)
      : in_(input), mesh_(mesh), rep_(report)
  {
  }

  void run()
  {
    rep_.n_vertices = mesh_.vertices.size();
    rep_.n_triangles = mesh_.triangles.size();
    const bool input_ok = prepare_input();
    if(!prepare_mesh_vertices()) return;
    classify_triangles();
    build_edges();
    check_vertex_usage();
    compute_quality();
    check_boundary_edges();
    check_delaunay();
    if(!input_ok || !build_arrangement()) return;
    find_components();
    locate_queries();
    check_input_points();
    check_segments();
    check_components();
    check_area();
  }

private:
  const Pslg& in_;
  const Mesh& mesh_;
  Report& rep_;

  // Input points deduplicated by exact coordinates ("canonical" points).
  std::vector<Point2> canon_points_;
  std::vector<std::size_t> first_input_of_canon_; // for messages
  std::vector<bool> canon_is_endpoint_;
  std::unordered_map<Coord_key, std::size_t, Coord_hash> canon_by_coord_;
  std::vector<std::array<std::size_t, 2>> segments_; // canonical, distinct
  std::unordered_map<Pair_key, std::size_t, Pair_hash> segment_by_pair_;

  std::vector<Epick::Point_2> vpoints_;
  std::unordered_map<Coord_key, std::size_t, Coord_hash> mesh_by_coord_;
  std::vector<std::size_t> input_of_vertex_; // canonical input id or none
  std::vector<std::size_t> vertex_of_canon_; // mesh vertex or none
  std::vector<bool> vertex_used_;

  std::vector<bool> tri_valid_; // indices in range and distinct
  std::vector<int> tri_orient_; // +1 CCW, 0 flat, -1 CW
  std::vector<Edge> edges_;
  std::unordered_map<Pair_key, std::size_t, Pair_hash> edge_by_pair_;

  Arrangement arr_;
  std::vector<Arrangement::Vertex_const_handle> arr_vertex_of_canon_;
  std::vector<bool> canon_in_closure_;

  std::vector<std::size_t> component_rep_; // a triangle of each component
  std::vector<std::size_t> component_size_;

  // Query results of the batched point location. Most queries are input
  // points, exactly doubles, and a hash on their bits avoids the exact
  // comparisons a std::map would need; centroids go to the map.
  std::unordered_map<Coord_key, Location, Coord_hash> located_double_;
  std::map<Epeck::Point_2, Location, Less_xy> located_other_;
  std::vector<Epeck::Point_2> seed_points_, free_points_, centroid_points_;
  std::vector<std::size_t> free_canon_;

  // Formats the message only if the report will store it: a badly broken
  // mesh can have an error per edge.
  template <class Make_message>
  void fail(const char* kind, Make_message&& make_message)
  {
    rep_.add_error(kind, rep_.stores_next_error() ? make_message() : std::string());
  }

  static bool finite(const Point2& p) { return std::isfinite(p[0]) && std::isfinite(p[1]); }

  const Point2& vcoord(std::size_t v) const { return mesh_.vertices[v]; }

  std::string describe_vertex(std::size_t v) const
  {
    return "vertex " + std::to_string(v) + " " + fmt(vcoord(v));
  }

  std::string describe_triangle(std::size_t t) const
  {
    const auto& tr = mesh_.triangles[t];
    std::string s = "triangle " + std::to_string(t) + " [" + std::to_string(tr[0]) + ","
                    + std::to_string(tr[1]) + "," + std::to_string(tr[2]) + "]";
    if(tri_valid_.empty() || tri_valid_[t])
      s += " " + fmt(vcoord(tr[0])) + " " + fmt(vcoord(tr[1])) + " " + fmt(vcoord(tr[2]));
    return s;
  }

  std::string describe_edge(const Edge& e) const
  {
    return "edge {" + std::to_string(e.a) + "," + std::to_string(e.b) + "} " + fmt(vcoord(e.a))
           + "-" + fmt(vcoord(e.b));
  }

  std::string describe_input_point(std::size_t c) const
  {
    return "input point " + std::to_string(first_input_of_canon_[c]) + " " + fmt(canon_points_[c]);
  }

  std::string describe_segment(std::size_t ca, std::size_t cb) const
  {
    return "input segment " + fmt(canon_points_[ca]) + "-" + fmt(canon_points_[cb]);
  }

  static Epeck::Point_2 exact_point(const Point2& p) { return Epeck::Point_2(p[0], p[1]); }

  // ---------------------------------------------------------------- input

  bool prepare_input()
  {
    bool ok = true;
    std::vector<std::size_t> canon_of_input(in_.points.size(), none);
    for(std::size_t i = 0; i < in_.points.size(); ++i) {
      const Point2& p = in_.points[i];
      if(!finite(p)) {
        fail(error_kind::input,
             [&] { return "input point " + std::to_string(i) + " " + fmt(p) + " is not finite"; });
        ok = false;
        continue;
      }
      auto ins = canon_by_coord_.emplace(coord_key(p), canon_points_.size());
      if(ins.second) {
        canon_points_.push_back(p);
        first_input_of_canon_.push_back(i);
      }
      canon_of_input[i] = ins.first->second;
    }
    canon_is_endpoint_.assign(canon_points_.size(), false);

    for(std::size_t s = 0; s < in_.segments.size(); ++s) {
      const auto& seg = in_.segments[s];
      if(seg[0] >= in_.points.size() || seg[1] >= in_.points.size()) {
        fail(error_kind::input, [&] {
          return "input segment " + std::to_string(s) + " has an out-of-range point index";
        });
        ok = false;
        continue;
      }
      const std::size_t a = canon_of_input[seg[0]], b = canon_of_input[seg[1]];
      if(a == none || b == none) { // a non-finite end, already reported
        ok = false;
        continue;
      }
      if(a == b) {
        fail(error_kind::input, [&] {
          return "input segment " + std::to_string(s) + " is degenerate (both ends at "
                 + fmt(canon_points_[a]) + ")";
        });
        ok = false;
        continue;
      }
      const Pair_key key = pair_key(a, b);
      if(segment_by_pair_.emplace(key, segments_.size()).second)
        segments_.push_back({key.a, key.b});
      canon_is_endpoint_[a] = canon_is_endpoint_[b] = true;
    }

    for(std::size_t h = 0; h < in_.holes.size(); ++h) {
      if(!finite(in_.holes[h])) {
        fail(error_kind::input, [&] {
          return "hole seed " + std::to_string(h) + " " + fmt(in_.holes[h]) + " is not finite";
        });
        ok = false;
      }
    }
    return ok;
  }

  bool is_segment(std::size_t u, std::size_t v) const
  {
    const std::size_t a = input_of_vertex_[u], b = input_of_vertex_[v];
    if(a == none || b == none) return false;
    return segment_by_pair_.count(pair_key(a, b)) != 0;
  }

  // ----------------------------------------------------------------- mesh

  bool prepare_mesh_vertices()
  {
    const std::size_t n = mesh_.vertices.size();
    bool all_finite = true;
    for(std::size_t v = 0; v < n; ++v) {
      if(!finite(vcoord(v))) {
        fail(error_kind::bad_coordinate, [&] { return describe_vertex(v) + " is not finite"; });
        all_finite = false;
      }
    }
    // Exact geometry on NaN/inf is meaningless; stop rather than guess.
    if(!all_finite) return false;

    vpoints_.reserve(n);
    input_of_vertex_.assign(n, none);
    vertex_of_canon_.assign(canon_points_.size(), none);
    mesh_by_coord_.reserve(n);
    for(std::size_t v = 0; v < n; ++v) {
      const Point2& p = vcoord(v);
      vpoints_.emplace_back(p[0], p[1]);
      const Coord_key key = coord_key(p);
      auto ins = mesh_by_coord_.emplace(key, v);
      if(!ins.second) {
        fail(error_kind::duplicate_vertex, [&] {
          return describe_vertex(v) + " has the same coordinates as vertex "
                 + std::to_string(ins.first->second);
        });
        continue;
      }
      auto it = canon_by_coord_.find(key);
      if(it != canon_by_coord_.end()) {
        input_of_vertex_[v] = it->second;
        vertex_of_canon_[it->second] = v;
      }
    }
    return true;
  }

  void classify_triangles()
  {
    const std::size_t nt = mesh_.triangles.size(), nv = mesh_.vertices.size();
    tri_valid_.assign(nt, false);
    tri_orient_.assign(nt, 0);
    for(std::size_t t = 0; t < nt; ++t) {
      const auto& tr = mesh_.triangles[t];
      if(tr[0] >= nv || tr[1] >= nv || tr[2] >= nv) {
        fail(error_kind::index,
             [&] { return describe_triangle(t) + " has a vertex index >= " + std::to_string(nv); });
        continue;
      }
      if(tr[0] == tr[1] || tr[1] == tr[2] || tr[0] == tr[2]) {
        fail(error_kind::degenerate_triangle, [&] {
          return "triangle " + std::to_string(t) + " [" + std::to_string(tr[0]) + ","
                 + std::to_string(tr[1]) + "," + std::to_string(tr[2]) + "] repeats a vertex";
        });
        continue;
      }
      tri_valid_[t] = true;
      const CGAL::Orientation o =
          CGAL::orientation(vpoints_[tr[0]], vpoints_[tr[1]], vpoints_[tr[2]]);
      tri_orient_[t] = (o == CGAL::LEFT_TURN) ? 1 : (o == CGAL::RIGHT_TURN ? -1 : 0);
      if(o == CGAL::RIGHT_TURN)
        fail(error_kind::orientation, [&] { return describe_triangle(t) + " is clockwise"; });
      else if(o == CGAL::COLLINEAR)
        fail(error_kind::orientation, [&] { return describe_triangle(t) + " has zero area"; });
    }
  }

  void build_edges()
  {
    const std::size_t nt = mesh_.triangles.size();
    edges_.reserve(nt * 3 / 2 + 16);
    edge_by_pair_.reserve(nt * 3 / 2 + 16);
    for(std::size_t t = 0; t < nt; ++t) {
      if(!tri_valid_[t]) continue;
      const auto& tr = mesh_.triangles[t];
      for(int k = 0; k < 3; ++k) {
        const std::size_t from = tr[(k + 1) % 3], to = tr[(k + 2) % 3];
        const Pair_key key = pair_key(from, to);
        auto ins = edge_by_pair_.emplace(key, edges_.size());
        if(ins.second) {
          Edge e;
          e.a = key.a;
          e.b = key.b;
          edges_.push_back(e);
        }
        Edge& e = edges_[ins.first->second];
        if(e.uses < 2) {
          e.tri[e.uses] = t;
          e.opposite[e.uses] = k;
        }
        ++e.uses;
        e.net += (from < to) ? 1 : -1;
      }
    }
    for(Edge& e : edges_) {
      e.is_segment = is_segment(e.a, e.b);
      if(e.uses > 2) {
        fail(error_kind::non_manifold, [&] {
          return describe_edge(e) + " is used by " + std::to_string(e.uses) + " triangles (e.g. "
                 + std::to_string(e.tri[0]) + " and " + std::to_string(e.tri[1]) + ")";
        });
      } else if(e.uses == 2 && e.net != 0) {
        fail(error_kind::non_manifold, [&] {
          return describe_edge(e) + " is used by triangles " + std::to_string(e.tri[0]) + " and "
                 + std::to_string(e.tri[1])
                 + " in the same direction (overlap or flipped triangle)";
        });
      }
    }
  }

  const Edge* find_edge(std::size_t u, std::size_t v) const
  {
    auto it = edge_by_pair_.find(pair_key(u, v));
    return it == edge_by_pair_.end() ? nullptr : &edges_[it->second];
  }

  void check_vertex_usage()
  {
    vertex_used_.assign(mesh_.vertices.size(), false);
    for(std::size_t t = 0; t < mesh_.triangles.size(); ++t)
      if(tri_valid_[t])
        for(std::size_t v : mesh_.triangles[t]) vertex_used_[v] = true;
    for(std::size_t v = 0; v < vertex_used_.size(); ++v)
      if(!vertex_used_[v])
        fail(error_kind::unused_vertex,
             [&] { return describe_vertex(v) + " is used by no triangle"; });
  }

  void compute_quality()
  {
    const double rad_to_deg = 180.0 / 3.14159265358979323846;
    double min_ratio = std::numeric_limits<double>::infinity(), sum_ratio = 0;
    double min_angle = std::numeric_limits<double>::infinity(), max_angle = 0;
    std::size_t n = 0;
    for(std::size_t t = 0; t < mesh_.triangles.size(); ++t) {
      if(tri_orient_[t] <= 0) continue;
      const auto& tr = mesh_.triangles[t];
      const Point2* p[3] = {&vcoord(tr[0]), &vcoord(tr[1]), &vcoord(tr[2])};
      double len[3];
      for(int k = 0; k < 3; ++k) {
        const Point2& a = *p[(k + 1) % 3];
        const Point2& b = *p[(k + 2) % 3];
        len[k] = std::hypot(b[0] - a[0], b[1] - a[1]);
      }
      const Point2 &p0 = *p[0], &p1 = *p[1], &p2 = *p[2];
      const double cross2 = (p1[0] - p0[0]) * (p2[1] - p0[1]) - (p1[1] - p0[1]) * (p2[0] - p0[0]);
      const double area = 0.5 * std::fabs(cross2);
      const double s = 0.5 * (len[0] + len[1] + len[2]);
      const double prod = len[0] * len[1] * len[2];
      // r = A/s and R = abc/(4A), hence 2r/R = 8A^2/(s abc).
      const double ratio = (s > 0 && prod > 0) ? 8.0 * area * area / (s * prod) : 0.0;
      min_ratio = std::min(min_ratio, ratio);
      sum_ratio += ratio;
      for(int k = 0; k < 3; ++k) {
        const Point2& o = *p[k];
        const Point2& a = *p[(k + 1) % 3];
        const Point2& b = *p[(k + 2) % 3];
        const double ux = a[0] - o[0], uy = a[1] - o[1], vx = b[0] - o[0], vy = b[1] - o[1];
        // atan2 stays accurate for needle angles where acos would not.
        const double angle =
            std::atan2(std::fabs(ux * vy - uy * vx), ux * vx + uy * vy) * rad_to_deg;
        min_angle = std::min(min_angle, angle);
        max_angle = std::max(max_angle, angle);
      }
      ++n;
    }
    if(n > 0) {
      rep_.min_radius_ratio = min_ratio;
      rep_.mean_radius_ratio = sum_ratio / double(n);
      rep_.min_angle_deg = min_angle;
      rep_.max_angle_deg = max_angle;
    }
  }

  void check_boundary_edges()
  {
    for(const Edge& e : edges_)
      if(e.uses == 1 && !e.is_segment)
        fail(error_kind::boundary_edge, [&] {
          return describe_edge(e) + " of triangle " + std::to_string(e.tri[0])
                 + " is on the mesh boundary but is not an input segment";
        });
  }

  void check_delaunay()
  {
    for(const Edge& e : edges_) {
      if(e.uses != 2 || e.net != 0 || e.is_segment) continue;
      const std::size_t t0 = e.tri[0], t1 = e.tri[1];
      // The in-circle test only means "Delaunay" for CCW triangles; flipped
      // ones are already reported.
      if(tri_orient_[t0] <= 0 || tri_orient_[t1] <= 0) continue;
      const auto& tr = mesh_.triangles[t0];
      const std::size_t d = mesh_.triangles[t1][e.opposite[1]];
      if(CGAL::side_of_oriented_circle(vpoints_[tr[0]], vpoints_[tr[1]], vpoints_[tr[2]],
                                       vpoints_[d])
         == CGAL::ON_POSITIVE_SIDE) {
        ++rep_.n_non_delaunay_edges;
        fail(error_kind::non_delaunay, [&] {
          return describe_edge(e) + " is not locally Delaunay: " + describe_vertex(d)
                 + " of triangle " + std::to_string(t1) + " is strictly inside the circumcircle of "
                 + describe_triangle(t0);
        });
      }
    }
  }

  // --------------------------------------------------------------- domain

  bool build_arrangement()
  {
    std::vector<Arr_traits::Curve_2> curves;
    curves.reserve(segments_.size());
    for(const auto& s : segments_)
      curves.emplace_back(exact_point(canon_points_[s[0]]), exact_point(canon_points_[s[1]]));
    // The general (intersecting) insertion, so that crossing input is
    // detected instead of silently corrupting the arrangement.
    CGAL::insert(arr_, curves.begin(), curves.end());

    bool ok = true;
    arr_vertex_of_canon_.assign(canon_points_.size(), Arrangement::Vertex_const_handle());
    for(auto v = arr_.vertices_begin(); v != arr_.vertices_end(); ++v) {
      const Epeck::Point_2& p = v->point();
      const Point2 approx = {CGAL::to_double(p.x()), CGAL::to_double(p.y())};
      auto it = canon_by_coord_.end();
      if(p.x() == Epeck::FT(approx[0]) && p.y() == Epeck::FT(approx[1]))
        it = canon_by_coord_.find(coord_key(approx));
      if(it == canon_by_coord_.end()) {
        fail(error_kind::input, [&] {
          return "input segments cross at ~" + fmt(approx) + ", which is not an input point";
        });
        v->set_data(none);
        ok = false;
        continue;
      }
      v->set_data(it->second);
      arr_vertex_of_canon_[it->second] = v;
    }
    for(auto e = arr_.edges_begin(); e != arr_.edges_end(); ++e) {
      const std::size_t a = e->source()->data(), b = e->target()->data();
      if(a == none || b == none) continue;
      if(segment_by_pair_.count(pair_key(a, b)) == 0) {
        fail(error_kind::input, [&] {
          return "input segments overlap or an input point lies inside a segment: "
                 "arrangement edge "
                 + fmt(canon_points_[a]) + "-" + fmt(canon_points_[b])
                 + " is only part of an input segment";
        });
        ok = false;
      }
    }
    if(ok && arr_.number_of_edges() != segments_.size()) {
      fail(error_kind::input, [&] {
        return "the arrangement has " + std::to_string(arr_.number_of_edges()) + " edges for "
               + std::to_string(segments_.size()) + " distinct input segments";
      });
      ok = false;
    }
    for(auto f = arr_.faces_begin(); f != arr_.faces_end(); ++f)
      f->set_data(f->is_unbounded() ? unbounded_face : domain_face);
    return ok;
  }

  void find_components()
  {
    const std::size_t nt = mesh_.triangles.size();
    std::vector<std::size_t> parent(nt);
    for(std::size_t t = 0; t < nt; ++t) parent[t] = t;
    auto find = [&parent](std::size_t t) {
      while(parent[t] != t) t = parent[t] = parent[parent[t]];
      return t;
    };
    // A segment is where the domain may change, so it separates components.
    for(const Edge& e : edges_) {
      if(e.uses != 2 || e.net != 0 || e.is_segment) continue;
      const std::size_t r0 = find(e.tri[0]), r1 = find(e.tri[1]);
      if(r0 != r1) parent[std::max(r0, r1)] = std::min(r0, r1);
    }
    std::vector<std::size_t> component_of_root(nt, none);
    for(std::size_t t = 0; t < nt; ++t) {
      if(!tri_valid_[t]) continue;
      const std::size_t r = find(t);
      if(component_of_root[r] == none) {
        component_of_root[r] = component_rep_.size();
        component_rep_.push_back(t);
        component_size_.push_back(0);
      }
      const std::size_t c = component_of_root[r];
      ++component_size_[c];
      // Prefer a CCW representative: its centroid is strictly inside it.
      if(tri_orient_[component_rep_[c]] <= 0 && tri_orient_[t] > 0) component_rep_[c] = t;
    }
    rep_.n_components = component_rep_.size();
  }

  // One batched sweep answers all queries, so even many free points cost
  // O((n + m) log(n + m)) instead of a walk per query.
  void locate_queries()
  {
    for(const Point2& h : in_.holes) seed_points_.push_back(exact_point(h));
    for(std::size_t c = 0; c < canon_points_.size(); ++c) {
      if(canon_is_endpoint_[c]) continue;
      free_canon_.push_back(c);
      free_points_.push_back(exact_point(canon_points_[c]));
    }
    for(std::size_t t : component_rep_) {
      const auto& tr = mesh_.triangles[t];
      centroid_points_.push_back(CGAL::centroid(
          exact_point(vcoord(tr[0])), exact_point(vcoord(tr[1])), exact_point(vcoord(tr[2]))));
    }
    std::vector<Epeck::Point_2> queries;
    queries.insert(queries.end(), seed_points_.begin(), seed_points_.end());
    queries.insert(queries.end(), free_points_.begin(), free_points_.end());
    queries.insert(queries.end(), centroid_points_.begin(), centroid_points_.end());
    if(queries.empty()) return;
    if(arr_.number_of_edges() == 0) {
      const Arrangement::Face_const_handle unbounded = arr_.unbounded_face();
      for(const auto& q : queries) store_location(q, Location(unbounded));
    } else {
      std::vector<std::pair<Epeck::Point_2, Location>> results;
      results.reserve(queries.size());
      CGAL::locate(arr_, queries.begin(), queries.end(), std::back_inserter(results));
      for(auto& r : results) store_location(r.first, r.second);
    }

    // Seeds first: they decide which bounded faces are holes.
    for(std::size_t h = 0; h < seed_points_.size(); ++h) {
      const Location* loc = find_location(seed_points_[h]);
      if(loc == nullptr) continue;
      if(auto f = boost::get<Arrangement::Face_const_handle>(loc)) {
        if(!(*f)->is_unbounded()) arr_.non_const_handle(*f)->set_data(hole_face);
      } else {
        fail(error_kind::input, [&] {
          return "hole seed " + std::to_string(h) + " " + fmt(in_.holes[h])
                 + " lies on an input segment, so the face it "
                   "removes is ambiguous; it is ignored";
        });
      }
    }
  }

  // A singleton interval approximation is the exact value, so this needs no
  // exact arithmetic.
  static bool as_double(const Epeck::Point_2& p, Point2& out)
  {
    const auto& a = p.approx();
    if(a.x().inf() != a.x().sup() || a.y().inf() != a.y().sup()) return false;
    out = {a.x().inf(), a.y().inf()};
    return true;
  }

  void store_location(const Epeck::Point_2& p, const Location& loc)
  {
    Point2 d;
    if(as_double(p, d))
      located_double_.emplace(coord_key(d), loc);
    else
      located_other_.emplace(p, loc);
  }

  const Location* find_location(const Epeck::Point_2& p)
  {
    Point2 d;
    if(as_double(p, d)) {
      auto it = located_double_.find(coord_key(d));
      if(it != located_double_.end()) return &it->second;
    } else {
      auto it = located_other_.find(p);
      if(it != located_other_.end()) return &it->second;
    }
    fail(error_kind::input, [&] {
      return "internal: point location returned no answer for ~(" + fmt(CGAL::to_double(p.x()))
             + ", " + fmt(CGAL::to_double(p.y())) + ")";
    });
    return nullptr;
  }

  static bool in_domain(Arrangement::Face_const_handle f) { return f->data() == domain_face; }

  static bool touches_domain(Arrangement::Vertex_const_handle v)
  {
    if(v->is_isolated()) return in_domain(v->face());
    auto first = v->incident_halfedges(), cur = first;
    // Each sector around v is the face to the left of one incoming halfedge.
    do {
      if(in_domain(cur->face())) return true;
    } while(++cur != first);
    return false;
  }

  void check_input_points()
  {
    canon_in_closure_.assign(canon_points_.size(), false);
    for(std::size_t c = 0; c < canon_points_.size(); ++c)
      if(canon_is_endpoint_[c] && arr_vertex_of_canon_[c] != Arrangement::Vertex_const_handle())
        canon_in_closure_[c] = touches_domain(arr_vertex_of_canon_[c]);
    for(std::size_t i = 0; i < free_points_.size(); ++i) {
      const std::size_t c = free_canon_[i];
      const Location* loc = find_location(free_points_[i]);
      if(loc == nullptr) continue;
      if(auto f = boost::get<Arrangement::Face_const_handle>(loc)) {
        canon_in_closure_[c] = in_domain(*f);
      } else if(auto v = boost::get<Arrangement::Vertex_const_handle>(loc)) {
        canon_in_closure_[c] = touches_domain(*v);
      } else {
        fail(error_kind::input,
             [&] { return describe_input_point(c) + " is a free point inside an input segment"; });
      }
    }

    for(std::size_t c = 0; c < canon_points_.size(); ++c) {
      if(!canon_in_closure_[c]) continue;
      const std::size_t v = vertex_of_canon_[c];
      if(v == none)
        fail(error_kind::missing_input_point, [&] {
          return describe_input_point(c) + " lies in the closed domain but is not a mesh vertex";
        });
      else if(!vertex_used_[v])
        fail(error_kind::missing_input_point, [&] {
          return describe_input_point(c) + " is mesh vertex " + std::to_string(v)
                 + " but no triangle uses it";
        });
    }
    // Steiner vertices need no location: every vertex is used by a triangle
    // and, once coverage holds, every triangle lies in the closed domain.
    for(std::size_t v = 0; v < input_of_vertex_.size(); ++v) {
      const std::size_t c = input_of_vertex_[v];
      if(c != none && !canon_in_closure_[c])
        fail(error_kind::outside_domain, [&] {
          return describe_vertex(v) + " is " + describe_input_point(c)
                 + ", which lies outside the closed domain";
        });
    }
  }

  static const char* side_name(int left, int right)
  {
    if(left && right) return "both sides";
    if(left) return "its left side only";
    if(right) return "its right side only";
    return "neither side";
  }

  // Finds a mesh vertex strictly inside the segment, to say why it is missing.
  std::string split_diagnostic(std::size_t ca, std::size_t cb) const
  {
    const Epick::Point_2 p(canon_points_[ca][0], canon_points_[ca][1]);
    const Epick::Point_2 q(canon_points_[cb][0], canon_points_[cb][1]);
    for(std::size_t v = 0; v < vpoints_.size(); ++v)
      if(CGAL::collinear(p, vpoints_[v], q)
         && CGAL::collinear_are_strictly_ordered_along_line(p, vpoints_[v], q))
        return " (split by mesh " + describe_vertex(v) + ")";
    return "";
  }

  void check_segments()
  {
    for(auto h = arr_.edges_begin(); h != arr_.edges_end(); ++h) {
      const std::size_t ca = h->source()->data(), cb = h->target()->data();
      const int left = in_domain(h->face()) ? 1 : 0;
      const int right = in_domain(h->twin()->face()) ? 1 : 0;
      const std::size_t u = vertex_of_canon_[ca], v = vertex_of_canon_[cb];
      const Edge* e = (u != none && v != none) ? find_edge(u, v) : nullptr;
      if(e == nullptr) {
        if(left || right)
          fail(error_kind::missing_segment, [&] {
            return describe_segment(ca, cb) + " (domain on " + side_name(left, right)
                   + ") is not a mesh edge" + split_diagnostic(ca, cb);
          });
        continue;
      }
      if(e->uses > 2 || (e->uses == 2 && e->net != 0)) continue; // non-manifold, reported
      const int jump = (u < v) ? e->net : -e->net;
      if(jump == left - right) continue;
      const int mesh_left = (e->uses == 2 || jump > 0) ? 1 : 0;
      const int mesh_right = (e->uses == 2 || jump < 0) ? 1 : 0;
      fail(error_kind::coverage, [&] {
        return describe_segment(ca, cb) + ": the domain is on " + side_name(left, right)
               + " but mesh triangles are on " + side_name(mesh_left, mesh_right)
               + " (mesh triangle " + std::to_string(e->tri[0]) + ")";
      });
    }
  }

  void check_components()
  {
    for(std::size_t c = 0; c < component_rep_.size(); ++c) {
      const Location* loc = find_location(centroid_points_[c]);
      if(loc == nullptr) continue;
      auto what = [&] {
        return "component of " + std::to_string(component_size_[c]) + " triangles containing "
               + describe_triangle(component_rep_[c]);
      };
      if(auto f = boost::get<Arrangement::Face_const_handle>(loc)) {
        if((*f)->data() == hole_face)
          fail(error_kind::outside_domain, [&] { return what() + " lies in a hole"; });
        else if((*f)->data() == unbounded_face)
          fail(error_kind::outside_domain,
               [&] { return what() + " lies outside the outer boundary (unbounded face)"; });
      } else {
        fail(error_kind::outside_domain, [&] {
          return what()
                 + ": the centroid of that triangle lies on an input segment, "
                   "so the triangle crosses a segment";
        });
      }
    }
  }

  static CGAL::Exact_rational cross(const Point2& p, const Point2& q)
  {
    using Q = CGAL::Exact_rational;
    return Q(p[0]) * Q(q[1]) - Q(q[0]) * Q(p[1]);
  }

  void check_area()
  {
    // Summing each triangle's shoelace terms, the two directions of a shared
    // edge cancel exactly; only edges with a net direction contribute. This
    // is the exact signed sum of the triangle areas, at the cost of the
    // boundary only.
    CGAL::Exact_rational mesh2(0), domain2(0);
    for(const Edge& e : edges_)
      if(e.net != 0) mesh2 += CGAL::Exact_rational(e.net) * cross(vcoord(e.a), vcoord(e.b));
    // A face lies left of its halfedges (outer boundary CCW, inner ones CW);
    // both halfedges of a dangling segment are in the same face and cancel.
    for(auto h = arr_.halfedges_begin(); h != arr_.halfedges_end(); ++h)
      if(in_domain(h->face()))
        domain2 += cross(canon_points_[h->source()->data()], canon_points_[h->target()->data()]);
    const CGAL::Exact_rational half(1, 2);
    const CGAL::Exact_rational mesh_area = mesh2 * half, domain_area = domain2 * half;
    rep_.mesh_area = CGAL::to_double(mesh_area);
    rep_.domain_area = CGAL::to_double(domain_area);
    if(mesh_area != domain_area) {
      fail(error_kind::area, [&] {
        return "triangle areas sum to " + fmt(rep_.mesh_area) + " but the domain area is "
               + fmt(rep_.domain_area) + " (exact difference ~"
               + fmt(CGAL::to_double(mesh_area - domain_area)) + ")";
      });
    }
  }
};

} // namespace detail

inline Report check_mesh(const Pslg& input, const Mesh& mesh)
{
  // Coordinates of extreme magnitude (near 1e+300 or 1e-300) make the
  // arrangement's constructions overflow or underflow in CGAL's filtered
  // kernel (an assertion in Arr_segment_traits_2 fires at 1e+300). Every
  // test here is invariant under a uniform scaling, and scaling by a power
  // of two is exact, so such input is checked scaled to magnitudes near 1;
  // only the reported areas are scaled back.
  double largest = 0;
  auto see = [&largest](const std::array<double, 2>& p) {
    largest = (std::max)({largest, std::abs(p[0]), std::abs(p[1])});
  };
  for(const auto& p : input.points) see(p);
  for(const auto& p : input.holes) see(p);
  for(const auto& p : mesh.vertices) see(p);
  int exponent = 0;
  if(largest > 0 && std::isfinite(largest)) std::frexp(largest, &exponent);
  Report report;
  if(exponent > -200 && exponent < 200) {
    detail::Checker(input, mesh, report).run();
    return report;
  }
  auto scale = [exponent](std::array<double, 2> p) {
    return std::array<double, 2>{{std::ldexp(p[0], -exponent), std::ldexp(p[1], -exponent)}};
  };
  Pslg scaled_input = input;
  Mesh scaled_mesh = mesh;
  for(auto& p : scaled_input.points) p = scale(p);
  for(auto& p : scaled_input.holes) p = scale(p);
  for(auto& p : scaled_mesh.vertices) p = scale(p);
  detail::Checker(scaled_input, scaled_mesh, report).run();
  report.mesh_area = std::ldexp(report.mesh_area, 2 * exponent);
  report.domain_area = std::ldexp(report.domain_area, 2 * exponent);
  return report;
}

} // namespace afm_check

#endif // AFM_VALIDITY_CHECKER_H
