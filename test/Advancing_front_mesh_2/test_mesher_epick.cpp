// Mesher tests with the default kernel (Exact_predicates_inexact_constructions_kernel):
// the geometries of the issue, determinism, class API against the free function.
#include "afm_test_mesh.h"
#include "afm_geometries.h"

#include <CGAL/Advancing_front_mesh_2/IO/insert_poly.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Delaunay_mesh_size_criteria_2.h>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef afm_test::Types<K>::CDT CDT;
typedef K::Point_2 Point;
using afm_test::mesh_and_check;
using afm_test::uniform;

// A size growing linearly with the distance from a centre, as far fields need.
struct Graded_size
{
  double h0, growth, cx, cy;
  K::FT operator()(const Point& p) const
  {
    return h0 + growth * std::hypot(p.x() - cx, p.y() - cy);
  }
};

} // namespace

// The acceptance case of the issue: uniform h = 0.01, no smoothing.
AFM_TEST_CASE(test_square_with_hole_quality)
{
  const auto in = afm_geometry::square_with_circular_hole(1.0, 0.25, 0.01);
  const auto r = mesh_and_check<CDT>(in, uniform<K>(0.01), "square with hole h=0.01");
  AFM_CHECK_MSG(r.report.mean_radius_ratio >= 0.95, "mean radius ratio " << r.report.mean_radius_ratio);
  AFM_CHECK(r.report.n_triangles > 15000 && r.report.n_triangles < 25000);
  // the working set: the front stays a small fraction of the mesh
  AFM_CHECK_MSG(r.stats.largest_front < r.report.n_vertices / 5,
                "largest front " << r.stats.largest_front << " of " << r.report.n_vertices << " vertices");
}

// Pockets of the front meshed first: the front stays smaller than in plain
// shortest-first order (at h = 0.003, 2.7k edges at most against 9.1k), the
// mesh is as valid, and the front's loops stay consistent through the
// re-queued pocket edges (checked every 97 steps).
AFM_TEST_CASE(test_pocket_priority)
{
  const double h = 0.003;
  const auto in = afm_geometry::square_with_circular_hole(1.0, 0.25, h);
  const auto plain = mesh_and_check<CDT>(in, uniform<K>(h), "square with hole h=0.003, shortest first", 0, false);
  const auto pockets = mesh_and_check<CDT>(in, uniform<K>(h), "square with hole h=0.003, pockets first", 97, true);
  AFM_CHECK_MSG(plain.stats.pockets == 0, plain.stats.pockets);
  AFM_CHECK_MSG(pockets.stats.pockets > 0, pockets.stats.pockets);
  AFM_CHECK_MSG(2 * pockets.stats.largest_front < plain.stats.largest_front,
                "largest front " << pockets.stats.largest_front << " with pockets first, "
                                 << plain.stats.largest_front << " without");
  AFM_CHECK_MSG(pockets.report.mean_radius_ratio > 0.99, pockets.report.mean_radius_ratio);
  AFM_CHECK_MSG(pockets.stats.memory_compactions > 0, pockets.stats.memory_compactions);
}

AFM_TEST_CASE(test_square_with_hole_front_invariants)
{
  // step by step, checking the front's loops after every step; the
  // records of the active vertices are renumbered on the way (memory
  // release), and the checks also cover the steps after that
  const auto in = afm_geometry::square_with_circular_hole(1.0, 0.25, 0.05);
  const auto r = mesh_and_check<CDT>(in, uniform<K>(0.05), "square with hole, front checked", 1);
  AFM_CHECK_MSG(r.stats.memory_compactions > 0, r.stats.memory_compactions);
}

AFM_TEST_CASE(test_l_shape)
{
  const auto in = afm_geometry::l_shape(0.05);
  const auto r = mesh_and_check<CDT>(in, uniform<K>(0.05), "L-shape", 7);
  AFM_CHECK(r.report.mean_radius_ratio > 0.9);
}

// Fig. 9 of the paper: two thin plates, two very long edges on the lower
// plate's upper surface facing fine spacing: fronts of very different
// length scales merge.
AFM_TEST_CASE(test_two_thin_plates)
{
  const auto in = afm_geometry::two_thin_plates();
  // the size follows the fine plate spacing, so the long edges face a fine front
  mesh_and_check<CDT>(in, afm_test::Boundary_graded_size<K>(in, 0.15), "two thin plates, size from the boundary", 13);
  // a uniform size coarser than the plates' spacing in the gap
  mesh_and_check<CDT>(in, uniform<K>(0.04), "two thin plates, uniform 0.04");
}

