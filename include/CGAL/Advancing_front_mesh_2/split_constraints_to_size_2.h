// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_SPLIT_CONSTRAINTS_TO_SIZE_2_H
#define CGAL_ADVANCING_FRONT_MESH_2_SPLIT_CONSTRAINTS_TO_SIZE_2_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <CGAL/Advancing_front_mesh_2/internal/Segment_size_division.h>

#include <CGAL/enum.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Advancing_front_mesh_2 {

/*!
\ingroup PkgAdvancingFrontMesh2Ref

What `split_constraints_to_size_2()` did.
*/
struct Constraint_split_statistics
{
  /// constrained edges that were split
  std::size_t edges_split = 0;
  /// vertices inserted on them
  std::size_t points_inserted = 0;
  /// of those, points not exactly on their edge: the kernel rounded them
  /// (with `Epick`, where a point exactly on a sloped segment is rarely a
  /// double); see `split_constraints_to_size_2()` for how far they may lie
  std::size_t points_rounded = 0;
  /// points left out because the rounded point could not be inserted
  /// without changing the triangulation beyond the edge (see
  /// `split_constraints_to_size_2()`); their pieces stay longer
  std::size_t points_skipped = 0;
};

namespace internal {

template <class T, class = void>
struct Has_constraint_hierarchy : std::false_type {};
template <class T>
struct Has_constraint_hierarchy<T, std::void_t<typename T::Constraint_id> > : std::true_type {};

// `p`, just off the line q b on the side `side`, moved by units in the last
// place along the axis nearest the line's normal until it is on the line or
// beyond; at most 16 steps (the rounding of a cut is about one unit).
template <class Point, class Orientation_2>
Point nudged_across(const Point& p, const Point& q, const Point& b, Orientation side, const Orientation_2& orientation)
{
  const double dx = CGAL::to_double(b.x()) - CGAL::to_double(q.x());
  const double dy = CGAL::to_double(b.y()) - CGAL::to_double(q.y());
  // the normal pointing away from `side` is (dy, -dx) for a left side
  const double nx = side == LEFT_TURN ? dy : -dy, ny = side == LEFT_TURN ? -dx : dx;
  double x = CGAL::to_double(p.x()), y = CGAL::to_double(p.y());
  const double inf = std::numeric_limits<double>::infinity();
  for(int k = 0; k < 16; ++k) {
    if(std::abs(nx) >= std::abs(ny)) x = std::nextafter(x, nx > 0 ? inf : -inf);
    else y = std::nextafter(y, ny > 0 ? inf : -inf);
    const Point moved(x, y);
    if(orientation(q, b, moved) != side) return moved;
  }
  return p;
}

// A rounded cut must stay clear of every other constraint by more than its
// rounding, or no one could tell from the coordinates which segment it is
// on (two input segments can run within a unit in the last place of each
// other). The margin: 64 units in the last place of the largest coordinate
// of the points involved, four times what the tests' checker allows a cut
// to lie off its segment. Distances in doubles, scaled to stay finite.
constexpr double rounded_cut_clearance_ulps = 64;

template <class Point>
bool clear_of_segment(const Point& p, const Point& q, const Point& r, double scale)
{
  const double px = CGAL::to_double(p.x()), py = CGAL::to_double(p.y());
  const double qx = CGAL::to_double(q.x()), qy = CGAL::to_double(q.y());
  const double rx = CGAL::to_double(r.x()), ry = CGAL::to_double(r.y());
  for(double c : {px, py, qx, qy, rx, ry}) scale = (std::max)(scale, std::abs(c));
  if(!(scale > 0) || !std::isfinite(scale)) return false;
  // in units of `scale`, where every coordinate is at most 1
  const double ux = (rx - qx) / scale, uy = (ry - qy) / scale;
  const double wx = (px - qx) / scale, wy = (py - qy) / scale;
  const double len2 = ux * ux + uy * uy;
  double t = len2 > 0 ? (wx * ux + wy * uy) / len2 : 0;
  t = (std::min)(1.0, (std::max)(0.0, t));
  const double ex = wx - t * ux, ey = wy - t * uy;
  const double margin = rounded_cut_clearance_ulps * std::numeric_limits<double>::epsilon();
  return ex * ex + ey * ey > margin * margin;
}

// After a point rounded off an edge went into it, the edges at the point
// may not be Delaunay (on an edge they always are; just beside it, on the
// far side from an apex, not): Lawson flips from them, as CGAL's
// triangulation does after a constraint is removed.
template <class CDT>
void restore_delaunay_at(CDT& cdt, typename CDT::Vertex_handle v)
{
  typename CDT::List_edges edges;
  auto f = cdt.incident_faces(v), done = f;
  do {
    edges.push_back(typename CDT::Edge(f, CDT::cw(f->index(v))));
  } while(++f != done);
  cdt.propagating_flip(edges);
}

// Whether a constrained edge, other than the edge (`from`, `to`) being cut,
// lies within the clearance of `p`: a walk over the faces from `start`
// (the faces p lies in or on) across the unconstrained edges within that
// distance of p, which are the only ones a segment from p to such a
// constraint can cross.
template <class CDT>
bool constraint_near(const CDT& cdt, const typename CDT::Point& p, std::vector<typename CDT::Face_handle> start,
                     typename CDT::Vertex_handle from, typename CDT::Vertex_handle to, double scale)
{
  typedef typename CDT::Face_handle Face_handle;
  std::vector<Face_handle> seen(start);
  while(!start.empty()) {
    const Face_handle f = start.back();
    start.pop_back();
    if(cdt.is_infinite(f)) continue;
    for(int i = 0; i < 3; ++i) {
      const typename CDT::Vertex_handle a = f->vertex(CDT::ccw(i)), b = f->vertex(CDT::cw(i));
      if((a == from && b == to) || (a == to && b == from)) continue;
      if(clear_of_segment(p, a->point(), b->point(), scale)) continue;
      if(f->is_constrained(i)) return true;
      const Face_handle g = f->neighbor(i);
      if(std::find(seen.begin(), seen.end(), g) == seen.end()) {
        seen.push_back(g);
        start.push_back(g);
      }
    }
  }
  return false;
}

// The last resort for a cut rounded off its edge where it fits neither
// into the edge nor beside it in the two faces there (outside a hull edge,
// or where a face at the edge is thinner than the rounding): the constraint
// is removed, the point inserted, and the two edges from it to the ends
// made constraints, if the triangulation has them (nothing lies between the
// point and the edge); else the point is removed and the constraint put
// back, and the cut is left out. Not for Constrained_triangulation_plus_2,
// whose constraint hierarchy would lose the constraint: there the cut is
// left out.
template <class CDT>
typename CDT::Vertex_handle split_by_reinsertion(CDT&, typename CDT::Vertex_handle, typename CDT::Vertex_handle,
                                                 const typename CDT::Point&, double, std::true_type)
{
  return typename CDT::Vertex_handle();
}

template <class CDT>
typename CDT::Vertex_handle split_by_reinsertion(CDT& cdt, typename CDT::Vertex_handle from,
                                                 typename CDT::Vertex_handle to, const typename CDT::Point& p,
                                                 double scale, std::false_type)
{
  typedef typename CDT::Face_handle Face_handle;
  typedef typename CDT::Vertex_handle Vertex_handle;
  Face_handle f;
  int i;
  if(!cdt.is_edge(from, to, f, i)) return Vertex_handle();
  cdt.remove_constrained_edge(f, i);
  typename CDT::Locate_type lt;
  int li;
  const Face_handle loc = cdt.locate(p, lt, li, from->face());
  // on a vertex, or on another constraint: put the constraint back
  if(lt == CDT::VERTEX || (lt == CDT::EDGE && loc->is_constrained(li))) {
    cdt.insert_constraint(from, to);
    return Vertex_handle();
  }
  std::vector<Face_handle> around(1, loc);
  if(lt == CDT::EDGE) around.push_back(loc->neighbor(li));
  if(constraint_near(cdt, p, around, Vertex_handle(), Vertex_handle(), scale)) {
    cdt.insert_constraint(from, to);
    return Vertex_handle();
  }
  const Vertex_handle v = cdt.insert(p, lt, loc, li);
  Face_handle fe;
  int ie;
  if(cdt.is_edge(from, v, fe, ie) && cdt.is_edge(v, to, fe, ie)) {
    cdt.insert_constraint(from, v);
    cdt.insert_constraint(v, to);
    return v;
  }
  cdt.remove(v);
  cdt.insert_constraint(from, to);
  return Vertex_handle();
}

// Inserts the cut `p` into the constrained edge (f, i) from `from` to `to`
// (`side`: where p lies from the line); returns the new vertex, or no
// vertex when p does not fit there. On the edge, the triangulation splits
// the constraint. Rounded off it: into the edge when the four new triangles
// keep their orientation (p lies inside the two faces at the edge, so
// nothing else changes), then Lawson flips; else not.
template <class CDT>
typename CDT::Vertex_handle insert_cut(CDT& cdt, typename CDT::Face_handle f, int i,
                                       typename CDT::Vertex_handle from, typename CDT::Vertex_handle to,
                                       const typename CDT::Point& p, Orientation side, double scale)
{
  typedef typename CDT::Vertex_handle Vertex_handle;
  const auto orientation = cdt.geom_traits().orientation_2_object();
  if(side == COLLINEAR) {
    if(!CGAL::collinear_are_strictly_ordered_along_line(from->point(), p, to->point())) return Vertex_handle();
    return cdt.insert(p, CDT::EDGE, f, i);
  }
  const typename CDT::Face_handle g = f->neighbor(i);
  // on the hull the point would dent it or leave it
  if(cdt.is_infinite(f) || cdt.is_infinite(g)) return Vertex_handle();
  const typename CDT::Point& u = f->vertex(CDT::ccw(i))->point();
  const typename CDT::Point& w = f->vertex(CDT::cw(i))->point();
  const typename CDT::Point& c = f->vertex(i)->point();
  const typename CDT::Point& d = g->vertex(g->index(f))->point();
  if(orientation(u, p, c) != LEFT_TURN || orientation(p, w, c) != LEFT_TURN || orientation(w, p, d) != LEFT_TURN ||
     orientation(p, u, d) != LEFT_TURN)
    return Vertex_handle();
  if(constraint_near(cdt, p, {f, g}, from, to, scale)) return Vertex_handle();
  const Vertex_handle v = cdt.insert(p, CDT::EDGE, f, i);
  restore_delaunay_at(cdt, v);
  return v;
}

// Splits the constrained edge (from, to) of `cdt` at `cuts` (parameters
// along it, increasing); reports each split to `on_split`.
template <class CDT, class OnSplit>
void split_constrained_edge(CDT& cdt, typename CDT::Vertex_handle from, typename CDT::Vertex_handle to,
                            const std::vector<double>& cuts, OnSplit& on_split, Constraint_split_statistics& st)
{
  typedef typename CDT::Point Point;
  typedef typename CDT::Face_handle Face_handle;
  typedef typename CDT::Vertex_handle Vertex_handle;
  const auto orientation = cdt.geom_traits().orientation_2_object();
  const Point a = from->point(), b = to->point();
  const double ax = CGAL::to_double(a.x()), ay = CGAL::to_double(a.y());
  const double bx = CGAL::to_double(b.x()), by = CGAL::to_double(b.y());
  // the scale of a cut's rounding, for its clearance
  const double scale = (std::max)((std::max)(std::abs(ax), std::abs(ay)), (std::max)(std::abs(bx), std::abs(by)));
  Vertex_handle prev = from;
  bool split_any = false;
  for(double t : cuts) {
    // in doubles with every kernel: the mesher needs coordinates that are
    // doubles (its certified searches, its checkpoints)
    const Point p(ax + t * (bx - ax), ay + t * (by - ay));
    // the rest of the edge, from the last cut to its end
    Face_handle f;
    int i;
    if(!cdt.is_edge(prev, to, f, i)) break;
    const Point& q = prev->point();
    const Orientation side = orientation(q, b, p);
    Vertex_handle v = insert_cut(cdt, f, i, prev, to, p, side, scale);
    if(v == Vertex_handle() && side != COLLINEAR) {
      // Rounded to a side where it does not fit (into a face thinner than
      // the rounding, or into the hull): moved across the edge by a few
      // units in the last place, onto it or just beyond.
      const Point moved = nudged_across(p, q, b, side, orientation);
      // on the hull, the point moved out of it makes no sliver behind it
      // (asked before the faces at the edge may change)
      const bool on_hull = cdt.is_infinite(f) || cdt.is_infinite(f->neighbor(i));
      v = insert_cut(cdt, f, i, prev, to, moved, orientation(q, b, moved), scale);
      if(v == Vertex_handle())
        v = split_by_reinsertion(cdt, prev, to, on_hull ? moved : p, scale,
                                 std::integral_constant<bool, Has_constraint_hierarchy<CDT>::value>());
    }
    if(v == Vertex_handle()) {
      ++st.points_skipped;
      continue;
    }
    if(orientation(q, b, v->point()) != COLLINEAR) ++st.points_rounded;
    ++st.points_inserted;
    split_any = true;
    on_split(prev, to, v);
    prev = v;
  }
  if(split_any) ++st.edges_split;
}

struct No_split_callback
{
  template <class V>
  void operator()(V, V, V) const {}
};

struct Every_constrained_edge
{
  template <class Edge>
  bool operator()(const Edge&) const { return true; }
};

} // namespace internal

