// Shared helpers of the mesher tests: kernels and triangulation types,
// building a CDT from a PSLG, meshing it through the class or the free
// function, and checking the result with the independent validity checker.
#ifndef AFM_TEST_MESH_H
#define AFM_TEST_MESH_H

#include "afm_test_harness.h"
#include "afm_split_segments.h"
#include "afm_validity_checker.h"

#include <CGAL/Advancing_front_mesher_2.h>
#include <CGAL/Advancing_front_mesh_2/IO/Poly_data.h>

#if defined(AFM_TEST_KD_TREE_POINT_INDEX) || defined(AFM_TEST_BRUTE_FORCE_INDICES)
#include "afm_brute_force_indices.h"
#include <CGAL/Advancing_front_mesh_2/Kd_tree_point_index.h>
#endif

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Constrained_triangulation_plus_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Triangulation_data_structure_2.h>
#include <CGAL/Triangulation_vertex_base_2.h>

#include <array>
#include <chrono>
#include <cmath>
#include <iostream>
#include <list>
#include <map>
#include <string>
#include <vector>

namespace afm_test {

typedef CGAL::Advancing_front_mesh_2::IO::Poly_data Poly_data;

// The search structures the mesher is tested with: the defaults, or, in the
// builds of the mesher's tests named after them (CMakeLists.txt), CGAL's
// Kd_tree as point index, or the brute-force models of both concepts.
#if defined(AFM_TEST_KD_TREE_POINT_INDEX)
typedef CGAL::Advancing_front_mesh_2::Kd_tree_point_index Test_point_index;
typedef CGAL::Default Test_circle_index;
inline const char* search_structures() { return "Kd_tree point index"; }
#elif defined(AFM_TEST_BRUTE_FORCE_INDICES)
typedef Brute_force_point_index Test_point_index;
typedef Brute_force_circle_index<> Test_circle_index;
inline const char* search_structures() { return "brute-force indices"; }
#else
typedef CGAL::Default Test_point_index;
typedef CGAL::Default Test_circle_index;
inline const char* search_structures() { return "default indices"; }
#endif

template <class CDT,
          class Sizing = CGAL::Advancing_front_mesh_2::Uniform_sizing_field_2<typename CDT::Geom_traits>,
          class Visitor = CGAL::Advancing_front_mesh_2::Default_visitor>
using Mesher = CGAL::Advancing_front_mesher_2<CDT, Sizing, Visitor, Test_point_index, Test_circle_index>;

template <class K>
struct Types
{
  typedef CGAL::Triangulation_vertex_base_2<K> Vb;
  typedef CGAL::Delaunay_mesh_face_base_2<K> Fb;
  typedef CGAL::Triangulation_data_structure_2<Vb, Fb> Tds;
  // Constraints of legal input never cross; this tag makes the
  // triangulation refuse (throw) instead of splitting them.
  typedef CGAL::Constrained_Delaunay_triangulation_2<
    K, Tds, CGAL::No_constraint_intersection_requiring_constructions_tag> CDT;
  typedef CGAL::Constrained_triangulation_plus_2<CDT> CDT_plus;
};

template <class CDT>
void build_cdt(CDT& cdt, const Poly_data& in)
{
  typedef typename CDT::Point Point;
  std::vector<typename CDT::Vertex_handle> vh;
  vh.reserve(in.points.size());
  for(const auto& p : in.points) vh.push_back(cdt.insert(Point(p[0], p[1])));
  for(const auto& s : in.segments) cdt.insert_constraint(vh[s[0]], vh[s[1]]);
}

template <class CDT>
std::list<typename CDT::Point> seeds_of(const Poly_data& in)
{
  std::list<typename CDT::Point> seeds;
  for(const auto& h : in.holes) seeds.push_back(typename CDT::Point(h[0], h[1]));
  return seeds;
}

// Inserts `in` into `cdt` with every x divided exactly by `sx` and every
// y by `sy` in the kernel's number type (coordinates that are not doubles
// for an exact kernel), its hole seeds into `seeds`; returns the input as
// the checker reads it, the points and seeds rounded to doubles.
template <class CDT>
Poly_data insert_divided(CDT& cdt, const Poly_data& in, const typename CDT::Geom_traits::FT& sx,
                         const typename CDT::Geom_traits::FT& sy, std::list<typename CDT::Point>& seeds)
{
  typedef typename CDT::Geom_traits::FT FT;
  typedef typename CDT::Point Point;
  Poly_data rounded = in;
  std::vector<typename CDT::Vertex_handle> vh;
  vh.reserve(in.points.size());
  for(std::size_t i = 0; i < in.points.size(); ++i) {
    const Point p(FT(in.points[i][0]) / sx, FT(in.points[i][1]) / sy);
    vh.push_back(cdt.insert(p));
    rounded.points[i] = {{CGAL::to_double(p.x()), CGAL::to_double(p.y())}};
  }
  for(const auto& s : in.segments) cdt.insert_constraint(vh[s[0]], vh[s[1]]);
  for(std::size_t i = 0; i < in.holes.size(); ++i) {
    seeds.push_back(Point(FT(in.holes[i][0]) / sx, FT(in.holes[i][1]) / sy));
    rounded.holes[i] = {{CGAL::to_double(seeds.back().x()), CGAL::to_double(seeds.back().y())}};
  }
  return rounded;
}

inline afm_check::Pslg to_pslg(const Poly_data& in)
{
  afm_check::Pslg p;
  p.points = in.points;
  p.segments = in.segments;
  p.holes = in.holes;
  return p;
}

// The independent checker on a mesh of `in` whose segments may be split
// (the boundary discretisation): each input segment must be covered by a
// chain of mesh edges through the mesh vertices on it.
inline afm_check::Report check_split_mesh(const Poly_data& in, const afm_check::Mesh& mesh)
{
  return afm_check::check_mesh(afm_check::split_at_mesh_vertices(to_pslg(in), mesh), mesh);
}

// The in-domain triangles, with vertices numbered in order of appearance.
template <class CDT>
afm_check::Mesh extract_mesh(const CDT& cdt)
{
  afm_check::Mesh m;
  std::map<typename CDT::Vertex_handle, std::size_t> ids;
  for(auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if(!f->is_in_domain()) continue;
    std::array<std::size_t, 3> t;
    for(int i = 0; i < 3; ++i) {
      auto v = f->vertex(i);
      auto it = ids.find(v);
      if(it == ids.end()) {
        it = ids.emplace(v, m.vertices.size()).first;
        m.vertices.push_back({{CGAL::to_double(v->point().x()), CGAL::to_double(v->point().y())}});
      }
      t[i] = it->second;
    }
    m.triangles.push_back(t);
  }
  return m;
}

struct Result
{
  afm_check::Report report;
  CGAL::Advancing_front_mesh_2::Statistics stats;
  afm_check::Mesh mesh;
  double seconds = 0;
};

// Meshes `in` with the class API and checks everything a mesh must satisfy:
// the independent checker, CGAL's own validity test, the front invariants
// (every `check_front_every` steps when non-zero) and that the advancing
// front built a Delaunay mesh by itself (no repair flip). The segments are
// kept, as in the paper (the front is tested on coarse boundaries), unless
// `split_constraints`.
template <class CDT, class Sizing>
Result mesh_and_check(const Poly_data& in, const Sizing& sizing, const std::string& label,
                      std::size_t check_front_every = 0, bool pocket_priority = true,
                      bool split_constraints = false)
{
  CDT cdt;
  build_cdt(cdt, in);
  auto seeds = seeds_of<CDT>(in);
  Mesher<CDT, Sizing> mesher(cdt, sizing);
  mesher.set_seeds(seeds.begin(), seeds.end());
  mesher.set_pocket_priority(pocket_priority);
  mesher.set_constraint_splitting(split_constraints);
  const auto start = std::chrono::steady_clock::now();
  if(check_front_every == 0) {
    mesher.refine_mesh();
  } else {
    mesher.init();
    AFM_CHECK_MSG(mesher.is_front_valid(), label << ": initial front invalid");
    std::size_t steps = 0;
    while(mesher.step_by_step_refine_mesh())
      if(++steps % check_front_every == 0)
        AFM_CHECK_MSG(mesher.is_front_valid(), label << ": front invalid after step " << steps);
  }
  Result r;
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  r.stats = mesher.statistics();
  AFM_CHECK_MSG(cdt.is_valid(), label << ": CGAL's is_valid() failed");
  r.mesh = extract_mesh(cdt);
  r.report = check_split_mesh(in, r.mesh);
  std::cout << "  " << label << ": " << r.report.summary() << ", " << r.seconds << " s, inserted "
            << r.stats.points_inserted << ", forced " << r.stats.forced_closures << ", largest front "
            << r.stats.largest_front << ", pockets " << r.stats.pockets << "\n";
  AFM_CHECK_MSG(r.report.ok, label << ": " << r.report.summary());
  AFM_CHECK_MSG(r.stats.delaunay_repair_flips == 0,
                label << ": " << r.stats.delaunay_repair_flips << " edges needed a Delaunay repair flip");
  return r;
}

template <class K>
CGAL::Advancing_front_mesh_2::Uniform_sizing_field_2<K> uniform(double h)
{
  return CGAL::Advancing_front_mesh_2::Uniform_sizing_field_2<K>(typename K::FT(h));
}

// A size that agrees with the boundary discretisation and grows away from
// it at a bounded rate: h(p) = min over boundary points i of
// (s_i + grading |p - x_i|), s_i the mean length of the segments at i.
// Brute force over the boundary points, which is fine for test inputs.
template <class K>
struct Boundary_graded_size
{
  std::vector<std::array<double, 3> > sources; // x, y, spacing
  double grading = 0.2;
  double h_max = 1e300;

  Boundary_graded_size(const Poly_data& in, double grading_, double h_max_ = 1e300)
    : grading(grading_), h_max(h_max_)
  {
    std::vector<double> sum(in.points.size(), 0.);
    std::vector<int> count(in.points.size(), 0);
    for(const auto& s : in.segments) {
      const auto& a = in.points[s[0]];
      const auto& b = in.points[s[1]];
      const double l = std::hypot(b[0] - a[0], b[1] - a[1]);
      for(std::size_t v : {s[0], s[1]}) {
        sum[v] += l;
        ++count[v];
      }
    }
    for(std::size_t i = 0; i < in.points.size(); ++i)
      if(count[i] > 0) sources.push_back({{in.points[i][0], in.points[i][1], sum[i] / count[i]}});
  }

  typename K::FT operator()(const typename K::Point_2& p) const
  {
    const double x = CGAL::to_double(p.x()), y = CGAL::to_double(p.y());
    double h = h_max;
    for(const auto& s : sources) h = (std::min)(h, s[2] + grading * std::hypot(x - s[0], y - s[1]));
    return typename K::FT(h);
  }
};

} // namespace afm_test

#endif // AFM_TEST_MESH_H
