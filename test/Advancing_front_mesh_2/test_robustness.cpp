// Robustness: every geometry of the suite (the issue geometries and the
// adversarial ones: a slit of width 1e-7, boundary spacing varying by 1e4
// along a loop, exactly cocircular and one-ulp-off points, a huge hole
// among tiny ones, coordinates near 1e+300 and 1e-300, an offset of 1e9)
// meshed with each kernel of the kernel matrix (Epick, Epeck,
// Simple_cartesian<Exact_rational>); and the degenerate inputs of
// ../shared/data (CDT library test cases, coastlines), each of which must
// give either a valid mesh or a clear error.
#include "afm_gmsh_geo.h"
#include "afm_robustness_catalogue.h"
#include "afm_test_mesh.h"

#include <CGAL/Advancing_front_mesh_2/IO/insert_poly.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Exact_rational.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <fstream>
#include <numeric>
#include <sstream>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Epick;
typedef CGAL::Exact_predicates_exact_constructions_kernel Epeck;
typedef CGAL::Simple_cartesian<CGAL::Exact_rational> Rational_kernel;
typedef afm_test::Poly_data Poly_data;
using afm_robustness::Case;
using afm_robustness::Case_size;
using afm_robustness::catalogue;
using afm_robustness::read_cdt_txt;

template <class K>
void mesh_catalogue(const std::string& kernel, std::size_t check_front_every)
{
  typedef typename afm_test::Types<K>::CDT CDT;
  for(const Case& c : catalogue())
    afm_test::mesh_and_check<CDT>(c.in, Case_size<K>(c), kernel + ": " + c.name, check_front_every);
}

// Inserts `in` and meshes it with the boundary-graded size, or expects
// insert_poly() to refuse it with `expected_error` (when not empty).
void mesh_or_refuse(const std::string& file, const Poly_data& in, const std::string& expected_error)
{
  typedef afm_test::Types<Epick>::CDT CDT;
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
  if(!error.empty()) return;
  afm_test::Boundary_graded_size<Epick> size(in, 0.3);
  afm_test::Mesher<CDT, afm_test::Boundary_graded_size<Epick> > mesher(cdt, size);
  mesher.set_seeds(inserted.hole_seeds.begin(), inserted.hole_seeds.end());
  AFM_CHECK(mesher.refine_mesh() == CGAL::Advancing_front_mesh_2::MESH_COMPLETE);
  AFM_CHECK_MSG(mesher.statistics().delaunay_repair_flips == 0, file);
  AFM_CHECK_MSG(cdt.is_valid(), file);
  const auto report = afm_test::check_split_mesh(in, afm_test::extract_mesh(cdt));
  std::cout << "    " << report.summary() << "\n";
  AFM_CHECK_MSG(report.ok, file << ": " << report.summary());
}

