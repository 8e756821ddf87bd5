// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

// Geometry generators for the examples, tests and benchmarks of
// Advancing_front_mesh_2. Everything here is plain C++17; the only CGAL
// dependency is the `Poly_data` struct that the generators return.
//
// Conventions of every generator:
//  - the output is a planar straight-line graph made of closed loops;
//  - outer boundaries run counter-clockwise, hole boundaries clockwise;
//  - each hole loop has exactly one seed point strictly inside it (and not
//    inside any loop nested in that hole), computed by `interior_point()`
//    and checked with a point-in-polygon test;
//  - no two points are identical and no two segments cross or touch except
//    at a shared end point (see `is_simple_pslg()`).

#ifndef AFM_GEOMETRIES_H
#define AFM_GEOMETRIES_H

#include <CGAL/Advancing_front_mesh_2/IO/Poly_data.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace afm_geometry {

using Poly_data = CGAL::Advancing_front_mesh_2::IO::Poly_data;
using Point = std::array<double, 2>;
using Loop = std::vector<Point>;

constexpr double pi = 3.14159265358979323846;

// ---------------------------------------------------------------------------
// Small geometric helpers (double arithmetic; good enough for generating and
// checking inputs, not meant to be exact predicates).
// ---------------------------------------------------------------------------

namespace detail {

inline double orient(const Point& a, const Point& b, const Point& c)
{
  // Evaluated in long double: cheap extra safety margin for nearly collinear
  // input (x86-64: 64-bit mantissa; elsewhere it is at least a double).
  const long double abx = (long double)b[0] - a[0], aby = (long double)b[1] - a[1];
  const long double acx = (long double)c[0] - a[0], acy = (long double)c[1] - a[1];
  return double(abx * acy - aby * acx);
}

inline int sign_of(double v) { return (v > 0) - (v < 0); }

// p known to be collinear with [a,b]: is it inside the closed bounding box?
inline bool in_box(const Point& p, const Point& a, const Point& b)
{
  return std::min(a[0], b[0]) <= p[0] && p[0] <= std::max(a[0], b[0]) &&
         std::min(a[1], b[1]) <= p[1] && p[1] <= std::max(a[1], b[1]);
}

inline bool point_on_segment(const Point& p, const Point& a, const Point& b)
{
  return orient(a, b, p) == 0 && in_box(p, a, b);
}

// Closed segments [a,b] and [c,d] have a common point.
inline bool segments_intersect(const Point& a, const Point& b, const Point& c, const Point& d)
{
  const int o1 = sign_of(orient(a, b, c)), o2 = sign_of(orient(a, b, d));
  const int o3 = sign_of(orient(c, d, a)), o4 = sign_of(orient(c, d, b));
  if(o1 * o2 < 0 && o3 * o4 < 0)
    return true;
  if(o1 == 0 && in_box(c, a, b)) return true;
  if(o2 == 0 && in_box(d, a, b)) return true;
  if(o3 == 0 && in_box(a, c, d)) return true;
  if(o4 == 0 && in_box(b, c, d)) return true;
  return false;
}

inline double squared_distance_point_segment(const Point& p, const Point& a, const Point& b)
{
  const double ux = b[0] - a[0], uy = b[1] - a[1];
  const double wx = p[0] - a[0], wy = p[1] - a[1];
  const double uu = ux * ux + uy * uy;
  double t = uu > 0 ? (wx * ux + wy * uy) / uu : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  const double dx = wx - t * ux, dy = wy - t * uy;
  return dx * dx + dy * dy;
}

inline double segment_distance(const Point& a, const Point& b, const Point& c, const Point& d)
{
  if(segments_intersect(a, b, c, d))
    return 0.0;
  const double d2 = std::min({squared_distance_point_segment(a, c, d),
                              squared_distance_point_segment(b, c, d),
                              squared_distance_point_segment(c, a, b),
                              squared_distance_point_segment(d, a, b)});
  return std::sqrt(d2);
}

inline std::string point_string(const Point& p)
{
  std::ostringstream os;
  os.precision(17);
  os << "(" << p[0] << ", " << p[1] << ")";
  return os.str();
}

inline bool set_why(std::string* why, const std::string& msg)
{
  if(why != nullptr)
    *why = msg;
  return false;
}

} // namespace detail

/// Signed area of a closed polygon (positive when it runs counter-clockwise).
/// The closing edge last -> first is implicit.
inline double signed_area(const Loop& loop)
{
  double a = 0;
  const std::size_t n = loop.size();
  for(std::size_t i = 0; i < n; ++i) {
    const Point& p = loop[i];
    const Point& q = loop[(i + 1) % n];
    a += p[0] * q[1] - q[0] * p[1];
  }
  return 0.5 * a;
}

/// Even-odd (crossing number) point-in-polygon test. The result for a point
/// exactly on the boundary is unspecified.
inline bool point_in_polygon(const Point& p, const Loop& loop)
{
  bool inside = false;
  const std::size_t n = loop.size();
  for(std::size_t i = 0, j = n - 1; i < n; j = i++) {
    const Point& a = loop[i];
    const Point& b = loop[j];
    if((a[1] > p[1]) != (b[1] > p[1])) {
      const double x = a[0] + (p[1] - a[1]) * (b[0] - a[0]) / (b[1] - a[1]);
      if(p[0] < x)
        inside = !inside;
    }
  }
  return inside;
}

/// Distance from `p` to the nearest edge of `loop`.
inline double distance_to_loop(const Point& p, const Loop& loop)
{
  double d2 = std::numeric_limits<double>::infinity();
  for(std::size_t i = 0, n = loop.size(); i < n; ++i)
    d2 = std::min(d2, detail::squared_distance_point_segment(p, loop[i], loop[(i + 1) % n]));
  return std::sqrt(d2);
}

/// Smallest distance between the boundaries of two closed polygons; 0 when
/// their edges intersect or when one polygon lies inside the other.
inline double loop_clearance(const Loop& a, const Loop& b)
{
  if(a.empty() || b.empty())
    return std::numeric_limits<double>::infinity();
  if(point_in_polygon(a[0], b) || point_in_polygon(b[0], a))
    return 0.0;
  double d = std::numeric_limits<double>::infinity();
  for(std::size_t i = 0, n = a.size(); i < n; ++i)
    for(std::size_t j = 0, m = b.size(); j < m; ++j) {
      d = std::min(d, detail::segment_distance(a[i], a[(i + 1) % n], b[j], b[(j + 1) % m]));
      if(d == 0.0)
        return 0.0;
    }
  return d;
}

inline Loop reversed(Loop loop)
{
  std::reverse(loop.begin(), loop.end());
  return loop;
}