/*!
\ingroup PkgAdvancingFrontMesh2Ref

The edge filter of `split_constraints_to_size_2()` that the mesher uses:
the constrained edges with a face of the domain (Mesh_2's in-domain mark)
on at least one side, the ones that bound or cross the domain.
*/
template <class CDT>
struct Constraint_touches_domain
{
  const CDT* cdt;
  bool operator()(const typename CDT::Edge& e) const
  {
    const typename CDT::Face_handle f = e.first, g = f->neighbor(e.second);
    return (!cdt->is_infinite(f) && f->is_in_domain()) || (!cdt->is_infinite(g) && g->is_in_domain());
  }
};

/*!
\ingroup PkgAdvancingFrontMesh2Ref

The boundary discretisation (the "1D mesh" of Triangle, Mesh_2, Gmsh and
JIGSAW): splits the constrained edges of `cdt` that are longer than the
local size into pieces that follow the sizing field, keeping every vertex.
Along an edge of length L the number of target lengths that fit is
N = integral of ds / h(s); the edge gets round(N) pieces (at least one),
cut where that integral reaches equal shares of N, so pieces are graded as
the field is (and within its gradation limit) and hold under 1.25 local
sizes each. Edges shorter than 1.5 h stay whole.

The cut points are made in double precision with every kernel, because the
mesher needs vertex coordinates that are doubles (its certified searches and
its checkpoints; with exact kernels, cut points exactly on a sloped edge are
rarely doubles). A cut point exactly on its edge (axis-parallel and
diagonal edges, or by chance) splits the constraint there, and the
triangulation stays a constrained Delaunay triangulation of the split
constraints. Otherwise the point is rounded off the edge
(`points_rounded` counts them). Such a point goes into
the edge, which becomes a chain of two constrained edges bent by the
rounding, when the four triangles it makes keep their orientation, and
Lawson flips restore the Delaunay property at it. Where the faces at the
edge are thinner than the rounding (an input vertex nearly on the edge's
line) or the edge is on the convex hull, the point is first moved across
the edge by units in the last place; failing that (plain constrained
triangulations only) the constraint is removed, the point inserted, and the
two edges from it made constraints. A cut point thus lies within a few
units in the last place of the edge's largest coordinate from the edge:
the checker of the tests accepts a mesh vertex as lying on an input
segment within 16 such units. A rounded point must also keep clear of
every other edge around it by 64 such units, so that no one can take it
for a point of another constraint (two input segments may run within a
unit in the last place of each other). A point that fits nowhere (another
vertex or constraint within that distance, or, for a
`Constrained_triangulation_plus_2`, a rounded point on the convex hull,
whose constraint hierarchy would lose the edge) is left out
(`points_skipped`) and that piece stays longer; the constraint may have
been taken out and put back, so the faces around it may be new ones (and,
where points are cocircular, differently triangulated). In the tests' 300
random domains with `Epick`, 9,736 cut points were inserted, 8,913 of them
rounded, none left out.

The faces the splits make are new faces of the triangulation, and so may
be the faces at a cut left out: Mesh_2's in-domain marks are not kept, so
mark the domain again (`Delaunay_mesher_2::mark_facets()`) after every
call whose marks are needed before meshing, whether or not points were
inserted (the mesher marks it itself).

Each split of the edge `(a, b)` at the new vertex `v` is reported as
`on_split(a, b, v)` (`Markers_and_regions_2::split_constraint()` carries a
marker over), edges in turn and cuts from `a` to `b`.

\tparam CDT a constrained Delaunay triangulation (or
  `Constrained_triangulation_plus_2` of one)
\tparam SizingField a model of `AdvancingFrontSizingField_2`
\param edge_filter which constrained edges to split: called with each
  constrained edge (a `CDT::Edge`) before any is split
\throws std::invalid_argument if the sizing field returns a value that is
  not a positive finite number (the triangulation is then valid, split up
  to that edge)
*/
template <class CDT, class SizingField, class EdgeFilter, class OnSplit>
Constraint_split_statistics split_constraints_to_size_2(CDT& cdt, const SizingField& sizing, EdgeFilter edge_filter,
                                                        OnSplit on_split)
{
  typedef typename CDT::Vertex_handle Vertex_handle;
  typedef typename CDT::Point Point;
  Constraint_split_statistics st;
  if(cdt.dimension() < 1) return st;
  std::vector<std::pair<Vertex_handle, Vertex_handle> > edges;
  for(const auto& e : cdt.constrained_edges())
    if(edge_filter(e)) edges.emplace_back(e.first->vertex(CDT::ccw(e.second)), e.first->vertex(CDT::cw(e.second)));
  for(const auto& e : edges) {
    const double ax = CGAL::to_double(e.first->point().x()), ay = CGAL::to_double(e.first->point().y());
    const double bx = CGAL::to_double(e.second->point().x()), by = CGAL::to_double(e.second->point().y());
    const double length = std::hypot(bx - ax, by - ay); // no overflow near 1e+300
    const std::vector<double> cuts = internal::segment_cut_parameters(length, [&](double t) {
      return CGAL::to_double(sizing(Point(ax + t * (bx - ax), ay + t * (by - ay))));
    });
    if(!cuts.empty()) internal::split_constrained_edge(cdt, e.first, e.second, cuts, on_split, st);
  }
  return st;
}

/*!
\ingroup PkgAdvancingFrontMesh2Ref
Same as above for every constrained edge, with no report of the splits.
*/
template <class CDT, class SizingField>
Constraint_split_statistics split_constraints_to_size_2(CDT& cdt, const SizingField& sizing)
{
  return split_constraints_to_size_2(cdt, sizing, internal::Every_constrained_edge(), internal::No_split_callback());
}

} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_SPLIT_CONSTRAINTS_TO_SIZE_2_H