// Removes the closed loops (connected components of the segments) holding
// the segments ks, and the hole seeds they enclose. Their points stay, as
// free points of the region around them.
void remove_loops_of_segments(Poly_data& in, const std::vector<std::size_t>& ks)
{
  std::vector<std::size_t> parent(in.points.size());
  std::iota(parent.begin(), parent.end(), std::size_t(0));
  auto root = [&parent](std::size_t i) {
    while(parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  for(const auto& sg : in.segments) parent[root(sg[0])] = root(sg[1]);
  std::vector<std::size_t> loops;
  for(std::size_t k : ks) loops.push_back(root(in.segments[k][0]));
  std::vector<std::array<std::size_t, 2> > kept;
  std::vector<std::vector<std::array<std::size_t, 2> > > removed(loops.size());
  for(const auto& sg : in.segments) {
    const auto l = std::find(loops.begin(), loops.end(), root(sg[0]));
    if(l == loops.end()) kept.push_back(sg);
    else removed[std::size_t(l - loops.begin())].push_back(sg);
  }
  // even-odd crossings of a ray to the right: the seeds lie well inside
  auto inside = [&in](const std::array<double, 2>& h, const std::vector<std::array<std::size_t, 2> >& loop) {
    bool odd = false;
    for(const auto& sg : loop) {
      const auto& a = in.points[sg[0]];
      const auto& b = in.points[sg[1]];
      if((a[1] > h[1]) != (b[1] > h[1]) && h[0] < a[0] + (h[1] - a[1]) / (b[1] - a[1]) * (b[0] - a[0]))
        odd = !odd;
    }
    return odd;
  };
  std::vector<std::array<double, 2> > holes;
  for(const auto& h : in.holes)
    if(std::none_of(removed.begin(), removed.end(), [&](const auto& loop) { return inside(h, loop); }))
      holes.push_back(h);
  in.segments.swap(kept);
  in.holes.swap(holes);
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

// The mesher works in coordinates scaled by a power of two, so a domain near
// 1e+300 or 1e-300 gets exactly the mesh it gets at unit scale, scaled
// (before, squared lengths overflowed near 1e+300 and 103 of 115 front
// edges were closed on existing points).
AFM_TEST_CASE(test_scale_invariance)
{
  typedef afm_test::Types<Epick>::CDT CDT;
  typedef afm_test::Boundary_graded_size<Epick> Graded;
  const Poly_data unit = afm_geometry::square_with_circular_hole(1, 0.25, 0.02);
  // graded from the boundary spacing up to 0.1: sizes that vary with the
  // position, which must be evaluated at the user's coordinates
  const auto reference = afm_test::mesh_and_check<CDT>(unit, Graded(unit, 0.3, 0.1), "unit scale");
  auto sorted_vertices = [](afm_check::Mesh m, double scale) {
    for(auto& v : m.vertices) v = {{v[0] * scale, v[1] * scale}};
    std::sort(m.vertices.begin(), m.vertices.end());
    return m.vertices;
  };
  for(const double scale : {afm_robustness::huge_scale, 1 / afm_robustness::huge_scale}) {
    std::ostringstream label;
    label << "scaled by " << scale;
    const Poly_data in = afm_geometry::scaled(unit, scale);
    const auto r = afm_test::mesh_and_check<CDT>(in, Graded(in, 0.3, 0.1 * scale), label.str());
    AFM_CHECK_MSG(r.mesh.triangles.size() == reference.mesh.triangles.size(),
                  label.str() << ": " << r.mesh.triangles.size() << " triangles, " << reference.mesh.triangles.size()
                              << " at unit scale");
    AFM_CHECK_MSG(sorted_vertices(r.mesh, 1 / scale) == sorted_vertices(reference.mesh, 1), label.str());
    AFM_CHECK_MSG(r.stats.forced_closures == reference.stats.forced_closures, label.str());
  }
  // A size far beyond the domain, 1e9 for a domain near 1e-300, is larger
  // than any double once scaled: it is taken as no bound, as 1e300 is at
  // unit scale.
  const auto unbounded = afm_test::mesh_and_check<CDT>(unit, afm_test::uniform<Epick>(1e300), "unit scale, size 1e300");
  const Poly_data tiny = afm_geometry::scaled(unit, 1 / afm_robustness::huge_scale);
  const auto r = afm_test::mesh_and_check<CDT>(tiny, afm_test::uniform<Epick>(1e9), "scaled to 1e-300, size 1e9");
  AFM_CHECK_MSG(sorted_vertices(r.mesh, afm_robustness::huge_scale) == sorted_vertices(unbounded.mesh, 1),
                r.mesh.triangles.size() << " triangles, " << unbounded.mesh.triangles.size() << " at unit scale");
}

// Each file of the CDT library's inputs (and the other degenerate inputs of
// ../shared/data) either meshes into a valid mesh or is refused with a
// Poly_read_error; which one is pinned, so that a change shows.
AFM_TEST_CASE(test_shared_data_degenerate_inputs)
{
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
  for(const Expected& e : files) {
    Poly_data in;
    std::string why;
    AFM_CHECK_MSG(read_cdt_txt(dir + "/cdt_artem-ogre/" + e.file, in, why), e.file << ": " << why);
    in.origin.file = e.file;
    mesh_or_refuse(e.file, in, e.error);
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
      mesh_or_refuse("Constrained Sweden.txt, closed loops only", in, "");
    }
  }
}

// The classic .poly inputs of ../shared/data through the library's reader:
// Triangle's face.poly (dangling segments, free points, holes), la.poly
// (layers meeting at vertices of degree 3 and 4), Mesh_2's clusters.poly
// (segments fanning out of one vertex) and fish-and-rectangle.poly
// (segments between two holes). Each meshes into a valid mesh or is
// refused with a clear error; which one is pinned.
AFM_TEST_CASE(test_shared_data_poly_inputs)
{
  const std::string dir = afm_test::shared_data_dir();
  if(dir.empty() || !std::ifstream(dir + "/triangle_drufat/face.poly")) {
    std::cout << "  skipped: no ../shared/data/triangle_drufat\n";
    return;
  }
  struct Expected { const char* file; const char* error; };  // error: empty for a mesh
  const Expected files[] = {
    {"triangle_drufat/A.poly", ""},
    {"triangle_drufat/face.poly", ""},
    {"triangle_drufat/la.poly", ""},
    {"triangle_drufat/double_hex3.poly", ""},
    {"triangle_drufat/square_circle_hole.poly", ""},
    // its outer box is one segment and four free corners: Triangle meshes
    // the convex hull, which the mesher does not do
    {"triangle_drufat/box.poly", "the boundary is open at vertex 1"},
    {"cgal_mesh2/clusters.poly", ""},
    {"cgal_mesh2/fish-and-rectangle.poly", ""},
    // no hole section: Triangle's reader refuses it too
    {"cgal_mesh2/fish.poly", "expected the hole header"},
  };
  for(const Expected& e : files) {
    Poly_data in;
    try {
      in = CGAL::Advancing_front_mesh_2::IO::read_poly(dir + "/" + e.file);
    } catch(const CGAL::Advancing_front_mesh_2::IO::Poly_read_error& x) {
      std::cout << "  " << e.file << ": " << x.what() << "\n";
      AFM_CHECK_MSG(*e.error != 0 && std::string(x.what()).find(e.error) != std::string::npos,
                    e.file << ": " << x.what());
      continue;
    }
    mesh_or_refuse(e.file, in, e.error);
  }
}

// The coastlines of Gmsh's benchmarks (../shared/data/gmsh), read from their
// .geo scripts with the curves' listed points as polylines: the North
// Atlantic with 60 islands (ocean.geo, straight lines) and the British Isles
// (uk.geo, B-spline control polygons) mesh validly; in the Mediterranean two
// islands' control polygons cross, which insert_poly() refuses; in world.geo
// the ocean is unbounded in the projection plane, so the largest continent
// is what is left to mesh. The Mediterranean without the two crossing
// islands meshes validly.
AFM_TEST_CASE(test_shared_data_gmsh_coastlines)
{
  const std::string dir = afm_test::shared_data_dir();
  if(dir.empty() || !std::ifstream(dir + "/gmsh/ocean.geo")) {
    std::cout << "  skipped: no ../shared/data/gmsh\n";
    return;
  }
  struct Expected { const char* file; const char* error; std::size_t holes; };
  const Expected files[] = {
    {"gmsh/ocean.geo", "", 60},
    {"gmsh/uk.geo", "", 39},
    {"gmsh/mediterranean.geo", "segment 2556 crosses segment 2398", 125},
    {"gmsh/world.geo", "", 22},
  };
  for(const Expected& e : files) {
    const Poly_data in = afm_gmsh_geo::read_plane_surface(dir + "/" + e.file);
    AFM_CHECK_MSG(in.holes.size() == e.holes, e.file << ": " << in.holes.size() << " holes");
    mesh_or_refuse(e.file, in, e.error);
  }
  Poly_data med = afm_gmsh_geo::read_plane_surface(dir + "/gmsh/mediterranean.geo");
  remove_loops_of_segments(med, {2556, 2398});
  AFM_CHECK_MSG(med.holes.size() == 123, med.holes.size());
  mesh_or_refuse("gmsh/mediterranean.geo without the two crossing islands", med, "");
}