/// `loop` in counter-clockwise order (reversed if needed).
inline Loop ccw(Loop loop)
{
  if(signed_area(loop) < 0)
    std::reverse(loop.begin(), loop.end());
  return loop;
}

/// `loop` in clockwise order (reversed if needed).
inline Loop cw(Loop loop)
{
  if(signed_area(loop) > 0)
    std::reverse(loop.begin(), loop.end());
  return loop;
}

/// A point strictly inside the region bounded by `outer` minus the interiors
/// of the loops `excluded` (which must lie inside `outer` and be disjoint).
///
/// Robust for non-convex and very thin loops: horizontal and vertical scan
/// lines are cut by all the edges, the even-odd intervals on each line are
/// interior, and among their midpoints the one farthest from every edge is
/// returned (an approximation of the centre of the largest inscribed
/// circle). The result is checked with point-in-polygon tests; throws
/// std::runtime_error if no interior point was found.
inline Point interior_point(const Loop& outer, const std::vector<Loop>& excluded = {})
{
  if(outer.size() < 3)
    throw std::runtime_error("interior_point: loop with fewer than 3 points");
  std::vector<std::pair<Point, Point> > edges;
  auto add_edges = [&](const Loop& l) {
    for(std::size_t i = 0, n = l.size(); i < n; ++i)
      edges.emplace_back(l[i], l[(i + 1) % n]);
  };
  add_edges(outer);
  for(const Loop& l : excluded)
    add_edges(l);

  double lo[2] = {outer[0][0], outer[0][1]}, hi[2] = {outer[0][0], outer[0][1]};
  for(const Point& p : outer)
    for(int k = 0; k < 2; ++k) {
      lo[k] = std::min(lo[k], p[k]);
      hi[k] = std::max(hi[k], p[k]);
    }

  struct Candidate { Point p; double half_length; };
  std::vector<Candidate> candidates;
  const int n_lines = 64;
  std::vector<double> cuts;
  for(int axis = 0; axis < 2; ++axis) {     // axis 0: horizontal lines y = c
    const int fixed = 1 - axis;             // coordinate that is constant on the line
    const int other = axis;                 // coordinate that varies along it
    for(int k = 0; k < n_lines; ++k) {
      // Irrational-looking offset so that lines rarely pass through vertices.
      const double c = lo[fixed] + (hi[fixed] - lo[fixed]) * ((k + 0.5 + 0.0731) / (n_lines + 0.1462));
      cuts.clear();
      for(const auto& e : edges) {
        const Point& a = e.first;
        const Point& b = e.second;
        if((a[fixed] > c) != (b[fixed] > c))
          cuts.push_back(a[other] + (c - a[fixed]) * (b[other] - a[other]) / (b[fixed] - a[fixed]));
      }
      std::sort(cuts.begin(), cuts.end());
      for(std::size_t i = 0; i + 1 < cuts.size(); i += 2) {
        if(!(cuts[i + 1] > cuts[i]))
          continue;
        Point p;
        p[fixed] = c;
        p[other] = 0.5 * (cuts[i] + cuts[i + 1]);
        candidates.push_back({p, 0.5 * (cuts[i + 1] - cuts[i])});
      }
    }
  }
  // The distance to the boundary is at most half the interval length, so
  // visiting candidates by decreasing half length allows early exit.
  std::sort(candidates.begin(), candidates.end(),
            [](const Candidate& a, const Candidate& b) { return a.half_length > b.half_length; });
  auto inside = [&](const Point& p) {
    if(!point_in_polygon(p, outer))
      return false;
    for(const Loop& l : excluded)
      if(point_in_polygon(p, l))
        return false;
    return true;
  };
  double best_d = 0;
  Point best{0, 0};
  for(const Candidate& cand : candidates) {
    if(cand.half_length <= best_d)
      break;
    double d2 = std::numeric_limits<double>::infinity();
    for(const auto& e : edges) {
      d2 = std::min(d2, detail::squared_distance_point_segment(cand.p, e.first, e.second));
      if(d2 <= best_d * best_d)
        break;
    }
    const double d = std::sqrt(d2);
    if(d > best_d && inside(cand.p)) {
      best_d = d;
      best = cand.p;
    }
  }
  if(!(best_d > 0))
    throw std::runtime_error("interior_point: no interior point found (degenerate loop?)");
  return best;
}

// ---------------------------------------------------------------------------
// Building and analysing Poly_data
// ---------------------------------------------------------------------------

/// Appends `loop` as new points joined by a closed chain of segments.
inline void append_loop(Poly_data& pd, const Loop& loop)
{
  if(loop.size() < 3)
    throw std::invalid_argument("append_loop: a loop needs at least 3 points");
  const std::size_t base = pd.points.size();
  const std::size_t n = loop.size();
  pd.points.insert(pd.points.end(), loop.begin(), loop.end());
  for(std::size_t i = 0; i < n; ++i)
    pd.segments.push_back({base + i, base + (i + 1) % n});
}

/// Splits the segments of `pd` into closed loops (vertex index lists, in
/// segment direction where possible). Fails if a vertex used by a segment
/// does not have exactly two incident segments. Points used by no segment
/// are ignored.
inline bool extract_loop_indices(const Poly_data& pd,
                                 std::vector<std::vector<std::size_t> >& loops,
                                 std::string* why = nullptr)
{
  loops.clear();
  const std::size_t n = pd.points.size();
  std::vector<std::array<std::size_t, 2> > adj(n, {{std::size_t(-1), std::size_t(-1)}});
  std::vector<int> degree(n, 0);
  for(std::size_t s = 0; s < pd.segments.size(); ++s) {
    const auto& seg = pd.segments[s];
    if(seg[0] >= n || seg[1] >= n || seg[0] == seg[1])
      return detail::set_why(why, "segment " + std::to_string(s) + " has an invalid vertex index");
    for(int k = 0; k < 2; ++k) {
      const std::size_t v = seg[k];
      if(degree[v] >= 2)
        return detail::set_why(why, "vertex " + std::to_string(v) + " has more than two incident segments");
      adj[v][degree[v]++] = s;
    }
  }
  std::vector<bool> used(pd.segments.size(), false);
  for(std::size_t s0 = 0; s0 < pd.segments.size(); ++s0) {
    if(used[s0])
      continue;
    std::vector<std::size_t> loop;
    std::size_t s = s0;
    std::size_t v = pd.segments[s0][0];
    const std::size_t start = v;
    while(true) {
      used[s] = true;
      loop.push_back(v);
      const std::size_t w = pd.segments[s][0] == v ? pd.segments[s][1] : pd.segments[s][0];
      if(degree[w] != 2)
        return detail::set_why(why, "vertex " + std::to_string(w) + " is the end of an open chain");
      if(w == start)
        break;
      const std::size_t next = adj[w][0] == s ? adj[w][1] : adj[w][0];
      if(used[next])
        return detail::set_why(why, "inconsistent loop structure at vertex " + std::to_string(w));
      s = next;
      v = w;
    }
    if(loop.size() < 3)
      return detail::set_why(why, "a loop with fewer than 3 vertices starts at vertex " + std::to_string(start));
    loops.push_back(std::move(loop));
  }
  return true;
}

