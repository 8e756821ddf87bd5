// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_IO_READ_OGR_POLYGONS_H
#define CGAL_ADVANCING_FRONT_MESH_2_IO_READ_OGR_POLYGONS_H

#include <CGAL/license/Advancing_front_mesh_2.h>

// GDAL is an optional dependency: only this header needs it, and only
// programs that include it link with it (CMake: find_package(GDAL), target
// GDAL::GDAL; Debian: libgdal-dev).
#include <CGAL/Advancing_front_mesh_2/IO/Poly_data.h>
#include <CGAL/Advancing_front_mesh_2/IO/Poly_read_error.h>
#include <CGAL/Advancing_front_mesh_2/IO/polygons_to_poly.h>

#include <cpl_error.h>
#include <gdal.h>
#include <ogr_api.h>
#include <ogr_core.h>

#include <array>
#include <cstddef>
#include <filesystem>
#include <memory>
#include <string>
#include <system_error>
#include <vector>

namespace CGAL {
namespace Advancing_front_mesh_2 {
namespace IO {

namespace internal {

// The last GDAL error, for a message.
inline std::string ogr_last_error()
{
  const char* m = CPLGetLastErrorMsg();
  return (m != nullptr && *m != '\0') ? std::string(" (GDAL: ") + m + ")" : std::string();
}

inline std::string ogr_where(const std::string& layer, GIntBig fid)
{
  return "layer '" + layer + "', feature " + std::to_string(static_cast<long long>(fid));
}

// The rings of a polygon geometry, 2D (a height is ignored); curved rings
// are approximated by GDAL's default stroking.
inline Polygon_rings ogr_polygon(OGRGeometryH polygon)
{
  Polygon_rings out;
  for(int r = 0, nr = OGR_G_GetGeometryCount(polygon); r < nr; ++r) {
    OGRGeometryH ring = OGR_G_GetGeometryRef(polygon, r);
    std::vector<std::array<double, 2> > points;
    for(int i = 0, n = OGR_G_GetPointCount(ring); i < n; ++i)
      points.push_back({{OGR_G_GetX(ring, i), OGR_G_GetY(ring, i)}});
    // closed rings repeat their first point; poly_data_from_polygons() drops it
    out.rings.push_back(points);
  }
  return out;
}

} // namespace internal

/*!
\ingroup PkgAdvancingFrontMesh2IO

Reads the polygons with holes of an OGR vector source with GDAL
(<a href="https://gdal.org/drivers/vector/">any format GDAL reads</a>:
Shapefile, GeoPackage, GeoJSON, GML, KML, FlatGeobuf, ...) and makes the
planar straight-line graph of them with `poly_data_from_polygons()`: every
ring a closed chain of segments, a hole seed in every hole.

Every feature of every layer (or of the layer named `layer`) is read: its
geometry must be a polygon or a multipolygon (curve polygons are stroked
into straight segments by GDAL; a height is ignored). Coordinates are used
as they are, in the source's own coordinate system: for a source in
longitude and latitude, project it first (`ogr2ogr -t_srs ...`) for a mesh
in metres. Needs GDAL (only this header does).

\param file the source: a file, a directory of Shapefiles, or anything
`GDALOpenEx()` opens as vector data
\param layer the layer to read; empty for all

\throws Poly_read_error naming the file (and the layer and feature) if the
source cannot be opened as vector data, if `layer` is not one of its
layers, if a feature has no geometry or one that is not a polygon or a
multipolygon, if it holds no polygon at all, or as
`poly_data_from_polygons()` for rings of fewer than three distinct points
or coordinates that are not finite
*/
inline Poly_data read_OGR_polygons(const std::string& file, const std::string& layer = std::string())
{
  static const bool registered = [] {
    GDALAllRegister();
    return true;
  }();
  static_cast<void>(registered);
  CPLErrorReset();
  // GDAL's own messages on stderr would duplicate ours
  CPLPushErrorHandler(CPLQuietErrorHandler);
  struct Pop_handler
  {
    ~Pop_handler() { CPLPopErrorHandler(); }
  } pop;
  std::unique_ptr<void, void (*)(void*)> source(
    GDALOpenEx(file.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY, nullptr, nullptr, nullptr),
    [](void* d) { if(d != nullptr) GDALClose(d); });
  if(!source) {
    std::error_code ec;
    if(!std::filesystem::exists(file, ec)) throw Poly_read_error(file, 0, "cannot open (no such file)");
    throw Poly_read_error(file, 0, "cannot open as vector data" + internal::ogr_last_error());
  }

  std::vector<Polygon_rings> polygons;
  bool found_layer = layer.empty();
  for(int l = 0, nl = GDALDatasetGetLayerCount(source.get()); l < nl; ++l) {
    OGRLayerH lh = GDALDatasetGetLayer(source.get(), l);
    const std::string name = OGR_L_GetName(lh);
    if(!layer.empty() && name != layer) continue;
    found_layer = true;
    OGR_L_ResetReading(lh);
    for(;;) {
      std::unique_ptr<void, void (*)(void*)> feature(OGR_L_GetNextFeature(lh), [](void* f) {
        if(f != nullptr) OGR_F_Destroy(f);
      });
      if(!feature) break;
      const GIntBig fid = OGR_F_GetFID(feature.get());
      OGRGeometryH g = OGR_F_GetGeometryRef(feature.get());
      if(g == nullptr)
        throw Poly_read_error(file, 0, internal::ogr_where(name, fid) + ": no geometry");
      // curves stroked to lines, 3D flattened
      std::unique_ptr<void, void (*)(void*)> linear(OGR_G_GetLinearGeometry(g, 0, nullptr),
                                                    [](void* h) { if(h != nullptr) OGR_G_DestroyGeometry(h); });
      if(!linear)
        throw Poly_read_error(file, 0, internal::ogr_where(name, fid) + ": cannot read the geometry" +
                                         internal::ogr_last_error());
      OGRGeometryH lg = linear.get();
      const OGRwkbGeometryType type = wkbFlatten(OGR_G_GetGeometryType(lg));
      if(type == wkbPolygon) {
        polygons.push_back(internal::ogr_polygon(lg));
      } else if(type == wkbMultiPolygon) {
        for(int k = 0, n = OGR_G_GetGeometryCount(lg); k < n; ++k)
          polygons.push_back(internal::ogr_polygon(OGR_G_GetGeometryRef(lg, k)));
      } else {
        throw Poly_read_error(file, 0, internal::ogr_where(name, fid) + ": a " + OGR_G_GetGeometryName(lg) +
                                         " is not a polygon or a multipolygon");
      }
    }
  }
  if(!found_layer) throw Poly_read_error(file, 0, "no layer named '" + layer + "'");
  if(polygons.empty()) throw Poly_read_error(file, 0, "no polygon");
  return poly_data_from_polygons(polygons, file);
}

} // namespace IO
} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_IO_READ_OGR_POLYGONS_H
