// The same mesher with exact-construction kernels and with
// Simple_cartesian<Exact_rational>: every decision is taken by the kernel's
// predicates, new points are rounded to doubles (notes, step 6).
#include "afm_test_mesh.h"
#include "afm_geometries.h"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_rational.h>
#include <CGAL/Simple_cartesian.h>

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
