// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_DELAUNAY_APEX_H
#define CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_DELAUNAY_APEX_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <CGAL/Advancing_front_mesh_2/internal/Front_2.h>
#include <CGAL/Advancing_front_mesh_2/internal/Front_visibility.h>
#include <CGAL/Advancing_front_mesh_2/internal/Neighbourhood.h>

#include <CGAL/enum.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace CGAL {
namespace Advancing_front_mesh_2 {
namespace internal {

// Step 5 of Mavriplis (1992), Merriam's iteration: the Delaunay apex of a
// front edge among the neighbourhood's vertices visible from both its end
// points, i.e. the candidate whose circle through the edge contains no
// other candidate (found in one pass over the candidates in the order of
// their circles, see lowest_visible_by_runs()).
template <class Front, class Visibility>
class Delaunay_apex
{
public:
  typedef typename Front::Context Context;
  typedef typename Front::Vid Vid;
  typedef typename Front::Point Point;
  typedef typename Context::Phase_scope Phase_scope;
  typedef internal::Neighbourhood<Front> Neighbourhood;
  static constexpr Vid no_vertex = Front::no_vertex;

  Delaunay_apex(Context& ctx, const Front& front, const Visibility& visibility)
    : ctx_(ctx), front_(front), visibility_(visibility) {}

  Vid operator()(Vid a, Vid b, const Neighbourhood& n,
                 double max_centre_height = std::numeric_limits<double>::infinity());

private:
  struct Candidate
  {
    double height;         // approximate circle-centre height, for the order
    Vid vertex;
    double low;            // a lower bound of the true height
    double high;           // an upper bound of the true height
  };

  // the edge a -> b in internal coordinates, for the candidates' heights
  struct Edge_frame
  {
    static constexpr double eps = 1e-15;
    Edge_frame(const Context& ctx, const Front& front, Vid a, Vid b);
    const Point& pa;
    const Point& pb;
    bool exact;
    double xa, ya, xb, yb, mx, my, tx, ty, quarter_l2, half_length;
    double e_t; // error bound of tx and ty
  };

  void collect_candidates(Vid a, Vid b, const Neighbourhood& n, double max_centre_height);
  bool evaluate(const Edge_frame& e, Vid c, Candidate& out) const;
  bool qualifies(Vid a, Vid b, Vid c) const;
  Vid lowest_visible_by_runs(Vid a, Vid b, const Neighbourhood& n);