AFM_TEST_CASE(test_naca0012_far_field)
{
  const auto in = afm_geometry::naca0012_far_field(100, 20, 64);
  const auto r = mesh_and_check<CDT>(in, afm_test::Boundary_graded_size<K>(in, 0.2),
                                     "NACA 0012 in far field, size from the boundary");
  AFM_CHECK_MSG(r.report.mean_radius_ratio > 0.9, r.report.mean_radius_ratio);
  // a size field that ignores the fine surface spacing: still valid
  mesh_and_check<CDT>(in, Graded_size{0.01, 0.25, 0.5, 0.}, "NACA 0012 in far field, coarse field");
}

AFM_TEST_CASE(test_multi_element_airfoil)
{
  const auto in = afm_geometry::multi_element_airfoil(15, 80);
  const auto r = mesh_and_check<CDT>(in, afm_test::Boundary_graded_size<K>(in, 0.2),
                                     "four-element airfoil, size from the boundary");
  AFM_CHECK_MSG(r.report.mean_radius_ratio > 0.9, r.report.mean_radius_ratio);
}

AFM_TEST_CASE(test_many_holes)
{
  const auto in = afm_geometry::many_holes(40, 1);
  const auto r = mesh_and_check<CDT>(in, uniform<K>(0.02), "many holes", 11);
  AFM_CHECK(r.report.mean_radius_ratio > 0.85);
}

// A size field jumping by a factor of 1000 over a short distance: fronts of
// very different length scales meet (Fig. 2 of the paper). The small sizes
// sit around a tiny hole whose boundary is discretised at that size, so the
// fine front really starts there and runs into the coarse one.
AFM_TEST_CASE(test_size_jump_factor_1000)
{
  const auto outer = afm_geometry::subdivided_polygon({{{0, 0}}, {{1, 0}}, {{1, 1}}, {{0, 1}}}, 0.1);
  const auto hole = afm_geometry::circle({{0.3, 0.3}}, 0.002, 126, false);
  const auto in = afm_geometry::polygon_with_holes({outer, hole});
  auto jump = [](const Point& p) -> K::FT {
    return std::hypot(p.x() - 0.3, p.y() - 0.3) < 0.004 ? 1e-4 : 0.1;
  };
  const auto r1 = mesh_and_check<CDT>(in, jump, "size jump x1000 at distance 0.002 from the hole", 101);
  AFM_CHECK(r1.report.n_triangles > 1000);
  // and a smooth but steep variation: x1000 over 0.02
  auto steep = [](const Point& p) -> K::FT {
    const double d = std::hypot(p.x() - 0.3, p.y() - 0.3) - 0.002;
    return 1e-4 * std::pow(1000., (std::max)(0., (std::min)(1., d / 0.02)));
  };
  mesh_and_check<CDT>(in, steep, "size x1000 over 0.02");
}

AFM_TEST_CASE(test_nearly_collinear_boundary)
{
  const auto in = afm_geometry::nearly_collinear_boundary(1e-9);
  mesh_and_check<CDT>(in, uniform<K>(0.02), "nearly collinear boundary", 5);
  mesh_and_check<CDT>(afm_geometry::nearly_collinear_boundary(1e-14), uniform<K>(0.05),
                      "nearly collinear boundary 1e-14");
}

AFM_TEST_CASE(test_offset_1e6)
{
  const auto in = afm_geometry::offset(afm_geometry::square_with_circular_hole(1.0, 0.25, 0.02), 1e6, 1e6);
  const auto r = mesh_and_check<CDT>(in, uniform<K>(0.02), "square with hole offset by 1e6");
  AFM_CHECK(r.report.mean_radius_ratio > 0.95);
}

AFM_TEST_CASE(test_constrained_triangulation_plus)
{
  typedef afm_test::Types<K>::CDT_plus CDTP;
  const auto in = afm_geometry::square_with_circular_hole(1.0, 0.25, 0.05);
  mesh_and_check<CDTP>(in, uniform<K>(0.05), "Constrained_triangulation_plus_2");
}

