// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_SIZING_FIELD_MESH_CRITERIA_2_H
#define CGAL_ADVANCING_FRONT_MESH_2_SIZING_FIELD_MESH_CRITERIA_2_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <CGAL/Delaunay_mesh_criteria_2.h>
#include <CGAL/Mesh_2/Face_badness.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

namespace CGAL {
namespace Advancing_front_mesh_2 {

/*!
\ingroup PkgAdvancingFrontMesh2Sizing

Meshing criteria for `CGAL::refine_Delaunay_mesh_2()` and
`CGAL::Delaunay_mesher_2` that take the size bound from a sizing field of
this package (`Poisson_sizing_field_2`, or any model of
`AdvancingFrontSizingField_2`), so that the same field drives both meshers.

A triangle is bad when its longest edge exceeds `S(c) = h(c) / ratio`, where
`h` is the field's target edge length and `c` the triangle's centroid, or
when its smallest angle is below the bound given by `aspect_bound` (as in
`CGAL::Delaunay_mesh_size_criteria_2`: `B = sin^2` of the smallest angle,
default 0.125, about 20.7 degrees). `ratio` defaults to 0.7, the same
mapping between Mesh_2's size bound and this package's target edge length as
`Size_criteria_sizing_field_2` uses, measured to give comparable numbers of
triangles (see the user manual).

The field is evaluated in double precision at the centroid, computed from
`CGAL::to_double` of the vertices. A value that is not a positive finite
number makes the face test throw `std::invalid_argument` (Mesh_2 would
otherwise refine forever or ignore the size).

\cgalModels `MeshingCriteria_2`

\tparam CDT a constrained Delaunay triangulation whose faces have the
information Mesh_2 needs (`CGAL::Delaunay_mesh_face_base_2`).
\tparam SizingField a model of `AdvancingFrontSizingField_2` for
`CDT::Geom_traits`.
*/
template <class CDT, class SizingField>
class Sizing_field_mesh_criteria_2 : public virtual Delaunay_mesh_criteria_2<CDT>
{
  typedef Delaunay_mesh_criteria_2<CDT> Base;
  typedef typename CDT::Geom_traits Geom_traits;

public:
  typedef typename CDT::Face_handle Face_handle;
  typedef typename Geom_traits::Point_2 Point_2;

  /// The squared sine of the smallest angle and the squared ratio of the
  /// longest edge over the local size bound, as in Mesh_2's size criteria.
  struct Quality : public std::pair<double, double>
  {
    Quality() : std::pair<double, double>(0, 0) {}
    Quality(double sine, double size) : std::pair<double, double>(sine, size) {}
    double sine() const { return this->first; }
    double size() const { return this->second; }
    // Mesh_2 refines the smallest Quality first: too large before too flat,
    // the largest first among the too large.
    bool operator<(const Quality& q) const
    {
      if(size() > 1) return q.size() > 1 ? size() > q.size() : true;
      if(q.size() > 1) return false;
      return sine() < q.sine();
    }
  };

  /*!
  \param field the sizing field (copied).
  \param aspect_bound the bound `B` on the squared sine of the smallest angle.
  \param ratio the ratio `h / S` between the field's target edge length and
  the longest edge allowed.
  \throws std::invalid_argument if `ratio` is not a positive finite number.
  */
  explicit Sizing_field_mesh_criteria_2(const SizingField& field, double aspect_bound = 0.125,
                                        double ratio = 0.7, const Geom_traits& traits = Geom_traits())
    : Base(aspect_bound, traits), field_(field), ratio_(ratio)
  {
    if(!(ratio > 0) || !std::isfinite(ratio))
      throw std::invalid_argument("Sizing_field_mesh_criteria_2: the ratio must be a positive number");
  }

  const SizingField& sizing_field() const { return field_; }
  double ratio() const { return ratio_; }

  class Is_bad : public Base::Is_bad
  {
  public:
    // Mesh_2 makes an Is_bad for every face it tests: it refers to the
    // criteria's field (as Mesh_2's own criteria refer to their traits)
    // instead of copying it.
    Is_bad(const SizingField& field, double ratio, double aspect_bound, const Geom_traits& traits)
      : Base::Is_bad(aspect_bound, traits), field_(&field), ratio_(ratio)
    {}

    Mesh_2::Face_badness operator()(const Quality& q) const
    {
      if(q.size() > 1) return Mesh_2::IMPERATIVELY_BAD;
      return q.sine() < this->B ? Mesh_2::BAD : Mesh_2::NOT_BAD;
    }

    Mesh_2::Face_badness operator()(const Face_handle& fh, Quality& q) const
    {
      const Point_2& pa = fh->vertex(0)->point();
      const Point_2& pb = fh->vertex(1)->point();
      const Point_2& pc = fh->vertex(2)->point();
      const double ax = CGAL::to_double(pa.x()), ay = CGAL::to_double(pa.y());
      const double bx = CGAL::to_double(pb.x()), by = CGAL::to_double(pb.y());
      const double cx = CGAL::to_double(pc.x()), cy = CGAL::to_double(pc.y());
      double l[3] = {(bx - cx) * (bx - cx) + (by - cy) * (by - cy),
                     (cx - ax) * (cx - ax) + (cy - ay) * (cy - ay),
                     (ax - bx) * (ax - bx) + (ay - by) * (ay - by)};
      std::sort(l, l + 3);
      const double h = CGAL::to_double((*field_)(Point_2((ax + bx + cx) / 3, (ay + by + cy) / 3)));
      if(!(h > 0) || !std::isfinite(h))
        throw std::invalid_argument("Sizing_field_mesh_criteria_2: the sizing field returned " + std::to_string(h) +
                                    ", not a positive finite number");
      const double bound = h / ratio_;
      q.second = l[2] / (bound * bound);
      if(q.size() > 1) {
        q.first = 1; // the sine is not needed
        return Mesh_2::IMPERATIVELY_BAD;
      }
      const double area2 = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
      q.first = (area2 * area2) / (l[2] * l[1]);
      return q.sine() < this->B ? Mesh_2::BAD : Mesh_2::NOT_BAD;
    }

  private:
    const SizingField* field_;
    double ratio_;
  };

  Is_bad is_bad_object() const { return Is_bad(field_, ratio_, this->bound(), this->traits); }

private:
  SizingField field_;
  double ratio_;
};

} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_SIZING_FIELD_MESH_CRITERIA_2_H
