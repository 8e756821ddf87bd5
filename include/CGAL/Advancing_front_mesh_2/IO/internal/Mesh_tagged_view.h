// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_IO_INTERNAL_MESH_TAGGED_VIEW_H
#define CGAL_ADVANCING_FRONT_MESH_2_IO_INTERNAL_MESH_TAGGED_VIEW_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <CGAL/Advancing_front_mesh_2/IO/internal/Mesh_writer_common.h>
#include <CGAL/Advancing_front_mesh_2/Markers_and_regions_2.h>

#include <cstddef>
#include <ostream>

namespace CGAL {
namespace Advancing_front_mesh_2 {
namespace IO {
namespace internal {

// The markers of the view's vertices and segments and the regions of its
// triangles, from `tags`, whose regions must have been marked on `cdt`'s
// current faces.
template <class CDT>
void mesh_collect_tags(const CDT& cdt, const Markers_and_regions_2<CDT>& tags, Mesh_domain_view<CDT>& m)
{
  m.tagged = true;
  m.has_regions = tags.has_regions();
  m.point_markers.reserve(m.vertices.size());
  for(const auto& v : m.vertices) m.point_markers.push_back(tags.vertex_marker(cdt, v));
  m.segment_markers.reserve(m.segment_edges.size());
  for(const auto& e : m.segment_edges) m.segment_markers.push_back(tags.edge_marker(cdt, e.first, e.second));
  if(!m.has_regions) return;
  m.triangle_regions.reserve(m.faces.size());
  m.triangle_attributes.reserve(m.faces.size());
  for(const auto& f : m.faces) {
    m.triangle_regions.push_back(tags.region(f));
    m.triangle_attributes.push_back(tags.region_attribute(f));
  }
}

// The view of `cdt`'s domain, with the tags when `tags` is not null.
template <class CDT>
void mesh_collect(const CDT& cdt, const Markers_and_regions_2<CDT>* tags, Mesh_domain_view<CDT>& m)
{
  mesh_collect_domain(cdt, m);
  if(tags != nullptr) mesh_collect_tags(cdt, *tags, m);
}

// Writes the view of `cdt` (with `tags` when not null) to `os` with
// `write(os, view)`, in the exact number format, restoring the stream's
// formatting and locale afterwards (not its error state: that would hide a
// failed write).
template <class CDT, class Write>
void mesh_write_view(std::ostream& os, const CDT& cdt, const Markers_and_regions_2<CDT>* tags, Write write)
{
  Mesh_domain_view<CDT> m;
  mesh_collect(cdt, tags, m);
  const Mesh_exact_format_scope format(os);
  write(os, m);
}

} // namespace internal
} // namespace IO
} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_IO_INTERNAL_MESH_TAGGED_VIEW_H
