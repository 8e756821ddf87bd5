// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_REGION_SIZING_FIELD_2_H
#define CGAL_ADVANCING_FRONT_MESH_2_REGION_SIZING_FIELD_2_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <CGAL/Advancing_front_mesh_2/Markers_and_regions_2.h>

#include <CGAL/number_utils.h>

#include <cmath>
#include <memory>
#include <stdexcept>
#include <unordered_map>

namespace CGAL {
namespace Advancing_front_mesh_2 {

/*!
\ingroup PkgAdvancingFrontMesh2Sizing

A sizing field bounded in each region by the region's area limit: the
value of `base` at a point, or less inside a region of `tags` with a
positive `max_area`, where it is at most the edge length of the equilateral
triangle of area `area_ratio * max_area`:
`h = sqrt(4 * area_ratio * max_area / sqrt(3))`.

Near-equilateral triangles of edge `h` have areas spread around the
equilateral one, some above it; the default `area_ratio` = 0.8 was measured
to keep the triangles of a region with a limit below it (the user manual
gives the figures). The regions are found once, in a copy of the input
triangulation `input` (its constraints and in-domain marks as
`insert_poly()` left them, before meshing), and a point is located in that
copy at each evaluation, starting from the face of the previous one.

A copy of the field shares the regions and keeps its own starting face: it
is cheap to copy, and not to be used by two threads at once.

\tparam CDT the triangulation type the input was inserted into
\tparam SizingField a model of `AdvancingFrontSizingField_2` for the same
kernel

\cgalModels `AdvancingFrontSizingField_2`
*/
template <class CDT, class SizingField>
class Region_sizing_field_2
{
public:
  typedef typename CDT::Geom_traits::FT FT;
  typedef typename CDT::Geom_traits::Point_2 Point_2;

  /*!
  \throws std::invalid_argument if `area_ratio` is not positive and finite
  */
  Region_sizing_field_2(const CDT& input, const Markers_and_regions_2<CDT>& tags, const SizingField& base,
                        double area_ratio = 0.8)
    : base_(base), regions_(std::make_shared<Regions>(input))
  {
    if(!(area_ratio > 0) || !std::isfinite(area_ratio))
      throw std::invalid_argument("Region_sizing_field_2: area_ratio must be positive and finite");
    Markers_and_regions_2<CDT> own;
    for(const auto& r : tags.regions()) own.add_region(r.seed, r.attribute, r.max_area);
    own.mark_regions(regions_->cdt);
    for(auto f = regions_->cdt.finite_faces_begin(); f != regions_->cdt.finite_faces_end(); ++f) {
      const std::size_t r = own.region(f);
      if(r == Markers_and_regions_2<CDT>::no_region || !(own.regions()[r].max_area > 0)) continue;
      regions_->limit[&*f] = std::sqrt(4 * area_ratio * own.regions()[r].max_area / std::sqrt(3.));
    }
  }

  /// the base field's value at `p`, bounded by the limit of the region of `p`
  FT operator()(const Point_2& p) const
  {
    const FT h = base_(p);
    if(regions_->cdt.dimension() < 2) return h;
    hint_ = regions_->cdt.locate(p, hint_);
    if(regions_->cdt.is_infinite(hint_)) return h;
    const auto it = regions_->limit.find(&*hint_);
    if(it == regions_->limit.end()) return h;
    const double limit = it->second;
    return CGAL::to_double(h) > limit ? FT(limit) : h;
  }

  /// the base field
  const SizingField& base() const { return base_; }

private:
  struct Regions
  {
    explicit Regions(const CDT& input) : cdt(input) {}
    CDT cdt;
    std::unordered_map<const void*, double> limit; // per face of `cdt` (by address) with a limit
  };

  SizingField base_;
  std::shared_ptr<Regions> regions_;
  mutable typename CDT::Face_handle hint_;
};

} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_REGION_SIZING_FIELD_2_H
