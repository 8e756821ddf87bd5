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
#include <CGAL/Advancing_front_mesh_2/IO/internal/Poly_graph_checks.h>

#include <CGAL/Delaunay_mesh_criteria_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/property_map.h>
#include <CGAL/spatial_sort.h>
#include <CGAL/Spatial_sort_traits_adapter_2.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <map>
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
  /// one edge of the triangulation made of an input segment: its end
  /// points and the segment's index in `Poly_data::segments`
  struct Segment_piece
  {
    typename CDT::Vertex_handle a, b;
    std::size_t segment;
  };
  /// the edges the kept segments became, split at the points inside them
  std::vector<Segment_piece> segment_pieces;
};

namespace internal {

// The checks that need the graph in the triangulation, in the order
// insert_poly() makes them.

// Three of the points (by index into data.points), roughly the triangle of
// largest area among them: the left- and rightmost point, and the one
// farthest from the line through them (in doubles: only an order).
inline std::array<std::size_t, 3> poly_spanning_triangle(const Poly_data& data, const std::vector<std::size_t>& ids)
{
  CGAL_precondition(!ids.empty());
  auto x = [&](std::size_t i) { return data.points[i][0]; };
  auto y = [&](std::size_t i) { return data.points[i][1]; };
  std::size_t lo = ids.front(), hi = ids.front();
  for(std::size_t i : ids) {
    if(x(i) < x(lo) || (x(i) == x(lo) && y(i) < y(lo))) lo = i;
    if(x(i) > x(hi) || (x(i) == x(hi) && y(i) > y(hi))) hi = i;
  }
  std::size_t far = lo;
  double best = -1;
  for(std::size_t i : ids) {
    const double area = std::abs((x(hi) - x(lo)) * (y(i) - y(lo)) - (y(hi) - y(lo)) * (x(i) - x(lo)));
    if(area > best) {
      best = area;
      far = i;
    }
  }
  return {{lo, hi, far}};
}

// The points `order` (indices into `points`, each once) inserted into `cdt`,
// their vertices stored in `vertices`. They go in in spatial (Hilbert)
// order, each located from the one before: in file order, a boundary's long
// collinear chains cost one flip per point already on the chain, quadratic
// in all (a 1000 x 0.001 strip with 12,500 points per side took 3.3 s,
// against 0.03 s sorted). A triangle spanning the input goes in first:
// while the triangulation is one-dimensional, every insertion walks the
// whole line (100,000 collinear points and three corners took 6.4 s).
template <class CDT>
void poly_insert_points(CDT& cdt, const Poly_data& data, const std::vector<typename CDT::Point>& points,
                        std::vector<std::size_t> order, std::vector<typename CDT::Vertex_handle>& vertices)
{
  typedef typename CGAL::Pointer_property_map<typename CDT::Point>::const_type Point_map;
  typedef CGAL::Spatial_sort_traits_adapter_2<typename CDT::Geom_traits, Point_map> Sort_traits;
  if(order.empty()) return;
  const std::array<std::size_t, 3> spanning = poly_spanning_triangle(data, order);
  CGAL::spatial_sort(order.begin(), order.end(), Sort_traits(CGAL::make_property_map(points)));
  for(std::size_t i : spanning) vertices[i] = cdt.insert(points[i]);
  typename CDT::Face_handle hint = vertices[spanning[0]]->face();
  for(std::size_t i : order) {
    if(i == spanning[0] || i == spanning[1] || i == spanning[2]) continue;
    vertices[i] = cdt.insert(points[i], hint);
    hint = vertices[i]->face();
  }
}

// Per point, the number of kept segments and pieces of them (between the
// points inside a segment) it ends.
inline std::vector<std::size_t> poly_segment_degrees(const Poly_graph& g, std::size_t n)
{
  std::vector<std::size_t> degree(n, 0);
  for(std::size_t k = 0; k < g.kept.size(); ++k) {
    ++degree[g.seg_a(g.kept[k])];
    ++degree[g.seg_b(g.kept[k])];
    for(std::size_t p : g.inside[k]) degree[p] += 2;
  }
  return degree;
}

template <class CDT>
void poly_insert(CDT& cdt, const Poly_graph& g, Poly_insertion<CDT>& result)
{
  typedef typename CDT::Point Point;
  const Poly_data& data = g.data;
  const std::size_t n = data.points.size();
  std::vector<Point> points;
  std::vector<std::size_t> order; // the points not merged into an earlier one
  points.reserve(n);
  for(std::size_t i = 0; i < n; ++i) {
    points.push_back(Point(data.points[i][0], data.points[i][1]));
    if(g.rep[i] == i) order.push_back(i);
  }
  result.vertices.resize(n);
  poly_insert_points(cdt, data, points, std::move(order), result.vertices);
  for(std::size_t i = 0; i < n; ++i) result.vertices[i] = result.vertices[g.rep[i]];
  // With the crossings and overlaps excluded, the triangulation only splits
  // segments at points already there.
  // CGAL looks for the constraint among the edges of its first end point:
  // that of fewer segments goes first, or the centre of a star of n
  // segments is searched n times (n^2 steps).
  const std::vector<std::size_t> degree = poly_segment_degrees(g, n);
  for(std::size_t k = 0; k < g.kept.size(); ++k) {
    const std::size_t i = g.kept[k], a = g.seg_a(i), b = g.seg_b(i);
    if(degree[a] <= degree[b]) cdt.insert_constraint(result.vertices[a], result.vertices[b]);
    else cdt.insert_constraint(result.vertices[b], result.vertices[a]);
    std::size_t from = a;
    for(std::size_t p : g.inside[k]) {
      result.segment_pieces.push_back({result.vertices[from], result.vertices[p], i});
      from = p;
    }
    result.segment_pieces.push_back({result.vertices[from], result.vertices[b], i});
  }
  for(const auto& h : data.holes) result.hole_seeds.push_back(Point(h[0], h[1]));
}

[[noreturn]] inline void poly_nothing_to_mesh(const Poly_namer& name)
{
  poly_fail(name.file(), 0, "nothing to mesh: no bounded region is left once the holes are removed");
}

// Hole seeds outside every closed boundary: without seeds, the bounded
// regions are the domain.
template <class CDT>
void poly_check_seeds_enclosed(CDT& cdt, const Poly_namer& name,
                               const std::vector<typename CDT::Point>& hole_seeds)
{
  typedef CGAL::Delaunay_mesher_2<CDT, CGAL::Delaunay_mesh_criteria_2<CDT> > Marker;
  const std::vector<typename CDT::Point> none;
  Marker::mark_facets(cdt, none.begin(), none.end());
  for(std::size_t h = 0; h < hole_seeds.size(); ++h) {
    const auto f = cdt.locate(hole_seeds[h]);
    if(cdt.is_infinite(f) || !f->is_in_domain())
      poly_fail(name.file(), name.hole_line(h),
                name.hole_id(h) + " lies outside every closed boundary, so it would remove nothing");
  }
}

// Region seeds in a hole or outside the domain would tag nothing: a region
// meant for a part of the domain that the seed missed.
template <class CDT>
void poly_check_regions_in_domain(const CDT& cdt, const Poly_data& data, const Poly_namer& name)
{
  for(std::size_t r = 0; r < data.regions.size(); ++r) {
    const auto f = cdt.locate(typename CDT::Point(data.regions[r].seed[0], data.regions[r].seed[1]));
    if(cdt.is_infinite(f) || !f->is_in_domain())
      poly_fail(name.file(), name.region_line(r),
                name.region_id(r) + " lies outside the domain to mesh (in a hole or outside every closed "
                                    "boundary), so it would tag nothing");
  }
}

// Whether a constrained edge at `v` has a region to mesh on one of its sides.
template <class CDT>
bool poly_constraint_beside_domain(const CDT& cdt, typename CDT::Vertex_handle v)
{
  bool beside_domain = false;
  auto e = cdt.incident_edges(v), end = e;
  do {
    if(cdt.is_constrained(*e)) {
      const auto f = e->first, g = f->neighbor(e->second);
      if((!cdt.is_infinite(f) && f->is_in_domain()) || (!cdt.is_infinite(g) && g->is_in_domain()))
        beside_domain = true;
    }
  } while(++e != end && !beside_domain);
  return beside_domain;
}

// Open boundaries: a point where an odd number of segments end, none of
// them beside a region to mesh (a segment ending inside the domain is an
// interior constraint, which is legal).
template <class CDT>
void poly_check_closed_boundaries(const CDT& cdt, const Poly_graph& g,
                                  const Poly_insertion<CDT>& result)
{
  const Poly_namer& name = g.name;
  const std::size_t n = g.data.points.size();
  std::vector<std::size_t> degree(n, 0);
  for(std::size_t i : g.kept) {
    ++degree[g.seg_a(i)];
    ++degree[g.seg_b(i)];
  }
  for(std::size_t i = 0; i < n; ++i) {
    if(g.rep[i] != i || degree[i] % 2 == 0) continue;
    if(poly_constraint_beside_domain(cdt, result.vertices[i])) continue;
    std::size_t first_segment = 0;
    for(std::size_t j : g.kept)
      if(g.seg_a(j) == i || g.seg_b(j) == i) {
        first_segment = j;
        break;
      }
    poly_fail(name.point_file(), name.point_line(i),
              "the boundary is open at " + name.point_id(i) + ": " + std::to_string(degree[i]) +
                (degree[i] == 1 ? " segment ends" : " segments end") + " there (" +
                name.segment(first_segment, name.point_file()) +
                ") and no region to mesh lies beside " + (degree[i] == 1 ? "it" : "them"));
  }
}

template <class CDT>
bool poly_has_region_to_mesh(const CDT& cdt)
{
  bool any = false;
  for(auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end() && !any; ++f) any = f->is_in_domain();
  return any;
}

// The kept segments with no region to mesh on either side, each with the
// pieces the triangulation split it into, as edges.
template <class CDT>
std::vector<std::pair<std::size_t, std::vector<std::pair<typename CDT::Face_handle, int> > > >
poly_unmeshed_segments(const CDT& cdt, const Poly_graph& g, const Poly_insertion<CDT>& result)
{
  std::vector<std::pair<std::size_t, std::vector<std::pair<typename CDT::Face_handle, int> > > > unmeshed;
  // is_edge() searches the edges of its first vertex: that of fewer segments
  const std::vector<std::size_t> degree = poly_segment_degrees(g, result.vertices.size());
  for(std::size_t k = 0; k < g.kept.size(); ++k) {
    const std::size_t i = g.kept[k];
    std::vector<std::size_t> chain(1, g.seg_a(i));
    chain.insert(chain.end(), g.inside[k].begin(), g.inside[k].end());
    chain.push_back(g.seg_b(i));
    std::vector<std::pair<typename CDT::Face_handle, int> > pieces;
    bool beside_domain = false;
    for(std::size_t t = 0; t + 1 < chain.size() && !beside_domain; ++t) {
      typename CDT::Face_handle f;
      int e = 0;
      const bool forward = degree[chain[t]] <= degree[chain[t + 1]];
      if(!cdt.is_edge(result.vertices[chain[forward ? t : t + 1]], result.vertices[chain[forward ? t + 1 : t]], f, e))
        continue;
      const typename CDT::Face_handle h = f->neighbor(e);
      beside_domain = (!cdt.is_infinite(f) && f->is_in_domain()) || (!cdt.is_infinite(h) && h->is_in_domain());
      pieces.emplace_back(f, e);
    }
    if(!beside_domain) unmeshed.emplace_back(i, std::move(pieces));
  }
  return unmeshed;
}

// The regions not meshed: faces connected across edges that are not
// constrained (the infinite faces join through the infinite vertex's
// edges, which are never constrained, so the outside is one region).
template <class CDT>
std::map<typename CDT::Face_handle, std::size_t> poly_unmeshed_regions(const CDT& cdt)
{
  std::map<typename CDT::Face_handle, std::size_t> region_of;
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
  return region_of;
}

// Every segment borders the region to mesh on at least one side, or
// separates two regions that are not meshed (two holes, or a hole and the
// outside: harmless, it is left in place). A segment with the same
// unmeshed region on both sides is the trace of an open boundary whose
// ends are not free: an open polyline from one region to another lets the
// region it was meant to close leak away into the outside or a hole.
template <class CDT>
void poly_check_segments_border_domain(const CDT& cdt, const Poly_graph& g,
                                       const Poly_insertion<CDT>& result)
{
  const Poly_namer& name = g.name;
  const auto unmeshed = poly_unmeshed_segments(cdt, g, result);
  if(unmeshed.empty()) return;
  std::map<typename CDT::Face_handle, std::size_t> region_of = poly_unmeshed_regions(cdt);
  for(const auto& u : unmeshed) {
    bool separates = false;
    for(const auto& piece : u.second)
      separates = separates || region_of[piece.first] != region_of[piece.first->neighbor(piece.second)];
    if(!separates)
      poly_fail(name.file(), name.segment_line(u.first),
                name.segment_id(u.first) + " borders no region to mesh: both of its sides are in the same hole or "
                                           "outside the domain (is a boundary meant to enclose a region open?)");
  }
}

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
- a region seed on a segment or on a point, or outside the domain (in a
  hole or outside every closed boundary);
- markers given for some points or segments but not all;
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
  typedef CGAL::Delaunay_mesher_2<CDT, CGAL::Delaunay_mesh_criteria_2<CDT> > Marker;
  CGAL_precondition(cdt.number_of_vertices() == 0);

