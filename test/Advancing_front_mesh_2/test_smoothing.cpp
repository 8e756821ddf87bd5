// The two smoothers, each with edge swapping (laplacian_smooth_mesh_2,
// quality_smooth_mesh_2): the acceptance figures on the square with a hole,
// validity (constrained Delaunay included) on other geometries, on a Mesh_2
// result, held vertices; the quality smoother's gain on graded meshes.
#include "afm_test_mesh.h"
#include "afm_geometries.h"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Exact_rational.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Advancing_front_mesh_2/Mesh_quality.h>
#include <CGAL/Advancing_front_mesh_2/laplacian_smooth_mesh_2.h>
#include <CGAL/Advancing_front_mesh_2/quality_smooth_mesh_2.h>
#include <CGAL/Delaunay_mesh_size_criteria_2.h>
#include <CGAL/Delaunay_mesher_2.h>

#include <boost/property_map/function_property_map.hpp>

#include <map>
#include <set>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef afm_test::Types<K>::CDT CDT;
typedef K::Point_2 Point;

enum class Smoother { laplacian, quality };
const Smoother smoothers[] = {Smoother::laplacian, Smoother::quality};

std::string name(Smoother s) { return s == Smoother::laplacian ? "Laplacian" : "quality"; }

template <class Tr, class NP>
CGAL::Advancing_front_mesh_2::Smoothing_statistics smooth(Tr& cdt, Smoother s, const NP& np)
{
  return s == Smoother::laplacian ? CGAL::laplacian_smooth_mesh_2(cdt, np) : CGAL::quality_smooth_mesh_2(cdt, np);
}

template <class Tr>
afm_check::Report smooth_and_check(Tr& cdt, const afm_test::Poly_data& in, std::size_t passes, std::string label,
                                   Smoother smoother,
                                   CGAL::Advancing_front_mesh_2::Smoothing_statistics* out = nullptr)
{
  label = name(smoother) + ", " + label;
  const afm_check::Report before = afm_test::check_split_mesh(in, afm_test::extract_mesh(cdt));
  const auto st = smooth(cdt, smoother, CGAL::parameters::number_of_iterations(passes));
  AFM_CHECK(cdt.is_valid());
  const afm_check::Report after = afm_test::check_split_mesh(in, afm_test::extract_mesh(cdt));
  std::cout << "  " << label << ", before: " << before.summary() << "\n  " << label << ", after " << passes
            << " passes (" << st.moves << " moves, " << st.flips << " flips): " << after.summary() << "\n";
  AFM_CHECK_MSG(after.ok, label << ": " << after.summary());
  AFM_CHECK(after.n_triangles == before.n_triangles && after.n_vertices == before.n_vertices);
  AFM_CHECK(st.passes == passes && st.flips_per_pass.size() == passes);
  // the guard: the worst triangle never gets worse
  AFM_CHECK_MSG(after.min_radius_ratio >= before.min_radius_ratio - 1e-12,
                label << ": min radius ratio " << before.min_radius_ratio << " -> " << after.min_radius_ratio);
  if(out) *out = st;
  return after;
}

template <class Tr>
void mesh_into(Tr& cdt, const afm_test::Poly_data& in, double h)
{
  afm_test::build_cdt(cdt, in);
  auto seeds = afm_test::seeds_of<Tr>(in);
  CGAL::advancing_front_mesh_2(cdt, seeds.begin(), seeds.end(), h);
}

} // namespace

// The acceptance case: square with a hole, h = 0.01, 5 passes.
AFM_TEST_CASE(test_smoothing_square_with_hole)
{
  const auto in = afm_geometry::square_with_circular_hole(1.0, 0.25, 0.01);
  for(const Smoother s : smoothers) {
    CDT cdt;
    mesh_into(cdt, in, 0.01);
    const auto r = smooth_and_check(cdt, in, 5, "square with hole h=0.01", s);
    const auto q = CGAL::Advancing_front_mesh_2::mesh_quality(cdt);
    AFM_CHECK_MSG(q.mean_radius_ratio >= 0.98, name(s) << ": mean " << q.mean_radius_ratio);
    AFM_CHECK_MSG(q.share_above_0_9 >= 0.97, name(s) << ": share above 0.9: " << q.share_above_0_9);
    AFM_CHECK_MSG(q.min_angle_degrees >= 30, name(s) << ": min angle " << q.min_angle_degrees);
    AFM_CHECK(r.n_non_delaunay_edges == 0);
  }
}