/// Loops of `pd` as point lists; throws std::runtime_error if `pd` is not a
/// union of closed loops.
inline std::vector<Loop> extract_loops(const Poly_data& pd)
{
  std::vector<std::vector<std::size_t> > idx;
  std::string why;
  if(!extract_loop_indices(pd, idx, &why))
    throw std::runtime_error("extract_loops: " + why);
  std::vector<Loop> loops;
  for(const auto& l : idx) {
    Loop pl;
    for(std::size_t v : l)
      pl.push_back(pd.points[v]);
    loops.push_back(std::move(pl));
  }
  return loops;
}

/// Nesting level of each loop: the number of other loops containing it
/// (0 = outermost). For non-intersecting loops, even levels bound the domain
/// from outside and odd levels are holes (even-odd rule).
inline std::vector<int> loop_levels(const std::vector<Loop>& loops)
{
  std::vector<int> level(loops.size(), 0);
  for(std::size_t i = 0; i < loops.size(); ++i)
    for(std::size_t j = 0; j < loops.size(); ++j)
      if(i != j && point_in_polygon(loops[i][0], loops[j]))
        ++level[i];
  return level;
}

/// One seed per hole loop (odd nesting level): inside the loop and outside
/// every loop nested directly in it. Same order as the hole loops in `loops`.
inline std::vector<Point> hole_seeds(const std::vector<Loop>& loops)
{
  const std::vector<int> level = loop_levels(loops);
  std::vector<Point> seeds;
  for(std::size_t i = 0; i < loops.size(); ++i) {
    if(level[i] % 2 == 0)
      continue;
    std::vector<Loop> children;
    for(std::size_t j = 0; j < loops.size(); ++j)
      if(level[j] == level[i] + 1 && point_in_polygon(loops[j][0], loops[i]))
        children.push_back(loops[j]);
    seeds.push_back(interior_point(loops[i], children));
  }
  return seeds;
}

/// Builds a Poly_data from arbitrarily nested, non-intersecting loops:
/// outer boundaries (even level) are made counter-clockwise, holes (odd
/// level) clockwise, and each hole receives a seed.
inline Poly_data from_nested_loops(const std::vector<Loop>& loops)
{
  const std::vector<int> level = loop_levels(loops);
  Poly_data pd;
  for(std::size_t i = 0; i < loops.size(); ++i)
    append_loop(pd, level[i] % 2 == 0 ? ccw(loops[i]) : cw(loops[i]));
  pd.holes = hole_seeds(loops);
  return pd;
}

/// Checks that `pd` is a valid simple PSLG: indices in range, finite
/// coordinates, no degenerate or repeated segment, no two identical points,
/// no two segments with a common point other than a shared end point
/// (crossings, T-junctions, collinear overlaps), and no isolated point on a
/// segment. On failure returns false and describes the first problem in
/// `*why`. Sweep over x: O(n log n + k), k = pairs whose x-ranges overlap.
inline bool is_simple_pslg(const Poly_data& pd, std::string* why = nullptr)
{
  using detail::set_why;
  const std::size_t n = pd.points.size();
  for(std::size_t i = 0; i < n; ++i)
    if(!std::isfinite(pd.points[i][0]) || !std::isfinite(pd.points[i][1]))
      return set_why(why, "point " + std::to_string(i) + " is not finite");
  for(std::size_t i = 0; i < pd.holes.size(); ++i)
    if(!std::isfinite(pd.holes[i][0]) || !std::isfinite(pd.holes[i][1]))
      return set_why(why, "hole seed " + std::to_string(i) + " is not finite");
  std::vector<bool> used(n, false);
  for(std::size_t s = 0; s < pd.segments.size(); ++s) {
    const auto& seg = pd.segments[s];
    if(seg[0] >= n || seg[1] >= n)
      return set_why(why, "segment " + std::to_string(s) + " has a vertex index out of range");
    if(seg[0] == seg[1])
      return set_why(why, "segment " + std::to_string(s) + " is degenerate (both ends are vertex " +
                              std::to_string(seg[0]) + ")");
    used[seg[0]] = used[seg[1]] = true;
  }
  // Identical points.
  {
    std::vector<std::size_t> order(n);
    for(std::size_t i = 0; i < n; ++i) order[i] = i;
    std::sort(order.begin(), order.end(),
              [&](std::size_t a, std::size_t b) { return pd.points[a] < pd.points[b]; });
    for(std::size_t k = 1; k < n; ++k)
      if(pd.points[order[k]] == pd.points[order[k - 1]])
        return set_why(why, "points " + std::to_string(order[k - 1]) + " and " + std::to_string(order[k]) +
                                " are identical " + detail::point_string(pd.points[order[k]]));
  }
  // Repeated segments.
  {
    std::vector<std::pair<std::array<std::size_t, 2>, std::size_t> > segs;
    for(std::size_t s = 0; s < pd.segments.size(); ++s)
      segs.push_back({{{std::min(pd.segments[s][0], pd.segments[s][1]),
                        std::max(pd.segments[s][0], pd.segments[s][1])}}, s});
    std::sort(segs.begin(), segs.end());
    for(std::size_t k = 1; k < segs.size(); ++k)
      if(segs[k].first == segs[k - 1].first)
        return set_why(why, "segments " + std::to_string(segs[k - 1].second) + " and " +
                                std::to_string(segs[k].second) + " are the same");
  }
  // Items: segments, then isolated points as degenerate items (a == b).
  struct Item { std::size_t a, b, id; bool is_point; double xmin, xmax, ymin, ymax; };
  std::vector<Item> items;
  auto make = [&](std::size_t a, std::size_t b, std::size_t id, bool is_point) {
    const Point& p = pd.points[a];
    const Point& q = pd.points[b];
    items.push_back({a, b, id, is_point, std::min(p[0], q[0]), std::max(p[0], q[0]),
                     std::min(p[1], q[1]), std::max(p[1], q[1])});
  };
  for(std::size_t s = 0; s < pd.segments.size(); ++s)
    make(pd.segments[s][0], pd.segments[s][1], s, false);
  for(std::size_t i = 0; i < n; ++i)
    if(!used[i])
      make(i, i, i, true);
  std::sort(items.begin(), items.end(), [](const Item& a, const Item& b) { return a.xmin < b.xmin; });
  auto describe = [&](const Item& it) {
    if(it.is_point)
      return "isolated point " + std::to_string(it.id) + " " + detail::point_string(pd.points[it.a]);
    return "segment " + std::to_string(it.id) + " (" + std::to_string(it.a) + "-" + std::to_string(it.b) + ")";
  };
  std::vector<std::size_t> active;
  for(std::size_t k = 0; k < items.size(); ++k) {
    const Item& it = items[k];
    std::size_t kept = 0;
    for(std::size_t m = 0; m < active.size(); ++m)
      if(items[active[m]].xmax >= it.xmin)
        active[kept++] = active[m];
    active.resize(kept);
    for(std::size_t m : active) {
      const Item& jt = items[m];
      if(jt.ymax < it.ymin || it.ymax < jt.ymin)
        continue;
      if(it.is_point && jt.is_point)
        continue; // identical points were rejected above
      bool bad = false;
      if(it.is_point || jt.is_point) {
        const Item& pt = it.is_point ? it : jt;
        const Item& sg = it.is_point ? jt : it;
        bad = detail::point_on_segment(pd.points[pt.a], pd.points[sg.a], pd.points[sg.b]);
      } else {
        // Shared end point?
        std::size_t shared = std::size_t(-1), oi = 0, oj = 0;
        if(it.a == jt.a) { shared = it.a; oi = it.b; oj = jt.b; }
        else if(it.a == jt.b) { shared = it.a; oi = it.b; oj = jt.a; }
        else if(it.b == jt.a) { shared = it.b; oi = it.a; oj = jt.b; }
        else if(it.b == jt.b) { shared = it.b; oi = it.a; oj = jt.a; }
        if(shared != std::size_t(-1)) {
          const Point& v = pd.points[shared];
          const Point& p = pd.points[oi];
          const Point& q = pd.points[oj];
          bad = detail::orient(v, p, q) == 0 &&
                (p[0] - v[0]) * (q[0] - v[0]) + (p[1] - v[1]) * (q[1] - v[1]) > 0;
        } else {
          bad = detail::segments_intersect(pd.points[it.a], pd.points[it.b], pd.points[jt.a], pd.points[jt.b]);
        }
      }
      if(bad)
        return set_why(why, describe(jt) + " and " + describe(it) + " intersect");
    }
    active.push_back(k);
  }
  return true;
}

