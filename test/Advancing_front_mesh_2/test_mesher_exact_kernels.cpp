// The same mesher with exact-construction kernels and with
// Simple_cartesian<Exact_rational>: every decision is taken by the kernel's
// predicates, new points are rounded to doubles (notes, step 6).
#include "afm_test_mesh.h"
#include "afm_geometries.h"
#include "afm_random_pslg.h"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_rational.h>
#include <CGAL/Simple_cartesian.h>

#include <cstdint>
#include <initializer_list>
#include <list>
#include <string>

namespace {
typedef CGAL::Exact_predicates_exact_constructions_kernel Epeck;
typedef CGAL::Simple_cartesian<CGAL::Exact_rational> Rational_kernel;

template <class K>
void run_kernel(const std::string& name)
{
  typedef typename afm_test::Types<K>::CDT CDT;
  using afm_test::mesh_and_check;
  using afm_test::uniform;
  mesh_and_check<CDT>(afm_geometry::square_with_circular_hole(1.0, 0.25, 0.05), uniform<K>(0.05),
                      name + ": square with hole", 17);
  mesh_and_check<CDT>(afm_geometry::l_shape(0.1), uniform<K>(0.1), name + ": L-shape");
  mesh_and_check<CDT>(afm_geometry::many_holes(8, 2), uniform<K>(0.05), name + ": many holes");
  mesh_and_check<CDT>(afm_geometry::nearly_collinear_boundary(1e-12), uniform<K>(0.05),
                      name + ": nearly collinear");
  mesh_and_check<CDT>(afm_geometry::offset(afm_geometry::l_shape(0.1), 1e6, -1e6), uniform<K>(0.1),
                      name + ": offset 1e6");
}
} // namespace

AFM_TEST_CASE(test_kernel_epeck)
{
  run_kernel<Epeck>("Epeck");
}

AFM_TEST_CASE(test_kernel_exact_rational)
{
  run_kernel<Rational_kernel>("Simple_cartesian<Exact_rational>");
}

AFM_TEST_CASE(test_kernel_epeck_thin_plates)
{
  typedef afm_test::Types<Epeck>::CDT CDT;
  const auto in = afm_geometry::two_thin_plates();
  afm_test::mesh_and_check<CDT>(in, afm_test::Boundary_graded_size<Epeck>(in, 0.3), "Epeck: two thin plates");
}

namespace {
// Coordinates that are not doubles: random domains with every x divided
// exactly by 3 and every y by 7, meshed at a size small against the
// coordinates' magnitude (a fifth of the parallel test's). The circles'
// error bounds once assumed to_double's promised relative precision (1e-5
// of the magnitude, larger than these triangles), so no triangle was built
// about a new point and later points spiralled into it without end (Epeck:
// domains 1, 5 and 7 of the first eight; Exact_rational: 5 and 7, the two
// tried); the step limit turns that into a failure. The checker reads the mesh
// in doubles: the input points rounded, the segments' split points within
// its tolerance.
template <class K>
void mesh_coordinates_not_doubles(const std::string& name, std::initializer_list<std::uint64_t> seeds_to_run)
{
  typedef typename afm_test::Types<K>::CDT CDT;
  typedef typename K::FT FT;
  typedef typename K::Point_2 Point;
  const FT sx(3), sy(7);
  for(const std::uint64_t seed : seeds_to_run) {
    afm_random::Generator g(seed);
    const afm_random::Domain d = g.domain();
    const double h = g.uniform(0.01, 0.03) * d.scale / 5;
    const std::string label = name + ": seed " + std::to_string(seed) + ", coordinates divided by 3 and 7";
    CDT cdt;
    std::list<Point> seeds;
    const afm_test::Poly_data rounded = afm_test::insert_divided(cdt, d.pslg, sx, sy, seeds);
    afm_test::Mesher<CDT> mesher(cdt, CGAL::Advancing_front_mesh_2::Uniform_sizing_field_2<K>(h));
    mesher.set_seeds(seeds.begin(), seeds.end());
    mesher.init();
    // with Epeck the meshes take 17,959, 19,489 and 3,444 steps; before
    // the fix, domain 1 had made 7,059 points in 20,000 steps, most of them
    // in the spiral
    const std::size_t step_limit = 50000;
    std::size_t steps = 0;
    while(steps < step_limit && mesher.step_by_step_refine_mesh()) ++steps;
    AFM_CHECK_MSG(steps < step_limit, label << ": no end after " << steps << " steps, "
                                            << mesher.statistics().points_inserted << " points inserted");
    AFM_CHECK_MSG(cdt.is_valid(), label << ": CGAL's is_valid() failed");
    const auto report = afm_test::check_split_mesh(rounded, afm_test::extract_mesh(cdt));
    std::cout << "  " << label << ": " << report.summary() << "\n";
    AFM_CHECK_MSG(report.ok, label << ": " << report.summary());
  }
}
} // namespace

AFM_TEST_CASE(test_kernel_epeck_coordinates_not_doubles)
{
  mesh_coordinates_not_doubles<Epeck>("Epeck", {1, 5, 7});
}

// (the rational kernel is slower: one domain)
AFM_TEST_CASE(test_kernel_exact_rational_coordinates_not_doubles)
{
  mesh_coordinates_not_doubles<Rational_kernel>("Simple_cartesian<Exact_rational>", {7});
}
