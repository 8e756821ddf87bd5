// Robustness: every geometry of the suite (the issue geometries and the
// adversarial ones: a slit of width 1e-7, boundary spacing varying by 1e4
// along a loop, exactly cocircular and one-ulp-off points, a huge hole
// among tiny ones, coordinates near 1e+300 and 1e-300, an offset of 1e9)
// meshed with each kernel of the kernel matrix (Epick, Epeck,
// Simple_cartesian<Exact_rational>); and the degenerate inputs of
// ../shared/data (CDT library test cases, coastlines), each of which must
// give either a valid mesh or a clear error.
#include "afm_geometries.h"
#include "afm_test_mesh.h"

#include <CGAL/Advancing_front_mesh_2/IO/insert_poly.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Exact_rational.h>
#include <CGAL/Simple_cartesian.h>

#include <fstream>
#include <sstream>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Epick;
typedef CGAL::Exact_predicates_exact_constructions_kernel Epeck;
typedef CGAL::Simple_cartesian<CGAL::Exact_rational> Rational_kernel;
typedef afm_test::Poly_data Poly_data;

// A geometry with its size: uniform h, or graded from the boundary spacing
// (grading > 0, at most h).
struct Case
{
  std::string name;
  Poly_data in;
  double h;
  double grading;
};

// 2^996, about 6.7e299: scaling by a power of two is exact
const double huge_scale = std::ldexp(1.0, 996);

std::vector<Case> catalogue()
{
  using namespace afm_geometry;
  std::vector<Case> c;
  c.push_back({"square with hole", square_with_circular_hole(1, 0.25, 0.05), 0.05, 0});
  c.push_back({"L-shape", l_shape(0.1), 0.1, 0});
  c.push_back({"two thin plates (Fig. 9)", two_thin_plates(), 1e300, 0.3});
  c.push_back({"NACA 0012 far field", naca0012_far_field(40, 10, 24), 1e300, 0.3});
  c.push_back({"four-element airfoil", multi_element_airfoil(10, 32), 1e300, 0.3});
  c.push_back({"many holes", many_holes(8, 2), 0.05, 0});
  c.push_back({"nearly collinear boundary (1e-12)", nearly_collinear_boundary(1e-12), 0.05, 0});
  c.push_back({"slit of width 1e-7", square_with_slit(1e-7, 0.05), 0.05, 0});
  c.push_back({"boundary spacing varying by 1e4 on one loop", graded_circle(1e4, 0.4), 0.4, 0.3});
  c.push_back({"boundary spacing varying by 1e4, uniform size 0.2", graded_circle(1e4, 0.4), 0.2, 0});
  c.push_back({"cocircular and one-ulp-off points", cocircular_points(), 0.5, 0});
  c.push_back({"huge hole among tiny ones", huge_and_tiny_holes(60), 0.5, 0.3});
  c.push_back({"offset by 1e9", offset(square_with_circular_hole(1, 0.25, 0.05), 1e9, 1e9), 0.05, 0});
  c.push_back({"scaled to 1e+300", scaled(square_with_circular_hole(1, 0.25, 0.05), huge_scale), 0.05 * huge_scale, 0});
  c.push_back({"scaled to 1e-300", scaled(square_with_circular_hole(1, 0.25, 0.05), 1 / huge_scale), 0.05 / huge_scale,
               0});
  return c;
}

template <class K>
struct Case_size
{
  afm_test::Boundary_graded_size<K> graded;
  double h;
  bool uniform;
  Case_size(const Case& c) : graded(c.in, c.grading > 0 ? c.grading : 1, c.h), h(c.h), uniform(c.grading <= 0) {}
  typename K::FT operator()(const typename K::Point_2& p) const
  {
    return uniform ? typename K::FT(h) : graded(p);
  }
};

template <class K>
void mesh_catalogue(const std::string& kernel, std::size_t check_front_every)
{
  typedef typename afm_test::Types<K>::CDT CDT;
  for(const Case& c : catalogue())
    afm_test::mesh_and_check<CDT>(c.in, Case_size<K>(c), kernel + ": " + c.name, check_front_every);
}

// The CDT library's format: "nVertices nEdges", the vertices "x y", the
// edges "i j" (0-based). Holes are implied there by even-odd nesting, which
// the mesher does not do: every bounded region is meshed.
bool read_cdt_txt(const std::string& path, Poly_data& out, std::string& why)
{
  std::ifstream in(path);
  std::size_t nv = 0, ne = 0;
  if(!(in >> nv >> ne)) {
    why = "no header";
    return false;
  }
  for(std::size_t i = 0; i < nv; ++i) {
    double x, y;
    if(!(in >> x >> y)) {
      why = "truncated vertices";
      return false;
    }
    out.points.push_back({{x, y}});
  }
  for(std::size_t i = 0; i < ne; ++i) {
    std::size_t a, b;
    if(!(in >> a >> b) || a >= nv || b >= nv) {
      why = "bad edge " + std::to_string(i);
      return false;
    }
    out.segments.push_back({{a, b}});
  }
  return true;
}

} // namespace

