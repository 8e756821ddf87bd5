// afmesh_2: the input read, inserted into a triangulation, and the size
// field made from it.
#ifndef AFMESH_2_INPUT_H
#define AFMESH_2_INPUT_H

#include "geojson.h"
#include "ogr_input.h"
#include "options.h"

#include <CGAL/Advancing_front_mesh_2/IO/insert_poly.h>
#include <CGAL/Advancing_front_mesh_2/IO/markers_and_regions.h>
#include <CGAL/Advancing_front_mesh_2/IO/read_WKT_polygons.h>
#include <CGAL/Advancing_front_mesh_2/IO/read_gmsh_boundary.h>
#include <CGAL/Advancing_front_mesh_2/IO/read_poly.h>
#include <CGAL/Advancing_front_mesh_2/IO/read_size_sources.h>
#include <CGAL/Advancing_front_mesh_2/Markers_and_regions_2.h>
#include <CGAL/Advancing_front_mesh_2/Poisson_sizing_field_2.h>
#include <CGAL/Advancing_front_mesh_2/Region_sizing_field_2.h>
#include <CGAL/Advancing_front_mesh_2/Sampled_sizing_field_2.h>
#include <CGAL/Advancing_front_mesh_2/split_constraints_to_size_2.h>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Triangulation_data_structure_2.h>
#include <CGAL/Triangulation_vertex_base_2.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <chrono>
#include <iostream>
#include <iterator>
#include <list>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace afmesh_2 {

inline double seconds_since(std::chrono::steady_clock::time_point t)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

template <class K>
struct Types
{
  typedef CGAL::Triangulation_vertex_base_2<K> Vb;
  // Mesh_2's in-domain mark over the constrained face base: all that the
  // mesher and Mesh_2's refinement (--min-angle) use. Mesh_2's default base,
  // Constrained_Delaunay_triangulation_face_base_2, adds the "blind" records
  // of CGAL's constrained Voronoi diagram: 88 bytes a face instead of 64.
  typedef CGAL::Delaunay_mesh_face_base_2<K, CGAL::Constrained_triangulation_face_base_2<K> > Fb;
  typedef CGAL::Triangulation_data_structure_2<Vb, Fb> Tds;
  // legal input has no crossing segments: refuse them instead of splitting
  typedef CGAL::Constrained_Delaunay_triangulation_2<
    K, Tds, CGAL::No_constraint_intersection_requiring_constructions_tag> CDT;
};

// A uniform size, a background field, or (from the Python module) a field
// sampled from a function, so that one mesher type serves all.
template <class K>
struct Cli_base_sizing_field
{
  typedef AFM::Poisson_sizing_field_2<K> Background;
  typedef AFM::Sampled_sizing_field_2<K> Sampled;
  double uniform = 0;
  std::shared_ptr<const Background> background;
  std::shared_ptr<const Sampled> sampled;
  typename K::FT operator()(const typename K::Point_2& p) const
  {
    if(sampled) return (*sampled)(p);
    return background ? (*background)(p) : typename K::FT(uniform);
  }
};

// The base field, bounded in the regions with an area limit.
template <class K>
struct Cli_sizing_field
{
  typedef AFM::Region_sizing_field_2<typename Types<K>::CDT, Cli_base_sizing_field<K> > Region_field;
  Cli_base_sizing_field<K> base;
  // held by value: a copy of the region field shares its regions but has
  // its own locate hint, so each thread of --threads evaluates its own copy
  std::optional<Region_field> regions;
  typename K::FT operator()(const typename K::Point_2& p) const { return regions ? (*regions)(p) : base(p); }
};

// Where the time of the run went before meshing (seconds).
struct Input_times
{
  double read = 0, boundary = 0, size_field = 0, boundary_split = 0;
};