/// Checks that `pd` is made of closed loops only (every point used by a
/// segment has exactly two), and that the hole seeds match the holes: every
/// seed lies strictly inside a hole loop (odd nesting level) and outside
/// the loops nested in it, and every hole loop holds exactly one seed.
inline bool hole_seeds_valid(const Poly_data& pd, std::string* why = nullptr)
{
  using detail::set_why;
  std::vector<std::vector<std::size_t> > idx;
  if(!extract_loop_indices(pd, idx, why))
    return false;
  std::vector<Loop> loops;
  for(const auto& l : idx) {
    Loop pl;
    for(std::size_t v : l)
      pl.push_back(pd.points[v]);
    loops.push_back(std::move(pl));
  }
  const std::vector<int> level = loop_levels(loops);
  std::vector<int> count(loops.size(), 0);
  for(std::size_t h = 0; h < pd.holes.size(); ++h) {
    const Point& s = pd.holes[h];
    int depth = 0;
    std::size_t innermost = std::size_t(-1);
    for(std::size_t i = 0; i < loops.size(); ++i) {
      if(distance_to_loop(s, loops[i]) == 0)
        return set_why(why, "hole seed " + std::to_string(h) + " lies on a segment");
      if(point_in_polygon(s, loops[i])) {
        ++depth;
        if(innermost == std::size_t(-1) || level[i] > level[innermost])
          innermost = i;
      }
    }
    if(depth == 0)
      return set_why(why, "hole seed " + std::to_string(h) + " " + detail::point_string(s) + " is outside all loops");
    if(depth % 2 == 1)
      return set_why(why, "hole seed " + std::to_string(h) + " " + detail::point_string(s) + " is inside the domain");
    ++count[innermost];
  }
  for(std::size_t i = 0; i < loops.size(); ++i) {
    if(level[i] % 2 == 1 && count[i] != 1)
      return set_why(why, "hole loop " + std::to_string(i) + " (starting at vertex " + std::to_string(idx[i][0]) +
                              ") has " + std::to_string(count[i]) + " seeds");
  }
  return true;
}

// ---------------------------------------------------------------------------
// Airfoils
// ---------------------------------------------------------------------------

/// NACA 4-digit airfoil "MPTT" (e.g. "0012", "2412"): chord 1 from the
/// leading edge (0,0) to the trailing edge (1,0), maximum camber M % at P/10
/// chord, thickness TT %. Stations are cosine spaced in x (finer at both
/// edges): x_i = (1 - cos(pi i / n)) / 2, i = 0..n, n = `n_per_side`.
///
/// The result is a counter-clockwise closed loop (the closing edge
/// last -> first is implicit): it starts at the trailing edge, runs over the
/// upper surface to the leading edge and back along the lower surface.
///
/// With `closed_trailing_edge` the thickness coefficient -0.1036 gives zero
/// thickness at x = 1: the trailing edge (1,0) appears once, and the loop
/// has 2 n points. Otherwise the standard -0.1015 leaves a blunt base: the
/// loop has 2 n + 1 points and the closing edge is the base. The leading
/// edge (0,0) appears once in both cases.
inline Loop naca4_airfoil(const std::string& digits, std::size_t n_per_side, bool closed_trailing_edge = true)
{
  if(digits.size() != 4 || !std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; }))
    throw std::invalid_argument("naca4_airfoil: expected 4 digits, got \"" + digits + "\"");
  if(n_per_side < 2)
    throw std::invalid_argument("naca4_airfoil: n_per_side must be at least 2");
  const double m = (digits[0] - '0') / 100.0;
  const double p = (digits[1] - '0') / 10.0;
  const double t = ((digits[2] - '0') * 10 + (digits[3] - '0')) / 100.0;
  if(t <= 0)
    throw std::invalid_argument("naca4_airfoil: zero thickness");
  if(m > 0 && (p <= 0 || p >= 1))
    throw std::invalid_argument("naca4_airfoil: cambered section needs 0 < P < 10");
  const double a4 = closed_trailing_edge ? -0.1036 : -0.1015;

  auto thickness = [&](double x) {
    return 5.0 * t * (0.2969 * std::sqrt(x) + x * (-0.1260 + x * (-0.3516 + x * (0.2843 + x * a4))));
  };
  auto surface = [&](double x, bool upper) -> Point {
    double yc = 0, dyc = 0;
    if(m > 0) {
      if(x < p) {
        yc = m / (p * p) * (2 * p * x - x * x);
        dyc = 2 * m / (p * p) * (p - x);
      } else {
        yc = m / ((1 - p) * (1 - p)) * ((1 - 2 * p) + 2 * p * x - x * x);
        dyc = 2 * m / ((1 - p) * (1 - p)) * (p - x);
      }
    }
    const double yt = thickness(x);
    const double th = std::atan(dyc);
    const double sg = upper ? 1.0 : -1.0;
    return {x - sg * yt * std::sin(th), yc + sg * yt * std::cos(th)};
  };
  const std::size_t n = n_per_side;
  auto station = [&](std::size_t i) {
    if(i == 0) return 0.0;
    if(i == n) return 1.0;
    return 0.5 * (1.0 - std::cos(pi * double(i) / double(n)));
  };
  Loop out;
  out.reserve(2 * n + 1);
  if(closed_trailing_edge)
    out.push_back({1.0, 0.0});
  else
    out.push_back(surface(1.0, true));
  for(std::size_t i = n - 1; i >= 1; --i)
    out.push_back(surface(station(i), true));
  out.push_back({0.0, 0.0});
  for(std::size_t i = 1; i < n; ++i)
    out.push_back(surface(station(i), false));
  if(!closed_trailing_edge)
    out.push_back(surface(1.0, false));
  return out;
}

