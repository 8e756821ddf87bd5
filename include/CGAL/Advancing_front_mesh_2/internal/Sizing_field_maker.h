// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_SIZING_FIELD_MAKER_H
#define CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_SIZING_FIELD_MAKER_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <CGAL/Advancing_front_mesh_2/Sizing_fields.h>

#include <CGAL/number_utils.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <type_traits>
#include <utility>

namespace CGAL {
namespace Advancing_front_mesh_2 {
namespace internal {

template <class T, class = void>
struct Has_size_bound : std::false_type {};
template <class T>
struct Has_size_bound<T, decltype(void(std::declval<const T&>().size_bound()))> : std::true_type {};

// Turns what the user passed as "size" into a sizing field: a number is a
// uniform target edge length, a Mesh_2 size criteria object gives its
// size bound, anything else must be callable as FT(const Point_2&).
template <class Gt, class T, class = void>
struct Sizing_field_maker
{
  typedef T type;
  static const T& make(const T& t) { return t; }
  static double minimum_angle(const T&) { return 0; }
};
template <class Gt, class T>
struct Sizing_field_maker<Gt, T, std::enable_if_t<std::is_arithmetic<T>::value ||
                                                  std::is_same<T, typename Gt::FT>::value> >
{
  typedef Uniform_sizing_field_2<Gt> type;
  static type make(const T& t)
  {
    // checked before the triangulation is touched
    const double h = CGAL::to_double(t);
    if(!(h > 0) || !std::isfinite(h))
      throw std::invalid_argument("advancing_front_mesh_2: the target edge length must be a positive finite number");
    return type(typename Gt::FT(t));
  }
  static double minimum_angle(const T&) { return 0; }
};
template <class Gt, class T>
struct Sizing_field_maker<Gt, T, std::enable_if_t<Has_size_bound<T>::value> >
{
  typedef Size_criteria_sizing_field_2<T, Gt> type;
  static type make(const T& t)
  {
    if(!(t.size_bound() > 0))
      throw std::invalid_argument("advancing_front_mesh_2: the Mesh_2 criteria have no size bound "
                                  "(size_bound() == 0); an advancing front needs a size");
    return type(t);
  }
  // Mesh_2's shape bound B (the squared sine of the smallest angle, 0.125
  // for 20.7 degrees by default) as an angle in degrees, at most 30 (see
  // refine_to_minimum_angle_2()); 0 when B asks for nothing
  static double minimum_angle(const T& t)
  {
    const double b = t.bound();
    if(!(b > 0)) return 0;
    return (std::min)(30.0, std::asin(std::sqrt((std::min)(b, 1.0))) * 180 / CGAL_PI);
  }
};

} // namespace internal
} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_SIZING_FIELD_MAKER_H