AFM_TEST_CASE(test_interior_constraint_and_free_point)
{
  // a square with a dangling interior segment and a free point: both must
  // appear in the mesh, the segment with triangles on both sides
  afm_test::Poly_data in;
  in.points = {{{0, 0}}, {{1, 0}}, {{1, 1}}, {{0, 1}}, {{0.3, 0.5}}, {{0.6, 0.55}}, {{0.7, 0.2}}};
  in.segments = {{{0, 1}}, {{1, 2}}, {{2, 3}}, {{3, 0}}, {{4, 5}}};
  mesh_and_check<CDT>(in, uniform<K>(0.05), "interior constraint and free point", 3);
}

// Input repaired by insert_poly() (duplicate points merged, a repeated
// segment dropped, segments split at the points inside them, among them a
// T-junction) meshes into a valid mesh of the segments as split.
AFM_TEST_CASE(test_repaired_input_meshes)
{
  afm_test::Poly_data in;
  in.points = {{{0, 0}}, {{1, 0}}, {{1, 1}}, {{0, 1}}, {{1, 0}},     // 4 repeats 1
               {{0.5, 0}}, {{0.25, 0.5}}, {{0.75, 0.5}}, {{0.5, 0.5}}, // 5 inside a side
               {{0.5, 0.8}}, {{0.1, 0.9}}};                          // 10: a free point
  in.segments = {{{0, 1}}, {{4, 2}}, {{2, 3}}, {{3, 0}}, {{1, 0}}, // 4 repeats 0
                 {{6, 7}},                                         // 8 inside it
                 {{8, 9}}};                                        // a T-junction
  CDT cdt;
  const auto inserted = CGAL::Advancing_front_mesh_2::IO::insert_poly(cdt, in);
  AFM_CHECK(inserted.merged_points == 1 && inserted.duplicate_segments == 1 && inserted.points_on_segments == 2);
  afm_test::Mesher<CDT, CGAL::Advancing_front_mesh_2::Uniform_sizing_field_2<K> > mesher(
    cdt, CGAL::Advancing_front_mesh_2::Uniform_sizing_field_2<K>(0.05));
  mesher.set_seeds(inserted.hole_seeds.begin(), inserted.hole_seeds.end());
  AFM_CHECK(mesher.refine_mesh() == CGAL::Advancing_front_mesh_2::MESH_COMPLETE);
  AFM_CHECK(cdt.is_valid());
  const auto report = afm_test::check_split_mesh(in, afm_test::extract_mesh(cdt));
  AFM_CHECK_MSG(report.ok, report.summary());
  // the sides are split to the size (the boundary discretisation)
  AFM_CHECK_MSG(mesher.statistics().number_of_faces > 100, mesher.statistics().number_of_faces);
}

