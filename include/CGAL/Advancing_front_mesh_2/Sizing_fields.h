// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_SIZING_FIELDS_H
#define CGAL_ADVANCING_FRONT_MESH_2_SIZING_FIELDS_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <CGAL/number_utils.h>

namespace CGAL {
namespace Advancing_front_mesh_2 {

/*!
\ingroup PkgAdvancingFrontMesh2Sizing

A sizing field with the same target edge length `h` everywhere.

\cgalModels `AdvancingFrontSizingField_2`
*/
template <class GeomTraits>
class Uniform_sizing_field_2
{
public:
  typedef typename GeomTraits::FT FT;
  typedef typename GeomTraits::Point_2 Point_2;

  explicit Uniform_sizing_field_2(const FT& h = FT(1)) : h_(h) {}
  FT operator()(const Point_2&) const { return h_; }
  const FT& target_edge_length() const { return h_; }

private:
  FT h_;
};

/*!
\ingroup PkgAdvancingFrontMesh2Sizing

Turns a Mesh_2 size criteria object (`CGAL::Delaunay_mesh_size_criteria_2`
or any class with `double size_bound() const`) into a uniform sizing field,
so a Mesh_2 user can switch meshers without changing the criteria.

Mesh_2's size bound `S` is an upper bound on every edge length; Mesh_2
meshes have most edges between 0.5 S and S. This mesher produces
near-equilateral triangles with edges close to `h`, so the field returns
`h = ratio * S` with the default `ratio = 0.7`, measured to give a
number of triangles comparable to Mesh_2's for the same `S` (see the user
manual). A `size_bound()` of 0 (no size criterion in Mesh_2) is rejected
with `std::invalid_argument`, since an advancing front needs a size.
*/
template <class Criteria, class GeomTraits>
class Size_criteria_sizing_field_2
{
public:
  typedef typename GeomTraits::FT FT;
  typedef typename GeomTraits::Point_2 Point_2;

  explicit Size_criteria_sizing_field_2(const Criteria& criteria, double ratio = 0.7)
    : h_(ratio * criteria.size_bound())
  {}
  FT operator()(const Point_2&) const { return FT(h_); }

private:
  double h_;
};

} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_SIZING_FIELDS_H
