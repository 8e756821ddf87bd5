// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_STAR_SMOOTHER_H
#define CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_STAR_SMOOTHER_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <CGAL/Advancing_front_mesh_2/Smoothing_statistics.h>
#include <CGAL/Advancing_front_mesh_2/internal/Double_geometry.h>
#include <CGAL/Advancing_front_mesh_2/internal/Lawson_flips.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/assertions.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/enum.h>
#include <CGAL/number_utils.h>
#include <CGAL/property_map.h>
#include <CGAL/use.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Advancing_front_mesh_2 {
namespace internal {

// Squared sine of the smallest angle, as Mesh_2's criteria measure shape:
// the smallest angle faces the shortest edge, sin = 2 area / (b c) with b, c
// the two longer edges.
// Computed on lengths divided by the longest edge, against under- and overflow.
inline double squared_sine_of_smallest_angle(double ax, double ay, double bx, double by, double cx, double cy)
{
  const double longest = (std::max)({std::hypot(bx - cx, by - cy), std::hypot(cx - ax, cy - ay),
                                     std::hypot(ax - bx, ay - by)});
  if(!(longest > 0) || !std::isfinite(longest)) return 0;
  const double ux = (bx - ax) / longest, uy = (by - ay) / longest, vx = (cx - ax) / longest, vy = (cy - ay) / longest;
  const double wx = vx - ux, wy = vy - uy;
  double l[3] = {wx * wx + wy * wy, vx * vx + vy * vy, ux * ux + uy * uy};
  std::sort(l, l + 3);
  const double area2 = ux * vy - uy * vx;
  if(!(area2 > 0)) return 0;
  const double q = area2 * area2 / (l[1] * l[2]);
  return std::isfinite(q) ? q : 0.;
}

// The shape of the triangles about a vertex: the worst radius ratio, the
// worst smallest angle (as a squared sine) and the sum of the radius ratios.
struct Star_quality
{
  double worst_ratio = 1;
  double worst_sine2 = 1;
  double ratio_sum = 0;

  void account(double ax, double ay, double bx, double by, double cx, double cy)
  {
    const double r = radius_ratio(ax, ay, bx, by, cx, cy);
    worst_ratio = (std::min)(worst_ratio, r);
    worst_sine2 = (std::min)(worst_sine2, squared_sine_of_smallest_angle(ax, ay, bx, by, cx, cy));
    ratio_sum += r;
  }
};

// The engine of the guarded smoothers (laplacian_smooth_mesh_2(),
// quality_smooth_mesh_2()): moves of the interior vertices, one at a time,
// each followed by Lawson's flips about the vertex, undone with the move
// when the star is not acceptable; a final Lawson pass closes each pass.
// `Held` is a readable map from vertex handles to bool: vertices mapped to
// true never move.
//
// `Moves` proposes the positions and judges them:
// - `candidates(x, y, ring, out)`: positions (doubles) for the vertex at
//   (x, y) whose neighbours, counter-clockwise, are `ring`;
// - `acceptable(after, before)`: may a star of quality `after` replace one
//   of quality `before`? (the guard: it must never let the worst get worse);
// - `best_first`: try the acceptable candidates from the best star (the
//   largest sum of radius ratios) down, among those that `improves(after,
//   before)`; or, when false, in the order proposed.
template <class CDT, class Held, class Moves>
class Star_smoother
{
public:
  typedef typename CDT::Vertex_handle Vertex_handle;
  typedef typename CDT::Face_handle Face_handle;
  typedef typename CDT::Face_circulator Face_circulator;
  typedef typename CDT::Vertex_circulator Vertex_circulator;
  typedef typename CDT::Geom_traits::FT FT;
  typedef typename CDT::Point Point;
  typedef std::array<double, 2> XY;

  Star_smoother(CDT& cdt, const Held& held, const Moves& moves = Moves()) : cdt_(cdt), held_(held), moves_(moves)
  {
    find_movable_vertices();
  }

