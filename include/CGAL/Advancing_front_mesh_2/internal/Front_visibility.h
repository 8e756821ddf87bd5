// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_FRONT_VISIBILITY_H
#define CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_FRONT_VISIBILITY_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <CGAL/Advancing_front_mesh_2/internal/Constraint_hubs.h>
#include <CGAL/Advancing_front_mesh_2/internal/Front_2.h>
#include <CGAL/Advancing_front_mesh_2/internal/Neighbourhood.h>

#include <CGAL/assertions.h>
#include <CGAL/enum.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace CGAL {
namespace Advancing_front_mesh_2 {
namespace internal {

// Visibility through the unmeshed region: the free sectors at the front
// vertices, segments blocked by front edges or vertices (steps 5 and 6),
// and segments blocked by input constraints, which decide which broken
// triangles a new point can see (Fig. 6). Every decision is taken with the
// exact predicates; boxes in doubles only skip the far edges.
//
// `ConstraintCircleIndex` models AdvancingFrontCircleIndex_2 with pairs of
// vertex handles (an input constraint's end points) as payloads.
template <class Front, class ConstraintCircleIndex>
class Front_visibility
{
public:
  typedef typename Front::Context Context;
  typedef typename Front::Vid Vid;
  typedef typename Front::Edge_key Edge_key;
  typedef typename Front::Point Point;
  typedef typename Front::Vertex_handle Vertex_handle;
  typedef typename Context::Phase_scope Phase_scope;
  typedef internal::Neighbourhood<Front> Neighbourhood;
  typedef ConstraintCircleIndex Constraint_circle_index;
  // an input constraint, by its end vertices (which may become inactive)
  typedef std::pair<Vertex_handle, Vertex_handle> Constraint;
  static constexpr Vid no_vertex = Front::no_vertex;

  Front_visibility(Context& ctx, const Front& front) : ctx_(ctx), front_(front) {}

  bool in_free_sector(Vid v, const Point& q, Vid qid = no_vertex) const;
  bool visible_from_both(Vid s1, const Point& ps1, Vid s2, const Point& ps2, Vid t, const Point& pt,
                         const Neighbourhood& n, bool sectors_tested = false) const;
  bool sees_point(const Point& p, double px, double py, double qx, double qy);

  // The input constraints as diametral circles. They never change: the
  // static index answers the visibility questions of the circle search.
  // The constraints at a hub enter it as one circle about the hub, whose
  // payload names the hub twice (Constraint_hubs.h).
  Constraint_circle_index constraint_circles;
  Constraint_hubs<Vertex_handle, typename Context::Predicates> constraint_hubs;

private:
  bool edge_blocks(Vid g, Vid h, Vid s, const Point& ps, Vid t, const Point& pt) const;
  bool hub_blocks(Vid v, Vid s, const Point& ps, Vid t, const Point& pt) const;
  Vid closing_edge(Vid v, Vid o) const;
  Vid nearest_outgoing_clockwise(Vid v, const Point& d) const;
  Vid closing_edge_at_hub(Vid v, Vid o) const;
  Vid nearest_outgoing_clockwise_at_hub(Vid v, const Point& d) const;
  bool in_free_sector_of_any(Vid v, const Point& q, Vid qid) const;
  bool in_free_sector_of_nearest(Vid v, const Point& q, Vid qid) const;

  // A segment's bounding box in doubles, padded by more than the rounding
  // of the coordinates: most front edges and vertices of a neighbourhood are
  // far from a segment, and this test skips their exact tests.
  struct Segment_box
  {
    // exact coordinates are exact up to the rounding of the computations
    // here; CGAL promises to_double of other numbers (a lazy exact number)
    // only to a relative precision of 1e-5
    static double relative_pad_for(bool exact_coordinates) { return exact_coordinates ? 1e-14 : 1e-5; }
    double relative_pad;
    double x0, y0, x1, y1;
    double magnitude; // of the end points' coordinates

    // the end points' internal coordinates
    Segment_box(double sx, double sy, double tx, double ty, bool exact_coordinates)
      : relative_pad(relative_pad_for(exact_coordinates))
    {
      magnitude = (std::max)({std::abs(sx), std::abs(sy), std::abs(tx), std::abs(ty)});
      const double pad = relative_pad * magnitude;
      x0 = (std::min)(sx, tx) - pad; x1 = (std::max)(sx, tx) + pad;
      y0 = (std::min)(sy, ty) - pad; y1 = (std::max)(sy, ty) + pad;
    }

