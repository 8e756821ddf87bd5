// afmesh_2: GIS vector sources read with GDAL (Shapefile, GeoPackage, GML,
// KML, FlatGeobuf, ...), when afmesh_2 was built with it (AFMESH_2_HAS_GDAL,
// set by CMake when libgdal-dev is installed); without it, a clear error.
#ifndef AFMESH_2_OGR_INPUT_H
#define AFMESH_2_OGR_INPUT_H

#include <CGAL/Advancing_front_mesh_2/IO/Poly_data.h>
#include <CGAL/Advancing_front_mesh_2/IO/Poly_read_error.h>
#include <CGAL/Advancing_front_mesh_2/IO/internal/Mesh_writer_common.h>

#if defined(AFMESH_2_HAS_GDAL)
#  include <CGAL/Advancing_front_mesh_2/IO/read_OGR_polygons.h>
#  include <gdal_version.h>
#endif

#include <string>

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

inline CGAL::Advancing_front_mesh_2::IO::Poly_data read_ogr_input(const std::string& file)
{
#if defined(AFMESH_2_HAS_GDAL)
  return CGAL::Advancing_front_mesh_2::IO::read_OGR_polygons(file);
#else
  throw CGAL::Advancing_front_mesh_2::IO::Poly_read_error(
    file, 0,
    "this afmesh_2 was built without GDAL, which reads this format (install libgdal-dev and rebuild, or "
    "convert it: ogr2ogr -f GeoJSON out.geojson " + file + ")");
#endif
}

} // namespace afmesh_2

#endif // AFMESH_2_OGR_INPUT_H