/// Similarity transform for airfoil elements: scale by `scale` (> 0) and
/// rotate by `angle_deg` about the origin (the leading edge of a
/// naca4_airfoil() output), then translate by (dx, dy).
///
/// Angle convention (aerodynamic, flow in +x): a POSITIVE angle raises the
/// nose, i.e. it is a CLOCKWISE rotation in the x-y plane (incidence /
/// downward flap deflection); a negative angle lowers the nose
/// (counter-clockwise, e.g. a drooped slat). With angle 20 the trailing
/// edge (1,0) goes to scale * (cos 20deg, -sin 20deg) + (dx, dy).
inline Loop transform(const Loop& points, double scale, double angle_deg, double dx, double dy)
{
  if(!(scale > 0))
    throw std::invalid_argument("transform: scale must be positive");
  const double a = angle_deg * pi / 180.0;
  const double c = std::cos(a), s = std::sin(a);
  Loop out;
  out.reserve(points.size());
  for(const Point& p : points)
    out.push_back({scale * (c * p[0] + s * p[1]) + dx, scale * (-s * p[0] + c * p[1]) + dy});
  return out;
}

inline Loop translate(const Loop& points, double dx, double dy)
{
  Loop out(points);
  for(Point& p : out) {
    p[0] += dx;
    p[1] += dy;
  }
  return out;
}

// ---------------------------------------------------------------------------
// Loop primitives
// ---------------------------------------------------------------------------

/// Circle of radius r about c with n points, counter-clockwise if `ccw_order`.
inline Loop circle(const Point& c, double r, std::size_t n, bool ccw_order = true)
{
  if(n < 3 || !(r > 0))
    throw std::invalid_argument("circle: need r > 0 and n >= 3");
  Loop out;
  out.reserve(n);
  for(std::size_t i = 0; i < n; ++i) {
    const double a = 2 * pi * double(i) / double(n) * (ccw_order ? 1.0 : -1.0);
    out.push_back({c[0] + r * std::cos(a), c[1] + r * std::sin(a)});
  }
  return out;
}

/// Closed polygon through `corners` with every side split into
/// max(1, round(length / h)) equal parts. Orientation is that of `corners`.
inline Loop subdivided_polygon(const Loop& corners, double h)
{
  if(!(h > 0))
    throw std::invalid_argument("subdivided_polygon: h must be positive");
  Loop out;
  for(std::size_t i = 0, n = corners.size(); i < n; ++i) {
    const Point& a = corners[i];
    const Point& b = corners[(i + 1) % n];
    const double len = std::hypot(b[0] - a[0], b[1] - a[1]);
    const std::size_t k = std::max<std::size_t>(1, std::size_t(std::llround(len / h)));
    for(std::size_t j = 0; j < k; ++j) {
      const double t = double(j) / double(k);
      out.push_back({a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])});
    }
  }
  return out;
}

// ---------------------------------------------------------------------------
// Generators
// ---------------------------------------------------------------------------

/// Polygon with holes: `loops[0]` is the outer boundary, the other loops are
/// holes (inside the outer loop, disjoint). Loops are given without a
/// repeated closing point (a last point equal to the first is dropped).
/// Orientations are normalised (outer CCW, holes CW) and one seed is
/// computed per hole.
inline Poly_data polygon_with_holes(const std::vector<Loop>& loops)
{
  if(loops.empty())
    throw std::invalid_argument("polygon_with_holes: no loop");
  Poly_data pd;
  for(std::size_t i = 0; i < loops.size(); ++i) {
    Loop l = loops[i];
    if(l.size() > 1 && l.front() == l.back())
      l.pop_back();
    if(l.size() < 3)
      throw std::invalid_argument("polygon_with_holes: loop " + std::to_string(i) + " has fewer than 3 points");
    if(i == 0) {
      append_loop(pd, ccw(l));
    } else {
      if(!point_in_polygon(l[0], loops[0]))
        throw std::invalid_argument("polygon_with_holes: hole " + std::to_string(i) + " is not inside the outer loop");
      l = cw(l);
      append_loop(pd, l);
      pd.holes.push_back(interior_point(l));
    }
  }
  return pd;
}

/// Square [0,side]^2 with a centred circular hole of radius `hole_radius`.
/// Both loops have spacing ~h: round(side/h) segments per side and
/// round(2 pi r / h) (at least 3) points on the circle.
inline Poly_data square_with_circular_hole(double side = 1.0, double hole_radius = 0.25, double h = 0.01)
{
  if(!(side > 0) || !(hole_radius > 0) || !(hole_radius < 0.5 * side) || !(h > 0))
    throw std::invalid_argument("square_with_circular_hole: need side > 0, 0 < r < side/2, h > 0");
  const std::size_t n_circle = std::max<std::size_t>(3, std::size_t(std::llround(2 * pi * hole_radius / h)));
  return polygon_with_holes({subdivided_polygon({{0, 0}, {side, 0}, {side, side}, {0, side}}, h),
                             circle({0.5 * side, 0.5 * side}, hole_radius, n_circle, false)});
}

/// L-shaped domain [0,2]x[0,1] U [0,1]x[0,2] (re-entrant corner at (1,1))
/// with boundary spacing h.
inline Poly_data l_shape(double h)
{
  return polygon_with_holes({subdivided_polygon({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}, h)});
}