    // the box of the segment (or point) g-h does not meet this one
    bool apart(double gx, double gy, double hx, double hy) const
    {
      const double gpad = relative_pad * (std::max)({std::abs(gx), std::abs(gy), std::abs(hx), std::abs(hy)});
      return (std::max)(gx, hx) + gpad < x0 || (std::min)(gx, hx) - gpad > x1 ||
             (std::max)(gy, hy) + gpad < y0 || (std::min)(gy, hy) - gpad > y1;
    }
  };

  // The union of two segment boxes with a fixed pad, a cheaper first test
  // for the many far edges: whatever is apart from it is apart from both
  // boxes. (The pad of Segment_box::apart() grows with the tested edge's
  // magnitude G; for G <= 2 M, M the boxes' magnitude, it is at most the
  // 2 relative_pad M added here, and for larger G the edge lies more than
  // G - M >= G / 2 away from the boxes in some coordinate, beyond both
  // pads.)
  struct Union_box
  {
    double x0, y0, x1, y1;

    Union_box(const Segment_box& b1, const Segment_box& b2)
    {
      const double pad = 2 * (std::max)(b1.relative_pad, b2.relative_pad) * (std::max)(b1.magnitude, b2.magnitude);
      x0 = (std::min)(b1.x0, b2.x0) - pad; x1 = (std::max)(b1.x1, b2.x1) + pad;
      y0 = (std::min)(b1.y0, b2.y0) - pad; y1 = (std::max)(b1.y1, b2.y1) + pad;
    }

    bool apart(double gx, double gy, double hx, double hy) const
    {
      return (std::max)(gx, hx) < x0 || (std::min)(gx, hx) > x1 ||
             (std::max)(gy, hy) < y0 || (std::min)(gy, hy) > y1;
    }
  };

