// Meshing a PSLG with Gmsh through its C++ API, for the mesher comparison.
//
// The PSLG becomes a built-in ("geo") CAD model: one point per PSLG vertex,
// one straight line per segment, one curve loop per boundary loop and one
// plane surface per outer loop with the loops nested directly in it as
// holes. Every line gets a transfinite constraint of 2 nodes, so that each
// input segment is exactly one mesh edge, as with our mesher. PSLG points
// on no segment are embedded in the surface containing them. The size comes
// from Mesh.MeshSizeMin/Max (uniform) or from a size callback (graded
// fields), with every other size source switched off.
#ifndef AFM_BENCHMARK_GMSH_RUNNER_H
#define AFM_BENCHMARK_GMSH_RUNNER_H

#include "bench_common.h"

#include <CGAL/Advancing_front_mesh_2/IO/Poly_data.h>

#include "afm_geometries.h"

#include <gmsh.h>

#include <functional>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace afm_bench {

/// The Gmsh model of a PSLG, prepared once per case (outside the timing):
/// the loops as signed line numbers and how they nest. Building it is the
/// counterpart of the hole seeds our mesher and Mesh_2 receive.
struct Gmsh_geometry
{
  struct Surface
  {
    std::vector<std::vector<int> > wires; // outer loop first, then holes; signed line tags
  };
  const CGAL::Advancing_front_mesh_2::IO::Poly_data* in = nullptr;
  std::vector<Surface> surfaces;
  std::vector<std::pair<int, std::size_t> > embedded; // (point tag, surface index)

  explicit Gmsh_geometry(const CGAL::Advancing_front_mesh_2::IO::Poly_data& pd) : in(&pd)
  {
    std::vector<std::vector<std::size_t> > idx;
    std::string why;
    if(!afm_geometry::extract_loop_indices(pd, idx, &why)) throw std::runtime_error("Gmsh_geometry: " + why);
    std::map<std::pair<std::size_t, std::size_t>, std::size_t> segment_of;
    for(std::size_t s = 0; s < pd.segments.size(); ++s)
      segment_of[std::minmax(pd.segments[s][0], pd.segments[s][1])] = s;
    std::vector<afm_geometry::Loop> loops;
    std::vector<std::vector<int> > wires;
    for(const auto& l : idx) {
      afm_geometry::Loop pl;
      std::vector<int> w;
      for(std::size_t i = 0; i < l.size(); ++i) {
        const std::size_t a = l[i], b = l[(i + 1) % l.size()];
        const std::size_t s = segment_of.at(std::minmax(a, b));
        // line s + 1 runs from segments[s][0] to segments[s][1]
        w.push_back(pd.segments[s][0] == a ? int(s + 1) : -int(s + 1));
        pl.push_back(pd.points[a]);
      }
      loops.push_back(std::move(pl));
      wires.push_back(std::move(w));
    }
    // even-odd nesting, as the hole seeds of the inputs describe it
    const std::vector<int> level = afm_geometry::loop_levels(loops);
    std::vector<std::size_t> outer_of_surface;
    for(std::size_t i = 0; i < loops.size(); ++i) {
      if(level[i] % 2 != 0) continue;
      Surface s;
      s.wires.push_back(wires[i]);
      for(std::size_t j = 0; j < loops.size(); ++j)
        if(level[j] == level[i] + 1 && afm_geometry::point_in_polygon(loops[j][0], loops[i]))
          s.wires.push_back(wires[j]);
      surfaces.push_back(std::move(s));
      outer_of_surface.push_back(i);
    }
    // points on no segment: in the deepest outer loop containing them
    std::vector<bool> on_segment(pd.points.size(), false);
    for(const auto& s : pd.segments) on_segment[s[0]] = on_segment[s[1]] = true;
    for(std::size_t p = 0; p < pd.points.size(); ++p) {
      if(on_segment[p]) continue;
      int best = -1;
      for(std::size_t k = 0; k < surfaces.size(); ++k) {
        const std::size_t i = outer_of_surface[k];
        if(afm_geometry::point_in_polygon(pd.points[p], loops[i]) &&
           (best < 0 || level[i] > level[outer_of_surface[std::size_t(best)]]))
          best = int(k);
      }
      if(best >= 0) embedded.push_back({int(p + 1), std::size_t(best)});
    }
  }
};

/// What Gmsh produced, read back after the timed part.
struct Gmsh_outcome
{
  double seconds = 0;
  std::size_t peak_bytes = 0;
  std::shared_ptr<afm_check::Mesh> mesh = std::make_shared<afm_check::Mesh>();
};

