// The real geometries of ../shared/data that are plain polygons, meshed and
// checked. Each case returns early (passes trivially, saying so) when the
// folder is not beside the checkout.
#include "afm_test_mesh.h"
#include "afm_shared_data.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <fstream>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef afm_test::Types<K>::CDT CDT;

bool have_data(const std::string& relative)
{
  const std::string dir = afm_test::shared_data_dir();
  if(dir.empty() || !std::ifstream(dir + "/" + relative)) {
    std::cout << "  skipped: " << relative << " not found under '" << dir << "'\n";
    return false;
  }
  return true;
}

} // namespace

AFM_TEST_CASE(test_data_30p30n)
{
  if(!have_data("30p30n_linuxguy123/30P-30N-Main-raw.dat")) return;
  const auto in = afm_shared_data::thirty_p_thirty_n(afm_test::shared_data_dir(), 20, 96);
  afm_test::mesh_and_check<CDT>(in, afm_test::Boundary_graded_size<K>(in, 0.2), "30P-30N");
}

AFM_TEST_CASE(test_data_nlr7301_flap)
{
  if(!have_data("nlr7301_viiflow/NLR7301.dat")) return;
  const auto in = afm_shared_data::nlr7301_with_flap(afm_test::shared_data_dir());
  afm_test::mesh_and_check<CDT>(in, afm_test::Boundary_graded_size<K>(in, 0.2), "NLR 7301 with flap");
}

AFM_TEST_CASE(test_data_mesh2d_lake)
{
  if(!have_data("mesh2d/lake.msh")) return;
  const auto in = afm_shared_data::mesh2d_jigsaw(afm_test::shared_data_dir() + "/mesh2d/lake.msh");
  afm_test::mesh_and_check<CDT>(in, afm_test::uniform<K>(0.1), "MESH2D lake");
}

AFM_TEST_CASE(test_data_mesh2d_islands)
{
  if(!have_data("mesh2d/islands.msh")) return;
  const auto in = afm_shared_data::mesh2d_jigsaw(afm_test::shared_data_dir() + "/mesh2d/islands.msh");
  afm_test::mesh_and_check<CDT>(in, afm_test::Boundary_graded_size<K>(in, 0.2, 0.25), "MESH2D islands");
}

AFM_TEST_CASE(test_data_triangle_A)
{
  if(!have_data("triangle_drufat/A.poly")) return;
  const auto in = afm_shared_data::triangle_poly(afm_test::shared_data_dir() + "/triangle_drufat/A.poly");
  afm_test::mesh_and_check<CDT>(in, afm_test::uniform<K>(0.02), "Triangle A.poly", 9);
}

AFM_TEST_CASE(test_data_triangle_double_hex)
{
  if(!have_data("triangle_drufat/double_hex.poly")) return;
  const auto in = afm_shared_data::triangle_poly(afm_test::shared_data_dir() + "/triangle_drufat/double_hex.poly");
  afm_test::mesh_and_check<CDT>(in, afm_test::uniform<K>(0.02), "Triangle double_hex.poly");
}