  Context& ctx_;
  const Front& front_;
  const Visibility& visibility_;
  std::vector<Candidate> candidates_, dropped_; // scratch space reused across steps
  std::vector<Vid> far_;                         // dropped unevaluated (see collect_candidates())
  std::vector<double> lowest_after_;
};

// The Delaunay apex of front edge a -> b, or no_vertex.
//
// When the caller has no use for an apex whose circle's centre lies at
// `max_centre_height` or more above the edge (such a triangle is too large
// to be built, and the new point would lie inside its circle), the
// candidates surely beyond that height are dropped before their costly
// tests; since they lie outside the circles of all lower candidates, the
// answer among the others is unchanged, and no_vertex means "no apex
// below".
template <class Front, class Visibility>
typename Front::Vid Delaunay_apex<Front, Visibility>::operator()(Vid a, Vid b, const Neighbourhood& n,
                                                                 double max_centre_height)
{
  Phase_scope phase(ctx_.timer, DELAUNAY_CLOSURE);
  collect_candidates(a, b, n, max_centre_height);
  return lowest_visible_by_runs(a, b, n);
}

// Candidates are taken in the order of their circles' approximate centre
// heights over the edge: the Delaunay apex is then nearly always the first
// candidate that qualifies, so the costly free-sector tests run for few
// candidates. The exact in-circle iteration decides; the order only saves
// work.
template <class Front, class Visibility>
void Delaunay_apex<Front, Visibility>::collect_candidates(Vid a, Vid b, const Neighbourhood& n,
                                                          double max_centre_height)
{
  const Edge_frame e(ctx_, front_, a, b);
  // Unless every point's coordinates are doubles, the stored coordinates
  // are only approximations (to_double of a lazy number may be off by
  // 1e-5), so no candidate is dropped on their account.
  const double cutoff = e.exact ? max_centre_height / e.half_length : std::numeric_limits<double>::infinity();
  candidates_.clear();
  dropped_.clear();
  far_.clear();
  // A candidate is dropped only if its height's lower bound is above the
  // cut-off; if a kept one may lie above it (its upper bound is), the
  // dropped ones it might not exclude are taken back, so the answer among
  // the kept candidates is the answer among all.
  //
  // The neighbourhood's disk also holds the new point's star (Point_placement.h),
  // and many of its vertices lie beyond every circle through a and b
  // whose centre is below the cut-off (such a circle reaches at most
  // h + sqrt(h^2 + L^2 / 4) from the edge's midpoint, h the cut-off's
  // height > 0, L the edge's length; for a centre below the edge, the arc on
  // the left lies in the disk of radius L / 2): their heights surely exceed
  // the cut-off, by far more than their error bounds with the margins (a
  // millionth of that reach, and a billionth of the coordinates' magnitude
  // for the rounding of the distances), and they are set aside without their
  // evaluation, which is needed only when they may be taken back (their
  // evaluation was 2.4% of the instructions of a run at 1e5 triangles).
  const double h = max_centre_height;
  const double far = (std::isfinite(cutoff) && h > 0)
                       ? (h + std::sqrt(h * h + e.quarter_l2)) * (1 + 1e-6) + 1e-9 * (std::abs(e.mx) + std::abs(e.my))
                       : std::numeric_limits<double>::infinity();
  const double far2 = far * far;
  double straddle = -std::numeric_limits<double>::infinity();
  Candidate cand;
  for(std::size_t i = 0; i < n.vertices.size(); ++i) {
    const Vid c = Vid(n.vertices[i]);
    if(c == a || c == b) continue;
    const double dx = n.vertex_xy[i][0] - e.mx, dy = n.vertex_xy[i][1] - e.my;
    if(dx * dx + dy * dy > far2) {
      far_.push_back(c);
      continue;
    }
    if(!evaluate(e, c, cand)) continue;
    if(cand.low > cutoff && std::isfinite(cand.low)) {
      dropped_.push_back(cand);
    } else {
      candidates_.push_back(cand);
      if(!(cand.high <= cutoff))
        straddle = (std::max)(straddle, std::isnan(cand.high) ? std::numeric_limits<double>::infinity() : cand.high);
    }
  }
  if(straddle > cutoff) {
    for(const Candidate& d : dropped_)
      if(!(d.low > straddle)) candidates_.push_back(d);
    for(Vid c : far_)
      if(evaluate(e, c, cand) && !(cand.low > straddle)) candidates_.push_back(cand);
  }
#ifndef CGAL_NO_ASSERTIONS
  // what was claimed of the vertices set aside
  for(Vid c : far_) CGAL_assertion(!evaluate(e, c, cand) || cand.low > cutoff);
#endif
  std::sort(candidates_.begin(), candidates_.end(),
            [](const Candidate& p, const Candidate& q) { return p.height < q.height; });
}

// The edge a -> b as the height computations read it.
template <class Front, class Visibility>
Delaunay_apex<Front, Visibility>::Edge_frame::Edge_frame(const Context& ctx, const Front& front, Vid a_, Vid b_)
  : pa(front.point(a_)), pb(front.point(b_)), exact(ctx.exact_coordinates())
{
  xa = front.x(a_), ya = front.y(a_), xb = front.x(b_), yb = front.y(b_);
  mx = 0.5 * (xa + xb), my = 0.5 * (ya + yb);
  tx = xb - xa, ty = yb - ya;
  quarter_l2 = 0.25 * (tx * tx + ty * ty);
  half_length = std::sqrt(quarter_l2);
  e_t = eps * (std::abs(xa) + std::abs(ya) + std::abs(xb) + std::abs(yb));
}

// Candidate c of edge e, if it lies to the edge's left: the approximate
// height of its circle's centre over the edge's midpoint, in units of half
// the edge's length, and error bounds of the double computation (a few
// units in the last place of every term, generously): the true height lies
// in [low, high].
template <class Front, class Visibility>
bool Delaunay_apex<Front, Visibility>::evaluate(const Edge_frame& e, Vid c, Candidate& out) const
{
  const double eps = Edge_frame::eps;
  const double xc = front_.x(c), yc = front_.y(c);
  // Points in line with an axis-parallel edge (boundary points on the
  // sides of a box) are exactly collinear, where the filtered predicate
  // falls back to exact arithmetic: with exact coordinates, equal
  // coordinates decide it at once.
  if(e.exact && ((e.ya == e.yb && yc == e.ya) || (e.xa == e.xb && xc == e.xa))) return false;
  // with half the edge's length as unit: the circle through a, b and c
  // has its centre at height num / v over the midpoint
  const double dx = xc - e.mx, dy = yc - e.my;
  const double tx = e.tx, ty = e.ty, quarter_l2 = e.quarter_l2;
  const double u = dx * tx + dy * ty, v = dy * tx - dx * ty;
  const double e_d = eps * (std::abs(xc) + std::abs(yc) + std::abs(e.mx) + std::abs(e.my));
  const double e_uv = e_d * (std::abs(tx) + std::abs(ty)) + e.e_t * (std::abs(dx) + std::abs(dy)) +
                      eps * (std::abs(dx * tx) + std::abs(dy * ty) + std::abs(dy * tx) + std::abs(dx * ty));
  // c must lie to the left of the edge. v is orientation(a, b, c)'s
  // determinant, so with exact coordinates its error bound settles most
  // candidates without the predicate (eps is 9 units in the last place,
  // four times what the bound needs; a bound below 1e-290 might hide
  // underflow, and the predicate decides)
  if(e.exact && e_uv > 1e-290 && std::abs(v) > e_uv) {
    if(v < 0) return false;
  } else if(ctx_.pred.orientation(e.pa, e.pb, front_.point(c)) != LEFT_TURN) {
    return false;
  }
  const double along2 = u * u / (4 * quarter_l2), across2 = v * v / (4 * quarter_l2);
  const double num = along2 + across2 - quarter_l2;
  const double e_num = (2 * (std::abs(u) + std::abs(v)) * e_uv + e_uv * e_uv) / (4 * quarter_l2) +
                       eps * (along2 + across2 + quarter_l2) + 4 * eps * quarter_l2;
  const double height = v > 0 ? num / v : 0;
  const double low = (v + e_uv > 0 && num - e_num > 0) ? (num - e_num) / (v + e_uv)
                                                      : -std::numeric_limits<double>::infinity();
  // (a numerator that may be negative is divided by the larger denominator)
  const double high = !(v - e_uv > 0) ? std::numeric_limits<double>::infinity()
                      : num + e_num >= 0 ? (num + e_num) / (v - e_uv)
                                         : (num + e_num) / (v + e_uv);
  out = Candidate{std::isfinite(height) ? height : 0., c, low, high};
  return true;
}

// The circles through a and b are nested on the unmeshed side of the edge:
// a candidate lies strictly inside another's circle exactly when its own
// circle's centre is lower. Merriam's answer is therefore the qualifying,
// visible candidate of lowest exact height (of equal ones, the first in the
// approximate order). The approximate order is exact between runs of
// candidates whose heights' error bounds do not overlap: the answer lies in
// the first run that holds a qualifying, visible candidate, and within it is
// found by one in-circle test per such candidate. Rounds of Merriam's
// iteration instead cost an in-circle test per candidate each, and the
// candidates on one circle (the ends of a star's spokes, seen from the edge
// between two of them), rejected one by one as not visible, cost n^2 tests
// per edge: 95 million for a star of 2,000 spokes.
template <class Front, class Visibility>
typename Front::Vid Delaunay_apex<Front, Visibility>::lowest_visible_by_runs(Vid a, Vid b, const Neighbourhood& n)
{
  const Point& pa = front_.point(a);
  const Point& pb = front_.point(b);
  // the least lower bound from each candidate on (not a number: -infinity);
  // unless the coordinates are exact the bounds are not bounds (see
  // collect_candidates()), and all candidates make one run
  const bool exact = ctx_.exact_coordinates();
  lowest_after_.assign(candidates_.size() + 1, std::numeric_limits<double>::infinity());
  for(std::size_t i = candidates_.size(); i-- > 0;)
    lowest_after_[i] = (!exact || std::isnan(candidates_[i].low))
                         ? -std::numeric_limits<double>::infinity()
                         : (std::min)(lowest_after_[i + 1], candidates_[i].low);
  std::size_t run = 0;
  while(run < candidates_.size()) {
    // the run ends where every later candidate is surely higher than all of
    // it (a bound that is not a number joins the run)
    std::size_t end = run + 1;
    double run_high = std::isnan(candidates_[run].high) ? std::numeric_limits<double>::infinity()
                                                        : candidates_[run].high;
    while(end < candidates_.size() && !(lowest_after_[end] > run_high)) {
      run_high = std::isnan(candidates_[end].high) ? std::numeric_limits<double>::infinity()
                                                   : (std::max)(run_high, candidates_[end].high);
      ++end;
    }
    std::size_t best = end;
    for(std::size_t i = run; i < end; ++i) {
      const Candidate& cand = candidates_[i];
      if(best != end) {
        ++ctx_.stats.incircle_tests;
        if(!ctx_.pred.strictly_inside_circle(pa, pb, front_.point(candidates_[best].vertex),
                                             front_.point(cand.vertex)))
          continue;
      }
      // its four free-sector tests are done when it qualifies
      if(qualifies(a, b, cand.vertex) &&
         visibility_.visible_from_both(a, pa, b, pb, cand.vertex, front_.point(cand.vertex), n, true))
        best = i;
    }
    if(best != end) return candidates_[best].vertex;
    run = end;
  }
  return no_vertex;
}

// Are c's and the edge's end points in each other's free sectors? (The one
// pass asks at most once per candidate.)
template <class Front, class Visibility>
bool Delaunay_apex<Front, Visibility>::qualifies(Vid a, Vid b, Vid c) const
{
  const Point& pc = front_.point(c);
  return visibility_.in_free_sector(a, pc, c) && visibility_.in_free_sector(b, pc, c) &&
         visibility_.in_free_sector(c, front_.point(a), a) && visibility_.in_free_sector(c, front_.point(b), b);
}

} // namespace internal
} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_DELAUNAY_APEX_H