  Context& ctx_;
  const Front& front_;
};

// Is the direction from front vertex v towards q inside the unmeshed region
// at v? The unmeshed sectors at v run counter-clockwise from each outgoing
// front edge to the first incoming one. Directions strictly inside a sector
// qualify, and so do the sector's own bounding front edges when q is their
// other end point (vertex id qid): the segment is then that front edge,
// which a triangle may close.
//
// Testing every outgoing edge costs the product of the degrees, which at a
// vertex where n constraints meet made the mesher cubic in n (17.5 s for a
// star of 2,000 spokes). Only one outgoing edge can decide, though: if q
// lies in the sector of o, it lies in the sector of the outgoing edge o*
// nearest to q clockwise too (the arc from o* to q is part of the arc from
// o to q, so it holds no incoming edge either); and likewise for the
// incoming edge qid closing a sector. Above a few edges only those are
// tested, in time linear in the degree.
template <class Front, class C>
bool Front_visibility<Front, C>::in_free_sector(Vid v, const Point& q, Vid qid) const
{
  if(front_.out[v].empty()) return front_.in[v].empty();
  if(front_.out[v].size() <= 4) return in_free_sector_of_any(v, q, qid);
  const bool free = in_free_sector_of_nearest(v, q, qid);
  CGAL_assertion(front_.out[v].size() > 64 || free == in_free_sector_of_any(v, q, qid));
  return free;
}

// The first incoming front edge at v counter-clockwise from the outgoing
// one to o (directions in (0, 2 pi]; of equal ones, the first listed).
template <class Front, class C>
typename Front::Vid Front_visibility<Front, C>::closing_edge(Vid v, Vid o) const
{
  if(front_.is_hub(v)) return closing_edge_at_hub(v, o);
  const Point& pv = front_.point(v);
  Vid closing = no_vertex;
  for(Vid i : front_.in[v])
    if(closing == no_vertex || ctx_.pred.turns_before(pv, front_.point(o), front_.point(i), front_.point(closing)))
      closing = i;
  return closing;
}

// The definition: every outgoing edge's sector in turn.
template <class Front, class C>
bool Front_visibility<Front, C>::in_free_sector_of_any(Vid v, const Point& q, Vid qid) const
{
  const Point& pv = front_.point(v);
  for(Vid o : front_.out[v]) {
    const Vid closing = closing_edge(v, o);
    if(closing == no_vertex) continue;
    if(qid != no_vertex && (qid == o || qid == closing)) return true;
    if(ctx_.pred.turn_region(pv, front_.point(o), q) == 3) continue;
    if(ctx_.pred.turns_before(pv, front_.point(o), q, front_.point(closing))) return true;
  }
  return false;
}

// The outgoing edge at v nearest clockwise to direction v -> d, of those not
// in that direction (no_vertex if there is none).
template <class Front, class C>
typename Front::Vid Front_visibility<Front, C>::nearest_outgoing_clockwise(Vid v, const Point& d) const
{
  if(front_.is_hub(v)) return nearest_outgoing_clockwise_at_hub(v, d);
  const Point& pv = front_.point(v);
  Vid nearest = no_vertex;
  for(Vid o : front_.out[v]) {
    if(ctx_.pred.turn_region(pv, d, front_.point(o)) == 3) continue;
    // the largest counter-clockwise turn from d is the nearest clockwise
    if(nearest == no_vertex || ctx_.pred.turns_before(pv, d, front_.point(nearest), front_.point(o))) nearest = o;
  }
  return nearest;
}

// The same answers at a hub, from its edges sorted by direction: walking
// from the place of a direction among them, clockwise to the first
// outgoing edge, or counter-clockwise to the first incoming one. The front's
// edges alternate between outgoing and incoming around a vertex (but for
// the two sides of a constraint, which share a direction), so the walks
// are short.
template <class Front, class C>
typename Front::Vid Front_visibility<Front, C>::nearest_outgoing_clockwise_at_hub(Vid v, const Point& d) const
{
  const auto& spokes = front_.hubs.spokes(v);
  const Point& pv = front_.point(v);
  const std::size_t n = spokes.size();
  // the first spoke whose direction is not before d's
  const std::size_t at = std::size_t(std::partition_point(spokes.begin(), spokes.end(), [&](const auto& k) {
    return ctx_.pred.direction_before(pv, front_.point(k.other), d);
  }) - spokes.begin());
  for(std::size_t step = 1; step <= n; ++step) {
    const auto& k = spokes[(at + n - step) % n];
    if(k.outgoing && ctx_.pred.turn_region(pv, d, front_.point(k.other)) != 3) return k.other;
  }
  return no_vertex;
}

template <class Front, class C>
typename Front::Vid Front_visibility<Front, C>::closing_edge_at_hub(Vid v, Vid o) const
{
  const auto& spokes = front_.hubs.spokes(v);
  const Point& pv = front_.point(v);
  const Point& po = front_.point(o);
  const std::size_t n = spokes.size();
  std::size_t at = std::size_t(std::partition_point(spokes.begin(), spokes.end(), [&](const auto& k) {
    return ctx_.pred.direction_before(pv, front_.point(k.other), po);
  }) - spokes.begin());
  while(at < n && !(spokes[at].outgoing && spokes[at].other == o)) ++at;
  CGAL_assertion(at < n);
  // an incoming edge along o closes o's sector last (a turn of 2 pi)
  Vid along = no_vertex;
  for(std::size_t step = 1; step < n; ++step) {
    const auto& k = spokes[(at + step) % n];
    if(k.outgoing) continue;
    if(ctx_.pred.turn_region(pv, po, front_.point(k.other)) != 3) return k.other;
    if(along == no_vertex) along = k.other;
  }
  return along;
}

// The same answer as in_free_sector_of_any(), from the one or two outgoing
// edges that decide it.
template <class Front, class C>
bool Front_visibility<Front, C>::in_free_sector_of_nearest(Vid v, const Point& q, Vid qid) const
{
  if(front_.in[v].empty()) return false; // no sector closes
  if(qid != no_vertex) {
    const auto& out = front_.out[v];
    if(std::find(out.begin(), out.end(), qid) != out.end()) return true;
    const auto& in = front_.in[v];
    if(std::find(in.begin(), in.end(), qid) != in.end()) {
      // if qid closes some sector, it closes that of the outgoing edge
      // nearest to it clockwise (or, with all of them in its direction, of
      // any of them)
      Vid o = nearest_outgoing_clockwise(v, front_.point(qid));
      if(o == no_vertex) o = *out.begin();
      if(closing_edge(v, o) == qid) return true;
    }
  }
  const Vid o = nearest_outgoing_clockwise(v, q);
  if(o == no_vertex) return false; // q runs along every outgoing edge
  const Point& pv = front_.point(v);
  return ctx_.pred.turns_before(pv, front_.point(o), q, front_.point(closing_edge(v, o)));
}

// Does front edge (g, h) block the segment s-t (s, t given as vertex ids, or
// no_vertex for the new point), which is not a front edge and leaves its end
// points strictly inside free sectors (in_free_sector() passed)? An edge
// sharing an end point with the segment could only block it by running
// along it, and no front edge enters the inside of a free sector (around a
// vertex, the front's edges alternate between leaving and entering it, and
// a free sector runs from a leaving edge to the next entering one): such an
// edge never blocks, without a predicate.
template <class Front, class C>
bool Front_visibility<Front, C>::edge_blocks(Vid g, Vid h, Vid s, const Point& ps, Vid t, const Point& pt) const
{
  const bool gs = (g == s), gt = (g == t), hs = (h == s), ht = (h == t);
  if(gs || hs || gt || ht) {
    CGAL_assertion(((gs && ht) || (gt && hs)) ||
                   !((gs || hs) ? ctx_.pred.overlap_from_shared_end(ps, front_.point(gs ? h : g), pt)
                                : ctx_.pred.overlap_from_shared_end(pt, front_.point(gt ? h : g), ps)));
    return false;
  }
  return ctx_.pred.closed_segments_meet(ps, pt, front_.point(g), front_.point(h));
}

// Does a front edge at hub v (Front_hubs.h) block the segment s-t, as
// edge_blocks() decides? Only the edges whose direction from v lies in the
// cone that the segment spans from v can meet it: found by binary search,
// they are few where the edges of a star's centre were all scanned.
template <class Front, class C>
bool Front_visibility<Front, C>::hub_blocks(Vid v, Vid s, const Point& ps, Vid t, const Point& pt) const
{
  if(v == s || v == t) return false; // its edges share an end point with the segment
  if(!front_.is_hub(v)) {            // not since the gathering: it has few edges
    for(Vid w : front_.out[v])
      if(edge_blocks(v, w, s, ps, t, pt)) return true;
    for(Vid w : front_.in[v])
      if(edge_blocks(w, v, s, ps, t, pt)) return true;
    return false;
  }
  const Point& pv = front_.point(v);
  const Orientation o = ctx_.pred.orientation(pv, ps, pt);
  // through the segment's inside, every edge at v meets it
  if(o == COLLINEAR && ctx_.pred.collinear_on_segment(ps, pt, pv)) return true;
  // the arc from direction v->s counter-clockwise to v->t, or the reverse,
  // whichever is shorter than a half turn (one direction when collinear)
  const Point& from = o == RIGHT_TURN ? pt : ps;
  const Point& to = o == RIGHT_TURN ? ps : pt;
  return front_.hubs.any_in_arc(v, from, to, [this](Vid w) -> const Point& { return front_.point(w); }, ctx_.pred,
                                [&](const typename Front::Hubs::Spoke& k) {
    return k.outgoing ? edge_blocks(v, k.other, s, ps, t, pt) : edge_blocks(k.other, v, s, ps, t, pt);
  });
}

// Are the open segments s1-t and s2-t inside the unmeshed region: leaving
// their end points into free sectors, crossing no front edge and passing
// through no vertex? (s1, s2, t are vertex ids, or no_vertex for the new
// point.) Complete when the segments lie in the neighbourhood's disk. Both
// segments are tested in one pass over the neighbourhood: the callers
// always need both (an apex seen from a and b, a new point seen from a and
// b).
template <class Front, class C>
bool Front_visibility<Front, C>::visible_from_both(Vid s1, const Point& ps1, Vid s2, const Point& ps2, Vid t,
                                                   const Point& pt, const Neighbourhood& n,
                                                   bool sectors_tested) const
{
  Phase_scope phase(ctx_.timer, VISIBILITY);
  if(!sectors_tested) {
    if(s1 != no_vertex && !in_free_sector(s1, pt, t)) return false;
    if(t != no_vertex && !in_free_sector(t, ps1, s1)) return false;
    if(s2 != no_vertex && !in_free_sector(s2, pt, t)) return false;
    if(t != no_vertex && !in_free_sector(t, ps2, s2)) return false;
  }
  // A segment that is a front edge itself (the apex is the next vertex
  // along the front, the most common closure) crosses no front edge and
  // holds no vertex, the front being a planar straight-line graph: only its
  // end points' sectors, tested above, matter.
  const bool open1 = !front_.is_front_segment(s1, t), open2 = !front_.is_front_segment(s2, t);
  if(!open1 && !open2) return true;
  const double tx = ctx_.ix(pt), ty = ctx_.iy(pt);
  const bool exact = ctx_.exact_coordinates();
  const Segment_box box1(ctx_.ix(ps1), ctx_.iy(ps1), tx, ty, exact), box2(ctx_.ix(ps2), ctx_.iy(ps2), tx, ty, exact);
  const Union_box both(box1, box2);
  // every front edge that can block: those near the disk when it was
  // gathered, and those created since
  auto blocks = [&](Vid g, Vid h, double gx, double gy, double hx, double hy, Edge_key k) {
    if(both.apart(gx, gy, hx, hy)) return false;
    const bool near1 = open1 && !box1.apart(gx, gy, hx, hy), near2 = open2 && !box2.apart(gx, gy, hx, hy);
    if(!(near1 || near2) || !n.still_on_front(k)) return false;
    return (near1 && edge_blocks(g, h, s1, ps1, t, pt)) || (near2 && edge_blocks(g, h, s2, ps2, t, pt));
  };
  for(const auto& e : n.edges)
    if(blocks(Front::source(e.key), Front::target(e.key), e.x0, e.y0, e.x1, e.y1, e.key)) return false;
  for(Edge_key k : n.new_edges()) {
    const Vid g = Front::source(k), h = Front::target(k);
    if(blocks(g, h, front_.x(g), front_.y(g), front_.x(h), front_.y(h), k)) return false;
  }
  for(Vid v : n.hubs)
    if((open1 && hub_blocks(v, s1, ps1, t, pt)) || (open2 && hub_blocks(v, s2, ps2, t, pt))) return false;
  for(std::size_t i = 0; i < n.vertices.size(); ++i) {
    const std::size_t z = n.vertices[i];
    if(z == t) continue;
    const double zx = n.vertex_xy[i][0], zy = n.vertex_xy[i][1];
    if(both.apart(zx, zy, zx, zy)) continue;
    if(open1 && z != s1 && !box1.apart(zx, zy, zx, zy) && ctx_.pred.in_open_segment(ps1, pt, front_.point(Vid(z))))
      return false;
    if(open2 && z != s2 && !box2.apart(zx, zy, zx, zy) && ctx_.pred.in_open_segment(ps2, pt, front_.point(Vid(z))))
      return false;
  }
  return true;
}

// Does the segment from p to (qx, qy) cross no input constraint? The end
// point is rounded; this only selects which triangles are removed.
template <class Front, class C>
bool Front_visibility<Front, C>::sees_point(const Point& p, double px, double py, double qx, double qy)
{
  Phase_scope phase(ctx_.timer, VISIBILITY);
  const Point q = ctx_.scaling.to_user_point(qx, qy);
  bool blocked = false;
  ++ctx_.stats.constraint_index_queries;
  // a proper crossing only: touching an end point does not hide
  auto crosses = [&](const Point& pu, const Point& pv) {
    const Orientation o1 = ctx_.pred.orientation(p, q, pu), o2 = ctx_.pred.orientation(p, q, pv);
    if(o1 == COLLINEAR || o2 == COLLINEAR || o1 == o2) return false;
    const Orientation o3 = ctx_.pred.orientation(pu, pv, p), o4 = ctx_.pred.orientation(pu, pv, q);
    return o3 != COLLINEAR && o4 != COLLINEAR && o3 != o4;
  };
  constraint_circles.query(0.5 * (px + qx), 0.5 * (py + qy), 0.5 * length(qx - px, qy - py),
                           [&](const Constraint& c) {
    if(blocked) return;
    if(c.first != c.second) {
      blocked = crosses(c.first->point(), c.second->point());
      return;
    }
    // a hub: only a constraint in the cone that p-q spans from it can cross
    // p-q, and none can when the hub is in line with p and q
    const Point& ph = c.first->point();
    const Orientation o = ctx_.pred.orientation(ph, p, q);
    if(o == COLLINEAR) return;
    blocked = constraint_hubs.any_in_arc(c.first, o == LEFT_TURN ? p : q, o == LEFT_TURN ? q : p, ctx_.pred,
                                         [&](const Vertex_handle& w) { return crosses(ph, w->point()); });
  });
  return !blocked;
}

} // namespace internal
} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_FRONT_VISIBILITY_H
