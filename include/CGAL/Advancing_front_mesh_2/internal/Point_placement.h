// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_POINT_PLACEMENT_H
#define CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_POINT_PLACEMENT_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <CGAL/Advancing_front_mesh_2/internal/Delaunay_apex.h>
#include <CGAL/Advancing_front_mesh_2/internal/Front_2.h>
#include <CGAL/Advancing_front_mesh_2/internal/Front_triangles.h>
#include <CGAL/Advancing_front_mesh_2/internal/Front_visibility.h>
#include <CGAL/Advancing_front_mesh_2/internal/Neighbourhood.h>
#include <CGAL/Advancing_front_mesh_2/internal/Size_bound.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace CGAL {
namespace Advancing_front_mesh_2 {
namespace internal {

// Where a front edge and its step-5 apex leave the new point: the edge's
// frame (midpoint, normal, size bound) and the distances of step 6.
struct Edge_frame
{
  double L;              // the edge's length
  double mx, my, nx, ny; // midpoint, unit normal towards the unmeshed side
  double rho;            // the size bound at the midpoint (step 3)
  double accept;         // largest circumradius accepted for a closure
  double d_target;       // the new point's ideal distance from the midpoint
  double radius;         // the disk holding every circle through the edge that matters
  double star_reach;     // the disk that also holds the new point's star
};

// Step 6 of Mavriplis (1992) and its Fig. 7: the edge is closed on its
// Delaunay apex when that triangle is small enough; otherwise a point is
// placed along the bisector, clamped below the apex's circle, and kept only
// if it is acceptable; with no room for it, the edge is closed anyway (the
// robustness fallback, a forced closure).
template <class Front, class Visibility, class Triangles, class Sizing_bound>
class Point_placement
{
public:
  typedef typename Front::Context Context;
  typedef typename Front::Vid Vid;
  typedef typename Front::Point Point;
  typedef typename Context::Phase_scope Phase_scope;
  typedef internal::Neighbourhood<Front> Neighbourhood;
  typedef internal::Delaunay_apex<Front, Visibility> Apex;
  static constexpr Vid no_vertex = Front::no_vertex;

  // A triangle on an existing point is accepted up to this factor over the
  // size bound rho; a little slack avoids placing a point next to an
  // existing one when the closing triangle is barely too large.
  static constexpr double closure_tolerance = 1.25;
  // A new point clamped closer than this fraction of the edge length is not
  // placed: the existing apex is used instead.
  static constexpr double placement_floor = 0.3;
  // A new point must keep this fraction of its distance to the edge from
  // every other front point and edge.
  static constexpr double point_clearance = 0.5;
  // A front edge much shorter than the size asks for a point far ahead of
  // it, and the triangle would be a needle of height about 2 rho on a short
  // base (a boundary divided every 1 under a size of 2500). The edge's
  // target size is therefore at most this factor times its length: the
  // triangles grow by about that factor per layer, the mesh grades from the
  // fine boundary to the coarse size, and every search of the step stays
  // within a few edge lengths instead of gathering the whole boundary.
  // Measured (factor: triangles, mean radius ratio of the square with a
  // hole, boundary spacing 0.01, at size 0.05; and of the 10,000-point
  // zigzag under size 2500, with its meshing time): none: 1,245, 0.675;
  // 10,008, 0.41, 1.98 s. 2: 1,627, 0.79; 20,316, 0.79, 0.10 s. 1.5:
  // 2,133, 0.84; 23,924, 0.80, 0.21 s. 1.3: 3,885, 0.92; 39,458, 0.89,
  // 0.18 s. Below 2 the limit starts to bind where fronts of the same size
  // meet (the uniform square at 0.01 changes at 1.3), so 2.
  static constexpr double max_growth = 2.0;
  // Where the size changes across the new layer by this fraction or more
  // (between the edge's midpoint and the new point), the new point stands
  // at the height of the equilateral triangle of the size; where it does
  // not change, at the paper's distance; in between, proportionally (see
  // target_distance()).
  static constexpr double graded_change = 0.1;

  Point_placement(Context& ctx, const Front& front, Neighbourhood& neighbourhood, Apex& apex,
                  const Visibility& visibility, Triangles& triangles, Sizing_bound& size)
    : ctx_(ctx), front_(front), neighbourhood_(neighbourhood), apex_(apex), visibility_(visibility),
      triangles_(triangles), size_(size) {}

