// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_IO_INTERNAL_POLY_GRAPH_CHECKS_H
#define CGAL_ADVANCING_FRONT_MESH_2_IO_INTERNAL_POLY_GRAPH_CHECKS_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <CGAL/Advancing_front_mesh_2/IO/Poly_data.h>
#include <CGAL/Advancing_front_mesh_2/IO/Poly_read_error.h>
#include <CGAL/Advancing_front_mesh_2/internal/Front_predicates.h>

#include <CGAL/Bbox_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/box_intersection_d.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <map>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Advancing_front_mesh_2 {
namespace IO {

namespace internal {

// Names the items of a PSLG as its file does (ids from the file's first id,
// lines), or by 0-based index for data built in code.
class Poly_namer
{
public:
  explicit Poly_namer(const Poly_data& d) : d_(d) {}

  std::string file() const { return d_.origin.file.empty() ? std::string("PSLG") : d_.origin.file; }
  std::string point_file() const
  {
    return d_.origin.point_file.empty() ? file() : d_.origin.point_file;
  }
  std::size_t point_line(std::size_t i) const { return at(d_.origin.point_lines, i); }
  std::size_t segment_line(std::size_t i) const { return at(d_.origin.segment_lines, i); }
  std::size_t hole_line(std::size_t i) const { return at(d_.origin.hole_lines, i); }
  std::size_t region_line(std::size_t i) const { return at(d_.origin.region_lines, i); }

  std::string point(std::size_t i) const
  {
    return "vertex " + std::to_string(point_number(i)) +
           where(point_line(i), point_file() != file() ? point_file() : std::string());
  }
  // in a message about `message_file`, the line names its file if it is another
  std::string segment(std::size_t i, const std::string& message_file = std::string()) const
  {
    return "segment " + std::to_string(segment_number(i)) +
           where(segment_line(i), message_file.empty() || message_file == file() ? std::string() : file());
  }
  std::string hole(std::size_t i) const
  {
    return "hole " + std::to_string(d_.origin.first_hole_id + static_cast<long long>(i)) +
           where(hole_line(i), std::string());
  }
  // the bare id, for the subject of a message whose line is the message's
  std::string segment_id(std::size_t i) const
  {
    return "segment " + std::to_string(segment_number(i));
  }
  std::string hole_id(std::size_t i) const
  {
    return "hole " + std::to_string(d_.origin.first_hole_id + static_cast<long long>(i));
  }
  std::string region_id(std::size_t i) const
  {
    return "region " + std::to_string(d_.origin.first_region_id + static_cast<long long>(i));
  }
  std::string point_id(std::size_t i) const
  {
    return "vertex " + std::to_string(point_number(i));
  }

  // the id of an item in its file: its own when the file gives ids that are
  // not consecutive (Gmsh's tags), else the file's first id plus the index
  long long point_number(std::size_t i) const
  {
    return i < d_.origin.point_ids.size() ? d_.origin.point_ids[i]
                                          : d_.origin.first_point_id + static_cast<long long>(i);
  }
  long long segment_number(std::size_t i) const
  {
    return i < d_.origin.segment_ids.size() ? d_.origin.segment_ids[i]
                                            : d_.origin.first_segment_id + static_cast<long long>(i);
  }

private:
  static std::size_t at(const std::vector<std::size_t>& v, std::size_t i) { return i < v.size() ? v[i] : 0; }
  static std::string where(std::size_t line, const std::string& other_file)
  {
    if(line == 0) return std::string();
    return " (" + (other_file.empty() ? std::string() : other_file + " ") + "line " + std::to_string(line) + ")";
  }
  const Poly_data& d_;
};

// A problem between two segments (or a segment and a point); the one
// reported is the first in file order, i.e. the pair whose later item
// comes first.
struct Poly_problem
{
  std::size_t later = (std::numeric_limits<std::size_t>::max)(), earlier = 0;
  int kind = 0;
  bool found() const { return later != (std::numeric_limits<std::size_t>::max)(); }
  void offer(std::size_t a, std::size_t b, int k)
  {
    const std::size_t l = (std::max)(a, b), e = (std::min)(a, b);
    if(l < later || (l == later && e < earlier)) {
      later = l;
      earlier = e;
      kind = k;
    }
  }
};

enum Poly_pair_kind { POLY_CROSSING = 1, POLY_OVERLAP = 2 };

[[noreturn]] inline void poly_fail(const std::string& file, std::size_t line,
                                   const std::string& problem)
{
  throw Poly_read_error(file, line, problem);
}

// The input graph as insert_poly() inserts it, found by the checks below in
// this order: points at the same position merged, zero-length and duplicate
// segments sorted out, the points lying inside segments. Every decision is
// made with exact predicates on the input's doubles, whatever the kernel of
// the triangulation.
struct Poly_graph
{
  typedef CGAL::Exact_predicates_inexact_constructions_kernel Ek;
  typedef Ek::Point_2 Ep;
  typedef CGAL::Box_intersection_d::Box_with_info_d<double, 2, std::size_t> Box;

