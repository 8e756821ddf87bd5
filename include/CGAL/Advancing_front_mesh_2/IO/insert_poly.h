// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_IO_INSERT_POLY_H
#define CGAL_ADVANCING_FRONT_MESH_2_IO_INSERT_POLY_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <CGAL/Advancing_front_mesh_2/IO/Poly_data.h>
#include <CGAL/Advancing_front_mesh_2/IO/read_poly.h>

#include <CGAL/Bbox_2.h>
#include <CGAL/Delaunay_mesh_criteria_2.h>
#include <CGAL/Delaunay_mesher_2.h>
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

/*!
\ingroup PkgAdvancingFrontMesh2IO

What `insert_poly()` inserted and what it repaired on the way.
*/
template <class CDT>
struct Poly_insertion
{
  /// the vertex of each input point (points merged as duplicates share one)
  std::vector<typename CDT::Vertex_handle> vertices;
  /// the hole seeds, for `Advancing_front_mesher_2::set_seeds()`
  std::vector<typename CDT::Point> hole_seeds;
  /// points at exactly the position of an earlier point, merged into it
  std::size_t merged_points = 0;
  /// segments joining the same two points as an earlier segment, dropped
  std::size_t duplicate_segments = 0;
  /// points lying inside a segment (between its end points), where the
  /// triangulation splits the segment (also where two segments cross
  /// exactly at an input point)
  std::size_t points_on_segments = 0;
};

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

  std::string point(std::size_t i) const
  {
    return "vertex " + std::to_string(d_.origin.first_point_id + static_cast<long long>(i)) +
           where(point_line(i), point_file() != file() ? point_file() : std::string());
  }
  // in a message about `message_file`, the line names its file if it is another
  std::string segment(std::size_t i, const std::string& message_file = std::string()) const
  {
    return "segment " + std::to_string(d_.origin.first_segment_id + static_cast<long long>(i)) +
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
    return "segment " + std::to_string(d_.origin.first_segment_id + static_cast<long long>(i));
  }
  std::string hole_id(std::size_t i) const
  {
    return "hole " + std::to_string(d_.origin.first_hole_id + static_cast<long long>(i));
  }
  std::string point_id(std::size_t i) const
  {
    return "vertex " + std::to_string(d_.origin.first_point_id + static_cast<long long>(i));
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

} // namespace internal

