// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_IO_WRITE_MESH_H
#define CGAL_ADVANCING_FRONT_MESH_2_IO_WRITE_MESH_H

#include <CGAL/license/Advancing_front_mesh_2.h>

// The header users include for the mesh writers: write_mesh() below, and
// through the headers it includes write_OFF(), write_triangle_node_ele(),
// write_boundary_poly() (write_mesh_formats.h), write_gmsh_msh()
// (write_gmsh_msh.h), write_mesh_VTU() (write_mesh_VTU.h) and write_SVG()
// with SVG_options (write_SVG.h). Mesh_quality.h is not used here; it stays because this
// header has always provided it.
#include <CGAL/Advancing_front_mesh_2/Mesh_quality.h>
#include <CGAL/Advancing_front_mesh_2/IO/internal/Mesh_writer_common.h>
#include <CGAL/Advancing_front_mesh_2/IO/write_gmsh_msh.h>
#include <CGAL/Advancing_front_mesh_2/IO/write_mesh_VTU.h>
#include <CGAL/Advancing_front_mesh_2/IO/write_mesh_formats.h>
#include <CGAL/Advancing_front_mesh_2/IO/write_SVG.h>
#include <CGAL/Advancing_front_mesh_2/Markers_and_regions_2.h>

#include <CGAL/Named_function_parameters.h>

#include <ostream>
#include <stdexcept>
#include <string>

namespace CGAL {
namespace Advancing_front_mesh_2 {
namespace IO {

namespace internal {

template <class CDT>
void write_mesh(const std::string& file_name, const CDT& cdt, const Markers_and_regions_2<CDT>* tags, bool binary)
{
  const std::string ext = internal::mesh_lower_extension(file_name);
  if(ext == "off") {
    internal::mesh_write_file(file_name, [&](std::ostream& os) { write_OFF(os, cdt); });
  } else if(ext == "vtu") {
    internal::mesh_write_file(file_name, [&](std::ostream& os) {
      const auto np = parameters::use_binary_mode(binary);
      if(tags != nullptr) write_mesh_VTU(os, cdt, *tags, np);
      else write_mesh_VTU(os, cdt, np);
    });
  } else if(ext == "node" || ext == "ele") {
    const std::string base = file_name.substr(0, file_name.size() - ext.size() - 1);
    if(tags != nullptr) write_triangle_node_ele(base, cdt, *tags);
    else write_triangle_node_ele(base, cdt);
  } else if(ext == "poly") {
    const Markers_and_regions_2<CDT> none;
    internal::mesh_write_file(file_name,
                              [&](std::ostream& os) { write_boundary_poly(os, cdt, tags != nullptr ? *tags : none); });
  } else if(ext == "msh") {
    internal::mesh_write_file(file_name, [&](std::ostream& os) {
      if(tags != nullptr) write_gmsh_msh(os, cdt, *tags);
      else write_gmsh_msh(os, cdt);
    });
  } else if(ext == "svg") {
    internal::mesh_write_file(file_name, [&](std::ostream& os) { write_SVG(os, cdt); });
  } else {
    throw std::invalid_argument("write_mesh: unknown extension of '" + file_name +
                                "' (expected .off, .vtu, .node, .ele, .poly, .msh or .svg)");
  }
}

} // namespace internal

/*!
\ingroup PkgAdvancingFrontMesh2IO

Writes the in-domain triangles of `cdt` to `file_name`, in the format given
by its extension (case-insensitive):
- `.off`: `write_OFF()`;
- `.vtu`: `write_mesh_VTU()`, binary unless `use_binary_mode(false)`;
- `.node` or `.ele`: `write_triangle_node_ele()`, which writes both files;
- `.poly`: `write_boundary_poly()`, the boundary of the domain;
- `.msh`: `write_gmsh_msh()`;
- `.svg`: `write_SVG()` with default options.

\tparam CDT as in `write_OFF()`
\tparam NamedParameters a sequence of named parameters

\param file_name path of the file to create or overwrite
\param cdt the meshed triangulation
\param np an optional sequence of named parameters among the ones listed below

\cgalNamedParamsBegin
  \cgalParamNBegin{use_binary_mode}
    \cgalParamDescription{for `.vtu`: binary (raw appended) or ASCII arrays; the other formats are text}
    \cgalParamType{Boolean}
    \cgalParamDefault{`true`}
  \cgalParamNEnd
\cgalNamedParamsEnd

\throws std::invalid_argument if the extension is none of the above; nothing
is written then
\throws std::runtime_error "cannot write FILE" when a file cannot be opened
or written
*/
template <class CDT, class NamedParameters = parameters::Default_named_parameters>
void write_mesh(const std::string& file_name, const CDT& cdt, const NamedParameters& np = parameters::default_values())
{
  internal::write_mesh(file_name, cdt, static_cast<const Markers_and_regions_2<CDT>*>(nullptr),
                       parameters::choose_parameter(parameters::get_parameter(np, internal_np::use_binary_mode), true));
}

/*!
\ingroup PkgAdvancingFrontMesh2IO

Writes the in-domain triangles of `cdt` with their markers and regions to
`file_name`, in the format given by its extension, as
`write_mesh(const std::string&, const CDT&, const NamedParameters&)` but with the writers that take
`tags`: `.node`/`.ele` also write `.edge`, and `.node`, `.ele`, `.edge`,
`.poly`, `.msh` and `.vtu` carry the markers and region attributes (OFF and
SVG have no place for them).

\param file_name path of the file to create or overwrite
\param cdt the meshed triangulation
\param tags its markers and regions, with `Markers_and_regions_2::mark_regions()`
called on the current faces of `cdt` when there are regions
\param np as in `write_mesh(const std::string&, const CDT&, const NamedParameters&)`

\throws as `write_mesh(const std::string&, const CDT&, const NamedParameters&)`
*/
template <class CDT, class NamedParameters = parameters::Default_named_parameters>
void write_mesh(const std::string& file_name, const CDT& cdt, const Markers_and_regions_2<CDT>& tags,
                const NamedParameters& np = parameters::default_values())
{
  internal::write_mesh(file_name, cdt, &tags,
                       parameters::choose_parameter(parameters::get_parameter(np, internal_np::use_binary_mode), true));
}

} // namespace IO
} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_IO_WRITE_MESH_H
