// afmesh_2: GIS vector sources read with GDAL (Shapefile, GeoPackage, GML,
// KML, FlatGeobuf, ...), when afmesh_2 was built with it (AFMESH_2_HAS_GDAL,
// set by CMake when libgdal-dev is installed); without it, a clear error.
// GDAL is in a module loaded on demand (ogr_plugin.h).
#ifndef AFMESH_2_OGR_INPUT_H
#define AFMESH_2_OGR_INPUT_H

#include <CGAL/Advancing_front_mesh_2/IO/Poly_data.h>
#include <CGAL/Advancing_front_mesh_2/IO/Poly_read_error.h>
#include <CGAL/Advancing_front_mesh_2/IO/internal/Mesh_writer_common.h>

#if defined(AFMESH_2_HAS_GDAL)
#  include "ogr_plugin.h"
#  include <dlfcn.h>
#  include <filesystem>
#  include <gdal_version.h>
#endif

#include <string>
#include <system_error>
#include <utility>

namespace afmesh_2 {

// Whether `file` is in one of the vector formats read through GDAL, by its
// extension in any case.
inline bool is_ogr_input(const std::string& file)
{
  const std::string ext = CGAL::Advancing_front_mesh_2::IO::internal::mesh_lower_extension(file);
  for(const char* e : {"shp", "gpkg", "gml", "kml", "fgb", "sqlite", "tab", "mif", "gpx", "dxf"})
    if(ext == e) return true;
  return false;
}

// The version of GDAL afmesh_2 was built with, or "" without it.
inline std::string gdal_version()
{
#if defined(AFMESH_2_HAS_GDAL)
  return GDAL_RELEASE_NAME;
#else
  return std::string();
#endif
}

#if defined(AFMESH_2_HAS_GDAL)
// The GDAL reader of the module beside the executable, loaded at the first
// call (and kept: GDAL's drivers stay registered); an error naming the
// module if it cannot be loaded.
inline Ogr_read_function ogr_reader(const std::string& file)
{
  static std::string failure;
  static const Ogr_read_function reader = []() -> Ogr_read_function {
    std::error_code ec;
    const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
    const std::string module = (ec ? std::filesystem::path(ogr_module_file)
                                   : exe.parent_path() / ogr_module_file).string();
    void* handle = dlopen(module.c_str(), RTLD_NOW | RTLD_LOCAL);
    if(handle == nullptr) {
      const char* why = dlerror();
      failure = "cannot load " + module + ", afmesh_2's GDAL reader (" + (why ? why : "unknown error") + ")";
      return nullptr;
    }
    void* symbol = dlsym(handle, ogr_module_symbol);
    if(symbol == nullptr) failure = module + " has no " + ogr_module_symbol;
    return reinterpret_cast<Ogr_read_function>(symbol);
  }();
  if(reader == nullptr) throw CGAL::Advancing_front_mesh_2::IO::Poly_read_error(file, 0, failure);
  return reader;
}
#endif

inline CGAL::Advancing_front_mesh_2::IO::Poly_data read_ogr_input(const std::string& file)
{
#if defined(AFMESH_2_HAS_GDAL)
  Ogr_read_result result;
  ogr_reader(file)(file, result);
  if(!result.ok) throw CGAL::Advancing_front_mesh_2::IO::Poly_read_error(file, result.line, result.problem);
  return std::move(result.data);
#else
  throw CGAL::Advancing_front_mesh_2::IO::Poly_read_error(
    file, 0,
    "this afmesh_2 was built without GDAL, which reads this format (install libgdal-dev and rebuild, or "
    "convert it: ogr2ogr -f GeoJSON out.geojson " + file + ")");
#endif
}

} // namespace afmesh_2

#endif // AFMESH_2_OGR_INPUT_H