/*!
\ingroup PkgAdvancingFrontMesh2IO

Checks the planar straight-line graph `data` and inserts it into `cdt`:
its points as vertices and its segments as constraints. Every decision is
made with exact predicates on the input's doubles, whatever the kernel of
`cdt`.

Repaired, because their meaning is plain (and counted in the result):
- points at exactly the same position as an earlier point are merged into it;
- a segment joining the same two points as an earlier one is dropped;
- a point lying inside a segment splits it there (the triangulation does
  this), also where two segments cross exactly at an input point.

Rejected, with a `Poly_read_error` naming the file, line and items of the
first problem in file order:
- a segment whose end points are at the same position (zero length);
- two segments that cross, or that overlap along a piece of line;
- a hole seed on a segment or on a point;
- a hole seed outside every closed boundary (it would remove nothing);
- a boundary left open: a point at which an odd number of segments end, none
  of which has a region to mesh beside it;
- nothing to mesh: no bounded region is left once the holes are removed;
- a segment with no region to mesh on either side (in a hole or outside):
  the trace of a boundary left open elsewhere, e.g. an open polyline whose
  ends touch two other regions.

Data read by `read_poly()` carries its file name and lines
(`Poly_data::Origin`); for data built in code the file is called `PSLG` and
items are named by their 0-based index.

\tparam CDT a `Constrained_Delaunay_triangulation_2` (or
`Constrained_triangulation_plus_2` of one) whose face type has
`is_in_domain()`/`set_in_domain()` (such as `Delaunay_mesh_face_base_2`);
its in-domain marks are set as for meshing with the hole seeds.

\pre `cdt` is empty.

\throws Poly_read_error for the problems above
*/
template <class CDT>
Poly_insertion<CDT> insert_poly(CDT& cdt, const Poly_data& data)
{
  typedef CGAL::Exact_predicates_inexact_constructions_kernel Ek;
  typedef Ek::Point_2 Ep;
  typedef typename CDT::Point Point;
  typedef typename CDT::Vertex_handle Vertex_handle;
  typedef CGAL::Box_intersection_d::Box_with_info_d<double, 2, std::size_t> Box;
  CGAL_precondition(cdt.number_of_vertices() == 0);

  const internal::Poly_namer name(data);
  const Ek ek;
  const auto orientation = ek.orientation_2_object();
  const auto strictly_between = ek.collinear_are_strictly_ordered_along_line_2_object();
  auto fail = [](const std::string& file, std::size_t line, const std::string& problem) {
    throw Poly_read_error(file, line, problem);
  };
  auto ep = [&data](std::size_t i) { return Ep(data.points[i][0], data.points[i][1]); };

  for(std::size_t i = 0; i < data.points.size(); ++i)
    if(!std::isfinite(data.points[i][0]) || !std::isfinite(data.points[i][1]))
      fail(name.point_file(), name.point_line(i), name.point_id(i) + " has a coordinate that is not a finite number");
  for(std::size_t i = 0; i < data.holes.size(); ++i)
    if(!std::isfinite(data.holes[i][0]) || !std::isfinite(data.holes[i][1]))
      fail(name.file(), name.hole_line(i), name.hole_id(i) + " has a coordinate that is not a finite number");

  Poly_insertion<CDT> result;

  // Points: each one represented by the first point at its position.
  const std::size_t n = data.points.size();
  std::vector<std::size_t> order(n), rep(n);
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::sort(order.begin(), order.end(), [&data](std::size_t a, std::size_t b) {
    if(data.points[a] != data.points[b]) return data.points[a] < data.points[b];
    return a < b;
  });
  for(std::size_t k = 0; k < n; ++k) {
    const std::size_t i = order[k];
    if(k > 0 && data.points[order[k - 1]] == data.points[i]) {
      rep[i] = rep[order[k - 1]];
      ++result.merged_points;
    } else {
      rep[i] = i;
    }
  }

  // Segments: zero length, duplicates.
  std::vector<std::size_t> kept; // indices into data.segments
  {
    std::vector<std::pair<std::array<std::size_t, 2>, std::size_t> > by_ends;
    for(std::size_t i = 0; i < data.segments.size(); ++i) {
      const std::size_t a = data.segments[i][0], b = data.segments[i][1];
      if(a >= n || b >= n)
        fail(name.file(), name.segment_line(i),
             name.segment_id(i) + " refers to point index " + std::to_string((std::max)(a, b)) +
               ", out of range (there are " + std::to_string(n) + " points)");
      if(rep[a] == rep[b])
        fail(name.file(), name.segment_line(i),
             name.segment_id(i) + " has zero length: its end points " + name.point(a) + " and " +
             name.point(b) + " are at the same position");
      by_ends.push_back({{{(std::min)(rep[a], rep[b]), (std::max)(rep[a], rep[b])}}, i});
    }
    std::sort(by_ends.begin(), by_ends.end());
    for(std::size_t k = 0; k < by_ends.size(); ++k) {
      if(k > 0 && by_ends[k].first == by_ends[k - 1].first) ++result.duplicate_segments;
      else kept.push_back(by_ends[k].second);
    }
    std::sort(kept.begin(), kept.end());
  }
  auto seg_a = [&](std::size_t i) { return rep[data.segments[i][0]]; };
  auto seg_b = [&](std::size_t i) { return rep[data.segments[i][1]]; };
  auto box_of_segment = [&](std::size_t i) {
    return Box(ep(seg_a(i)).bbox() + ep(seg_b(i)).bbox(), i);
  };

  // Points inside segments: the triangulation splits the segments there.
  // inside[k]: the points strictly inside kept segment k, in order along it.
  std::vector<Box> segment_boxes, point_boxes;
  for(std::size_t i : kept) segment_boxes.push_back(box_of_segment(i));
  for(std::size_t i = 0; i < n; ++i)
    if(rep[i] == i) point_boxes.push_back(Box(ep(i).bbox(), i));
  std::vector<std::size_t> kept_index(data.segments.size(), 0);
  for(std::size_t k = 0; k < kept.size(); ++k) kept_index[kept[k]] = k;
  std::vector<std::vector<std::size_t> > inside(kept.size());
  CGAL::box_intersection_d(point_boxes.begin(), point_boxes.end(), segment_boxes.begin(), segment_boxes.end(),
                           [&](const Box& p, const Box& s) {
    const std::size_t i = p.info(), j = s.info();
    const Ep pp = ep(i), pa = ep(seg_a(j)), pb = ep(seg_b(j));
    if(orientation(pa, pb, pp) == CGAL::COLLINEAR && strictly_between(pa, pp, pb))
      inside[kept_index[j]].push_back(i);
  });
  {
    std::vector<char> on_segment(n, 0);
    for(std::size_t k = 0; k < kept.size(); ++k) {
      const Ep pa = ep(seg_a(kept[k]));
      std::sort(inside[k].begin(), inside[k].end(), [&](std::size_t u, std::size_t v) {
        return CGAL::compare_distance_to_point(pa, ep(u), ep(v)) == CGAL::SMALLER;
      });
      for(std::size_t i : inside[k]) on_segment[i] = 1;
    }
    result.points_on_segments = std::size_t(std::count(on_segment.begin(), on_segment.end(), 1));
  }

  // Segment pairs: crossings and overlaps.
  enum { CROSSING = 1, OVERLAP = 2 };
  internal::Poly_problem pair_problem;
  {
    std::vector<Box> boxes;
    boxes.reserve(kept.size());
    for(std::size_t i : kept) boxes.push_back(box_of_segment(i));
    CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), [&](const Box& s, const Box& t) {
      const std::size_t i = s.info(), j = t.info();
      const std::size_t a = seg_a(i), b = seg_b(i), c = seg_a(j), d = seg_b(j);
      const Ep pa = ep(a), pb = ep(b), pc = ep(c), pd = ep(d);
      if(a == c || a == d || b == c || b == d) {
        // a shared end point: they overlap if the other ends lie on the same
        // ray from it
        const std::size_t shared = (a == c || a == d) ? a : b;
        const std::size_t other_i = (shared == a) ? b : a, other_j = (shared == c) ? d : c;
        const Ep ps = ep(shared), po = ep(other_i), pq = ep(other_j);
        if(orientation(ps, po, pq) == CGAL::COLLINEAR && !strictly_between(po, ps, pq))
          pair_problem.offer(i, j, OVERLAP);
        return;
      }
      const CGAL::Orientation o1 = orientation(pa, pb, pc), o2 = orientation(pa, pb, pd);
      const CGAL::Orientation o3 = orientation(pc, pd, pa), o4 = orientation(pc, pd, pb);
      if(o1 == CGAL::COLLINEAR && o2 == CGAL::COLLINEAR) {
        // on one line, distinct end points: any common point makes a piece
        if(strictly_between(pa, pc, pb) || strictly_between(pa, pd, pb) || strictly_between(pc, pa, pd) ||
           strictly_between(pc, pb, pd))
          pair_problem.offer(i, j, OVERLAP);
        return;
      }
      if(o1 != CGAL::COLLINEAR && o2 != CGAL::COLLINEAR && o1 != o2 && o3 != CGAL::COLLINEAR &&
         o4 != CGAL::COLLINEAR && o3 != o4) {
        // a proper crossing, unless an input point sits exactly at it: then
        // both segments are split there and share that vertex
        const auto& in_i = inside[kept_index[i]];
        for(std::size_t p : inside[kept_index[j]])
          if(std::find(in_i.begin(), in_i.end(), p) != in_i.end()) return;
        pair_problem.offer(i, j, CROSSING);
      }
      // an end point inside the other segment is a point on a segment (below)
    });
  }
  if(pair_problem.found()) {
    const std::size_t i = pair_problem.later, j = pair_problem.earlier;
    fail(name.file(), name.segment_line(i),
         name.segment_id(i) + (pair_problem.kind == CROSSING ? " crosses " : " overlaps ") + name.segment(j) +
           (pair_problem.kind == CROSSING ? "" : " along a piece of line"));
  }

  // Hole seeds on segments or points (rejected).
  {
    // per hole: what it lies on (1: a segment, 2: a point), the first by index
    std::vector<std::pair<int, std::size_t> > hole_on(data.holes.size(), {0, 0});
    auto note = [&hole_on](std::size_t h, int kind, std::size_t item) {
      if(hole_on[h].first == 0 || std::make_pair(kind, item) < hole_on[h]) hole_on[h] = {kind, item};
    };
    std::vector<Box> hole_boxes;
    for(std::size_t h = 0; h < data.holes.size(); ++h)
      hole_boxes.push_back(Box(Ep(data.holes[h][0], data.holes[h][1]).bbox(), h));
    CGAL::box_intersection_d(hole_boxes.begin(), hole_boxes.end(), segment_boxes.begin(), segment_boxes.end(),
                             [&](const Box& hb, const Box& s) {
      const std::size_t h = hb.info(), j = s.info();
      const Ep ph(data.holes[h][0], data.holes[h][1]), pa = ep(seg_a(j)), pb = ep(seg_b(j));
      if(orientation(pa, pb, ph) == CGAL::COLLINEAR && strictly_between(pa, ph, pb)) note(h, 1, j);
    });
    CGAL::box_intersection_d(hole_boxes.begin(), hole_boxes.end(), point_boxes.begin(), point_boxes.end(),
                             [&](const Box& hb, const Box& p) {
      const std::size_t h = hb.info(), i = p.info();
      if(data.holes[h] == data.points[i]) note(h, 2, i);
    });
    for(std::size_t h = 0; h < data.holes.size(); ++h)
      if(hole_on[h].first != 0)
        fail(name.file(), name.hole_line(h),
             name.hole_id(h) + " lies on " +
               (hole_on[h].first == 1 ? name.segment(hole_on[h].second) : name.point(hole_on[h].second)) +
               ": a hole seed must lie inside the hole, off its boundary");
  }

  // Insert. With the crossings and overlaps excluded, the triangulation only
  // splits segments at points already there.
  result.vertices.resize(n);
  for(std::size_t i = 0; i < n; ++i)
    if(rep[i] == i) result.vertices[i] = cdt.insert(Point(data.points[i][0], data.points[i][1]));
  for(std::size_t i = 0; i < n; ++i) result.vertices[i] = result.vertices[rep[i]];
  for(std::size_t i : kept) cdt.insert_constraint(result.vertices[seg_a(i)], result.vertices[seg_b(i)]);
  for(const auto& h : data.holes) result.hole_seeds.push_back(Point(h[0], h[1]));

  typedef CGAL::Delaunay_mesher_2<CDT, CGAL::Delaunay_mesh_criteria_2<CDT> > Marker;
  auto no_region = [&]() {
    fail(name.file(), 0, "nothing to mesh: no bounded region is left once the holes are removed");
  };
  if(cdt.dimension() < 2) no_region();

  // Hole seeds outside every closed boundary: without seeds, the bounded
  // regions are the domain.
  {
    const std::vector<Point> none;
    Marker::mark_facets(cdt, none.begin(), none.end());
    for(std::size_t h = 0; h < result.hole_seeds.size(); ++h) {
      const auto f = cdt.locate(result.hole_seeds[h]);
      if(cdt.is_infinite(f) || !f->is_in_domain())
        fail(name.file(), name.hole_line(h),
             name.hole_id(h) + " lies outside every closed boundary, so it would remove nothing");
    }
  }
  Marker::mark_facets(cdt, result.hole_seeds.begin(), result.hole_seeds.end());

  // Open boundaries: a point where an odd number of segments end, none of
  // them beside a region to mesh (a segment ending inside the domain is an
  // interior constraint, which is legal).
  {
    std::vector<std::size_t> degree(n, 0);
    for(std::size_t i : kept) {
      ++degree[seg_a(i)];
      ++degree[seg_b(i)];
    }
    for(std::size_t i = 0; i < n; ++i) {
      if(rep[i] != i || degree[i] % 2 == 0) continue;
      const Vertex_handle v = result.vertices[i];
      bool beside_domain = false;
      auto e = cdt.incident_edges(v), end = e;
      do {
        if(cdt.is_constrained(*e)) {
          const auto f = e->first, g = f->neighbor(e->second);
          if((!cdt.is_infinite(f) && f->is_in_domain()) || (!cdt.is_infinite(g) && g->is_in_domain()))
            beside_domain = true;
        }
      } while(++e != end && !beside_domain);
      if(!beside_domain) {
        std::size_t first_segment = 0;
        for(std::size_t j : kept)
          if(seg_a(j) == i || seg_b(j) == i) {
            first_segment = j;
            break;
          }
        fail(name.point_file(), name.point_line(i),
             "the boundary is open at " + name.point_id(i) + ": " + std::to_string(degree[i]) +
               (degree[i] == 1 ? " segment ends" : " segments end") + " there (" +
               name.segment(first_segment, name.point_file()) +
               ") and no region to mesh lies beside " + (degree[i] == 1 ? "it" : "them"));
      }
    }
  }

  bool any = false;
  for(auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end() && !any; ++f) any = f->is_in_domain();
  if(!any) no_region();

  // Every segment borders the region to mesh on at least one side, or
  // separates two regions that are not meshed (two holes, or a hole and the
  // outside: harmless, it is left in place). A segment with the same
  // unmeshed region on both sides is the trace of an open boundary whose
  // ends are not free: an open polyline from one region to another lets the
  // region it was meant to close leak away into the outside or a hole.
  // the segments with no region to mesh on either side, and their pieces
  std::vector<std::pair<std::size_t, std::vector<std::pair<typename CDT::Face_handle, int> > > > unmeshed;
  for(std::size_t k = 0; k < kept.size(); ++k) {
    const std::size_t i = kept[k];
    std::vector<std::size_t> chain(1, seg_a(i));
    chain.insert(chain.end(), inside[k].begin(), inside[k].end());
    chain.push_back(seg_b(i));
    std::vector<std::pair<typename CDT::Face_handle, int> > pieces;
    bool beside_domain = false;
    for(std::size_t t = 0; t + 1 < chain.size() && !beside_domain; ++t) {
      typename CDT::Face_handle f;
      int e = 0;
      if(!cdt.is_edge(result.vertices[chain[t]], result.vertices[chain[t + 1]], f, e)) continue;
      const typename CDT::Face_handle g = f->neighbor(e);
      beside_domain = (!cdt.is_infinite(f) && f->is_in_domain()) || (!cdt.is_infinite(g) && g->is_in_domain());
      pieces.emplace_back(f, e);
    }
    if(!beside_domain) unmeshed.emplace_back(i, std::move(pieces));
  }
  if(unmeshed.empty()) return result;
  // The regions not meshed: faces connected across edges that are not
  // constrained (the infinite faces join through the infinite vertex's
  // edges, which are never constrained, so the outside is one region).
  std::map<typename CDT::Face_handle, std::size_t> region_of;
  {
    std::size_t next_region = 0;
    std::vector<typename CDT::Face_handle> stack;
    for(auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f) {
      if((!cdt.is_infinite(f) && f->is_in_domain()) || !region_of.emplace(f, next_region).second) continue;
      const std::size_t r = next_region++;
      stack.push_back(f);
      while(!stack.empty()) {
        const typename CDT::Face_handle g = stack.back();
        stack.pop_back();
        for(int e = 0; e < 3; ++e)
          if(!cdt.is_constrained(std::make_pair(g, e)) && region_of.emplace(g->neighbor(e), r).second)
            stack.push_back(g->neighbor(e));
      }
    }
  }
  for(const auto& u : unmeshed) {
    bool separates = false;
    for(const auto& piece : u.second)
      separates = separates || region_of[piece.first] != region_of[piece.first->neighbor(piece.second)];
    if(!separates)
      fail(name.file(), name.segment_line(u.first),
           name.segment_id(u.first) + " borders no region to mesh: both of its sides are in the same hole or "
                                      "outside the domain (is a boundary meant to enclose a region open?)");
  }
  return result;
}

} // namespace IO
} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_IO_INSERT_POLY_H
