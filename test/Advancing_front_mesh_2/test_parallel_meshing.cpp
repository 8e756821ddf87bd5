// Meshing on several threads (mesh_in_parallel_2): the decomposition into
// strips, the validity of the merged meshes under the independent checker
// with 1, 2 and 4 threads (more threads than this machine's cores), their
// agreement with the serial mesh, and determinism. Built on its own so that
// scripts/test.sh can run it under ThreadSanitizer too.
#include "afm_test_harness.h"

#include "afm_geometries.h"
#include "afm_random_pslg.h"
#include "afm_robustness_catalogue.h"
#include "afm_test_mesh.h"
#include <CGAL/Advancing_front_mesh_2/Mesh_quality.h>
#include <CGAL/Advancing_front_mesh_2/mesh_in_parallel_2.h>
#include <CGAL/Advancing_front_mesh_2/split_constraints_to_size_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <list>
#include <string>
#include <vector>

namespace {

namespace AFM = CGAL::Advancing_front_mesh_2;
typedef CGAL::Exact_predicates_inexact_constructions_kernel Epick;
typedef afm_test::Types<Epick>::CDT CDT;
using afm_test::Poly_data;

struct Parallel_result
{
  AFM::Parallel_mesh_statistics st;
  afm_check::Mesh mesh;
  afm_check::Report report;
  AFM::Mesh_return_code rc = AFM::MESH_COMPLETE;
};

// Meshes `in` with `threads` threads and checks the result: CGAL's
// is_valid(), the independent checker (segments may be split, by the
// boundary discretisation and the cuts), and that every part was meshed.
template <class Size>
Parallel_result mesh_parallel(const Poly_data& in, const Size& size, std::size_t threads, const std::string& label,
                              bool split_constraints = true)
{
  CDT cdt;
  afm_test::build_cdt(cdt, in);
  const auto seeds = afm_test::seeds_of<CDT>(in);
  Parallel_result r;
  r.rc = AFM::mesh_in_parallel_2(cdt, seeds.begin(), seeds.end(), size, false, threads, r.st, split_constraints,
                                 AFM::internal::No_split_callback());
  AFM_CHECK_MSG(cdt.is_valid(), label << ": CGAL's is_valid() failed");
  r.mesh = afm_test::extract_mesh(cdt);
  r.report = afm_test::check_split_mesh(in, r.mesh);
  AFM_CHECK_MSG(r.report.ok, label << ", " << threads << " threads: " << r.report.summary());
  AFM_CHECK_MSG(r.rc == AFM::MESH_COMPLETE, label << ": return code " << int(r.rc));
  // the parts' triangles are stitched, not their points inserted again
  AFM_CHECK_MSG(r.st.parts == 1 || r.st.stitched, label << ": the parts were merged by insertion");
  std::size_t sum = 0;
  for(std::size_t t : r.st.part_triangles) sum += t;
  // the merge keeps every part's points; the triangles across the
  // interfaces may be others, but the count is about the parts' sum
  AFM_CHECK_MSG(std::abs(double(r.mesh.triangles.size()) - double(sum)) <= 0.01 * double(sum) + 10,
                label << ": " << r.mesh.triangles.size() << " triangles merged from parts of " << sum);
  return r;
}

double share_above_0_9(const afm_check::Mesh& m, double near_x = std::numeric_limits<double>::quiet_NaN(),
                        double band = 0)
{
  std::size_t above = 0, counted = 0;
  for(const auto& t : m.triangles) {
    if(!std::isnan(near_x)) {
      const double gx = (m.vertices[t[0]][0] + m.vertices[t[1]][0] + m.vertices[t[2]][0]) / 3;
      if(std::abs(gx - near_x) > band) continue;
    }
    ++counted;
    const auto& a = m.vertices[t[0]];
    const auto& b = m.vertices[t[1]];
    const auto& c = m.vertices[t[2]];
    const double la = std::hypot(b[0] - c[0], b[1] - c[1]), lb = std::hypot(a[0] - c[0], a[1] - c[1]),
                 lc = std::hypot(a[0] - b[0], a[1] - b[1]);
    const double s = 0.5 * (la + lb + lc);
    const double area = std::sqrt((std::max)(0., s * (s - la) * (s - lb) * (s - lc)));
    const double ratio = 2 * (area / s) / (la * lb * lc / (4 * area));
    if(ratio > 0.9) ++above;
  }
  return counted == 0 ? 0 : 100. * double(above) / double(counted);
}

} // namespace