// A segment that separates two holes (CGAL's fish-and-rectangle.poly has
// such segments) is accepted and left inside the holes; the region around
// them is meshed.
AFM_TEST_CASE(test_segment_between_two_holes)
{
  afm_test::Poly_data in;
  in.points = {{{0, 0}}, {{3, 0}}, {{3, 1}}, {{0, 1}},                 // outer
               {{1, 0.25}}, {{2, 0.25}}, {{2, 0.75}}, {{1, 0.75}},     // inner rectangle
               {{1.5, 0.25}}, {{1.5, 0.75}}};                         // splits it
  in.segments = {{{0, 1}}, {{1, 2}}, {{2, 3}}, {{3, 0}}, {{4, 8}}, {{8, 5}}, {{5, 6}},
                 {{6, 9}}, {{9, 7}}, {{7, 4}}, {{8, 9}}};
  in.holes = {{{1.25, 0.5}}, {{1.75, 0.5}}};
  CDT cdt;
  const auto inserted = CGAL::Advancing_front_mesh_2::IO::insert_poly(cdt, in);
  afm_test::Mesher<CDT, CGAL::Advancing_front_mesh_2::Uniform_sizing_field_2<K> > mesher(
    cdt, CGAL::Advancing_front_mesh_2::Uniform_sizing_field_2<K>(0.1));
  mesher.set_seeds(inserted.hole_seeds.begin(), inserted.hole_seeds.end());
  AFM_CHECK(mesher.refine_mesh() == CGAL::Advancing_front_mesh_2::MESH_COMPLETE);
  AFM_CHECK(cdt.is_valid());
  const auto report = afm_test::check_split_mesh(in, afm_test::extract_mesh(cdt));
  AFM_CHECK_MSG(report.ok, report.summary());
  double area = 0;
  for(auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
    if(f->is_in_domain()) area += CGAL::to_double(cdt.triangle(f).area());
  AFM_CHECK_MSG(std::abs(area - 2.5) < 1e-12, area);

  // a segment inside one hole, between two islands in it: the hole is on
  // both of its sides, which reads as a boundary left open by mistake
  in.points = {{{0, 0}}, {{3, 0}}, {{3, 1}}, {{0, 1}}, {{1, 0.25}}, {{2, 0.25}}, {{2, 0.75}}, {{1, 0.75}},
               {{1.2, 0.4}}, {{1.3, 0.4}}, {{1.25, 0.5}}, {{1.7, 0.4}}, {{1.8, 0.4}}, {{1.75, 0.5}}};
  in.segments = {{{0, 1}}, {{1, 2}}, {{2, 3}}, {{3, 0}}, {{4, 5}}, {{5, 6}}, {{6, 7}}, {{7, 4}},
                 {{8, 9}}, {{9, 10}}, {{10, 8}}, {{11, 12}}, {{12, 13}}, {{13, 11}}, {{9, 11}}};
  in.holes = {{{1.5, 0.7}}};
  CDT cdt2;
  std::string error;
  try {
    CGAL::Advancing_front_mesh_2::IO::insert_poly(cdt2, in);
  } catch(const CGAL::Advancing_front_mesh_2::IO::Poly_read_error& e) {
    error = e.what();
  }
  AFM_CHECK_MSG(error.find("segment 14 borders no region to mesh") != std::string::npos, error);
}

AFM_TEST_CASE(test_determinism)
{
  const auto in = afm_geometry::many_holes(15, 3);
  const auto r1 = mesh_and_check<CDT>(in, uniform<K>(0.03), "determinism run 1");
  const auto r2 = mesh_and_check<CDT>(in, uniform<K>(0.03), "determinism run 2");
  AFM_CHECK(r1.mesh.vertices == r2.mesh.vertices);
  AFM_CHECK(r1.mesh.triangles == r2.mesh.triangles);
}

AFM_TEST_CASE(test_class_api_equals_free_function)
{
  const auto in = afm_geometry::square_with_circular_hole(1.0, 0.25, 0.04);
  mesh_and_check<CDT>(in, uniform<K>(0.04), "class API");
  // the free function is the class with the default search structures
  auto seeds = afm_test::seeds_of<CDT>(in);
  CDT by_class;
  afm_test::build_cdt(by_class, in);
  CGAL::Advancing_front_mesher_2<CDT, CGAL::Advancing_front_mesh_2::Uniform_sizing_field_2<K> > mesher(by_class,
                                                                                                     uniform<K>(0.04));
  mesher.set_seeds(seeds.begin(), seeds.end());
  AFM_CHECK(mesher.refine_mesh() == CGAL::Advancing_front_mesh_2::MESH_COMPLETE);
  CDT cdt;
  afm_test::build_cdt(cdt, in);
  const auto rc = CGAL::advancing_front_mesh_2(cdt, seeds.begin(), seeds.end(), 0.04);
  AFM_CHECK(rc == CGAL::Advancing_front_mesh_2::MESH_COMPLETE);
  const auto by_function = afm_test::extract_mesh(cdt);
  AFM_CHECK(afm_test::extract_mesh(by_class).vertices == by_function.vertices);
  AFM_CHECK(afm_test::extract_mesh(by_class).triangles == by_function.triangles);
}

AFM_TEST_CASE(test_free_function_size_forms)
{
  const auto in = afm_geometry::l_shape(0.1);
  // a lambda sizing field
  {
    CDT cdt;
    afm_test::build_cdt(cdt, in);
    CGAL::advancing_front_mesh_2(cdt, [](const Point& p) { return K::FT(0.05 + 0.05 * p.x()); });
    AFM_CHECK(afm_test::check_split_mesh(in, afm_test::extract_mesh(cdt)).ok);
  }
  // a Mesh_2 criteria object: h = 0.7 * size bound
  {
    CDT cdt;
    afm_test::build_cdt(cdt, in);
    CGAL::advancing_front_mesh_2(cdt, CGAL::Delaunay_mesh_size_criteria_2<CDT>(0.125, 0.1));
    const auto rep = afm_test::check_split_mesh(in, afm_test::extract_mesh(cdt));
    AFM_CHECK_MSG(rep.ok, rep.summary());
  }
  // invalid sizes are reported, not crashed on, and the triangulation is
  // left valid: untouched for a bad number, closed without new points when
  // a sizing field fails during the run
  for(int mode = 0; mode < 3; ++mode) {
    CDT cdt;
    afm_test::build_cdt(cdt, in);
    bool thrown = false;
    try {
      if(mode == 0) CGAL::advancing_front_mesh_2(cdt, -1.0);
      if(mode == 1) CGAL::advancing_front_mesh_2(cdt, [](const Point&) { return K::FT(-1); });
      if(mode == 2)
        CGAL::advancing_front_mesh_2(cdt, [](const Point& p) { return K::FT(p.x() > 1.5 ? std::nan("") : 0.05); });
    } catch(const std::invalid_argument&) {
      thrown = true;
    }
    AFM_CHECK_MSG(thrown, "mode " << mode);
    AFM_CHECK(cdt.is_valid());
    if(mode > 0) {
      const auto rep = afm_test::check_split_mesh(in, afm_test::extract_mesh(cdt));
      AFM_CHECK_MSG(rep.ok, "mode " << mode << ": " << rep.summary());
    }
  }
}

AFM_TEST_CASE(test_limits_return_codes_and_valid_mesh)
{
  const auto in = afm_geometry::square_with_circular_hole(1.0, 0.25, 0.02);
  CDT cdt;
  afm_test::build_cdt(cdt, in);
  auto seeds = afm_test::seeds_of<CDT>(in);
  const auto rc = CGAL::advancing_front_mesh_2(cdt, seeds.begin(), seeds.end(), 0.02, false,
                                               CGAL::parameters::number_of_iterations(200));
  AFM_CHECK(rc == CGAL::Advancing_front_mesh_2::ITERATION_LIMIT_REACHED);
  AFM_CHECK(cdt.is_valid());
  const auto rep = afm_test::check_split_mesh(in, afm_test::extract_mesh(cdt));
  AFM_CHECK_MSG(rep.ok, rep.summary());

  // the time limit (checked every 64 steps, the first time before the first
  // step): a limit already passed stops the run at once, with a valid mesh
  CDT timed;
  afm_test::build_cdt(timed, in);
  const auto rc_time = CGAL::advancing_front_mesh_2(timed, seeds.begin(), seeds.end(), 0.02, false,
                                                    CGAL::parameters::maximum_running_time(1e-12));
  AFM_CHECK_MSG(rc_time == CGAL::Advancing_front_mesh_2::TIME_LIMIT_REACHED, int(rc_time));
  AFM_CHECK(timed.is_valid());
  const auto rep_time = afm_test::check_split_mesh(in, afm_test::extract_mesh(timed));
  AFM_CHECK_MSG(rep_time.ok, rep_time.summary());
}

// Found in review: a candidate nearly in line with the edge (left of it by
// less than the rounding of the double height formula) must not let the
// height cut-off of Merriam's iteration drop a point lying inside its
// circle, here the free point.
AFM_TEST_CASE(test_mesh_near_collinear_candidate_and_height_cutoff)
{
  afm_test::Poly_data in;
  in.points = {{{1.3896248043163184, -0.1424222458432004}}, {{0.7646549190404963, 0.4878783949750474}},
               {{0.44484097217371904, 0.9720416115605681}}, {{-0.2032050570665913, 1.9531121780145193}},
               {{-0.537677012391101, 2.7753011869528335}}, {{-10.220941344101515, -3.6209777503827123}},
               {{-8.293639527394097, -6.5387011831787465}}, {{-0.5821174948282521, 1.6845168872381877}}};
  for(std::size_t i = 0; i < 7; ++i) in.segments.push_back({{i, (i + 1) % 7}});
  mesh_and_check<CDT>(in, uniform<K>(1.1605084763239666), "near-collinear candidate, free point", 1);
}

// Found in review (older than the cut-off): with no room for a point below
// the circle of the apex, the edge was closed on it even when that circle
// reached beyond the searched disk, where a front point could lie in it.
AFM_TEST_CASE(test_mesh_placement_floor_with_incomplete_circle)
{
  afm_test::Poly_data in;
  in.points = {{{1.3896248043163184, -0.1424222458432004}}, {{0.7646549190404963, 0.4878783949750474}},
               {{0.44484097217371904, 0.9720416115605681}}, {{-0.2032050570665913, 1.9531121780145193}},
               {{-0.537677012391101, 2.7753011869528335}}, {{-48.95399867094317, -29.20609349972489}},
               {{-47.02669685423575, -32.123816932520924}}};
  for(std::size_t i = 0; i < 7; ++i) in.segments.push_back({{i, (i + 1) % 7}});
  mesh_and_check<CDT>(in, uniform<K>(5.802542381619833), "placement floor, incomplete circle", 1);
}