/// Mavriplis (1992), Fig. 9 of the paper: two thin parallel flat plates,
/// length 1, thickness 0.02, vertical gap 0.1 (lower plate [0,1]x[-0.07,-0.05],
/// upper plate [0,1]x[0.05,0.07]) in a far-field box [-2,3]x[-2,2] with
/// spacing 0.5. The plates have uniform spacing 0.01 except the upper
/// surface of the LOWER plate, which is only two edges of length 0.5 (three
/// points) facing a finely discretised surface 0.1 away.
inline Poly_data two_thin_plates()
{
  // Spacing 0.01: 100 edges along each fine surface, 2 across each end.
  const double up_bot = 0.05, up_top = 0.07;    // upper plate [0,1] x [0.05, 0.07]
  const double lo_bot = -0.07, lo_top = -0.05;  // lower plate [0,1] x [-0.07, -0.05]
  const double up_mid = 0.06, lo_mid = -0.06;   // mid points of the plate ends
  Loop box = subdivided_polygon({{-2, -2}, {3, -2}, {3, 2}, {-2, 2}}, 0.5);
  Loop upper;
  for(std::size_t i = 0; i < 100; ++i) upper.push_back({double(i) / 100.0, up_bot});
  upper.push_back({1.0, up_bot});
  upper.push_back({1.0, up_mid});
  for(std::size_t i = 0; i < 100; ++i) upper.push_back({1.0 - double(i) / 100.0, up_top});
  upper.push_back({0.0, up_top});
  upper.push_back({0.0, up_mid});
  // Lower plate, counter-clockwise: bottom (fine), right end (fine), top
  // (three points only), left end (fine).
  Loop lower;
  for(std::size_t i = 0; i < 100; ++i) lower.push_back({double(i) / 100.0, lo_bot});
  lower.push_back({1.0, lo_bot});
  lower.push_back({1.0, lo_mid});
  lower.push_back({1.0, lo_top}); // start of the coarse upper surface
  lower.push_back({0.5, lo_top}); // its middle
  lower.push_back({0.0, lo_top}); // its end
  lower.push_back({0.0, lo_mid});
  return polygon_with_holes({box, upper, lower});
}

namespace detail {

// Moves `element` along unit direction `dir` from offset `start` until its
// clearance to every loop of `fixed` is at least `gap` (first crossing found
// by doubling steps, refined by bisection). Returns the moved element.
inline Loop place_with_gap(const std::vector<Loop>& fixed, const Loop& element, const Point& start,
                           const Point& dir, double gap)
{
  auto moved = [&](double s) { return translate(element, start[0] + s * dir[0], start[1] + s * dir[1]); };
  auto clear = [&](double s) {
    const Loop l = moved(s);
    double c = std::numeric_limits<double>::infinity();
    for(const Loop& f : fixed)
      c = std::min(c, loop_clearance(l, f));
    return c;
  };
  if(clear(0) >= gap)
    return moved(0);
  double lo = 0, hi = gap;
  while(clear(hi) < gap) {
    lo = hi;
    hi *= 2;
    if(hi > 100)
      throw std::runtime_error("place_with_gap: cannot place element");
  }
  for(int it = 0; it < 40; ++it) {
    const double mid = 0.5 * (lo + hi);
    (clear(mid) >= gap ? hi : lo) = mid;
  }
  return moved(hi);
}

} // namespace detail

/// NACA 0012 with a closed trailing edge (chord [0,1] on the x axis) as a
/// hole in a circular far field of radius `far_radius` centred at
/// mid-chord (0.5, 0) with `n_far` points.
inline Poly_data naca0012_far_field(std::size_t n_per_side = 100, double far_radius = 20, std::size_t n_far = 64)
{
  return polygon_with_holes({circle({0.5, 0.0}, far_radius, n_far), naca4_airfoil("0012", n_per_side, true)});
}

/// The element loops of multi_element_airfoil() (counter-clockwise), in the
/// order slat, main, flap 1, flap 2.
inline std::vector<Loop> multi_element_airfoil_elements()
{
  // Main element: NACA 2412, chord 1, 100 points per side.
  const Loop main = naca4_airfoil("2412", 100);
  // Slat: NACA 4412, chord 0.15, 40 points per side, 25 deg nose down
  // (negative angle = counter-clockwise, its trailing edge is lifted).
  // Its leading edge starts 0.06 below the main leading edge; it is pushed
  // forwards until the gap to the main element is 0.025.
  const Loop slat0 = transform(naca4_airfoil("4412", 40), 0.15, -25.0, 0.0, 0.0);
  const Loop slat = detail::place_with_gap({main}, slat0, {-0.10, -0.06}, {-1.0, 0.0}, 0.025);
  // Flap 1: NACA 4412, chord 0.3, 20 deg down, leading edge under the main
  // trailing edge (x = 0.96), lowered until the gap is 0.02.
  const Loop flap1_0 = transform(naca4_airfoil("4412", 60), 0.3, 20.0, 0.0, 0.0);
  const Loop flap1 = detail::place_with_gap({main}, flap1_0, {0.96, 0.0}, {0.0, -1.0}, 0.02);
  // Flap 2: NACA 4412, chord 0.2, 35 deg down, leading edge 0.02 ahead of
  // the flap-1 trailing edge (the first point of its loop), gap 0.015.
  const Loop flap2_0 = transform(naca4_airfoil("4412", 45), 0.2, 35.0, 0.0, 0.0);
  const Loop flap2 = detail::place_with_gap({main, flap1}, flap2_0, {flap1[0][0] - 0.02, flap1[0][1]},
                                            {0.0, -1.0}, 0.015);
  return {slat, main, flap1, flap2};
}

/// The project's default demo input: a four-element high-lift airfoil
/// (slat, main element, two flap elements; see
/// multi_element_airfoil_elements()) as 4 holes in a circular far field of
/// radius `far_radius` about (0.5, 0) with `n_far` points. Gaps between
/// elements: slat/main 0.025, main/flap 1 0.02, flap 1/flap 2 0.015 chord.
inline Poly_data multi_element_airfoil(double far_radius = 15, std::size_t n_far = 80)
{
  std::vector<Loop> loops{circle({0.5, 0.0}, far_radius, n_far)};
  for(const Loop& e : multi_element_airfoil_elements())
    loops.push_back(e);
  return polygon_with_holes(loops);
}