// The square with a hole on 1, 2 and 4 threads: the parts are cut where
// the predicted counts balance, every merged mesh is valid, has the serial
// mesh's triangle count within 1% and its share of radius ratios above 0.9
// within a point.
AFM_TEST_CASE(test_parallel_square_with_hole)
{
  const Poly_data in = afm_geometry::square_with_circular_hole(1.0, 0.25, 0.01);
  const AFM::Uniform_sizing_field_2<Epick> size(0.01);
  const Parallel_result serial = mesh_parallel(in, size, 1, "square with hole");
  AFM_CHECK(serial.st.parts == 1 && serial.st.one_piece_reason == "one thread");
  const double serial_share = share_above_0_9(serial.mesh);
  for(std::size_t threads : {2, 3, 4}) {
    const Parallel_result r = mesh_parallel(in, size, threads, "square with hole");
    const double share = share_above_0_9(r.mesh);
    std::cout << "  " << threads << " threads: " << r.st.parts << " parts, " << r.mesh.triangles.size()
              << " triangles (serial " << serial.mesh.triangles.size() << "), share > 0.9 " << share << "% (serial "
              << serial_share << "%), " << r.st.cut_points << " cut points, " << r.st.interface_points
              << " interface points\n";
    for(std::size_t i = 0; i < r.st.parts; ++i)
      std::cout << "    part " << i << ": " << r.st.part_triangles[i] << " triangles, forced closures "
                << r.st.part_statistics[i].forced_closures << ", cut at " << (i < r.st.cuts.size() ? r.st.cuts[i] : 0.)
                << ", within 0.02 of the cut: share > 0.9 "
                << (i < r.st.cuts.size() ? share_above_0_9(r.mesh, r.st.cuts[i], 0.02) : 0.) << "% (serial "
                << (i < r.st.cuts.size() ? share_above_0_9(serial.mesh, r.st.cuts[i], 0.02) : 0.) << "%)\n";
    AFM_CHECK_MSG(r.st.parts == threads, r.st.parts << " parts: " << r.st.one_piece_reason);
    // each cut crosses the square's two sides, and the hole's circle twice or not
    AFM_CHECK(r.st.cut_points >= 2 * (threads - 1) && r.st.cut_points <= 4 * (threads - 1));
    AFM_CHECK(std::abs(double(r.mesh.triangles.size()) / double(serial.mesh.triangles.size()) - 1) < 0.01);
    AFM_CHECK_MSG(std::abs(share - serial_share) < 1, share << "% against " << serial_share << "%");
    // balanced: every part within 12% of the mean (a cut moves by up to 4%
    // of a part's count to a better place, and the prediction is a sampling)
    const double mean = double(r.mesh.triangles.size()) / double(r.st.parts);
    for(std::size_t t : r.st.part_triangles)
      AFM_CHECK_MSG(std::abs(double(t) / mean - 1) < 0.12, "a part of " << t << " triangles, mean " << mean);
  }
}

// The same threads give the same mesh, vertex for vertex and triangle for
// triangle, whatever order the parts finish in.
AFM_TEST_CASE(test_parallel_deterministic)
{
  const Poly_data in = afm_geometry::many_holes(20, 3);
  const AFM::Uniform_sizing_field_2<Epick> size(0.02);
  for(std::size_t threads : {2, 4}) {
    const Parallel_result a = mesh_parallel(in, size, threads, "many holes");
    const Parallel_result b = mesh_parallel(in, size, threads, "many holes");
    AFM_CHECK_MSG(a.st.parts > 1, a.st.one_piece_reason);
    AFM_CHECK(a.mesh.vertices == b.mesh.vertices);
    AFM_CHECK(a.mesh.triangles == b.mesh.triangles);
  }
}

// A graded field: the parts hold similar counts of triangles, not similar
// areas (the cut is far from the middle of the box).
AFM_TEST_CASE(test_parallel_graded_balance)
{
  const Poly_data in = afm_geometry::square_with_circular_hole(1.0, 0.25, 0.01);
  // fine on the left, coarse on the right: 0.004 to 0.04 (the balanced
  // cut is near x = 0.09 without the hole)
  auto size = [](const Epick::Point_2& p) { return Epick::FT(0.004 + 0.036 * p.x()); };
  const Parallel_result r = mesh_parallel(in, size, 2, "graded square with hole");
  AFM_CHECK_MSG(r.st.parts == 2, r.st.one_piece_reason);
  AFM_CHECK(r.st.axis == 0);
  AFM_CHECK_MSG(r.st.cuts[0] < 0.3, "cut at " << r.st.cuts[0]);
  const double a = double(r.st.part_triangles[0]), b = double(r.st.part_triangles[1]);
  std::cout << "  cut at x = " << r.st.cuts[0] << ", parts of " << a << " and " << b << " triangles (predicted "
            << r.st.predicted_triangles[0] << " and " << r.st.predicted_triangles[1] << ")\n";
  AFM_CHECK_MSG(std::abs(a / b - 1) < 0.15, a << " against " << b);
}