// The input as the mesher needs it.
template <class K>
struct Input
{
  typedef typename Types<K>::CDT CDT;
  AFM::IO::Poly_data poly;
  CDT cdt;
  AFM::IO::Poly_insertion<CDT> inserted;
  AFM::Markers_and_regions_2<CDT> tags;
  std::list<typename K::Point_2> seeds;
  Cli_sizing_field<K> sizing;
  AFM::Constraint_split_statistics split;
  // with --keep-segments: the segments longer than 1.5 local sizes, and the
  // largest number of sizes one of them spans
  std::size_t long_kept_segments = 0, longest_kept_segment_in_sizes = 0;
  Input_times times;
};

// Whether `file` is a Gmsh mesh: its name ends in .msh, in any case.
inline bool is_gmsh_input(const std::string& file)
{
  if(file.size() < 4) return false;
  std::string tail = file.substr(file.size() - 4);
  for(char& c : tail) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return tail == ".msh";
}

// A Gmsh 1D mesh: its line elements are the boundary; a note when the file
// has elements of other types, which are not read.
inline AFM::IO::Poly_data read_gmsh_input(const std::string& file)
{
  AFM::IO::Poly_data d = AFM::IO::read_gmsh_boundary(file);
  if(d.origin.ignored_elements > 0)
    std::cerr << "afmesh_2: note: " << file << ": the boundary is read from the line elements; "
              << d.origin.ignored_elements << " elements of other types (surfaces, volumes) are not read\n";
  return d;
}

// A .poly file; polygons from WKT (.wkt) or GeoJSON (.geojson, .json), or
// through GDAL from other GIS vector formats (Shapefile, GeoPackage, ...);
// the boundary in a Gmsh 1D mesh (.msh).
inline AFM::IO::Poly_data read_input(const std::string& file)
{
  try {
    if(is_gmsh_input(file)) return read_gmsh_input(file);
    if(is_ogr_input(file)) return read_ogr_input(file);
    if(ends_with(file, ".wkt") || ends_with(file, ".WKT")) return AFM::IO::read_WKT_polygons(file);
    if(ends_with(file, ".geojson") || ends_with(file, ".json") || ends_with(file, ".GEOJSON")) return read_geojson(file);
    return AFM::IO::read_poly(file);
  } catch(const AFM::IO::Poly_read_error& e) {
    throw Input_error(e.what());
  }
}

// The boundary, checked on the way (crossings, overlaps, open boundaries,
// misplaced hole seeds: one line naming the file and line).
template <class K>
void insert_boundary(const Options& opt, Input<K>& in)
{
  try {
    in.inserted = AFM::IO::insert_poly(in.cdt, in.poly);
  } catch(const AFM::IO::Poly_read_error& e) {
    throw Input_error(e.what());
  }
  in.seeds.assign(in.inserted.hole_seeds.begin(), in.inserted.hole_seeds.end());
  in.tags = AFM::IO::markers_and_regions(in.poly, in.inserted);
  const auto& ins = in.inserted;
  if(ins.merged_points + ins.duplicate_segments + ins.points_on_segments > 0)
    std::cerr << "afmesh_2: note: " << opt.input << ": " << ins.merged_points << " duplicate points merged, "
              << ins.duplicate_segments << " duplicate segments dropped, " << ins.points_on_segments
              << " points inside segments (split there)\n";
}

template <class K>
std::vector<AFM::Size_source_2<K> > read_sources(const Options& opt)
{
  std::vector<AFM::Size_source_2<K> > sources;
  if(opt.sources.empty()) return sources;
  try {
    for(const auto& s : AFM::IO::read_size_sources(opt.sources))
      sources.emplace_back(typename K::Point_2(s[0], s[1]), s[2]);
  } catch(const AFM::IO::Poly_read_error& e) {
    throw Input_error(e.what());
  }
  return sources;
}

