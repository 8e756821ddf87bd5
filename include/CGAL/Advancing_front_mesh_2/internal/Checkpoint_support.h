// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_CHECKPOINT_SUPPORT_H
#define CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_CHECKPOINT_SUPPORT_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <CGAL/Advancing_front_mesh_2/internal/Binary_io.h>

#include <type_traits>
#include <utility>

namespace CGAL {
namespace Advancing_front_mesh_2 {
namespace internal {

// Whether a search structure can be written to a checkpoint: a point index
// with save(Binary_writer&) and load(Binary_reader&), a circle index with
// the same taking a payload writer and reader.
template <class T, class = void>
struct Has_point_index_io : std::false_type {};
template <class T>
struct Has_point_index_io<T, decltype(void(std::declval<const T&>().save(std::declval<Binary_writer&>())),
                                      void(std::declval<T&>().load(std::declval<Binary_reader&>())))>
  : std::true_type {};

template <class T, class = void>
struct Has_circle_index_io : std::false_type {};
template <class T>
struct Has_circle_index_io<
  T, decltype(void(std::declval<const T&>().save(std::declval<Binary_writer&>(),
                                                 std::declval<void (*)(Binary_writer&, const typename T::Payload&)>())),
              void(std::declval<T&>().load(std::declval<Binary_reader&>(),
                                           std::declval<typename T::Payload (*)(Binary_reader&)>())))>
  : std::true_type {};

} // namespace internal
} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_CHECKPOINT_SUPPORT_H