// Too small for two parts, or one thread: today's serial mesher, and the
// statistics say so.
AFM_TEST_CASE(test_parallel_small_domain_in_one_piece)
{
  const Poly_data in = afm_geometry::square_with_circular_hole(1.0, 0.25, 0.1);
  const AFM::Uniform_sizing_field_2<Epick> size(0.1);
  const Parallel_result r = mesh_parallel(in, size, 4, "coarse square with hole");
  AFM_CHECK(r.st.parts == 1);
  AFM_CHECK(r.st.one_piece_reason == "the domain is too small for two parts");
  bool threw = false;
  try {
    CDT cdt;
    AFM::Parallel_mesh_statistics st;
    std::vector<Epick::Point_2> seeds;
    AFM::mesh_in_parallel_2(cdt, seeds.begin(), seeds.end(), 0.1, false, 0, st, true,
                            AFM::internal::No_split_callback());
  } catch(const std::invalid_argument&) {
    threw = true;
  }
  AFM_CHECK(threw);
}

// Random domains (holes, free points, sharp angles) on 3 threads: every
// merged mesh is valid; most are cut into parts.
AFM_TEST_CASE(test_parallel_random_domains)
{
  std::size_t decomposed = 0;
  const std::size_t n = 40;
  for(std::uint64_t seed = 0; seed < n; ++seed) {
    afm_random::Generator g(seed);
    const afm_random::Domain d = g.domain();
    const AFM::Uniform_sizing_field_2<Epick> size(g.uniform(0.01, 0.03) * d.scale);
    const Parallel_result r = mesh_parallel(d.pslg, size, 3, "random domain " + std::to_string(seed));
    if(r.st.parts > 1) ++decomposed;
    else std::cout << "  random domain " << seed << " in one piece: " << r.st.one_piece_reason << "\n";
  }
  std::cout << "  " << decomposed << " of " << n << " random domains meshed in parts\n";
  AFM_CHECK(decomposed >= n / 2);
}

// The robustness catalogue on 2 threads (extreme scales, slits, tiny
// holes): valid, in parts or in one piece.
AFM_TEST_CASE(test_parallel_catalogue)
{
  for(const afm_robustness::Case& c : afm_robustness::catalogue()) {
    const Parallel_result r = mesh_parallel(c.in, afm_robustness::Case_size<Epick>(c), 2, c.name);
    std::cout << "  " << c.name << ": " << r.st.parts << " parts"
              << (r.st.parts == 1 ? " (" + r.st.one_piece_reason + ")" : std::string()) << ", "
              << r.report.summary() << "\n";
  }
}

// Segments that cross several cuts (a 3 x 1 rectangle by its corners, its
// segments kept, 3 threads): each cut finds the pieces the previous cuts
// left, so both long sides are split at both cuts and the parts fit
// together (found by review: with the domain marked only after all cuts,
// the second cut missed the pieces beside the first one's splits).
AFM_TEST_CASE(test_parallel_segments_across_several_cuts)
{
  Poly_data in;
  in.points = {{{0, 0}}, {{3, 0}}, {{3, 1}}, {{0, 1}}};
  in.segments = {{{0, 1}}, {{1, 2}}, {{2, 3}}, {{3, 0}}};
  const AFM::Uniform_sizing_field_2<Epick> size(0.03);
  const Parallel_result r = mesh_parallel(in, size, 3, "3 x 1 rectangle, segments kept", false);
  AFM_CHECK_MSG(r.st.parts == 3, r.st.one_piece_reason);
  AFM_CHECK_MSG(r.st.cut_points == 4, r.st.cut_points << " cut points");
  AFM_CHECK(r.st.stitched);
}

namespace {

// Whether the time stamps of the items of `c` (when they have them) are
// distinct: CGAL orders handles by them.
template <class Container>
bool distinct_time_stamps(const Container& c)
{
  if constexpr(AFM::internal::has_time_stamps<Container>()) {
    std::vector<std::size_t> stamps;
    for(auto it = c.begin(); it != c.end(); ++it) stamps.push_back(it->time_stamp());
    std::sort(stamps.begin(), stamps.end());
    return std::adjacent_find(stamps.begin(), stamps.end()) == stamps.end();
  } else {
    return true;
  }
}

} // namespace