  const internal::Poly_namer name(data);
  internal::poly_check_finite(data, name);

  // The graph alone, checked before anything is inserted.
  internal::Poly_graph g(data, name);
  internal::poly_merge_points(g);
  internal::poly_keep_segments(g);
  internal::poly_find_points_on_segments(g);
  internal::poly_check_segment_pairs(g);
  internal::poly_check_holes_off_boundary(g);
  internal::poly_check_regions_off_boundary(g);

  Poly_insertion<CDT> result;
  result.merged_points = g.merged_points;
  result.duplicate_segments = g.duplicate_segments;
  result.points_on_segments = g.points_on_segments;
  internal::poly_insert(cdt, g, result);

  // The graph in the triangulation: its regions and what bounds them.
  if(cdt.dimension() < 2) internal::poly_nothing_to_mesh(name);
  internal::poly_check_seeds_enclosed(cdt, name, result.hole_seeds);
  Marker::mark_facets(cdt, result.hole_seeds.begin(), result.hole_seeds.end());
  internal::poly_check_closed_boundaries(cdt, g, result);
  if(!internal::poly_has_region_to_mesh(cdt)) internal::poly_nothing_to_mesh(name);
  internal::poly_check_segments_border_domain(cdt, g, result);
  internal::poly_check_regions_in_domain(cdt, data, name);
  return result;
}

} // namespace IO
} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_IO_INSERT_POLY_H
