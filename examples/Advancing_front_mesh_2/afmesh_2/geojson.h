// afmesh_2: polygons from GeoJSON (RFC 7946) files, read with nlohmann-json:
// Polygon and MultiPolygon geometries, alone, in a Feature, a
// FeatureCollection or a GeometryCollection. Coordinates are used as they
// are (longitude, latitude in degrees for a file in WGS 84: project it first
// for a mesh in metres); a third coordinate (height) is ignored.
#ifndef AFMESH_2_GEOJSON_H
#define AFMESH_2_GEOJSON_H

#include <CGAL/Advancing_front_mesh_2/IO/Poly_data.h>
#include <CGAL/Advancing_front_mesh_2/IO/Poly_read_error.h>
#include <CGAL/Advancing_front_mesh_2/IO/polygons_to_poly.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace afmesh_2 {

namespace geojson {

typedef CGAL::Advancing_front_mesh_2::IO::Poly_read_error Error;
typedef CGAL::Advancing_front_mesh_2::IO::Polygon_rings Polygon_rings;

struct Reader
{
  std::string file;
  std::vector<Polygon_rings> polygons;

  [[noreturn]] void fail(const std::string& where, const std::string& what) const
  {
    throw Error(file, 0, where + ": " + what);
  }

  std::array<double, 2> position(const nlohmann::json& p, const std::string& where) const
  {
    if(!p.is_array() || p.size() < 2 || p.size() > 3 || !p[0].is_number() || !p[1].is_number())
      fail(where, "a position must be an array of 2 or 3 numbers");
    return {{p[0].get<double>(), p[1].get<double>()}};
  }

  Polygon_rings polygon(const nlohmann::json& rings, const std::string& where) const
  {
    if(!rings.is_array() || rings.empty()) fail(where, "a Polygon's coordinates must be a non-empty array of rings");
    Polygon_rings out;
    for(std::size_t r = 0; r < rings.size(); ++r) {
      const std::string ring_where = where + ", ring " + std::to_string(r + 1);
      if(!rings[r].is_array()) fail(ring_where, "a ring must be an array of positions");
      std::vector<std::array<double, 2> > ring;
      for(std::size_t i = 0; i < rings[r].size(); ++i)
        ring.push_back(position(rings[r][i], ring_where + ", position " + std::to_string(i + 1)));
      // RFC 7946: a ring is closed, its last position equal to its first
      if(ring.size() < 4 || ring.front() != ring.back())
        fail(ring_where, "a linear ring must have at least 4 positions, the last equal to the first");
      ring.pop_back();
      out.rings.push_back(ring);
    }
    return out;
  }

  void geometry(const nlohmann::json& g, const std::string& where)
  {
    if(!g.is_object() || !g.contains("type") || !g["type"].is_string()) fail(where, "a geometry must be an object with a type");
    const std::string type = g["type"].get<std::string>();
    if(type == "GeometryCollection") {
      if(!g.contains("geometries") || !g["geometries"].is_array()) fail(where, "a GeometryCollection needs geometries");
      for(std::size_t i = 0; i < g["geometries"].size(); ++i)
        geometry(g["geometries"][i], where + ", geometry " + std::to_string(i + 1));
      return;
    }
    if(type != "Polygon" && type != "MultiPolygon")
      fail(where, "a " + type + " is not a polygon (only Polygon and MultiPolygon bound a domain)");
    if(!g.contains("coordinates")) fail(where, "a " + type + " needs coordinates");
    const nlohmann::json& c = g["coordinates"];
    if(type == "Polygon") {
      polygons.push_back(polygon(c, where));
      return;
    }
    if(!c.is_array()) fail(where, "a MultiPolygon's coordinates must be an array of polygons");
    for(std::size_t i = 0; i < c.size(); ++i) polygons.push_back(polygon(c[i], where + ", polygon " + std::to_string(i + 1)));
  }

  void object(const nlohmann::json& j)
  {
    if(!j.is_object() || !j.contains("type") || !j["type"].is_string())
      fail("the file", "a GeoJSON object with a type is expected");
    const std::string type = j["type"].get<std::string>();
    if(type == "FeatureCollection") {
      if(!j.contains("features") || !j["features"].is_array()) fail("the FeatureCollection", "it needs features");
      for(std::size_t i = 0; i < j["features"].size(); ++i) feature(j["features"][i], "feature " + std::to_string(i + 1));
    } else if(type == "Feature") {
      feature(j, "the feature");
    } else {
      geometry(j, "the geometry");
    }
  }

  void feature(const nlohmann::json& f, const std::string& where)
  {
    if(!f.is_object() || !f.contains("geometry")) fail(where, "a Feature needs a geometry");
    if(f["geometry"].is_null()) return; // an unlocated feature bounds nothing
    geometry(f["geometry"], where);
  }
};

} // namespace geojson

// The domain of the polygons of a GeoJSON file, as a planar straight-line
// graph; every problem is an error naming the file (and the line of a
// syntax error).
inline CGAL::Advancing_front_mesh_2::IO::Poly_data read_geojson(const std::string& file)
{
  std::ifstream in(file.c_str(), std::ios::in | std::ios::binary);
  if(!in) throw geojson::Error(file, 0, "cannot open file");
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(text);
  } catch(const nlohmann::json::parse_error& e) {
    const std::size_t at = (std::min)(e.byte == 0 ? 0 : e.byte - 1, text.size());
    const std::size_t line = 1 + std::size_t(std::count(text.begin(), text.begin() + std::ptrdiff_t(at), '\n'));
    throw geojson::Error(file, line, "not valid JSON (" + std::string(e.what()) + ")");
  }
  geojson::Reader r;
  r.file = file;
  r.object(j);
  if(r.polygons.empty()) throw geojson::Error(file, 0, "no Polygon or MultiPolygon in the file");
  return CGAL::Advancing_front_mesh_2::IO::poly_data_from_polygons(r.polygons, file);
}

} // namespace afmesh_2

#endif // AFMESH_2_GEOJSON_H
