// afmesh_2_ogr.so: afmesh_2's GDAL reader (see ogr_plugin.h), the only code
// of the tool that links GDAL.
#include "ogr_plugin.h"

#include <CGAL/Advancing_front_mesh_2/IO/read_OGR_polygons.h>

#include <exception>
#include <new>

extern "C" __attribute__((visibility("default"))) void afmesh_2_read_ogr(const std::string& file,
                                                                        afmesh_2::Ogr_read_result& result)
{
  namespace IO = CGAL::Advancing_front_mesh_2::IO;
  result = afmesh_2::Ogr_read_result();
  try {
    result.data = IO::read_OGR_polygons(file);
    result.ok = true;
  } catch(const IO::Poly_read_error& e) {
    result.line = e.line();
    result.problem = e.problem();
  } catch(const std::bad_alloc&) {
    result.problem = "out of memory while reading it";
  } catch(const std::exception& e) {
    result.problem = e.what();
  } catch(...) {
    result.problem = "unknown error while reading it";
  }
}