AFM_TEST_CASE(test_robustness_epick)
{
  mesh_catalogue<Epick>("Epick", 13);
}

AFM_TEST_CASE(test_kernel_matrix_epeck)
{
  mesh_catalogue<Epeck>("Epeck", 0);
}

AFM_TEST_CASE(test_kernel_matrix_exact_rational)
{
  mesh_catalogue<Rational_kernel>("Simple_cartesian<Exact_rational>", 0);
}

// Each file of the CDT library's inputs (and the other degenerate inputs of
// ../shared/data) either meshes into a valid mesh or is refused with a
// Poly_read_error; which one is pinned, so that a change shows.
AFM_TEST_CASE(test_shared_data_degenerate_inputs)
{
  typedef afm_test::Types<Epick>::CDT CDT;
  const std::string dir = afm_test::shared_data_dir();
  if(dir.empty() || !std::ifstream(dir + "/cdt_artem-ogre/kidney.txt")) {
    std::cout << "  skipped: no ../shared/data/cdt_artem-ogre\n";
    return;
  }
  struct Expected { const char* file; const char* error; };  // error: empty for a mesh
  const Expected files[] = {
    // its one open polyline lies in the sea, outside every region: refused
    // here, meshed below without it
    {"Constrained Sweden.txt", "the boundary is open at vertex 63"},
    {"Orange County.txt", ""},
    {"guitar.txt", ""},
    {"guitar no box.txt", ""},
    {"island.txt", ""},
    {"kidney.txt", ""},
    {"gh_issue.txt", ""},
    {"ditch.txt", ""},
    {"cdt.txt", "zero length"},
    {"square with crack.txt", ""},
    {"overlapping constraints.txt", "overlaps"},
    {"issue-42-hole-overlaps-bondary.txt", "segment 4 overlaps segment 0"},
    {"issue-42-multiple-boundary-overlaps.txt", "segment 4 overlaps segment 0"},
    {"Hanging2.txt", ""},
    {"corner cases.txt", "segment 1 overlaps segment 0"},
    {"crossing-edges.txt", "crosses"},
  };
  auto mesh_file = [&](const std::string& file, Poly_data in, const std::string& expected_error) {
    CDT cdt;
    std::string error;
    CGAL::Advancing_front_mesh_2::IO::Poly_insertion<CDT> inserted;
    try {
      inserted = CGAL::Advancing_front_mesh_2::IO::insert_poly(cdt, in);
    } catch(const CGAL::Advancing_front_mesh_2::IO::Poly_read_error& x) {
      error = x.what();
    }
    std::cout << "  " << file << ": " << (error.empty() ? "accepted" : error) << "\n";
    if(!expected_error.empty()) {
      AFM_CHECK_MSG(error.find(expected_error) != std::string::npos,
                    file << ": expected '" << expected_error << "', got '" << error << "'");
      return;
    }
    AFM_CHECK_MSG(error.empty(), file << ": refused: " << error);
    afm_test::Boundary_graded_size<Epick> size(in, 0.3);
    CGAL::Advancing_front_mesher_2<CDT, afm_test::Boundary_graded_size<Epick> > mesher(cdt, size);
    mesher.set_seeds(inserted.hole_seeds.begin(), inserted.hole_seeds.end());
    AFM_CHECK(mesher.refine_mesh() == CGAL::Advancing_front_mesh_2::MESH_COMPLETE);
    AFM_CHECK_MSG(mesher.statistics().delaunay_repair_flips == 0, file);
    AFM_CHECK_MSG(cdt.is_valid(), file);
    const auto report = afm_check::check_mesh(afm_test::refined_pslg(cdt, in), afm_test::extract_mesh(cdt));
    std::cout << "    " << report.summary() << "\n";
    AFM_CHECK_MSG(report.ok, file << ": " << report.summary());
  };
  for(const Expected& e : files) {
    Poly_data in;
    std::string why;
    AFM_CHECK_MSG(read_cdt_txt(dir + "/cdt_artem-ogre/" + e.file, in, why), e.file << ": " << why);
    in.origin.file = e.file;
    mesh_file(e.file, in, e.error);
    if(std::string(e.file) == "Constrained Sweden.txt") {
      // the coastline without its open polyline: segments at an end of a
      // chain pruned until only closed loops are left
      for(bool pruned = true; pruned;) {
        pruned = false;
        std::vector<int> degree(in.points.size(), 0);
        for(const auto& sg : in.segments) ++degree[sg[0]], ++degree[sg[1]];
        std::vector<std::array<std::size_t, 2> > kept;
        for(const auto& sg : in.segments)
          if(degree[sg[0]] > 1 && degree[sg[1]] > 1) kept.push_back(sg);
          else pruned = true;
        in.segments.swap(kept);
      }
      mesh_file("Constrained Sweden.txt, closed loops only", in, "");
    }
  }
}