  // Only `candidates` may move (those of them the rules allow), and the
  // safety net after each pass flips about them only: a pass costs their
  // number, not the mesh's (the seams of a decomposed mesh).
  Star_smoother(CDT& cdt, const Held& held, const std::vector<Vertex_handle>& candidates,
                const Moves& moves = Moves())
    : cdt_(cdt), held_(held), moves_(moves), local_(true)
  {
    for(Vertex_handle v : candidates)
      if(is_movable(v)) movable_.push_back(v);
    stats_.movable_vertices = movable_.size();
  }

  void pass();
  const Smoothing_statistics& statistics() const { return stats_; }

private:
  void find_movable_vertices();
  bool is_movable(Vertex_handle v) const;
  std::size_t restore_about_movable();
  bool try_move(Vertex_handle v);
  bool try_in_order(Vertex_handle v, const Star_quality& before);
  bool try_best_first(Vertex_handle v, const Star_quality& before);
  bool try_position(Vertex_handle v, const Point& candidate, const Star_quality& after, const Star_quality& before);
  Star_quality star_quality(const Point& p, bool& valid) const;
  std::size_t flip_about(Vertex_handle v);
  void undo_flips(std::size_t made);
  Star_quality worst_of_changed_faces(Vertex_handle v) const;

  CDT& cdt_;
  Held held_;
  Moves moves_;
  Smoothing_statistics stats_;
  std::vector<Vertex_handle> movable_;
  std::vector<Point> ring_; // the neighbours of the vertex being moved, counter-clockwise
  std::vector<XY> ring_xy_, candidates_;
  std::vector<std::pair<Star_quality, Point> > acceptable_;
  // The flips after a move, recorded to undo them: the two faces of each,
  // whose triangles changed, and the new diagonal, by its end points (a
  // flip and its undoing may leave the two triangles in each other's face
  // records, so later undoings cannot go by face handles).
  std::vector<std::pair<Face_handle, Face_handle> > flipped_;
  std::vector<std::pair<Vertex_handle, Vertex_handle> > diagonals_;
  std::vector<typename CDT::Edge> to_check_;
  std::size_t pass_flips_ = 0;
  bool local_ = false;
};

// A vertex may move when it is interior (all faces about it finite and in
// the domain), on no constrained edge and not held.
template <class CDT, class Held, class Moves>
bool Star_smoother<CDT, Held, Moves>::is_movable(Vertex_handle v) const
{
  if(get(held_, v) || cdt_.are_there_incident_constraints(v)) return false;
  Face_circulator fc = cdt_.incident_faces(v), done = fc;
  if(fc == nullptr) return false;
  do {
    if(cdt_.is_infinite(fc) || !fc->is_in_domain()) return false;
  } while(++fc != done);
  return true;
}

template <class CDT, class Held, class Moves>
void Star_smoother<CDT, Held, Moves>::find_movable_vertices()
{
  for(auto v = cdt_.finite_vertices_begin(); v != cdt_.finite_vertices_end(); ++v)
    if(is_movable(v)) movable_.push_back(v);
  stats_.movable_vertices = movable_.size();
}

// The safety net of a local smoother: Lawson's flips from the edges of the
// movable vertices' stars.
template <class CDT, class Held, class Moves>
std::size_t Star_smoother<CDT, Held, Moves>::restore_about_movable()
{
  std::vector<typename CDT::Edge> stack;
  std::size_t flips = 0;
  for(Vertex_handle v : movable_) {
    Face_circulator fc = cdt_.incident_faces(v), done = fc;
    if(fc == nullptr) continue;
    do {
      for(int k = 0; k < 3; ++k) stack.emplace_back(fc, k);
    } while(++fc != done);
    flips += lawson_flips(cdt_, stack, [](Face_handle, Face_handle) {});
  }
  return flips;
}

template <class CDT, class Held, class Moves>
void Star_smoother<CDT, Held, Moves>::pass()
{
  for(Vertex_handle v : movable_)
    if(try_move(v)) ++stats_.moves;
  // nothing is expected to need a flip here: kept as a safety net
  const std::size_t flips = pass_flips_ + (local_ ? restore_about_movable() : restore_constrained_delaunay(cdt_));
  pass_flips_ = 0;
  stats_.flips += flips;
  stats_.flips_per_pass.push_back(flips);
  ++stats_.passes;
}

// Tries v at the candidate positions; a move stands if the star stays
// positively oriented and is acceptable against the star before, flips
// included.
template <class CDT, class Held, class Moves>
bool Star_smoother<CDT, Held, Moves>::try_move(Vertex_handle v)
{
  ring_.clear();
  ring_xy_.clear();
  Vertex_circulator vc = cdt_.incident_vertices(v), done = vc;
  do {
    ring_.push_back(vc->point());
    ring_xy_.push_back({{CGAL::to_double(vc->point().x()), CGAL::to_double(vc->point().y())}});
  } while(++vc != done);
  const Point old = v->point();
  // The new positions are computed in double: with exact number types a
  // position built from positions built from ... would grow without bound
  // over the passes (the guard's orientation test stays exact).
  candidates_.clear();
  moves_.candidates(CGAL::to_double(old.x()), CGAL::to_double(old.y()), ring_xy_, candidates_);
  bool valid = false;
  const Star_quality before = star_quality(old, valid);
  if constexpr(Moves::best_first) return try_best_first(v, before);
  else return try_in_order(v, before);
}

template <class CDT, class Held, class Moves>
bool Star_smoother<CDT, Held, Moves>::try_in_order(Vertex_handle v, const Star_quality& before)
{
  bool valid = false;
  for(const XY& c : candidates_) {
    const Point candidate = Point(FT(c[0]), FT(c[1]));
    const Star_quality after = star_quality(candidate, valid);
    if(valid && moves_.acceptable(after, before) && try_position(v, candidate, after, before)) return true;
    ++stats_.rejected_moves;
  }
  return false;
}

template <class CDT, class Held, class Moves>
bool Star_smoother<CDT, Held, Moves>::try_best_first(Vertex_handle v, const Star_quality& before)
{
  bool valid = false;
  acceptable_.clear();
  for(const XY& c : candidates_) {
    const Point candidate = Point(FT(c[0]), FT(c[1]));
    const Star_quality after = star_quality(candidate, valid);
    if(valid && moves_.acceptable(after, before) && moves_.improves(after, before))
      acceptable_.emplace_back(after, candidate);
    else
      ++stats_.rejected_moves;
  }
  std::stable_sort(acceptable_.begin(), acceptable_.end(),
                   [](const auto& p, const auto& q) { return p.first.ratio_sum > q.first.ratio_sum; });
  for(const auto& a : acceptable_) {
    if(try_position(v, a.second, a.first, before)) return true;
    ++stats_.rejected_moves;
  }
  return false;
}

// Moves v to `candidate`, whose star is `after`, and flips about it. The
// move may call for flips, and Lawson's flips keep the smallest angle from
// decreasing but not the radius ratio: the flips are made now, and the move
// is undone (flips included) if what they made is not acceptable.
template <class CDT, class Held, class Moves>
bool Star_smoother<CDT, Held, Moves>::try_position(Vertex_handle v, const Point& candidate,
                                                   const Star_quality& after, const Star_quality& before)
{
  const Point old = v->point();
  v->set_point(candidate);
  const std::size_t made = flip_about(v);
  // without flips the star was judged already (and the face order could
  // change the last bit of a ratio)
  const Star_quality changed = made == 0 ? after : worst_of_changed_faces(v);
  if(moves_.acceptable(changed, before)) {
    pass_flips_ += made;
    return true;
  }
  undo_flips(made);
  v->set_point(old);
  return false;
}

// The quality of the star of the vertex placed at p; `valid` is false if a
// triangle would not be positively oriented.
template <class CDT, class Held, class Moves>
Star_quality Star_smoother<CDT, Held, Moves>::star_quality(const Point& p, bool& valid) const
{
  const auto orientation = cdt_.geom_traits().orientation_2_object();
  // each consecutive pair of the ring and p form one triangle of the star
  Star_quality q;
  valid = true;
  const double px = CGAL::to_double(p.x()), py = CGAL::to_double(p.y());
  for(std::size_t k = 0; k < ring_.size(); ++k) {
    const std::size_t l = (k + 1) % ring_.size();
    if(orientation(p, ring_[k], ring_[l]) != CGAL::LEFT_TURN) {
      valid = false;
      return q;
    }
    q.account(px, py, ring_xy_[k][0], ring_xy_[k][1], ring_xy_[l][0], ring_xy_[l][1]);
  }
  return q;
}

// Lawson's flips after the move of v: the edges of its star and of the
// star's ring first, then those of each flipped pair; recorded.
template <class CDT, class Held, class Moves>
std::size_t Star_smoother<CDT, Held, Moves>::flip_about(Vertex_handle v)
{
  flipped_.clear();
  diagonals_.clear();
  to_check_.clear();
  Face_circulator fc = cdt_.incident_faces(v), done = fc;
  do {
    for(int k = 0; k < 3; ++k) to_check_.emplace_back(fc, k);
  } while(++fc != done);
  return lawson_flips(cdt_, to_check_, [&](Face_handle f, Face_handle g) {
    flipped_.emplace_back(f, g);
    const int j = f->index(g);
    diagonals_.emplace_back(f->vertex(CDT::ccw(j)), f->vertex(CDT::cw(j)));
  });
}

template <class CDT, class Held, class Moves>
void Star_smoother<CDT, Held, Moves>::undo_flips(std::size_t made)
{
  for(std::size_t k = made; k-- > 0;) {
    // flipping the new diagonal back
    Face_handle f;
    int i = 0;
    const bool found = cdt_.is_edge(diagonals_[k].first, diagonals_[k].second, f, i);
    CGAL_assertion(found);
    CGAL_USE(found);
    cdt_.flip(f, i);
  }
}

// The quality of the faces about v and of the faces the flips changed
// (some of which may have left v's star); only the worst measures count.
template <class CDT, class Held, class Moves>
Star_quality Star_smoother<CDT, Held, Moves>::worst_of_changed_faces(Vertex_handle v) const
{
  Star_quality worst;
  auto face = [&worst](Face_handle f) {
    double x[3], y[3];
    for(int k = 0; k < 3; ++k) {
      x[k] = CGAL::to_double(f->vertex(k)->point().x());
      y[k] = CGAL::to_double(f->vertex(k)->point().y());
    }
    worst.account(x[0], y[0], x[1], y[1], x[2], y[2]);
  };
  Face_circulator fc = cdt_.incident_faces(v), done = fc;
  do face(fc); while(++fc != done);
  for(const auto& fg : flipped_) {
    face(fg.first);
    face(fg.second);
  }
  return worst;
}

// The named parameters of the public smoothers (number_of_iterations,
// vertex_is_constrained_map), unpacked, and the passes run.
template <class Moves, class CDT, class NamedParameters>
Smoothing_statistics smooth_with(CDT& cdt, const NamedParameters& np)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  typedef typename CDT::Vertex_handle Vertex_handle;
  const std::size_t passes = choose_parameter(get_parameter(np, internal_np::number_of_iterations), std::size_t(5));
  auto held = choose_parameter(get_parameter(np, internal_np::vertex_is_constrained),
                               Constant_property_map<Vertex_handle, bool>(false));
  Star_smoother<CDT, decltype(held), Moves> smoother(cdt, held);
  for(std::size_t pass = 0; pass < passes; ++pass) smoother.pass();
  return smoother.statistics();
}

// The same for `candidates` only (nothing else moves), at a cost of their
// number per pass.
template <class Moves, class CDT>
Smoothing_statistics smooth_vertices_with(CDT& cdt, const std::vector<typename CDT::Vertex_handle>& candidates,
                                          std::size_t passes)
{
  typedef typename CDT::Vertex_handle Vertex_handle;
  const Constant_property_map<Vertex_handle, bool> held(false);
  Star_smoother<CDT, Constant_property_map<Vertex_handle, bool>, Moves> smoother(cdt, held, candidates);
  for(std::size_t pass = 0; pass < passes; ++pass) smoother.pass();
  return smoother.statistics();
}

} // namespace internal
} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_STAR_SMOOTHER_H
