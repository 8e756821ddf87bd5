// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_REFINEMENT_CONTEXT_H
#define CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_REFINEMENT_CONTEXT_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <CGAL/Advancing_front_mesh_2/Statistics.h>
#include <CGAL/Advancing_front_mesh_2/internal/Coordinate_scaling.h>
#include <CGAL/Advancing_front_mesh_2/internal/Double_geometry.h>
#include <CGAL/Advancing_front_mesh_2/internal/Front_predicates.h>
#include <CGAL/Advancing_front_mesh_2/internal/Phase_timer.h>

#include <cmath>
#include <type_traits>

namespace CGAL {
namespace Advancing_front_mesh_2 {
namespace internal {

// What every component of the mesher shares: the triangulation being
// meshed, the exact predicates, the scaling of the internal coordinates,
// the phase timer and the statistics.
template <class Tr_>
struct Refinement_context
{
  typedef Tr_ Tr;
  typedef typename Tr::Geom_traits Geom_traits;
  typedef typename Geom_traits::FT FT;
  typedef Front_predicates<Geom_traits> Predicates;
  typedef typename Tr::Point Point;
  typedef typename Tr::Vertex_handle Vertex_handle;
  typedef typename Tr::Face_handle Face_handle;
  typedef typename Tr::Triangulation_data_structure Tds;
  typedef typename Tds::Vertex Tds_vertex;
  typedef typename Tds::Face Tds_face;
  typedef Phase_timer::Scope Phase_scope;

  explicit Refinement_context(Tr& t) : tr(t), pred(t.geom_traits()) {}

  // the internal coordinates are the points, moved and scaled exactly
  // (Coordinate_scaling::exact()): the double computations' error bounds
  // then bound the true values
  bool exact_coordinates() const { return scaling.exact(); }

  void set_scaling(const Coordinate_scaling<Point>& s)
  {
    scaling = s;
    pred.set_coordinates_are_doubles(s.exact());
  }

  static int ccw(int i) { return (i + 1) % 3; }
  static int cw(int i) { return (i + 2) % 3; }

  Tds& tds() { return tr.tds(); }
  const Tds& tds() const { return tr.tds(); }

  double ix(const Point& p) const { return scaling.ix(p); }
  double iy(const Point& p) const { return scaling.iy(p); }

  // the circumcircle of a face in internal coordinates, read through the
  // face (its vertices need not be active); with `error`, a bound on how far
  // its centre and radius may lie from the true ones (circle_through())
  Circle circle_of(Face_handle f, double* error = nullptr) const
  {
    auto X = [this, &f](int i) { return ix(f->vertex(i)->point()); };
    auto Y = [this, &f](int i) { return iy(f->vertex(i)->point()); };
    return circle_through(X(0), Y(0), X(1), Y(1), X(2), Y(2), error);
  }

  // The circle through three points given by their internal coordinates,
  // with `error` as circle_of()'s: the double computation's rounding and,
  // unless the coordinates are exact, their own error as measured on the
  // vertices (Coordinate_scaling::coordinate_error()). Where that is
  // unknown, CGAL's promise for to_double() (a relative 1e-5) stands in:
  // that much of the coordinates' magnitude more.
  Circle circle_through(double ax, double ay, double bx, double by, double cx, double cy, double* error) const
  {
    const double coordinate_error = scaling.coordinate_error();
    const bool known = !std::isnan(coordinate_error);
    const Circle c = internal::circle_of(ax, ay, bx, by, cx, cy, error, known ? coordinate_error : 0.);
    if(error && !known) *error += 1e-5 * (std::abs(c.cx) + std::abs(c.cy) + c.r);
    return c;
  }

  double triangle_area(Face_handle f) const
  {
    const double ax = ix(f->vertex(0)->point()), ay = iy(f->vertex(0)->point());
    const double bx = ix(f->vertex(1)->point()), by = iy(f->vertex(1)->point());
    const double cx = ix(f->vertex(2)->point()), cy = iy(f->vertex(2)->point());
    return signed_area(ax, ay, bx, by, cx, cy);
  }

  Tr& tr;
  Predicates pred;
  Coordinate_scaling<Point> scaling;
  Phase_timer timer;
  Advancing_front_mesh_2::Statistics stats;
};

} // namespace internal
} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_REFINEMENT_CONTEXT_H
