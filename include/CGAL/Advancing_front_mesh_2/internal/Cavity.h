// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_CAVITY_H
#define CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_CAVITY_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <CGAL/Advancing_front_mesh_2/internal/Delaunay_apex.h>
#include <CGAL/Advancing_front_mesh_2/internal/Front_2.h>
#include <CGAL/Advancing_front_mesh_2/internal/Front_triangles.h>
#include <CGAL/Advancing_front_mesh_2/internal/Front_visibility.h>
#include <CGAL/Advancing_front_mesh_2/internal/Neighbourhood.h>
#include <CGAL/Advancing_front_mesh_2/internal/Point_placement.h>
#include <CGAL/Advancing_front_mesh_2/internal/Streaming_state.h>

#include <CGAL/enum.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <unordered_set>
#include <vector>

namespace CGAL {
namespace Advancing_front_mesh_2 {
namespace internal {

// Steps 7-12 of Mavriplis (1992) for a new point p ahead of a front edge:
// the triangles whose circles p breaks (7-8), the size bound raised to the
// largest of them (10), the cavity carved (9), and the Delaunay triangles
// about p built at once (11-12); or, when p is not acceptable, the cavity
// restored and the mesh left as it was.
template <class Front, class Visibility, class Triangles, class Placement, class Visitor>
class Cavity
{
public:
  typedef typename Front::Context Context;
  typedef typename Front::Vid Vid;
  typedef typename Front::Edge_key Edge_key;
  typedef typename Front::Point Point;
  typedef typename Front::Vertex_handle Vertex_handle;
  typedef typename Front::Face_handle Face_handle;
  typedef typename Context::Phase_scope Phase_scope;
  typedef internal::Neighbourhood<Front> Neighbourhood;
  typedef internal::Delaunay_apex<Front, Visibility> Apex;
  typedef Streaming_state<Context> Stream;
  static constexpr Vid no_vertex = Front::no_vertex;
  static constexpr double closure_tolerance = Placement::closure_tolerance;
  // Triangles about a new point larger than the local bound (allowed by the
  // raised bound of step 10) must have at least this radius ratio.
  static constexpr double raised_bound_min_quality = 0.25;

  Cavity(Context& ctx, Front& front, Stream& stream, Neighbourhood& neighbourhood, Apex& apex,
         Visibility& visibility, Triangles& triangles, Placement& placement, Visitor& visitor)
    : ctx_(ctx), front_(front), stream_(stream), neighbourhood_(neighbourhood), apex_(apex),
      visibility_(visibility), triangles_(triangles), placement_(placement), visitor_(visitor) {}

  bool insert_point(Vid a, Vid b, double px, double py, double d, double rho, Vid apex_before);

private:
  struct Handle_hash
  {
    template <class H>
    std::size_t operator()(const H& h) const { return std::hash<const void*>()(&*h); }
  };

  // What steps 7-8 found for a point besides the broken triangles.
  struct Broken_circles
  {
    bool reaches_finished = false;    // a finished triangle (streaming) is next to the cavity
    std::size_t finished_broken = 0;  // finished triangles whose circle holds p
  };

  Broken_circles collect_broken(const Point& p, double px, double py);
  double raised_bound(double rho, double rho_p);
  bool is_broken(Face_handle f, const Point& p, double px, double py);
  void carve();
  void restore(bool acceptable, std::size_t finished_broken);
  void connect_star(Vid a, Vid b, Vid pid, const Point& p, double px, double py, double accept,
                    double accept_raised, double star_radius, bool no_cavity, Vid apex_before);
  bool may_join_star(Vid u, Vid v, Vid w, Vid a, Vid b, double px, double py, double accept,
                     double accept_raised, double star_radius) const;

