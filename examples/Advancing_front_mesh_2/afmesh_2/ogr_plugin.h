// afmesh_2: the interface between afmesh_2 and its GDAL reader, a module
// (afmesh_2_ogr.so, beside the executable) loaded only when an input is in
// an OGR format. Linked into afmesh_2 itself, GDAL and the hundred shared
// libraries it needs were loaded by every run: 27 MB of resident memory and
// 0.07 s before reading a .poly file.
#ifndef AFMESH_2_OGR_PLUGIN_H
#define AFMESH_2_OGR_PLUGIN_H

#include <CGAL/Advancing_front_mesh_2/IO/Poly_data.h>

#include <cstddef>
#include <string>

namespace afmesh_2 {

// What the module's reader returns: the polygons, or a Poly_read_error's
// parts (no exception crosses the module's boundary).
struct Ogr_read_result
{
  CGAL::Advancing_front_mesh_2::IO::Poly_data data;
  bool ok = false;
  std::size_t line = 0;
  std::string problem;
};

// the module's entry point, looked up by name
typedef void (*Ogr_read_function)(const std::string& file, Ogr_read_result& result);
constexpr const char* ogr_module_file = "afmesh_2_ogr.so";
constexpr const char* ogr_module_symbol = "afmesh_2_read_ogr";

} // namespace afmesh_2

#endif // AFMESH_2_OGR_PLUGIN_H