template <class K>
void make_base_size_field(const Options& opt, Input<K>& in, const std::vector<AFM::Size_source_2<K> >& sources)
{
  in.sizing.base.uniform = opt.size;
  if(opt.has_size && sources.empty()) return;
  std::vector<std::pair<typename K::Point_2, typename K::FT> > spacing;
  AFM::boundary_spacing_2(in.cdt, std::back_inserter(spacing));
  if(spacing.empty() && sources.empty())
    throw Input_error(opt.input + ": no segments to derive a size from; give --size or --sources");
  AFM::Poisson_sizing_field_options field_options;
  field_options.limit_gradation = opt.gradation > 0;
  if(opt.gradation > 0) field_options.gradation = opt.gradation;
  if(opt.has_size) field_options.max_size = opt.size;
  if(opt.boundary_spacing == "diffuse")
    field_options.boundary_spacing = AFM::Poisson_sizing_field_options::DIFFUSE_WITH_SOURCES;
  in.sizing.base.background = std::make_shared<AFM::Poisson_sizing_field_2<K> >(spacing, sources, field_options);
}

// The area limits of the regions, on whatever base field `in` has.
template <class K>
void limit_size_in_regions(Input<K>& in)
{
  if(in.tags.has_area_limits())
    in.sizing.regions.emplace(in.cdt, in.tags, in.sizing.base);
}

// --size alone: uniform; otherwise the background field of the boundary
// spacing (grown, or diffused with --boundary-spacing diffuse) and the
// sources (diffused), bounded above by --size when given. Either is then
// bounded in the regions that have an area limit.
template <class K>
void make_size_field(const Options& opt, Input<K>& in, const std::vector<AFM::Size_source_2<K> >& sources)
{
  make_base_size_field(opt, in, sources);
  limit_size_in_regions(in);
}

// The size field of a run from files: the sources of --sources.
template <class K>
void make_size_field(const Options& opt, Input<K>& in)
{
  make_size_field(opt, in, read_sources<K>(opt));
}

// The boundary discretisation: the segments split to the size field, their
// markers carried over; with --keep-segments only a count, and a note when
// segments much longer than the local size stay whole.
template <class K>
void split_boundary(const Options& opt, Input<K>& in)
{
  typedef typename Types<K>::CDT CDT;
  const AFM::Constraint_touches_domain<CDT> in_domain{&in.cdt};
  if(!opt.keep_segments) {
    in.split = AFM::split_constraints_to_size_2(
      in.cdt, in.sizing, in_domain,
      [&](typename CDT::Vertex_handle a, typename CDT::Vertex_handle b, typename CDT::Vertex_handle v) {
        in.tags.split_constraint(a, b, v);
      });
    // the faces the cuts made are marked as the input's were (the tagging
    // sink of a streamed run reads the regions and the boundary from them),
    // even when no cut went in: one left out may have made new faces
    CGAL::Delaunay_mesher_2<CDT, CGAL::Delaunay_mesh_criteria_2<CDT> >::mark_facets(in.cdt, in.seeds.begin(),
                                                                                   in.seeds.end());
    return;
  }
  for(const auto& e : in.cdt.constrained_edges()) {
    if(!in_domain(e)) continue;
    const auto& p = e.first->vertex(CDT::ccw(e.second))->point();
    const auto& q = e.first->vertex(CDT::cw(e.second))->point();
    const double ax = CGAL::to_double(p.x()), ay = CGAL::to_double(p.y());
    const double bx = CGAL::to_double(q.x()), by = CGAL::to_double(q.y());
    const std::size_t pieces = AFM::internal::segment_cut_parameters(std::hypot(bx - ax, by - ay), [&](double t) {
      return CGAL::to_double(in.sizing(typename K::Point_2(ax + t * (bx - ax), ay + t * (by - ay))));
    }).size() + 1;
    if(pieces < 2) continue;
    ++in.long_kept_segments;
    in.longest_kept_segment_in_sizes = (std::max)(in.longest_kept_segment_in_sizes, pieces);
  }
  if(in.long_kept_segments > 0)
    std::cerr << "afmesh_2: note: " << opt.input << ": --keep-segments: " << in.long_kept_segments
              << " segments are longer than 1.5 local sizes (the longest spans about "
              << in.longest_kept_segment_in_sizes
              << "); the triangles along them are larger and flatter than the size asks\n";
}

} // namespace afmesh_2

#endif // AFMESH_2_INPUT_H
