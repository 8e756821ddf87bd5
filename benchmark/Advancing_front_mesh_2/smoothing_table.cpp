// Quality before and after smoothing, this package against CGAL Mesh_2 (with
// and without lloyd_optimize_mesh_2), on the same input and size, in one run.
// Prints a Markdown table; every mesh is checked by the independent checker
// (constrained Delaunay included), against the input segments as split by
// the mesher (Mesh_2 splits encroached segments; this package never does).
//
//   smoothing_table
#include "afm_geometries.h"
#include "afm_test_mesh.h"

#include <CGAL/Advancing_front_mesh_2/Mesh_quality.h>
#include <CGAL/Advancing_front_mesh_2/Poisson_sizing_field_2.h>
#include <CGAL/Advancing_front_mesh_2/Sizing_field_mesh_criteria_2.h>
#include <CGAL/Advancing_front_mesh_2/laplacian_smooth_mesh_2.h>
#include <CGAL/Advancing_front_mesher_2.h>
#include <CGAL/Delaunay_mesh_vertex_base_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/lloyd_optimize_mesh_2.h>

#include <chrono>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
// Lloyd needs Mesh_2's vertex base; the advancing front works on it too.
typedef CGAL::Triangulation_data_structure_2<CGAL::Delaunay_mesh_vertex_base_2<K>, CGAL::Delaunay_mesh_face_base_2<K> >
  Tds;
typedef CGAL::Constrained_Delaunay_triangulation_2<K, Tds> CDT;
typedef K::Point_2 Point;
namespace AFM = CGAL::Advancing_front_mesh_2;
typedef AFM::Poisson_sizing_field_2<K> Field;
typedef afm_test::Poly_data Poly_data;

double seconds_since(std::chrono::steady_clock::time_point t)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

void print(const std::string& geometry, const std::string& mesher, const CDT& cdt, const Poly_data& in, double seconds)
{
  const AFM::Mesh_quality q = AFM::mesh_quality(cdt);
  const afm_check::Report r = afm_check::check_mesh(afm_test::refined_pslg(cdt, in), afm_test::extract_mesh(cdt));
  std::cout << "| " << geometry << " | " << mesher << " | " << q.number_of_triangles << " | " << std::fixed
            << std::setprecision(3) << seconds << " | " << std::setprecision(4) << q.mean_radius_ratio << " | "
            << q.min_radius_ratio << " | " << std::setprecision(1) << 100 * q.share_above_0_9 << "% | "
            << q.min_angle_degrees << " | " << q.max_angle_degrees << " | "
            << (r.ok ? "valid" : "INVALID: " + r.summary()) << " |\n"
            << std::defaultfloat;
}

// One geometry: the advancing front with the field, then smoothed; Mesh_2
// with the same field (Sizing_field_mesh_criteria_2), then Lloyd, then Lloyd
// and our smoothing.
template <class Sizing>
void compare(const std::string& name, const Poly_data& in, const Sizing& field)
{
  auto fresh = [&](CDT& cdt) { afm_test::build_cdt(cdt, in); };
  auto seeds = afm_test::seeds_of<CDT>(in);
  {
    CDT cdt;
    fresh(cdt);
    auto t = std::chrono::steady_clock::now();
    CGAL::advancing_front_mesh_2(cdt, seeds.begin(), seeds.end(), field);
    const double mesh = seconds_since(t);
    print(name, "advancing front", cdt, in, mesh);
    t = std::chrono::steady_clock::now();
    CGAL::laplacian_smooth_mesh_2(cdt, CGAL::parameters::number_of_iterations(5));
    print(name, "advancing front + smoothing (5 passes)", cdt, in, mesh + seconds_since(t));
  }
  {
    CDT cdt;
    fresh(cdt);
    auto t = std::chrono::steady_clock::now();
    CGAL::refine_Delaunay_mesh_2(cdt, seeds.begin(), seeds.end(), AFM::Sizing_field_mesh_criteria_2<CDT, Sizing>(field));
    const double mesh = seconds_since(t);
    print(name, "Mesh_2", cdt, in, mesh);
    t = std::chrono::steady_clock::now();
    CGAL::lloyd_optimize_mesh_2(cdt, CGAL::parameters::max_iteration_number = 10,
                                CGAL::parameters::seeds_begin = seeds.begin(), CGAL::parameters::seeds_end = seeds.end());
    const double lloyd = seconds_since(t);
    print(name, "Mesh_2 + Lloyd (10 iterations)", cdt, in, mesh + lloyd);
    t = std::chrono::steady_clock::now();
    CGAL::laplacian_smooth_mesh_2(cdt, CGAL::parameters::number_of_iterations(5));
    print(name, "Mesh_2 + Lloyd + our smoothing", cdt, in, mesh + lloyd + seconds_since(t));
  }
}

Field field_of(const Poly_data& in, const std::vector<AFM::Size_source_2<K> >& sources, double max_size = 1e300)
{
  CDT cdt;
  afm_test::build_cdt(cdt, in);
  std::vector<std::pair<Point, K::FT> > spacing;
  AFM::boundary_spacing_2(cdt, std::back_inserter(spacing));
  AFM::Poisson_sizing_field_options o;
  o.max_size = max_size;
  o.boundary_spacing = AFM::Poisson_sizing_field_options::DIFFUSE_WITH_SOURCES; // the paper's field
  return Field(spacing, sources, o);
}

} // namespace

int main()
{
  std::cout << "| geometry | mesher | triangles | time (s) | mean radius ratio | min radius ratio | above 0.9 |"
               " min angle | max angle | checker |\n|---|---|---|---|---|---|---|---|---|---|\n";
  const auto square = afm_geometry::square_with_circular_hole(1.0, 0.25, 0.01);
  compare("square with hole, h = 0.01", square, AFM::Uniform_sizing_field_2<K>(0.01));
  const auto holes = afm_geometry::many_holes(40, 1);
  compare("many holes (40), h = 0.02", holes, AFM::Uniform_sizing_field_2<K>(0.02));
  // the holes' boundaries are finer than 0.02: a field that follows them
  compare("many holes (40), boundary field, max 0.02", holes, field_of(holes, {}, 0.02));
  const auto four = afm_geometry::multi_element_airfoil(15, 64);
  std::vector<AFM::Size_source_2<K> > s;
  for(int i = 0; i < 4; ++i) {
    const double a = i * CGAL_PI / 2;
    s.emplace_back(Point(0.5 + 15 * std::cos(a), 15 * std::sin(a)), 2 * CGAL_PI * 15 / 64);
  }
  for(const auto& p : std::vector<std::array<double, 3> >{{{-0.25, -0.05, 0.012}}, {{-0.03, -0.04, 0.008}},
                                                         {{0.45, 0.15, 0.04}}, {{1.0, 0.02, 0.01}},
                                                         {{1.25, -0.12, 0.015}}, {{1.45, -0.3, 0.03}}})
    s.emplace_back(Point(p[0], p[1]), p[2]);
  compare("four-element airfoil, graded (Fig. 12 field)", four, field_of(four, s));
  return 0;
}