/// Unit square (spacing 0.02) with `n` disjoint circular holes whose radii
/// are log-uniform in [0.005, 0.15]; placed by rejection sampling (largest
/// first) with clearance 0.01 between circles and 0.02 to the square. Each
/// circle has max(6, round(2 pi r / min(0.02, r/3))) points. The random
/// numbers come from std::mt19937 (whose output sequence is fixed by the
/// standard) without std distributions, so the result is the same on every
/// platform for a given seed. Throws if the holes cannot be placed.
inline Poly_data many_holes(std::size_t n = 40, unsigned seed = 1)
{
  std::mt19937 rng(seed);
  auto uniform = [&rng]() { return (double(rng()) + 0.5) / 4294967296.0; }; // (0,1)
  const double r_min = 0.005, r_max = 0.15, gap = 0.01, wall_gap = 0.02;
  std::vector<double> radii(n);
  for(double& r : radii)
    r = r_min * std::pow(r_max / r_min, uniform());
  std::sort(radii.begin(), radii.end(), std::greater<double>());
  std::vector<std::pair<Point, double> > placed;
  for(double r : radii) {
    bool ok = false;
    while(!ok) {
      for(int attempt = 0; attempt < 5000 && !ok; ++attempt) {
        const double lo = wall_gap + r, span = 1 - 2 * lo;
        const Point c{lo + span * uniform(), lo + span * uniform()};
        ok = true;
        for(const auto& pc : placed)
          if(std::hypot(c[0] - pc.first[0], c[1] - pc.first[1]) < r + pc.second + gap) {
            ok = false;
            break;
          }
        if(ok)
          placed.push_back({c, r});
      }
      if(!ok) {
        if(r <= r_min)
          throw std::runtime_error("many_holes: cannot place " + std::to_string(n) + " holes");
        r = std::max(r_min, 0.8 * r);
      }
    }
  }
  std::vector<Loop> loops{subdivided_polygon({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 0.02)};
  for(const auto& pc : placed) {
    const double r = pc.second;
    const double h = std::min(0.02, r / 3);
    const std::size_t k = std::max<std::size_t>(6, std::size_t(std::llround(2 * pi * r / h)));
    loops.push_back(circle(pc.first, r, k, false));
  }
  return polygon_with_holes(loops);
}

/// Rectangle [0,1]x[0,0.5] whose bottom side has 100 points x = i/99 with
/// y = +eps / -eps alternately (corners exact), and whose top side has a
/// nearly flat V notch (depth 1e-4 over x in [0.3, 0.7], spacing 0.02, so
/// the notch sides are sampled by collinear-in-theory points). Left and
/// right sides have spacing 0.05.
inline Poly_data nearly_collinear_boundary(double eps = 1e-9)
{
  Loop l;
  for(std::size_t i = 0; i < 99; ++i)
    l.push_back({double(i) / 99.0, i == 0 ? 0.0 : (i % 2 == 1 ? eps : -eps)});
  for(std::size_t i = 0; i < 10; ++i)
    l.push_back({1.0, 0.05 * double(i)});
  const double depth = 1e-4;
  for(std::size_t i = 0; i < 50; ++i) {
    const double x = 1.0 - 0.02 * double(i);
    const double dist = std::abs(x - 0.5);
    const double y = dist < 0.2 ? 0.5 - depth * (1.0 - dist / 0.2) : 0.5;
    l.push_back({x, y});
  }
  for(std::size_t i = 0; i < 10; ++i)
    l.push_back({0.0, 0.5 - 0.05 * double(i)});
  return polygon_with_holes({l});
}

// ---------------------------------------------------------------------------
// Adversarial geometries (robustness tests)
// ---------------------------------------------------------------------------

/// Unit square (spacing h) with a straight slit cut into it from the middle
/// of its left side to its centre: a slot of width `width` (1e-7 by
/// default, under 1e-6 of the domain), whose two long sides, spacing h,
/// face each other across the slot; the domain wraps around its tip.
inline Poly_data square_with_slit(double width = 1e-7, double h = 0.05)
{
  if(!(width > 0) || !(width < 0.1) || !(h > 0))
    throw std::invalid_argument("square_with_slit: need 0 < width < 0.1 and h > 0");
  const double y0 = 0.5 - 0.5 * width, y1 = 0.5 + 0.5 * width;
  Loop l;
  const std::size_t k = std::max<std::size_t>(1, std::size_t(std::llround(0.5 / h)));
  for(std::size_t j = 0; j < k; ++j) l.push_back({0.5 * double(j) / double(k), y1});              // slot top, inwards
  l.push_back({0.5, y1});                                                                        // the tip
  l.push_back({0.5, y0});
  for(std::size_t j = k; j-- > 1;) l.push_back({0.5 * double(j) / double(k), y0});                 // slot bottom, outwards
  const Loop lower = subdivided_polygon({{0, y0}, {0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, y1}}, h);
  // lower starts at (0, y0) and ends on the left side just below (0, y1)
  for(const Point& p : lower) l.push_back(p);
  // drop points of the subdivided left side inside the slot's mouth
  Loop out;
  for(const Point& p : l)
    if(!(p[0] == 0 && p[1] > y0 && p[1] < y1)) out.push_back(p);
  return polygon_with_holes({out});
}

/// A disk of radius 1 whose boundary spacing grows geometrically by
/// `growth` per point from h_min at angle 0 to h_min * ratio and back: the
/// spacing varies by `ratio` (1e4 by default) along one loop.
inline Poly_data graded_circle(double ratio = 1e4, double h_max = 0.4, double growth = 1.25)
{
  if(!(ratio >= 1) || !(h_max > 0) || !(growth > 1))
    throw std::invalid_argument("graded_circle: need ratio >= 1, h_max > 0, growth > 1");
  const double h_min = h_max / ratio;
  // spacing as a function of the arc length from angle 0, symmetric about pi
  std::vector<double> half{0.0};
  double h = h_min, s = 0;
  while(s + h < pi) {
    s += h;
    half.push_back(s);
    h = (std::min)(h * growth, h_max);
  }
  // close the half loop at pi with the last gap shared, then mirror it
  Loop l;
  for(double a : half) l.push_back({std::cos(a), std::sin(a)});
  l.push_back({-1.0, 0.0});
  for(std::size_t i = half.size(); i-- > 1;) l.push_back({std::cos(half[i]), -std::sin(half[i])});
  return polygon_with_holes({l});
}

/// Square [-8,8]^2 (spacing 1) holding free points that are exactly
/// cocircular in double precision (the twelve integer points of the circle
/// x^2 + y^2 = 25, and of the circles about (1, 1) and (-2, 1) scaled by
/// 1/4), plus points one unit in the last place off such circles.
inline Poly_data cocircular_points()
{
  Poly_data pd = polygon_with_holes({subdivided_polygon({{-8, -8}, {8, -8}, {8, 8}, {-8, 8}}, 1.0)});
  const int pyth[12][2] = {{5, 0}, {4, 3}, {3, 4}, {0, 5}, {-3, 4}, {-4, 3}, {-5, 0}, {-4, -3}, {-3, -4}, {0, -5}, {3, -4}, {4, -3}};
  for(const auto& q : pyth) pd.points.push_back({double(q[0]), double(q[1])});
  for(const auto& q : pyth) pd.points.push_back({1.0 + 0.25 * q[0], 1.0 + 0.25 * q[1]});
  for(const auto& q : pyth)
    pd.points.push_back({std::nextafter(-2.0 + 0.25 * q[0], 10.0), 1.0 + 0.25 * q[1]}); // one ulp off
  return pd;
}

/// A square [0,10]^2 (spacing 0.25) with one huge centred circular hole
/// (radius 3.5, 200 points) and `n` tiny holes (radius 0.01 .. 0.05, 6 to
/// 12 points) scattered around it, placed deterministically.
inline Poly_data huge_and_tiny_holes(std::size_t n = 60, unsigned seed = 7)
{
  std::mt19937 rng(seed);
  auto uniform = [&rng]() { return (double(rng()) + 0.5) / 4294967296.0; };
  std::vector<Loop> loops{subdivided_polygon({{0, 0}, {10, 0}, {10, 10}, {0, 10}}, 0.25),
                          circle({5, 5}, 3.5, 200, false)};
  std::vector<std::pair<Point, double> > placed{{{5, 5}, 3.5}};
  while(placed.size() < n + 1) {
    const double r = 0.01 + 0.04 * uniform();
    const Point c{0.2 + 9.6 * uniform(), 0.2 + 9.6 * uniform()};
    bool ok = true;
    for(const auto& pc : placed)
      if(std::hypot(c[0] - pc.first[0], c[1] - pc.first[1]) < r + pc.second + 0.05) ok = false;
    if(!ok) continue;
    placed.push_back({c, r});
    loops.push_back(circle(c, r, 6 + std::size_t(6 * uniform()), false));
  }
  return polygon_with_holes(loops);
}

/// `pd` scaled by `factor` about the origin (points and hole seeds): with a
/// power of two the coordinates are scaled exactly.
inline Poly_data scaled(const Poly_data& pd, double factor)
{
  Poly_data out(pd);
  for(auto& p : out.points) {
    p[0] *= factor;
    p[1] *= factor;
  }
  for(auto& p : out.holes) {
    p[0] *= factor;
    p[1] *= factor;
  }
  return out;
}

/// `pd` translated by (dx, dy) (points and hole seeds).
inline Poly_data offset(const Poly_data& pd, double dx, double dy)
{
  Poly_data out(pd);
  for(auto& p : out.points) {
    p[0] += dx;
    p[1] += dy;
  }
  for(auto& p : out.holes) {
    p[0] += dx;
    p[1] += dy;
  }
  return out;
}

/// What a solver tags, on a domain made for it: the rectangle [0,2]x[0,1]
/// cut by an interface at x = 1 into two regions, with a circular inclusion
/// (radius 0.2 about (1.5, 0.5)) as a third region and a square hole (side
/// 0.2 about (0.5, 0.5)) in the left one; every segment split at spacing
/// `h`. Segment markers: bottom 1, right 2, top 3, left 4, interface 5,
/// inclusion 6, hole 7; the four corners have the vertex marker 9, the
/// other points 0. Regions: left (attribute 1, area limit `left_area`),
/// right (attribute 2, no limit), inclusion (attribute 3, area limit
/// `inclusion_area`).
inline Poly_data tagged_regions(double h = 0.01, double left_area = 2e-4, double inclusion_area = 5e-5)
{
  Poly_data pd;
  auto add_point = [&pd](const Point& p, int marker) {
    pd.points.push_back(p);
    pd.point_markers.push_back(marker);
    return pd.points.size() - 1;
  };
  auto add_chain = [&pd](const std::vector<std::size_t>& ids, int marker, bool closed) {
    for(std::size_t i = 0; i + 1 < ids.size() + (closed ? 1 : 0); ++i) {
      pd.segments.push_back({ids[i], ids[(i + 1) % ids.size()]});
      pd.segment_markers.push_back(marker);
    }
  };
  // a straight side from a to b (both already added), its inner points new
  auto side = [&](std::size_t a, std::size_t b) {
    const Point pa = pd.points[a], pb = pd.points[b];
    const std::size_t k = std::max<std::size_t>(1, std::size_t(std::llround(std::hypot(pb[0] - pa[0], pb[1] - pa[1]) / h)));
    std::vector<std::size_t> ids(1, a);
    for(std::size_t j = 1; j < k; ++j) {
      const double t = double(j) / double(k);
      ids.push_back(add_point({pa[0] + t * (pb[0] - pa[0]), pa[1] + t * (pb[1] - pa[1])}, 0));
    }
    ids.push_back(b);
    return ids;
  };
  const std::size_t c00 = add_point({0, 0}, 9), c20 = add_point({2, 0}, 9), c21 = add_point({2, 1}, 9),
                    c01 = add_point({0, 1}, 9), m0 = add_point({1, 0}, 0), m1 = add_point({1, 1}, 0);
  std::vector<std::size_t> bottom = side(c00, m0), bottom2 = side(m0, c20);
  bottom.insert(bottom.end(), bottom2.begin() + 1, bottom2.end());
  add_chain(bottom, 1, false);
  add_chain(side(c20, c21), 2, false);
  std::vector<std::size_t> top = side(c21, m1), top2 = side(m1, c01);
  top.insert(top.end(), top2.begin() + 1, top2.end());
  add_chain(top, 3, false);
  add_chain(side(c01, c00), 4, false);
  add_chain(side(m0, m1), 5, false);
  std::vector<std::size_t> inclusion;
  const std::size_t n_circle = std::max<std::size_t>(3, std::size_t(std::llround(2 * pi * 0.2 / h)));
  for(const Point& p : circle({1.5, 0.5}, 0.2, n_circle)) inclusion.push_back(add_point(p, 0));
  add_chain(inclusion, 6, true);
  std::vector<std::size_t> hole;
  for(const Point& p : subdivided_polygon({{0.4, 0.4}, {0.6, 0.4}, {0.6, 0.6}, {0.4, 0.6}}, h))
    hole.push_back(add_point(p, 0));
  add_chain(hole, 7, true);
  pd.holes.push_back({0.5, 0.5});
  Poly_data::Region left, right, inside;
  left.seed = {{0.2, 0.2}};
  left.attribute = 1;
  left.max_area = left_area;
  right.seed = {{1.9, 0.1}};
  right.attribute = 2;
  right.max_area = -1;
  inside.seed = {{1.5, 0.5}};
  inside.attribute = 3;
  inside.max_area = inclusion_area;
  pd.regions = {left, right, inside};
  return pd;
}

} // namespace afm_geometry

#endif // AFM_GEOMETRIES_H