// The parts' faces and vertices are spliced into the triangulation with
// their time stamps: they stay distinct after the merge, after insertions
// that reuse freed slots and take new ones, and after a second parallel
// meshing of the same triangulation.
AFM_TEST_CASE(test_parallel_time_stamps_distinct)
{
  const Poly_data in = afm_geometry::many_holes(20, 3);
  const AFM::Uniform_sizing_field_2<Epick> size(0.02);
  CDT cdt;
  afm_test::build_cdt(cdt, in);
  const auto seeds = afm_test::seeds_of<CDT>(in);
  AFM::Parallel_mesh_statistics st;
  AFM::mesh_in_parallel_2(cdt, seeds.begin(), seeds.end(), size, false, 2, st, true,
                          AFM::internal::No_split_callback());
  AFM_CHECK_MSG(st.parts == 2 && st.stitched, st.one_piece_reason);
  AFM_CHECK(distinct_time_stamps(cdt.tds().faces()));
  AFM_CHECK(distinct_time_stamps(cdt.tds().vertices()));
  for(int i = 0; i < 500; ++i) cdt.insert(CDT::Point(0.001 + 0.998 * (i % 25) / 25., 0.001 + 0.998 * (i / 25) / 20.));
  AFM_CHECK(cdt.is_valid());
  AFM_CHECK(distinct_time_stamps(cdt.tds().faces()));
  AFM_CHECK(distinct_time_stamps(cdt.tds().vertices()));
  AFM::mesh_in_parallel_2(cdt, seeds.begin(), seeds.end(), size, false, 2, st, true,
                          AFM::internal::No_split_callback());
  AFM_CHECK_MSG(st.parts == 2 && st.stitched, st.one_piece_reason);
  AFM_CHECK(cdt.is_valid());
  AFM_CHECK(distinct_time_stamps(cdt.tds().faces()));
  AFM_CHECK(distinct_time_stamps(cdt.tds().vertices()));
}

// Epeck with coordinates that are not doubles (the random domains 1, 5 and
// 7 of test_kernel_epeck_coordinates_not_doubles, every x divided exactly
// by 3 and every y by 7, at a fifth of test_parallel_random_domains' size)
// on 2 and 4 threads, always in parts: the parts share the input's lazy
// exact numbers, whose exact values CGAL computes on first use from any
// thread (std::call_once; ThreadSanitizer watches this test in CI), and the
// cuts' points are made from them. Every merged mesh is valid under CGAL
// and the checker (which reads the input rounded to doubles, and the split
// points within its tolerance). Unlike the serial test this has no step
// limit: a part that never ended would hang it until ctest's timeout.
AFM_TEST_CASE(test_parallel_epeck_coordinates_not_doubles)
{
  typedef CGAL::Exact_predicates_exact_constructions_kernel Epeck;
  typedef afm_test::Types<Epeck>::CDT Exact_cdt;
  typedef Epeck::FT FT;
  typedef Epeck::Point_2 Point;
  const FT sx(3), sy(7);
  for(const std::uint64_t seed : {1, 5, 7}) {
    afm_random::Generator g(seed);
    const afm_random::Domain d = g.domain();
    const double h = g.uniform(0.01, 0.03) * d.scale / 5;
    for(const std::size_t threads : {2, 4}) {
      const std::string label = "Epeck, seed " + std::to_string(seed) + ", coordinates divided by 3 and 7, " +
                                std::to_string(threads) + " threads";
      Exact_cdt cdt;
      std::list<Point> seeds;
      const Poly_data rounded = afm_test::insert_divided(cdt, d.pslg, sx, sy, seeds);
      AFM::Parallel_mesh_statistics st;
      const AFM::Mesh_return_code rc =
        AFM::mesh_in_parallel_2(cdt, seeds.begin(), seeds.end(), AFM::Uniform_sizing_field_2<Epeck>(h), false,
                                threads, st, true, AFM::internal::No_split_callback());
      AFM_CHECK_MSG(rc == AFM::MESH_COMPLETE, label << ": return code " << int(rc));
      AFM_CHECK_MSG(cdt.is_valid(), label << ": CGAL's is_valid() failed");
      const afm_check::Report report = afm_test::check_split_mesh(rounded, afm_test::extract_mesh(cdt));
      std::cout << "  " << label << ": " << st.parts << " parts, " << report.summary() << "\n";
      AFM_CHECK_MSG(report.ok, label << ": " << report.summary());
      // (in parts, spliced: otherwise no lazy number was shared)
      AFM_CHECK_MSG(st.parts > 1 && st.stitched, label << ": " << st.parts << " parts, " << st.one_piece_reason);
    }
  }
}
