// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_LAPLACIAN_SMOOTH_MESH_2_H
#define CGAL_ADVANCING_FRONT_MESH_2_LAPLACIAN_SMOOTH_MESH_2_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <CGAL/Advancing_front_mesh_2/Mesh_quality.h>
#include <CGAL/Advancing_front_mesh_2/internal/Lawson_flips.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/number_utils.h>
#include <CGAL/property_map.h>
#include <CGAL/use.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Advancing_front_mesh_2 {

/*!
\ingroup PkgAdvancingFrontMesh2Ref

What `CGAL::laplacian_smooth_mesh_2()` did.
*/
struct Smoothing_statistics
{
  std::size_t passes = 0;                   ///< smoothing + swapping alternations done
  std::size_t movable_vertices = 0;         ///< interior vertices free to move (first pass)
  std::size_t moves = 0;                    ///< accepted moves, over all passes
  std::size_t rejected_moves = 0;           ///< moves refused by the guard (full and half step)
  std::size_t flips = 0;                    ///< edge flips restoring the constrained Delaunay property
  std::vector<std::size_t> flips_per_pass;  ///< the same, pass by pass
};

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

} // namespace internal
} // namespace Advancing_front_mesh_2

/*!
\ingroup PkgAdvancingFrontMesh2Ref

Improves the shape of the triangles of a mesh as in Fig. 13 of Mavriplis
(1992): constrained Laplacian smoothing of the interior vertices, then edge
swapping that restores the constrained Delaunay property, alternated a few
times.

Only in-domain faces (`is_in_domain()`) are considered. A vertex moves only
if every face around it is a finite in-domain face, no constrained edge is
incident to it, and the `vertex_is_constrained_map` does not hold it: the
boundary, isolated input points and everything outside the domain never
move. Each movable vertex, in turn, is tried at the centroid of its
neighbours, then halfway there; a move is accepted only if every triangle
around the vertex stays positively oriented (exact predicate of the
triangulation's traits) and neither the smallest radius ratio 2r/R nor the
smallest angle around the vertex decreases (computed in double precision).
An accepted move is followed at once by Lawson's flips about the vertex, on
the edges between in-domain faces, until the triangulation is constrained
Delaunay again (the input segments are never flipped); if a triangle the
flips made is worse, by either measure, than the worst of the star before the
move, the flips are undone and the vertex goes back. So smoothing never
inverts a triangle and never makes the worst triangle of the mesh worse by
either measure (Lawson's flips alone could lower the smallest radius ratio).
Few edges need flipping after smoothing, as the paper notes; a final Lawson
pass after each pass of smoothing finds nothing left to flip. These
guarantees assume that the input is constrained Delaunay over its in-domain
faces, as the results of `CGAL::advancing_front_mesh_2()` and of Mesh_2 are;
otherwise the first pass's final Lawson flips make it so, unguarded.

Works on the result of `CGAL::advancing_front_mesh_2()` and on a CGAL Mesh_2
result (`CGAL::refine_Delaunay_mesh_2()`) alike.

\tparam CDT a `CGAL::Constrained_Delaunay_triangulation_2` (or
`Constrained_triangulation_plus_2`) whose faces have `is_in_domain()`, for
example `CGAL::Delaunay_mesh_face_base_2`.

\param cdt the mesh, modified in place
\param np optional named parameters among:
\cgalNamedParamsBegin
  \cgalParamNBegin{number_of_iterations}
    \cgalParamDescription{the number of smoothing + swapping passes}
    \cgalParamDefault{5}
  \cgalParamNEnd
  \cgalParamNBegin{vertex_is_constrained_map}
    \cgalParamDescription{a readable property map from `CDT::Vertex_handle`
      to `bool`: vertices mapped to `true` never move, in addition to those on
      constrained edges (use it for isolated input points)}
    \cgalParamDefault{no vertex held}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns what was done: passes, moves, flips.
*/
template <class CDT, class NamedParameters = parameters::Default_named_parameters>
Advancing_front_mesh_2::Smoothing_statistics
laplacian_smooth_mesh_2(CDT& cdt, const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  typedef typename CDT::Vertex_handle Vertex_handle;
  typedef typename CDT::Face_circulator Face_circulator;
  typedef typename CDT::Vertex_circulator Vertex_circulator;
  typedef typename CDT::Face_handle Face_handle;
  typedef typename CDT::Geom_traits::FT FT;
  typedef typename CDT::Point Point;

  const std::size_t passes = choose_parameter(get_parameter(np, internal_np::number_of_iterations), std::size_t(5));
  auto held = choose_parameter(get_parameter(np, internal_np::vertex_is_constrained),
                               Constant_property_map<Vertex_handle, bool>(false));
  const auto orientation = cdt.geom_traits().orientation_2_object();

  Advancing_front_mesh_2::Smoothing_statistics stats;
  std::vector<Vertex_handle> movable;
  for(auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) {
    if(get(held, Vertex_handle(v)) || cdt.are_there_incident_constraints(v)) continue;
    bool interior = true;
    Face_circulator fc = cdt.incident_faces(v), done = fc;
    if(fc == nullptr) continue;
    do {
      if(cdt.is_infinite(fc) || !fc->is_in_domain()) { interior = false; break; }
    } while(++fc != done);
    if(interior) movable.push_back(v);
  }
  stats.movable_vertices = movable.size();

  std::vector<Point> ring;
  // The worst radius ratio and the worst smallest angle (as a squared
  // sine) of the star of a vertex placed at p; `valid` is false if a
  // triangle would not be positively oriented.
  auto star_quality = [&](const Point& p, bool& valid) {
    // the ring is ordered counter-clockwise: each consecutive pair and p
    // form one triangle of the star
    std::pair<double, double> worst(1., 1.);
    valid = true;
    const double px = CGAL::to_double(p.x()), py = CGAL::to_double(p.y());
    for(std::size_t k = 0; k < ring.size(); ++k) {
      const Point& a = ring[k];
      const Point& b = ring[(k + 1) % ring.size()];
      if(orientation(p, a, b) != CGAL::LEFT_TURN) {
        valid = false;
        return worst;
      }
      const double ax = CGAL::to_double(a.x()), ay = CGAL::to_double(a.y());
      const double bx = CGAL::to_double(b.x()), by = CGAL::to_double(b.y());
      worst.first = (std::min)(worst.first, Advancing_front_mesh_2::internal::radius_ratio(px, py, ax, ay, bx, by));
      worst.second = (std::min)(worst.second,
                                Advancing_front_mesh_2::internal::squared_sine_of_smallest_angle(px, py, ax, ay, bx, by));
    }
    return worst;
  };

  // Lawson's flips after the move of v: the edges of its star and of the
  // star's ring first, then those of each flipped pair. The flips are
  // recorded: the two faces of each, whose triangles changed, and the new
  // diagonal, by its end points, to undo them (a flip and its undoing may
  // leave the two triangles in each other's face records, so later undoings
  // cannot go by face handles).
  std::vector<std::pair<Face_handle, Face_handle> > flipped;
  std::vector<std::pair<Vertex_handle, Vertex_handle> > diagonals;
  std::vector<typename CDT::Edge> to_check;
  std::size_t pass_flips = 0;
  auto flip_about = [&](Vertex_handle v) {
    flipped.clear();
    diagonals.clear();
    to_check.clear();
    Face_circulator fc = cdt.incident_faces(v), done = fc;
    do {
      for(int k = 0; k < 3; ++k) to_check.emplace_back(fc, k);
    } while(++fc != done);
    return Advancing_front_mesh_2::internal::lawson_flips(cdt, to_check, [&](Face_handle f, Face_handle g) {
      flipped.emplace_back(f, g);
      const int j = f->index(g);
      diagonals.emplace_back(f->vertex(CDT::ccw(j)), f->vertex(CDT::cw(j)));
    });
  };
  auto undo_flips = [&](std::size_t made) {
    for(std::size_t k = made; k-- > 0;) {
      // flipping the new diagonal back
      Face_handle f;
      int i = 0;
      const bool found = cdt.is_edge(diagonals[k].first, diagonals[k].second, f, i);
      CGAL_assertion(found);
      CGAL_USE(found);
      cdt.flip(f, i);
    }
  };
  // the worst radius ratio and smallest angle of the faces about v and of
  // the faces the flips changed (some of which may have left v's star)
  auto worst_of_changed_faces = [&](Vertex_handle v) {
    std::pair<double, double> worst(1., 1.);
    auto account = [&worst](Face_handle f) {
      double x[3], y[3];
      for(int k = 0; k < 3; ++k) {
        x[k] = CGAL::to_double(f->vertex(k)->point().x());
        y[k] = CGAL::to_double(f->vertex(k)->point().y());
      }
      worst.first = (std::min)(worst.first, Advancing_front_mesh_2::internal::radius_ratio(x[0], y[0], x[1], y[1], x[2], y[2]));
      worst.second = (std::min)(worst.second, Advancing_front_mesh_2::internal::squared_sine_of_smallest_angle(
                                                x[0], y[0], x[1], y[1], x[2], y[2]));
    };
    Face_circulator fc = cdt.incident_faces(v), done = fc;
    do account(fc); while(++fc != done);
    for(const auto& fg : flipped) {
      account(fg.first);
      account(fg.second);
    }
    return worst;
  };

  for(std::size_t pass = 0; pass < passes; ++pass) {
    for(Vertex_handle v : movable) {
      ring.clear();
      Vertex_circulator vc = cdt.incident_vertices(v), done = vc;
      // The new position is computed in double: with exact number types a
      // position built from positions built from ... would grow without
      // bound over the passes (the guard's orientation test stays exact).
      double sx = 0, sy = 0;
      do {
        ring.push_back(vc->point());
        sx += CGAL::to_double(vc->point().x());
        sy += CGAL::to_double(vc->point().y());
      } while(++vc != done);
      const double n = static_cast<double>(ring.size());
      const Point old = v->point();
      const double ox = CGAL::to_double(old.x()), oy = CGAL::to_double(old.y());
      const Point target(FT(sx / n), FT(sy / n));
      const Point halfway(FT(0.5 * (ox + sx / n)), FT(0.5 * (oy + sy / n)));
      bool valid = false;
      const std::pair<double, double> before = star_quality(old, valid);
      bool moved = false;
      for(const Point& candidate : {target, halfway}) {
        const std::pair<double, double> after = star_quality(candidate, valid);
        if(valid && after.first >= before.first && after.second >= before.second) {
          v->set_point(candidate);
          // The move may call for flips, and Lawson's flips keep the
          // smallest angle from decreasing but not the radius ratio: the
          // flips are made now, and the move is undone (flips included)
          // if a triangle they made is worse than the star's worst before.
          const std::size_t made = flip_about(v);
          // without flips the star was judged above (and the face order
          // could change the last bit of a ratio)
          const std::pair<double, double> changed = made == 0 ? after : worst_of_changed_faces(v);
          if(changed.first >= before.first && changed.second >= before.second) {
            moved = true;
            pass_flips += made;
            break;
          }
          undo_flips(made);
          v->set_point(old);
        }
        ++stats.rejected_moves;
      }
      if(moved) ++stats.moves;
    }
    // nothing is expected to need a flip here: kept as a safety net
    const std::size_t flips = pass_flips + Advancing_front_mesh_2::internal::restore_constrained_delaunay(cdt);
    pass_flips = 0;
    stats.flips += flips;
    stats.flips_per_pass.push_back(flips);
    ++stats.passes;
  }
  return stats;
}

} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_LAPLACIAN_SMOOTH_MESH_2_H