/// One Gmsh run: `algorithm` 6 (Frontal-Delaunay) or 5 (Delaunay); a
/// uniform size `h` when `size` is empty, else the callback `size(x, y)`;
/// or, when `extend_max` is positive, Gmsh's own size: the boundary mesh's
/// spacing extended into the surface (Mesh.MeshSizeExtendFromBoundary, its
/// default), bounded by `extend_max`. `smoothing`: the passes of Gmsh's
/// vertex relocation after meshing (Mesh.Smoothing), negative for Gmsh's
/// default (1).
/// Timed: building the model and generate(2). Gmsh must be initialised.
inline Gmsh_outcome run_gmsh(const Gmsh_geometry& g, int algorithm, double h,
                             const std::function<double(double, double)>& size, double extend_max = 0,
                             int smoothing = -1)
{
  namespace geo = gmsh::model::geo;
  const auto& pd = *g.in;
  gmsh::clear();
  gmsh::option::setNumber("General.Terminal", 0);
  // every mesher runs on one thread
  gmsh::option::setNumber("General.NumThreads", 1);
  gmsh::option::setNumber("Mesh.Algorithm", algorithm);
  gmsh::option::setNumber("Mesh.Smoothing", smoothing >= 0 ? smoothing : 1);
  gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 0);
  gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 0);
  gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", 0);
  if(extend_max > 0) {
    gmsh::model::mesh::removeSizeCallback();
    gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 1);
    gmsh::option::setNumber("Mesh.MeshSizeMin", 0);
    gmsh::option::setNumber("Mesh.MeshSizeMax", extend_max);
  } else if(size) {
    gmsh::option::setNumber("Mesh.MeshSizeMin", 0);
    gmsh::option::setNumber("Mesh.MeshSizeMax", 1e22);
    gmsh::model::mesh::setSizeCallback(
      [&size](int, int, double x, double y, double) { return size(x, y); });
  } else {
    gmsh::model::mesh::removeSizeCallback();
    gmsh::option::setNumber("Mesh.MeshSizeMin", h);
    gmsh::option::setNumber("Mesh.MeshSizeMax", h);
  }

  Gmsh_outcome out;
  Meter meter;
  meter.start();
  gmsh::model::add("pslg");
  for(std::size_t i = 0; i < pd.points.size(); ++i) geo::addPoint(pd.points[i][0], pd.points[i][1], 0, 0, int(i + 1));
  for(std::size_t s = 0; s < pd.segments.size(); ++s) {
    geo::addLine(int(pd.segments[s][0] + 1), int(pd.segments[s][1] + 1), int(s + 1));
    geo::mesh::setTransfiniteCurve(int(s + 1), 2);
  }
  std::vector<int> surface_tags;
  for(const auto& s : g.surfaces) {
    std::vector<int> wire_tags;
    for(const auto& w : s.wires) wire_tags.push_back(geo::addCurveLoop(w));
    surface_tags.push_back(geo::addPlaneSurface(wire_tags));
  }
  geo::synchronize();
  for(std::size_t k = 0; k < surface_tags.size(); ++k) {
    std::vector<int> points;
    for(const auto& e : g.embedded)
      if(e.second == k) points.push_back(e.first);
    if(!points.empty()) gmsh::model::mesh::embed(0, points, 2, surface_tags[k]);
  }
  gmsh::model::mesh::generate(2);
  meter.stop();
  out.seconds = meter.seconds();
  out.peak_bytes = meter.peak_bytes();

  // read back: nodes by tag, then the 3-node triangles
  std::vector<std::size_t> node_tags, element_tags, element_nodes;
  std::vector<double> coords, parametric;
  gmsh::model::mesh::getNodes(node_tags, coords, parametric, -1, -1, false, false);
  std::size_t max_tag = 0;
  for(std::size_t t : node_tags) max_tag = (std::max)(max_tag, t);
  // numbered in order of appearance in the triangles, as extract_mesh() does
  std::vector<std::size_t> index(max_tag + 1, std::size_t(-1));
  gmsh::model::mesh::getElementsByType(2, element_tags, element_nodes);
  afm_check::Mesh& m = *out.mesh;
  m.triangles.reserve(element_tags.size());
  for(std::size_t e = 0; e < element_tags.size(); ++e) {
    std::array<std::size_t, 3> t;
    for(int k = 0; k < 3; ++k) {
      const std::size_t tag = element_nodes[3 * e + k];
      if(index[tag] == std::size_t(-1)) {
        index[tag] = m.vertices.size();
        m.vertices.push_back({{0, 0}});
      }
      t[k] = index[tag];
    }
    m.triangles.push_back(t);
  }
  for(std::size_t i = 0; i < node_tags.size(); ++i) {
    const std::size_t v = index[node_tags[i]];
    if(v != std::size_t(-1)) m.vertices[v] = {{coords[3 * i], coords[3 * i + 1]}};
  }
  if(size) gmsh::model::mesh::removeSizeCallback();
  gmsh::clear();
  return out;
}

/// Gmsh's version, from the library itself.
inline std::string gmsh_version()
{
  std::string v;
  gmsh::option::getString("General.Version", v);
  return v;
}

} // namespace afm_bench

#endif // AFM_BENCHMARK_GMSH_RUNNER_H