  Edge_frame frame(Vid a, Vid b);
  double target_distance(const Edge_frame& e);
  bool close_or_clamp(Vid a, Vid b, Vid w, const Edge_frame& e, double& d);
  void close_on_existing_point(Vid a, Vid b, Vid c);
  void forced_closure(Vid a, Vid b);
  void forced_closure_in_growing_disks(Vid a, Vid b, double r);
  bool is_acceptable_point(Vid a, Vid b, const Point& p, double px, double py, double d) const;

private:
  bool hub_edge_within(Vid v, double px, double py, double min_dist) const;

  Context& ctx_;
  const Front& front_;
  Neighbourhood& neighbourhood_;
  Apex& apex_;
  const Visibility& visibility_;
  Triangles& triangles_;
  Sizing_bound& size_;
};

template <class Front, class V, class T, class S>
Edge_frame Point_placement<Front, V, T, S>::frame(Vid a, Vid b)
{
  Edge_frame e;
  const double ax = front_.x(a), ay = front_.y(a), bx = front_.x(b), by = front_.y(b);
  e.L = length(bx - ax, by - ay);
  e.mx = 0.5 * (ax + bx);
  e.my = 0.5 * (ay + by);
  e.nx = -(by - ay) / e.L;
  e.ny = (bx - ax) / e.L;
  // step 3, with the growth over one layer of triangles bounded (see
  // max_growth)
  e.rho = (std::min)(size_.target_circumradius(e.mx, e.my), max_growth * e.L / std::sqrt(3.));
  e.accept = closure_tolerance * e.rho;
  e.d_target = target_distance(e);
  // The search covers every circle through a and b that matters: those
  // small enough to accept, and those whose centre lies before d_target
  // (which limit the new point's position, Fig. 7).
  e.radius = (std::max)(2 * e.accept, e.d_target + std::sqrt(e.d_target * e.d_target + 0.25 * e.L * e.L));
  // The gathered disk is made large enough to also hold, in most steps, the
  // disk of the new point's star (see Cavity.h), which then needs no search
  // of its own: the new point lies at most d_target from m, and its star
  // reaches 2 * 1.25 * max(rho, r) from it, where the circle through a, b
  // and the point has a radius r of at most 0.57 L (at the placement floor)
  // or rho.
  e.star_reach = e.d_target + 2 * closure_tolerance * (std::max)(e.rho, 0.57 * e.L);
  return e;
}

// Step 6's ideal distance of the new point from the edge's midpoint, along
// the bisector.
//
// The paper's distance makes the triangle on the edge of circumradius rho
// (or of the edge's diametral circle when rho is smaller than half the
// edge): on an edge shorter than the size, a tall isosceles triangle whose
// new edges are longer than the size, on a longer one a flat one whose new
// edges are shorter. Where the size is uniform, the next layer corrects
// that, and the front stays in regular rows (the square with a hole: mean
// radius ratio 0.995). Where the size grows or shrinks across the layer,
// the edges are short or long for their place all the time, and the
// correction overshoots layer after layer: rows end in dislocations, whose
// fan triangles are nearly right-angled (the bad triangles of the graded
// airfoils). Rebay's and Gmsh's frontal-Delaunay methods place the point at
// the height of the equilateral triangle of the size instead, whatever the
// edge's length: the new edges come out closer to the size. That height
// alone breaks the rows of a uniform size (the square with a hole: 0.954),
// so the height is used in proportion to how much the size changes between
// the midpoint and the new point, fully from a change of `graded_change`.
// Measured (radius ratio, mean / share above 0.9, before smoothing, the
// paper's distance -> this one): the Fig. 12 field 0.942 / 78.8% -> 0.948 /
// 82.8%; 30P-30N 0.939 / 76.9% -> 0.945 / 82.5%; NLR 7301 0.943 / 77.9% ->
// 0.952 / 84.7%; the MESH2D airfoil 0.925 / 71.3% -> 0.940 / 79.7%; the
// MESH2D lake 0.957 / 89.5% -> 0.961 / 91.0%; the uniform square unchanged.
template <class Front, class V, class T, class S>
double Point_placement<Front, V, T, S>::target_distance(const Edge_frame& e)
{
  const double paper =
    (e.rho >= 0.5 * e.L) ? e.rho + std::sqrt(e.rho * e.rho - 0.25 * e.L * e.L) : 0.5 * e.L;
  // the height of the equilateral triangle of side h = sqrt(3) rho, and
  // at least half the edge (a right angle at the new point)
  const double level = (std::max)(1.5 * e.rho, 0.5 * e.L);
  const double ahead = (std::min)(size_.target_circumradius(e.mx + level * e.nx, e.my + level * e.ny),
                                  max_growth * e.L / std::sqrt(3.));
  const double change = std::abs(ahead - e.rho) / e.rho;
  // written so that a change that is not a number leaves the paper's distance
  const double w = change > 0 ? (std::min)(1., change / graded_change) : 0.;
  return (1 - w) * paper + w * level;
}

// Closes a -> b on its apex w when the triangle is small enough, or forced
// when there is no room for a point below w's circle; returns true then.
// Otherwise sets `d`, the new point's distance from the midpoint: the ideal
// one, or clamped below w's circle (Fig. 7).
template <class Front, class V, class T, class S>
bool Point_placement<Front, V, T, S>::close_or_clamp(Vid a, Vid b, Vid w, const Edge_frame& e, double& d)
{
  d = e.d_target;
  if(w == no_vertex) return false;
  double error;
  const Circle c = front_.circle_of(a, b, w, error);
  const double centre_offset = length(c.cx - e.mx, c.cy - e.my);
  // the circle surely lies in the searched disk (written so that an error
  // bound that is not finite says no)
  const bool complete = centre_offset + c.r + 2 * error <= e.radius;
  if(complete && c.r <= e.accept) { // step 6: close
    close_on_existing_point(a, b, w);
    return true;
  }
  const double h_w = (c.cx - e.mx) * e.nx + (c.cy - e.my) * e.ny; // signed height of its centre
  if(h_w < e.d_target) {
    if(!(h_w >= placement_floor * e.L)) {
      // No room for a point between the edge and the circle: close. On w
      // only if its circle lies in the searched disk (then no front point
      // outside can be in it); otherwise the closure searches on.
      ++ctx_.stats.forced_closures;
      if(complete) close_on_existing_point(a, b, w);
      else forced_closure(a, b);
      return true;
    }
    d = h_w; // upper clamp (Fig. 7)
  }
  return false;
}

template <class Front, class V, class T, class S>
void Point_placement<Front, V, T, S>::close_on_existing_point(Vid a, Vid b, Vid c)
{
  ++ctx_.stats.triangles_closed_on_existing_points;
  triangles_.make_triangle(a, b, c);
}

// Closes a -> b on its constrained Delaunay apex whatever its size. The
// unmeshed region is a polygonal region bounded by the front, so the apex
// exists.
//
// The search follows the circles through a and b: on the unmeshed side they
// are nested, a circle whose centre lies at height h over the edge holding
// there every lower one, so the gathered disk is the circle of height h
// itself. An apex found at height at most h is the true one (every
// candidate that could beat it, and every segment from a or b to one, lies
// in the disk); one found higher is checked in its own circle next; without
// one, h doubles. Circles around the edge's midpoint instead, doubled until
// they held the apex's circle, hold far more than it where the apex is far
// from a short edge: the end of a star's spoke closed on the star's centre
// gathered a third of the 4,000 spoke ends every time. After a few rounds
// h at least doubles, so that ever higher apexes still end the search soon.
// The circles never reach behind the edge, so they cannot end the search by
// holding every vertex: when an apex's height is not a number (a, b and it
// nearly in line), or h has doubled past any domain, the search ends in
// disks about the midpoint that grow until they hold everything.
template <class Front, class V, class T, class S>
void Point_placement<Front, V, T, S>::forced_closure(Vid a, Vid b)
{
  const double ax = front_.x(a), ay = front_.y(a), bx = front_.x(b), by = front_.y(b);
  const double mx = 0.5 * (ax + bx), my = 0.5 * (ay + by);
  const double L = length(bx - ax, by - ay);
  const double nx = -(by - ay) / L, ny = (bx - ax) / L; // towards the unmeshed side
  // a circle of radius 1.12 L, about as large as the disk of radius L the
  // search started with before, but ahead of the edge, where the apexes
  // whose closure is forced mostly lie
  double h = L;
  for(int round = 0; round < 64; ++round) {
    const double r = length(h, 0.5 * L) * (1 + 1e-9);
    if(!std::isfinite(r)) break;
    neighbourhood_.gather(mx + h * nx, my + h * ny, r);
    const Vid w = apex_(a, b, neighbourhood_);
    if(w != no_vertex) {
      double error;
      const Circle c = front_.circle_of(a, b, w, error);
      const double height = (c.cx - mx) * nx + (c.cy - my) * ny;
      if(!std::isfinite(height)) break;
      // surely at most h (the gathered circle's padding covers the rest)
      if(height + error <= h) {
        close_on_existing_point(a, b, w);
        return;
      }
      h = (std::max)(round < 3 ? h : 2 * h, height);
    } else {
      h *= 2;
    }
  }
  forced_closure_in_growing_disks(a, b, (std::max)(L, 2 * h));
}

// The search of forced_closure() in disks about the edge's midpoint, from
// radius r on, doubled until the apex's circle lies inside; it is
// exhaustive once the disk holds every active vertex (or its radius stopped
// being a number): the loop ends on that, not on a count.
template <class Front, class V, class T, class S>
void Point_placement<Front, V, T, S>::forced_closure_in_growing_disks(Vid a, Vid b, double r)
{
  const double mx = 0.5 * (front_.x(a) + front_.x(b)), my = 0.5 * (front_.y(a) + front_.y(b));
  for(;;) {
    neighbourhood_.gather(mx, my, r);
    const bool everything = neighbourhood_.vertices.size() >= front_.active_points.size() || !std::isfinite(r);
    const Vid w = apex_(a, b, neighbourhood_);
    if(w != no_vertex) {
      double error;
      const Circle c = front_.circle_of(a, b, w, error);
      const double needed = length(c.cx - mx, c.cy - my) + c.r + 2 * error;
      if(needed <= r || everything) {
        close_on_existing_point(a, b, w);
        return;
      }
      r = (std::max)(2 * r, needed * (1 + 1e-9));
    } else {
      if(everything) {
        throw std::logic_error("Advancing_front_mesher_2: internal error: a front edge has no "
                               "visible apex (the front is inconsistent)");
      }
      r *= 2;
    }
  }
}

// A placed point is kept only if it lies strictly inside the unmeshed
// region (seen from a and b through the region, so not across the front or
// a constraint) and not too close to any front point or edge: such a point
// would make a needle, and the closure fallback does better there.
template <class Front, class V, class T, class S>
bool Point_placement<Front, V, T, S>::is_acceptable_point(Vid a, Vid b, const Point& p, double px, double py,
                                                          double d) const
{
  Phase_scope phase(ctx_.timer, PLACEMENT);
  const Neighbourhood& n = neighbourhood_;
  const double min_dist = point_clearance * d;
  for(std::size_t i = 0; i < n.vertices.size(); ++i) {
    if(length(n.vertex_xy[i][0] - px, n.vertex_xy[i][1] - py) < min_dist) return false;
    if(front_.point(Vid(n.vertices[i])) == p) return false;
  }
  // the clearance tests first: plain arithmetic, they reject most points
  // that fail at all before the exact visibility tests run
  for(const auto& e : n.edges)
    if(segment_distance(px, py, e.x0, e.y0, e.x1, e.y1) < min_dist && n.still_on_front(e.key)) return false;
  for(typename Front::Edge_key k : n.new_edges()) {
    const Vid g = Front::source(k), h = Front::target(k);
    if(segment_distance(px, py, front_.x(g), front_.y(g), front_.x(h), front_.y(h)) < min_dist &&
       n.still_on_front(k))
      return false;
  }
  for(Vid v : n.hubs)
    if(hub_edge_within(v, px, py, min_dist)) return false;
  return visibility_.visible_from_both(a, front_.point(a), b, front_.point(b), no_vertex, p, n);
}

// Does a front edge at hub v (Front_hubs.h) come closer than min_dist to
// (px, py)? Only those whose direction from v points into the disk of that
// radius can: the cone between its two tangents from v, widened a little
// against rounding (a clearance is a choice of quality, not of validity:
// the exact tests decide that).
template <class Front, class V, class T, class S>
bool Point_placement<Front, V, T, S>::hub_edge_within(Vid v, double px, double py, double min_dist) const
{
  const double vx = front_.x(v), vy = front_.y(v);
  const double dx = px - vx, dy = py - vy, d = length(dx, dy);
  if(!(d > min_dist)) return true; // the hub itself is that close
  auto near = [&](Vid w) { return segment_distance(px, py, vx, vy, front_.x(w), front_.y(w)) < min_dist; };
  const double half = 1.01 * std::asin(min_dist / d) + 1e-9;
  if(!front_.is_hub(v) || !(half < 1.5)) { // not since the gathering, or a wide cone
    for(Vid w : front_.out[v]) if(near(w)) return true;
    for(Vid w : front_.in[v]) if(near(w)) return true;
    return false;
  }
  const double c = std::cos(half), s = std::sin(half);
  const auto direction = [&](double sign) {
    return ctx_.scaling.to_user_point(vx + c * dx - sign * s * dy, vy + sign * s * dx + c * dy);
  };
  return front_.hubs.any_in_arc(v, direction(-1), direction(1),
                                [this](Vid w) -> const Point& { return front_.point(w); }, ctx_.pred,
                                [&](const typename Front::Hubs::Spoke& k) { return near(k.other); });
}

} // namespace internal
} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_POINT_PLACEMENT_H