  Context& ctx_;
  Front& front_;
  Stream& stream_;
  Neighbourhood& neighbourhood_;
  Apex& apex_;
  Visibility& visibility_;
  Triangles& triangles_;
  Placement& placement_;
  Visitor& visitor_;
  // scratch space reused across steps
  std::vector<Face_handle> broken_;
  std::unordered_set<Face_handle, Handle_hash> broken_set_;
  std::vector<std::array<Vid, 3> > removed_;
  std::vector<Edge_key> cavity_edges_;
  std::vector<Edge_key> work_;
  std::vector<Edge_key> created_;
};

// Steps 6-12 for a new point p = (px, py) ahead of front edge a -> b, at
// distance d from its midpoint, rho the size bound there, `apex_before` the
// edge's apex among the old points. Returns false (leaving the mesh
// unchanged) when p is not acceptable.
template <class Front, class V, class T, class P, class Vis>
bool Cavity<Front, V, T, P, Vis>::insert_point(Vid a, Vid b, double px, double py, double d, double rho,
                                                Vid apex_before)
{
  if(!std::isfinite(px) || !std::isfinite(py)) return false;
  const Point p = ctx_.scaling.to_user_point(px, py);
  // the point as stored (scaling back may round, where a tiny domain's
  // points come near the subnormal numbers)
  px = ctx_.ix(p);
  py = ctx_.iy(p);
  if(ctx_.pred.orientation(front_.point(a), front_.point(b), p) != LEFT_TURN) return false;
  Phase_scope cavity_phase(ctx_.timer, CAVITY);
  const Broken_circles found = collect_broken(p, px, py);
  // the circle through a, b and p: the triangle p makes on the edge
  const Circle cp = circle_of(front_.x(a), front_.y(a), front_.x(b), front_.y(b), px, py);
  const double rho_new = raised_bound(rho, cp.r);
  carve();
  // Triangles about p are accepted up to the local bound, and up to the
  // raised bound of step 10 when they are not needles: a large cavity is
  // reconnected to p as the paper does (which is what lets fronts of very
  // different sizes merge, Fig. 9), but a cavity vertex nearly in line with
  // p and a short cavity edge is left to later steps instead of making a
  // sliver. Every accepted circle passes through p with radius at most
  // `accept_raised`, so the disk of twice that about p holds every point
  // that matters.
  const double accept = closure_tolerance * (std::max)(rho, cp.r);
  const double accept_raised = closure_tolerance * rho_new;
  const double star_radius = (std::max)({2 * accept_raised, length(px - front_.x(a), py - front_.y(a)),
                                         length(px - front_.x(b), py - front_.y(b))}) * (1 + 1e-9);
  // Without a cavity the front is as it was when the edge's neighbourhood
  // was gathered; if that disk holds the star's disk it serves as it is.
  const bool no_cavity = broken_.empty();
  if(!no_cavity || length(px - neighbourhood_.cx, py - neighbourhood_.cy) + star_radius > neighbourhood_.radius)
    neighbourhood_.gather(px, py, star_radius);
  // A point the run without streaming rejects is rejected here too, for the
  // same reasons, before reaching a finished triangle is held against it.
  const bool acceptable = placement_.is_acceptable_point(a, b, p, px, py, d);
  if(!acceptable || found.reaches_finished) {
    restore(acceptable, found.finished_broken);
    return false;
  }
  // p is inside the unmeshed region: insert it
  Vertex_handle vh = ctx_.tds().create_vertex();
  vh->set_point(p);
  const Vid pid = front_.activate(vh);
  // the vertices the mesher creates are removed once their last triangle
  // has gone to the sink; the input's stay (constraints refer to them)
  if(stream_.is_streaming()) stream_.live_faces.insert(&*vh, 0);
  ++ctx_.stats.points_inserted;
  visitor_.on_point_inserted(vh);
  connect_star(a, b, pid, p, px, py, accept, accept_raised, star_radius, no_cavity, apex_before);
  return true;
}

// Steps 7-8: the broken front triangles from the circle index, the
// interior ones by walking across unconstrained edges; the finished
// triangles (gone to the sink) next to the cavity, and those p breaks.
template <class Front, class V, class T, class P, class Vis>
typename Cavity<Front, V, T, P, Vis>::Broken_circles
Cavity<Front, V, T, P, Vis>::collect_broken(const Point& p, double px, double py)
{
  broken_.clear();
  broken_set_.clear();
  ++ctx_.stats.broken_circle_queries;
  {
    Phase_scope phase(ctx_.timer, CIRCLE_OCTREE);
    front_.front_triangle_circles.query(px, py, 0., [this, &p, px, py](Face_handle f) {
      Phase_scope cavity(ctx_.timer, CAVITY);
      if(broken_set_.find(f) == broken_set_.end() && is_broken(f, p, px, py)) {
        broken_set_.insert(f);
        broken_.push_back(f);
      }
    });
  }
  Broken_circles found;
  for(std::size_t i = 0; i < broken_.size(); ++i) {
    Face_handle f = broken_[i];
    for(int k = 0; k < 3; ++k) {
      Face_handle g = f->neighbor(k);
      if(stream_.is_streaming() && g == stream_.ghost) {
        if(stream_.is_finished_face_beyond(f, k, p, found.finished_broken, ctx_)) found.reaches_finished = true;
        continue;
      }
      if(f->is_constrained(k)) continue;
      if(g == Face_handle() || !g->is_in_domain() || broken_set_.count(g)) continue;
      ++ctx_.stats.incircle_tests;
      if(ctx_.pred.strictly_inside_circle(g->vertex(0)->point(), g->vertex(1)->point(), g->vertex(2)->point(), p)) {
        broken_set_.insert(g);
        broken_.push_back(g);
      }
    }
  }
  return found;
}

// Step 10: the size bound grows to the largest broken circle (rho_p: the
// radius of p's own triangle on the edge).
template <class Front, class V, class T, class P, class Vis>
double Cavity<Front, V, T, P, Vis>::raised_bound(double rho, double rho_p)
{
  double rho_new = (std::max)(rho, rho_p);
  for(Face_handle f : broken_) rho_new = (std::max)(rho_new, ctx_.circle_of(f).r);
  if(rho_new > (std::max)(rho, rho_p)) ++ctx_.stats.size_bound_raised;
  return rho_new;
}

// The circle of face f contains p and p can see f, as constrained Delaunay
// insertion requires: p is inside f, or the segment from p to a point of f
// (its centroid, or the midpoint of one of its front edges) crosses no input
// constraint. Non-constraint front edges do not hide anything: they are not
// edges of the final triangulation's constraints. Faces reached only
// through the mesh are found by the neighbour walk (Fig. 6). Without this
// test, a triangle whose circle reaches across a thin wall (a plate, a hole)
// would be removed for a point that cannot see it, opening a cavity that
// point cannot fill.
template <class Front, class V, class T, class P, class Vis>
bool Cavity<Front, V, T, P, Vis>::is_broken(Face_handle f, const Point& p, double px, double py)
{
  ++ctx_.stats.incircle_tests;
  if(!ctx_.pred.strictly_inside_circle(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point(), p))
    return false;
  // f's vertices need not be active: coordinates are read through f
  auto X = [this, &f](int i) { return ctx_.ix(f->vertex(i)->point()); };
  auto Y = [this, &f](int i) { return ctx_.iy(f->vertex(i)->point()); };
  bool inside = true;
  for(int i = 0; i < 3; ++i)
    if(ctx_.pred.orientation(f->vertex(Context::ccw(i))->point(), f->vertex(Context::cw(i))->point(), p) ==
       RIGHT_TURN)
      inside = false;
  if(inside) return true;
  if(visibility_.sees_point(p, px, py, (X(0) + X(1) + X(2)) / 3, (Y(0) + Y(1) + Y(2)) / 3)) return true;
  for(int i = 0; i < 3; ++i) {
    if(f->neighbor(i) != Face_handle()) continue;
    const int g = Context::ccw(i), h = Context::cw(i);
    if(visibility_.sees_point(p, px, py, 0.5 * (X(g) + X(h)), 0.5 * (Y(g) + Y(h)))) return true;
  }
  return false;
}

// Step 9: removes the broken triangles, remembering them to restore them if
// p is rejected; the cavity's boundary edges go to `cavity_edges_`.
template <class Front, class V, class T, class P, class Vis>
void Cavity<Front, V, T, P, Vis>::carve()
{
  removed_.clear();
  cavity_edges_.clear();
  for(Face_handle f : broken_) {
    removed_.push_back({{front_.activate(f->vertex(0)), front_.activate(f->vertex(1)), front_.activate(f->vertex(2))}});
    triangles_.remove_triangle(f, &cavity_edges_);
  }
}

// Puts the carved triangles back after p was refused.
template <class Front, class V, class T, class P, class Vis>
void Cavity<Front, V, T, P, Vis>::restore(bool acceptable, std::size_t finished_broken)
{
  for(const std::array<Vid, 3>& t : removed_) triangles_.make_triangle(t[0], t[1], t[2]);
  ctx_.stats.triangles_removed -= removed_.size();
  if(acceptable) {
    // The cavity would break a triangle already given to the sink, or leave
    // its edge on the front, where the run without streaming would put its
    // circle back in the circle index for later points to break: the sink
    // could follow neither. The point is refused, and the edge is closed on
    // an existing point instead, as for any refused point. The mesh stays a
    // constrained Delaunay triangulation; it differs from the run without
    // streaming here, which the statistics count.
    ++ctx_.stats.points_refused_for_finished_triangles;
    ctx_.stats.finished_triangles_broken += finished_broken;
  }
}

// Steps 11-12: the Delaunay triangles about p within the size bound, found
// by closing, with Merriam's iteration, the front edges that can reach p:
// the current edge, the cavity's boundary, and then each front edge at p in
// turn, which turns the fan about p in both directions. Since the
// neighbourhood was gathered only p has been added.
template <class Front, class V, class T, class P, class Vis>
void Cavity<Front, V, T, P, Vis>::connect_star(Vid a, Vid b, Vid pid, const Point& p, double px, double py,
                                                double accept, double accept_raised, double star_radius,
                                                bool no_cavity, Vid apex_before)
{
  neighbourhood_.add_vertex(pid, px, py);
  work_.clear();
  created_.clear();
  if(no_cavity && (apex_before == no_vertex ||
                   ctx_.pred.strictly_inside_circle(front_.point(a), front_.point(b), front_.point(apex_before), p))) {
    // The apex of a -> b among the old front points was apex_before and p
    // lies inside its circle: p is the apex now (it is visible from a and
    // b, is_acceptable_point checked that), no search needed.
    triangles_.make_triangle(a, b, pid, &created_);
    ++ctx_.stats.triangles_around_new_points;
    for(Edge_key e : created_) work_.push_back(e);
  } else {
    work_.push_back(Front::key(a, b));
  }
  for(Edge_key k : cavity_edges_) work_.push_back(k);
  while(!work_.empty()) {
    const Edge_key k = work_.back();
    work_.pop_back();
    if(!front_.contains(k)) continue;
    const Vid u = Front::source(k), v = Front::target(k);
    const bool at_p = (u == pid || v == pid);
    if(!at_p && ctx_.pred.orientation(front_.point(u), front_.point(v), p) != LEFT_TURN) continue;
    if(length(front_.x(u) - px, front_.y(u) - py) > star_radius ||
       length(front_.x(v) - px, front_.y(v) - py) > star_radius)
      continue;
    // apart from a -> b, triangles whose circle is larger than the raised
    // bound are not built: their apex need not be found
    const double luv2 = (front_.x(v) - front_.x(u)) * (front_.x(v) - front_.x(u)) +
                        (front_.y(v) - front_.y(u)) * (front_.y(v) - front_.y(u));
    const double max_height = (u == a && v == b) ? std::numeric_limits<double>::infinity()
                            : std::sqrt((std::max)(0., accept_raised * accept_raised - 0.25 * luv2));
    const Vid w = apex_(u, v, neighbourhood_, max_height);
    if(w == no_vertex) continue;
    if(!at_p && w != pid) continue;
    if(!may_join_star(u, v, w, a, b, px, py, accept, accept_raised, star_radius)) continue;
    created_.clear();
    triangles_.make_triangle(u, v, w, &created_);
    ++ctx_.stats.triangles_around_new_points;
    for(Edge_key e : created_)
      if(Front::source(e) == pid || Front::target(e) == pid) work_.push_back(e);
  }
}

// Is the triangle (u, v, w) about p small enough: within the star's disk,
// and within the local bound, or the raised bound when it is not a needle?
// (The current edge a -> b is closed whatever its size.)
template <class Front, class V, class T, class P, class Vis>
bool Cavity<Front, V, T, P, Vis>::may_join_star(Vid u, Vid v, Vid w, Vid a, Vid b, double px, double py,
                                                 double accept, double accept_raised, double star_radius) const
{
  double error;
  const Circle c = front_.circle_of(u, v, w, error);
  // the circle surely lies in the star's disk; written so that a circle
  // that could not be computed (NaN), or whose error has no bound, is
  // rejected
  if(!(length(c.cx - px, c.cy - py) + c.r + 2 * error <= star_radius)) return false;
  if(!(c.r <= accept) && !(u == a && v == b) &&
     (!(c.r <= accept_raised) ||
      !(radius_ratio(front_.x(u), front_.y(u), front_.x(v), front_.y(v), front_.x(w), front_.y(w)) >=
        raised_bound_min_quality)))
    return false;
  return true;
}

} // namespace internal
} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_CAVITY_H