  Poly_graph(const Poly_data& d, const Poly_namer& n) : data(d), name(n) {}

  Ep ep(std::size_t i) const { return Ep(data.points[i][0], data.points[i][1]); }
  // the end points of segment i, as their representative points
  std::size_t seg_a(std::size_t i) const { return rep[data.segments[i][0]]; }
  std::size_t seg_b(std::size_t i) const { return rep[data.segments[i][1]]; }
  Box box_of_segment(std::size_t i) const
  {
    return Box(ep(seg_a(i)).bbox() + ep(seg_b(i)).bbox(), i);
  }

  const Poly_data& data;
  const Poly_namer& name;
  // per point, the first point at its position, which represents it
  std::vector<std::size_t> rep;
  // the segments inserted, as indices into data.segments, increasing
  std::vector<std::size_t> kept;
  // per segment of data.segments, its position in `kept` if it is kept
  std::vector<std::size_t> kept_index;
  // inside[k]: the points strictly inside kept segment k, in order along it
  std::vector<std::vector<std::size_t> > inside;
  // of the kept segments and of the representative points; the box
  // intersections reorder them
  std::vector<Box> segment_boxes, point_boxes;
  std::size_t merged_points = 0, duplicate_segments = 0, points_on_segments = 0;
};

inline void poly_check_finite(const Poly_data& data, const Poly_namer& name)
{
  for(std::size_t i = 0; i < data.points.size(); ++i)
    if(!std::isfinite(data.points[i][0]) || !std::isfinite(data.points[i][1]))
      poly_fail(name.point_file(), name.point_line(i), name.point_id(i) + " has a coordinate that is not a finite number");
  for(std::size_t i = 0; i < data.holes.size(); ++i)
    if(!std::isfinite(data.holes[i][0]) || !std::isfinite(data.holes[i][1]))
      poly_fail(name.file(), name.hole_line(i), name.hole_id(i) + " has a coordinate that is not a finite number");
  for(std::size_t i = 0; i < data.regions.size(); ++i) {
    const Poly_data::Region& r = data.regions[i];
    if(!std::isfinite(r.seed[0]) || !std::isfinite(r.seed[1]) || !std::isfinite(r.attribute) ||
       !std::isfinite(r.max_area))
      poly_fail(name.file(), name.region_line(i), name.region_id(i) + " has a value that is not a finite number");
  }
  if(!data.point_markers.empty() && data.point_markers.size() != data.points.size())
    poly_fail(name.point_file(), 0, "point_markers must be empty or hold one marker per point");
  if(!data.segment_markers.empty() && data.segment_markers.size() != data.segments.size())
    poly_fail(name.file(), 0, "segment_markers must be empty or hold one marker per segment");
}

// Points: each one represented by the first point at its position.
inline void poly_merge_points(Poly_graph& g)
{
  const Poly_data& data = g.data;
  const std::size_t n = data.points.size();
  std::vector<std::size_t> order(n);
  g.rep.assign(n, 0);
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::sort(order.begin(), order.end(), [&data](std::size_t a, std::size_t b) {
    if(data.points[a] != data.points[b]) return data.points[a] < data.points[b];
    return a < b;
  });
  for(std::size_t k = 0; k < n; ++k) {
    const std::size_t i = order[k];
    if(k > 0 && data.points[order[k - 1]] == data.points[i]) {
      g.rep[i] = g.rep[order[k - 1]];
      ++g.merged_points;
    } else {
      g.rep[i] = i;
    }
  }
}

// Segments: zero length, duplicates.
inline void poly_keep_segments(Poly_graph& g)
{
  const Poly_data& data = g.data;
  const Poly_namer& name = g.name;
  const std::vector<std::size_t>& rep = g.rep;
  const std::size_t n = data.points.size();
  std::vector<std::pair<std::array<std::size_t, 2>, std::size_t> > by_ends;
  for(std::size_t i = 0; i < data.segments.size(); ++i) {
    const std::size_t a = data.segments[i][0], b = data.segments[i][1];
    if(a >= n || b >= n)
      poly_fail(name.file(), name.segment_line(i),
                name.segment_id(i) + " refers to point index " + std::to_string((std::max)(a, b)) +
                  ", out of range (there are " + std::to_string(n) + " points)");
    if(rep[a] == rep[b])
      poly_fail(name.file(), name.segment_line(i),
                name.segment_id(i) + " has zero length: its end points " + name.point(a) + " and " +
                name.point(b) + " are at the same position");
    by_ends.push_back({{{(std::min)(rep[a], rep[b]), (std::max)(rep[a], rep[b])}}, i});
  }
  std::sort(by_ends.begin(), by_ends.end());
  for(std::size_t k = 0; k < by_ends.size(); ++k) {
    if(k > 0 && by_ends[k].first == by_ends[k - 1].first) ++g.duplicate_segments;
    else g.kept.push_back(by_ends[k].second);
  }
  std::sort(g.kept.begin(), g.kept.end());
}

// Points inside segments: the triangulation splits the segments there.
inline void poly_find_points_on_segments(Poly_graph& g)
{
  typedef Poly_graph::Box Box;
  typedef Poly_graph::Ep Ep;
  const std::size_t n = g.data.points.size();
  const Poly_graph::Ek ek;
  const auto orientation = ek.orientation_2_object();
  const auto strictly_between = ek.collinear_are_strictly_ordered_along_line_2_object();
  for(std::size_t i : g.kept) g.segment_boxes.push_back(g.box_of_segment(i));
  for(std::size_t i = 0; i < n; ++i)
    if(g.rep[i] == i) g.point_boxes.push_back(Box(g.ep(i).bbox(), i));
  g.kept_index.assign(g.data.segments.size(), 0);
  for(std::size_t k = 0; k < g.kept.size(); ++k) g.kept_index[g.kept[k]] = k;
  g.inside.assign(g.kept.size(), std::vector<std::size_t>());
  CGAL::box_intersection_d(g.point_boxes.begin(), g.point_boxes.end(), g.segment_boxes.begin(), g.segment_boxes.end(),
                           [&](const Box& p, const Box& s) {
    const std::size_t i = p.info(), j = s.info();
    const Ep pp = g.ep(i), pa = g.ep(g.seg_a(j)), pb = g.ep(g.seg_b(j));
    if(orientation(pa, pb, pp) == CGAL::COLLINEAR && strictly_between(pa, pp, pb))
      g.inside[g.kept_index[j]].push_back(i);
  });
  std::vector<char> on_segment(n, 0);
  for(std::size_t k = 0; k < g.kept.size(); ++k) {
    const Ep pa = g.ep(g.seg_a(g.kept[k]));
    std::sort(g.inside[k].begin(), g.inside[k].end(), [&](std::size_t u, std::size_t v) {
      return CGAL::compare_distance_to_point(pa, g.ep(u), g.ep(v)) == CGAL::SMALLER;
    });
    for(std::size_t i : g.inside[k]) on_segment[i] = 1;
  }
  g.points_on_segments = std::size_t(std::count(on_segment.begin(), on_segment.end(), 1));
}

// Offers to `problem` what is wrong between the kept segments i and j, whose
// boxes intersect: a crossing or an overlap.
inline void poly_offer_pair_problem(const Poly_graph& g, std::size_t i, std::size_t j,
                                    Poly_problem& problem)
{
  typedef Poly_graph::Ep Ep;
  const Poly_graph::Ek ek;
  const auto orientation = ek.orientation_2_object();
  const auto strictly_between = ek.collinear_are_strictly_ordered_along_line_2_object();
  const std::size_t a = g.seg_a(i), b = g.seg_b(i), c = g.seg_a(j), d = g.seg_b(j);
  const Ep pa = g.ep(a), pb = g.ep(b), pc = g.ep(c), pd = g.ep(d);
  if(a == c || a == d || b == c || b == d) {
    // a shared end point: they overlap if the other ends lie on the same
    // ray from it
    const std::size_t shared = (a == c || a == d) ? a : b;
    const std::size_t other_i = (shared == a) ? b : a, other_j = (shared == c) ? d : c;
    const Ep ps = g.ep(shared), po = g.ep(other_i), pq = g.ep(other_j);
    if(orientation(ps, po, pq) == CGAL::COLLINEAR && !strictly_between(po, ps, pq))
      problem.offer(i, j, POLY_OVERLAP);
    return;
  }
  const CGAL::Orientation o1 = orientation(pa, pb, pc), o2 = orientation(pa, pb, pd);
  const CGAL::Orientation o3 = orientation(pc, pd, pa), o4 = orientation(pc, pd, pb);
  if(o1 == CGAL::COLLINEAR && o2 == CGAL::COLLINEAR) {
    // on one line, distinct end points: any common point makes a piece
    if(strictly_between(pa, pc, pb) || strictly_between(pa, pd, pb) || strictly_between(pc, pa, pd) ||
       strictly_between(pc, pb, pd))
      problem.offer(i, j, POLY_OVERLAP);
    return;
  }
  if(o1 != CGAL::COLLINEAR && o2 != CGAL::COLLINEAR && o1 != o2 && o3 != CGAL::COLLINEAR &&
     o4 != CGAL::COLLINEAR && o3 != o4) {
    // a proper crossing, unless an input point sits exactly at it: then
    // both segments are split there and share that vertex
    const auto& in_i = g.inside[g.kept_index[i]];
    for(std::size_t p : g.inside[g.kept_index[j]])
      if(std::find(in_i.begin(), in_i.end(), p) != in_i.end()) return;
    problem.offer(i, j, POLY_CROSSING);
  }
  // an end point inside the other segment is a point on a segment (see
  // poly_find_points_on_segments())
}

// The overlaps among segments sharing the end point c (`at`, sorted here):
// those along the same direction from c.
inline void poly_offer_overlaps_at_point(const Poly_graph& g, std::size_t c, std::vector<std::size_t>& at,
                                         Poly_problem& problem)
{
  const Advancing_front_mesh_2::internal::Front_predicates<Poly_graph::Ek> pred;
  const Poly_graph::Ep pc = g.ep(c);
  auto other = [&](std::size_t i) { return g.ep(g.seg_a(i) == c ? g.seg_b(i) : g.seg_a(i)); };
  auto before = [&](std::size_t i, std::size_t j) { return pred.direction_before(pc, other(i), other(j)); };
  std::sort(at.begin(), at.end(), before);
  for(std::size_t k = 0; k < at.size();) {
    std::size_t end = k + 1;
    while(end < at.size() && !before(at[k], at[end])) ++end;
    for(std::size_t u = k; u < end; ++u)
      for(std::size_t v = u + 1; v < end; ++v) problem.offer(at[u], at[v], POLY_OVERLAP);
    k = end;
  }
}

// Segment pairs: crossings and overlaps, from the pairs of intersecting
// boxes. The segments at a point where many meet (a star's centre) have
// boxes that all meet there: their pairs, n^2 / 2 of them, are left out of
// the box test; two segments sharing an end point can only overlap along a
// common direction, which sorting them by direction about it finds.
inline void poly_check_segment_pairs(const Poly_graph& g)
{
  typedef Poly_graph::Box Box;
  const Poly_namer& name = g.name;
  Poly_problem pair_problem;
  {
    constexpr std::size_t hub_degree = 32, max_hubs = 16;
    std::vector<std::size_t> degree(g.data.points.size(), 0);
    for(std::size_t i : g.kept) {
      ++degree[g.seg_a(i)];
      ++degree[g.seg_b(i)];
    }
    // each segment at a hub belongs to one of its hubs
    std::map<std::size_t, std::vector<std::size_t> > hub_segments;
    std::vector<Box> others;
    for(std::size_t i : g.kept) {
      const std::size_t a = g.seg_a(i), b = g.seg_b(i);
      if(degree[a] >= hub_degree || degree[b] >= hub_degree) hub_segments[degree[a] >= hub_degree ? a : b].push_back(i);
      else others.push_back(g.box_of_segment(i));
    }
    auto offer = [&](const Box& s, const Box& t) { poly_offer_pair_problem(g, s.info(), t.info(), pair_problem); };
    if(hub_segments.empty() || hub_segments.size() > max_hubs) { // then the pairs of all boxes
      for(const auto& h : hub_segments)
        for(std::size_t i : h.second) others.push_back(g.box_of_segment(i));
      CGAL::box_self_intersection_d(others.begin(), others.end(), offer);
    } else {
      CGAL::box_self_intersection_d(others.begin(), others.end(), offer);
      std::vector<std::vector<Box> > hub_boxes;
      for(auto& h : hub_segments) {
        hub_boxes.emplace_back();
        for(std::size_t i : h.second) hub_boxes.back().push_back(g.box_of_segment(i));
        // box_intersection_d() may reorder its ranges: copies
        std::vector<Box> plain(others);
        CGAL::box_intersection_d(hub_boxes.back().begin(), hub_boxes.back().end(), plain.begin(), plain.end(), offer);
        poly_offer_overlaps_at_point(g, h.first, h.second, pair_problem);
      }
      for(std::size_t x = 0; x < hub_boxes.size(); ++x)
        for(std::size_t y = x + 1; y < hub_boxes.size(); ++y) {
          std::vector<Box> bx(hub_boxes[x]), by(hub_boxes[y]);
          CGAL::box_intersection_d(bx.begin(), bx.end(), by.begin(), by.end(), offer);
        }
    }
  }
  if(pair_problem.found()) {
    const std::size_t i = pair_problem.later, j = pair_problem.earlier;
    poly_fail(name.file(), name.segment_line(i),
              name.segment_id(i) + (pair_problem.kind == POLY_CROSSING ? " crosses " : " overlaps ") + name.segment(j) +
                (pair_problem.kind == POLY_CROSSING ? "" : " along a piece of line"));
  }
}

// Hole seeds on segments or points (rejected).
// Per seed point (hole or region), what it lies on: (1, segment) or
// (2, point), the first by index; (0, 0) when it lies off the boundary.
inline std::vector<std::pair<int, std::size_t> >
poly_seeds_on_boundary(const Poly_graph& g, const std::vector<std::array<double, 2> >& seeds)
{
  typedef Poly_graph::Box Box;
  typedef Poly_graph::Ep Ep;
  const Poly_data& data = g.data;
  const Poly_graph::Ek ek;
  const auto orientation = ek.orientation_2_object();
  const auto strictly_between = ek.collinear_are_strictly_ordered_along_line_2_object();
  std::vector<std::pair<int, std::size_t> > seed_on(seeds.size(), {0, 0});
  auto note = [&seed_on](std::size_t h, int kind, std::size_t item) {
    if(seed_on[h].first == 0 || std::make_pair(kind, item) < seed_on[h]) seed_on[h] = {kind, item};
  };
  std::vector<Box> seed_boxes;
  for(std::size_t h = 0; h < seeds.size(); ++h)
    seed_boxes.push_back(Box(Ep(seeds[h][0], seeds[h][1]).bbox(), h));
  // box_intersection_d reorders its ranges: copies keep the graph's intact
  std::vector<Box> segment_boxes = g.segment_boxes, point_boxes = g.point_boxes;
  CGAL::box_intersection_d(seed_boxes.begin(), seed_boxes.end(), segment_boxes.begin(), segment_boxes.end(),
                           [&](const Box& hb, const Box& s) {
    const std::size_t h = hb.info(), j = s.info();
    const Ep ph(seeds[h][0], seeds[h][1]), pa = g.ep(g.seg_a(j)), pb = g.ep(g.seg_b(j));
    if(orientation(pa, pb, ph) == CGAL::COLLINEAR && strictly_between(pa, ph, pb)) note(h, 1, j);
  });
  CGAL::box_intersection_d(seed_boxes.begin(), seed_boxes.end(), point_boxes.begin(), point_boxes.end(),
                           [&](const Box& hb, const Box& p) {
    const std::size_t h = hb.info(), i = p.info();
    if(seeds[h] == data.points[i]) note(h, 2, i);
  });
  return seed_on;
}

inline void poly_check_holes_off_boundary(const Poly_graph& g)
{
  const Poly_namer& name = g.name;
  const auto hole_on = poly_seeds_on_boundary(g, g.data.holes);
  for(std::size_t h = 0; h < hole_on.size(); ++h)
    if(hole_on[h].first != 0)
      poly_fail(name.file(), name.hole_line(h),
                name.hole_id(h) + " lies on " +
                  (hole_on[h].first == 1 ? name.segment(hole_on[h].second) : name.point(hole_on[h].second)) +
                  ": a hole seed must lie inside the hole, off its boundary");
}

// A region seed on the boundary would leave its region ambiguous.
inline void poly_check_regions_off_boundary(const Poly_graph& g)
{
  const Poly_namer& name = g.name;
  std::vector<std::array<double, 2> > seeds;
  for(const Poly_data::Region& r : g.data.regions) seeds.push_back(r.seed);
  const auto region_on = poly_seeds_on_boundary(g, seeds);
  for(std::size_t h = 0; h < region_on.size(); ++h)
    if(region_on[h].first != 0)
      poly_fail(name.file(), name.region_line(h),
                name.region_id(h) + " lies on " +
                  (region_on[h].first == 1 ? name.segment(region_on[h].second) : name.point(region_on[h].second)) +
                  ": a region seed must lie inside its region, off the segments that bound it");
}

} // namespace internal

} // namespace IO
} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_IO_INTERNAL_POLY_GRAPH_CHECKS_H