// The percentiles are the sorted ratios' values at p (n - 1), and the
// histograms count every triangle (the 1% and 5% were once read after a
// later selection had moved them).
AFM_TEST_CASE(test_mesh_quality_percentiles)
{
  const auto in = afm_geometry::square_with_circular_hole(1.0, 0.25, 0.01);
  CDT cdt;
  mesh_into(cdt, in, 0.01);
  const auto q = CGAL::Advancing_front_mesh_2::mesh_quality(cdt);
  std::vector<double> ratios;
  for(auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
    if(f->is_in_domain()) {
      const auto &a = f->vertex(0)->point(), &b = f->vertex(1)->point(), &c = f->vertex(2)->point();
      ratios.push_back(CGAL::Advancing_front_mesh_2::internal::radius_ratio(a.x(), a.y(), b.x(), b.y(), c.x(), c.y()));
    }
  std::sort(ratios.begin(), ratios.end());
  AFM_CHECK(ratios.size() == q.number_of_triangles && ratios.size() > 10000);
  const auto at = [&](double p) { return ratios[std::size_t(p * double(ratios.size() - 1))]; };
  AFM_CHECK_MSG(q.radius_ratio_p1 == at(0.01), q.radius_ratio_p1 << " for " << at(0.01));
  AFM_CHECK_MSG(q.radius_ratio_p5 == at(0.05), q.radius_ratio_p5 << " for " << at(0.05));
  AFM_CHECK_MSG(q.radius_ratio_median == at(0.5), q.radius_ratio_median << " for " << at(0.5));
  AFM_CHECK(q.radius_ratio_p1 < q.radius_ratio_p5 && q.radius_ratio_p5 < q.radius_ratio_median);
  AFM_CHECK(q.min_radius_ratio == ratios.front());
  std::size_t counted = 0, angles = 0;
  for(std::size_t n : q.radius_ratio_histogram) counted += n;
  for(std::size_t n : q.angle_histogram) angles += n;
  AFM_CHECK(counted == ratios.size() && angles == 3 * ratios.size());
}

// Boundary and isolated points never move; a held vertex does not either.
AFM_TEST_CASE(test_smoothing_keeps_boundary_and_held_vertices)
{
  for(const Smoother s : smoothers) {
  const auto in = afm_geometry::l_shape(0.05);
  CDT cdt;
  mesh_into(cdt, in, 0.05);
  std::map<CDT::Vertex_handle, Point> before;
  for(auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) before[v] = v->point();
  // hold one interior vertex
  CDT::Vertex_handle held;
  for(auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
    if(!cdt.are_there_incident_constraints(v)) { held = v; break; }
  AFM_CHECK(held != CDT::Vertex_handle());
  std::set<CDT::Vertex_handle> held_set{held};
  auto held_map = boost::make_function_property_map<CDT::Vertex_handle>(
    [&](CDT::Vertex_handle v) { return held_set.count(v) > 0; });
  const auto st = smooth(cdt, s, CGAL::parameters::number_of_iterations(3).vertex_is_constrained_map(held_map));
  AFM_CHECK(st.moves > 0);
  std::size_t moved = 0;
  for(auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) {
    const bool same = before.at(v) == v->point();
    if(cdt.are_there_incident_constraints(v) || CDT::Vertex_handle(v) == held) AFM_CHECK_MSG(same, name(s));
    moved += !same;
  }
  AFM_CHECK_MSG(moved > 0, name(s));
  }
}

// A many-holes case and a graded one, and the exact kernel.
AFM_TEST_CASE(test_smoothing_other_geometries)
{
  for(const Smoother s : smoothers) {
  {
    const auto in = afm_geometry::many_holes(40, 1);
    CDT cdt;
    mesh_into(cdt, in, 0.02);
    smooth_and_check(cdt, in, 5, "many holes h=0.02", s);
  }
  {
    const auto in = afm_geometry::naca0012_far_field(100, 20, 64);
    CDT cdt;
    afm_test::build_cdt(cdt, in);
    auto seeds = afm_test::seeds_of<CDT>(in);
    CGAL::advancing_front_mesh_2(cdt, seeds.begin(), seeds.end(), afm_test::Boundary_graded_size<K>(in, 0.2));
    smooth_and_check(cdt, in, 5, "NACA 0012 graded", s);
  }
  {
    typedef CGAL::Exact_predicates_exact_constructions_kernel EK;
    typedef afm_test::Types<EK>::CDT ECDT;
    const auto in = afm_geometry::square_with_circular_hole(1.0, 0.25, 0.05);
    ECDT cdt;
    mesh_into(cdt, in, 0.05);
    smooth_and_check(cdt, in, 3, "square with hole, Epeck", s);
  }
  {
    // Exact rationals: new positions are rounded to doubles, so that their
    // size does not grow pass after pass.
    typedef CGAL::Simple_cartesian<CGAL::Exact_rational> RK;
    typedef afm_test::Types<RK>::CDT RCDT;
    const auto in = afm_geometry::square_with_circular_hole(1.0, 0.25, 0.1);
    RCDT cdt;
    mesh_into(cdt, in, 0.1);
    smooth_and_check(cdt, in, 20, "square with hole, exact rationals, 20 passes", s);
    for(auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
      AFM_CHECK(CGAL::Exact_rational(CGAL::to_double(v->point().x())) == v->point().x() &&
                CGAL::Exact_rational(CGAL::to_double(v->point().y())) == v->point().y());
  }
  }
}

// On a CGAL Mesh_2 result: valid, constrained Delaunay, and better shaped.
AFM_TEST_CASE(test_smoothing_mesh_2_result)
{
  for(const Smoother s : smoothers) {
  const auto in = afm_geometry::square_with_circular_hole(1.0, 0.25, 0.02);
  CDT cdt;
  afm_test::build_cdt(cdt, in);
  auto seeds = afm_test::seeds_of<CDT>(in);
  CGAL::refine_Delaunay_mesh_2(cdt, seeds.begin(), seeds.end(), CGAL::Delaunay_mesh_size_criteria_2<CDT>(0.125, 0.03));
  const double mean_before = CGAL::Advancing_front_mesh_2::mesh_quality(cdt).mean_radius_ratio;
  CGAL::Advancing_front_mesh_2::Smoothing_statistics st;
  smooth_and_check(cdt, in, 5, "Mesh_2 result", s, &st);
  const double mean_after = CGAL::Advancing_front_mesh_2::mesh_quality(cdt).mean_radius_ratio;
  AFM_CHECK_MSG(mean_after > mean_before + 0.02, name(s) << ": mean " << mean_before << " -> " << mean_after);
  AFM_CHECK(st.flips > 0); // Mesh_2's meshes are far from smooth: swapping has work to do
  }
}

// On a graded mesh the quality smoother's local optimisation beats the
// Laplacian's moves, pass for pass (the four-element airfoil with the
// boundary spacing graded at 20%: the mean radius ratio 0.941 before
// smoothing, after 2 passes 0.964 by the Laplacian's and 0.967 by the
// quality smoother's moves), and each pass raises the mean.
AFM_TEST_CASE(test_smoothing_quality_beats_laplacian_on_a_graded_mesh)
{
  const auto in = afm_geometry::multi_element_airfoil(15, 64);
  double mean[2] = {0, 0};
  for(const Smoother s : smoothers) {
    CDT cdt;
    afm_test::build_cdt(cdt, in);
    auto seeds = afm_test::seeds_of<CDT>(in);
    CGAL::advancing_front_mesh_2(cdt, seeds.begin(), seeds.end(), afm_test::Boundary_graded_size<K>(in, 0.2));
    double last = CGAL::Advancing_front_mesh_2::mesh_quality(cdt).mean_radius_ratio;
    std::cout << "  " << name(s) << ": mean radius ratio " << last;
    for(int pass = 0; pass < 2; ++pass) {
      smooth_and_check(cdt, in, 1, "four-element airfoil, graded, pass " + std::to_string(pass + 1), s);
      const double now = CGAL::Advancing_front_mesh_2::mesh_quality(cdt).mean_radius_ratio;
      std::cout << " -> " << now;
      AFM_CHECK_MSG(now > last, name(s) << ": pass " << pass + 1 << " " << last << " -> " << now);
      last = now;
    }
    std::cout << "\n";
    mean[s == Smoother::quality] = last;
  }
  AFM_CHECK_MSG(mean[1] > mean[0] + 0.001, "quality " << mean[1] << " against Laplacian " << mean[0]);
}
