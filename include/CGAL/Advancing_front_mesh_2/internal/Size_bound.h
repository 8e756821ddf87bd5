// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_SIZE_BOUND_H
#define CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_SIZE_BOUND_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <CGAL/Advancing_front_mesh_2/internal/Refinement_context.h>

#include <CGAL/number_utils.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace CGAL {
namespace Advancing_front_mesh_2 {
namespace internal {

// Step 3 of Mavriplis (1992): the bound rho on the circumradii of the
// triangles at a point. The sizing field gives the target edge length h,
// and rho = h / sqrt(3), the circumradius of the equilateral triangle of
// side h. A size that is not a positive finite number is refused.
template <class Context, class SizingField>
class Size_bound
{
public:
  typedef typename Context::FT FT;
  typedef typename Context::Point Point;
  typedef typename Context::Phase_scope Phase_scope;

  Size_bound(const Context& ctx, const SizingField& sizing) : ctx_(ctx), sizing_(sizing) {}

  const SizingField& sizing_field() const { return sizing_; }

  // rho at the internal point (mx, my); `phase`: where the time of the
  // sizing field goes
  // (not const: a sizing field's call operator need not be)
  double target_circumradius(double mx, double my, Phase phase = FRONT_SELECTION)
  {
    Phase_scope scope(ctx_.timer, phase);
    const Point m = ctx_.scaling.to_user_point(mx, my);
    const FT h = sizing_(m);
    const double user_h = CGAL::to_double(h);
    if(!(user_h > 0) || !std::isfinite(user_h)) {
      std::ostringstream os;
      os.precision(17);
      os << "Advancing_front_mesher_2: the sizing field returned " << CGAL::to_double(h) << " at ("
         << CGAL::to_double(m.x()) << ", " << CGAL::to_double(m.y()) << "); sizes must be positive finite numbers";
      throw std::invalid_argument(os.str());
    }
    // a size far beyond the domain's scale may leave the doubles once
    // scaled: it bounds nothing, as 1e300 does not at unit scale
    const double hd = (std::max)((std::min)(ctx_.scaling.to_internal_length(h), 1e300), (std::numeric_limits<double>::min)());
    return hd / std::sqrt(3.);
  }

private:
  const Context& ctx_;
  SizingField sizing_;
};

} // namespace internal
} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_SIZE_BOUND_H
