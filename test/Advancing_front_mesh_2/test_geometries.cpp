// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

// Sanity tests of the geometry generators (examples/.../afm_geometries.h)
// and of the shared-data loaders (test/.../afm_shared_data.h): every input
// the other tests mesh must be a simple PSLG of closed loops with one seed
// inside each hole.

#include <afm_geometries.h>
#include <afm_shared_data.h>
#include <afm_test_harness.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace {

using afm_geometry::Loop;
using afm_geometry::Point;
using afm_geometry::Poly_data;

// Simple PSLG, closed loops, valid hole seeds, expected hole count, and
// tidy orientations (outer loops CCW, holes CW). Empty string when fine.
std::string pslg_problem(const Poly_data& pd, std::size_t expected_holes, bool check_orientation = true)
{
  std::string why;
  if(!afm_geometry::is_simple_pslg(pd, &why))
    return "not simple: " + why;
  if(!afm_geometry::hole_seeds_valid(pd, &why))
    return "seeds: " + why;
  if(pd.holes.size() != expected_holes)
    return "expected " + std::to_string(expected_holes) + " holes, got " + std::to_string(pd.holes.size());
  if(check_orientation) {
    const std::vector<Loop> loops = afm_geometry::extract_loops(pd);
    const std::vector<int> level = afm_geometry::loop_levels(loops);
    for(std::size_t i = 0; i < loops.size(); ++i) {
      const double a = afm_geometry::signed_area(loops[i]);
      if((level[i] % 2 == 0) != (a > 0))
        return "loop " + std::to_string(i) + " (level " + std::to_string(level[i]) + ") has the wrong orientation";
    }
  }
  return std::string();
}

std::size_t loop_count(const Poly_data& pd)
{
  return afm_geometry::extract_loops(pd).size();
}

} // namespace

// --- is_simple_pslg itself ---------------------------------------------------

AFM_TEST_CASE(test_geometry_simple_pslg_detects_problems)
{
  Poly_data sq;
  afm_geometry::append_loop(sq, {{0, 0}, {1, 0}, {1, 1}, {0, 1}});
  std::string why;
  AFM_CHECK(afm_geometry::is_simple_pslg(sq, &why));

  Poly_data bow; // crossing edges
  afm_geometry::append_loop(bow, {{0, 0}, {1, 1}, {1, 0}, {0, 1}});
  AFM_CHECK(!afm_geometry::is_simple_pslg(bow, &why));
  AFM_CHECK(!why.empty());

  Poly_data dup = sq; // identical points
  dup.points.push_back({1, 1});
  AFM_CHECK(!afm_geometry::is_simple_pslg(dup, &why));

  Poly_data on_seg = sq; // isolated point on a segment
  on_seg.points.push_back({0.5, 0});
  AFM_CHECK(!afm_geometry::is_simple_pslg(on_seg, &why));

  Poly_data inside = sq; // isolated point inside: fine
  inside.points.push_back({0.5, 0.5});
  AFM_CHECK(afm_geometry::is_simple_pslg(inside, &why));

  Poly_data tee = sq; // T-junction: a vertex in the interior of a segment
  tee.points.push_back({0.5, 0.5});
  tee.points.push_back({0.5, 0.0});
  tee.segments.push_back({4, 5});
  AFM_CHECK(!afm_geometry::is_simple_pslg(tee, &why));

  Poly_data overlap; // collinear overlap of two segments sharing an end
  overlap.points = {{0, 0}, {2, 0}, {1, 0}};
  overlap.segments = {{{0, 1}}, {{0, 2}}};
  AFM_CHECK(!afm_geometry::is_simple_pslg(overlap, &why));

  Poly_data repeated = sq; // same segment twice
  repeated.segments.push_back({1, 0});
  AFM_CHECK(!afm_geometry::is_simple_pslg(repeated, &why));

  Poly_data bad_index = sq;
  bad_index.segments.push_back({0, 7});
  AFM_CHECK(!afm_geometry::is_simple_pslg(bad_index, &why));

  // Seeds: outside every loop or inside the domain are rejected.
  Poly_data seeded = afm_geometry::square_with_circular_hole();
  AFM_CHECK(afm_geometry::hole_seeds_valid(seeded, &why));
  seeded.holes[0] = {0.05, 0.05};
  AFM_CHECK(!afm_geometry::hole_seeds_valid(seeded, &why));
  seeded.holes[0] = {5, 5};
  AFM_CHECK(!afm_geometry::hole_seeds_valid(seeded, &why));
}

// --- NACA 4-digit generator ----------------------------------------------------

AFM_TEST_CASE(test_geometry_naca0012_shape)
{
  const std::size_t n = 200;
  const Loop a = afm_geometry::naca4_airfoil("0012", n);
  AFM_CHECK(a.size() == 2 * n);
  AFM_CHECK(a.front() == (Point{1.0, 0.0}));
  AFM_CHECK(afm_geometry::signed_area(a) > 0);
  std::size_t n_le = 0, n_te = 0;
  double max_y = 0, x_at_max = 0, min_y = 0;
  for(const Point& p : a) {
    n_le += (p == Point{0.0, 0.0});
    n_te += (p[0] == 1.0);
    if(p[1] > max_y) {
      max_y = p[1];
      x_at_max = p[0];
    }
    min_y = std::min(min_y, p[1]);
    AFM_CHECK(p[0] >= 0 && p[0] <= 1);
  }
  AFM_CHECK(n_le == 1);
  AFM_CHECK(n_te == 1);
  AFM_CHECK_MSG(std::abs(max_y - min_y - 0.12) < 5e-4, "thickness " << max_y - min_y);
  AFM_CHECK_MSG(std::abs(x_at_max - 0.3) < 0.02, "x of max thickness " << x_at_max);
  AFM_CHECK(std::abs(max_y + min_y) < 1e-15); // symmetric

  // Open trailing edge: one more point, blunt base of thickness ~0.00252.
  const Loop b = afm_geometry::naca4_airfoil("0012", n, false);
  AFM_CHECK(b.size() == 2 * n + 1);
  AFM_CHECK(std::abs(b.front()[1] - b.back()[1] - 0.00252) < 1e-5);

  // Cambered: 2412 has max camber 0.02 at 0.4; the upper surface is higher.
  const Loop c = afm_geometry::naca4_airfoil("2412", n);
  AFM_CHECK(afm_geometry::signed_area(c) > 0);
  Poly_data pc;
  afm_geometry::append_loop(pc, c);
  AFM_CHECK(afm_geometry::is_simple_pslg(pc));

  bool threw = false;
  try { afm_geometry::naca4_airfoil("12", 10); } catch(const std::invalid_argument&) { threw = true; }
  AFM_CHECK(threw);
}

AFM_TEST_CASE(test_geometry_transform_convention)
{
  // Positive angle = nose up = clockwise about the leading edge.
  const Loop a = afm_geometry::naca4_airfoil("0012", 20);
  const Loop t = afm_geometry::transform(a, 2.0, 10.0, 3.0, 4.0);
  const double r = 10.0 * afm_geometry::pi / 180.0;
  AFM_CHECK(std::abs(t[0][0] - (3.0 + 2.0 * std::cos(r))) < 1e-12);
  AFM_CHECK(std::abs(t[0][1] - (4.0 - 2.0 * std::sin(r))) < 1e-12);
  AFM_CHECK(a[20] == (Point{0.0, 0.0}));
  AFM_CHECK(std::abs(t[20][0] - 3.0) < 1e-15 && std::abs(t[20][1] - 4.0) < 1e-15);
  AFM_CHECK(std::abs(afm_geometry::signed_area(t) - 4.0 * afm_geometry::signed_area(a)) < 1e-12);
}

// --- generators ------------------------------------------------------------------

AFM_TEST_CASE(test_geometry_square_with_circular_hole)
{
  const Poly_data pd = afm_geometry::square_with_circular_hole(1.0, 0.25, 0.01);
  const std::string p = pslg_problem(pd, 1);
  AFM_CHECK_MSG(p.empty(), p);
  AFM_CHECK(pd.points.size() == 400 + 157);
  AFM_CHECK(std::hypot(pd.holes[0][0] - 0.5, pd.holes[0][1] - 0.5) < 0.05);
  const Poly_data coarse = afm_geometry::square_with_circular_hole(2.0, 0.9, 0.3);
  const std::string q = pslg_problem(coarse, 1);
  AFM_CHECK_MSG(q.empty(), q);
}

AFM_TEST_CASE(test_geometry_l_shape)
{
  const Poly_data pd = afm_geometry::l_shape(0.1);
  const std::string p = pslg_problem(pd, 0);
  AFM_CHECK_MSG(p.empty(), p);
  AFM_CHECK(pd.points.size() == 80);
  AFM_CHECK(std::abs(afm_geometry::signed_area(afm_geometry::extract_loops(pd)[0]) - 3.0) < 1e-12);
}

AFM_TEST_CASE(test_geometry_two_thin_plates)
{
  const Poly_data pd = afm_geometry::two_thin_plates();
  const std::string p = pslg_problem(pd, 2);
  AFM_CHECK_MSG(p.empty(), p);
  AFM_CHECK(loop_count(pd) == 3);
  // The upper surface of the lower plate is two edges of length 0.5.
  std::size_t long_edges = 0;
  double shortest_plate_edge = 1;
  for(const auto& s : pd.segments) {
    const Point& a = pd.points[s[0]];
    const Point& b = pd.points[s[1]];
    const double len = std::hypot(a[0] - b[0], a[1] - b[1]);
    const bool on_plate = std::abs(a[1]) < 0.1 && a[0] >= 0 && a[0] <= 1 && b[0] >= 0 && b[0] <= 1;
    if(on_plate && len > 0.4) {
      ++long_edges;
      AFM_CHECK(a[1] == -0.05 && b[1] == -0.05);
    } else if(on_plate) {
      shortest_plate_edge = std::min(shortest_plate_edge, len);
      AFM_CHECK(len < 0.0101);
    }
  }
  AFM_CHECK(long_edges == 2);
  AFM_CHECK(shortest_plate_edge > 0.0099);
}

AFM_TEST_CASE(test_geometry_naca0012_far_field)
{
  const Poly_data pd = afm_geometry::naca0012_far_field(100, 20, 64);
  const std::string p = pslg_problem(pd, 1);
  AFM_CHECK_MSG(p.empty(), p);
  AFM_CHECK(pd.points.size() == 200 + 64);
  // The seed is inside the airfoil.
  AFM_CHECK(pd.holes[0][0] > 0 && pd.holes[0][0] < 1 && std::abs(pd.holes[0][1]) < 0.06);
}

AFM_TEST_CASE(test_geometry_multi_element_airfoil)
{
  const Poly_data pd = afm_geometry::multi_element_airfoil();
  const std::string p = pslg_problem(pd, 4);
  AFM_CHECK_MSG(p.empty(), p);
  AFM_CHECK(loop_count(pd) == 5);
  const std::vector<Loop> el = afm_geometry::multi_element_airfoil_elements();
  AFM_CHECK(el.size() == 4);
  for(std::size_t i = 0; i < el.size(); ++i)
    for(std::size_t j = i + 1; j < el.size(); ++j) {
      const double c = afm_geometry::loop_clearance(el[i], el[j]);
      AFM_CHECK_MSG(c >= 0.005, "elements " << i << " and " << j << " clearance " << c);
      AFM_CHECK_MSG(c <= 0.2 || !(j == i + 1), "neighbouring elements " << i << ", " << j << " too far: " << c);
    }
  // Slat ahead of the main element, flaps behind it and below.
  auto xmin = [](const Loop& l) { double v = 1e300; for(const Point& q : l) v = std::min(v, q[0]); return v; };
  auto xmax = [](const Loop& l) { double v = -1e300; for(const Point& q : l) v = std::max(v, q[0]); return v; };
  AFM_CHECK(xmax(el[0]) < xmin(el[1]) + 0.01);
  AFM_CHECK(xmin(el[2]) > 0.9 && xmax(el[2]) > xmax(el[1]));
  AFM_CHECK(xmax(el[3]) > xmax(el[2]));
}

AFM_TEST_CASE(test_geometry_many_holes)
{
  const Poly_data pd = afm_geometry::many_holes(40, 1);
  const std::string p = pslg_problem(pd, 40);
  AFM_CHECK_MSG(p.empty(), p);
  const Poly_data again = afm_geometry::many_holes(40, 1);
  AFM_CHECK(again.points == pd.points && again.segments == pd.segments && again.holes == pd.holes);
  const Poly_data other = afm_geometry::many_holes(40, 2);
  AFM_CHECK(other.points != pd.points);
  const std::string q = pslg_problem(other, 40);
  AFM_CHECK_MSG(q.empty(), q);
  // Radii spread over at least an order of magnitude.
  const std::vector<Loop> loops = afm_geometry::extract_loops(pd);
  double r_min = 1, r_max = 0;
  for(std::size_t i = 1; i < loops.size(); ++i) {
    const double r = std::sqrt(-afm_geometry::signed_area(loops[i]) / afm_geometry::pi);
    r_min = std::min(r_min, r);
    r_max = std::max(r_max, r);
    AFM_CHECK(loops[i].size() >= 6);
  }
  AFM_CHECK(r_min >= 0.004 && r_max <= 0.15 && r_max > 10 * r_min);
  const Poly_data few = afm_geometry::many_holes(3, 7);
  const std::string f = pslg_problem(few, 3);
  AFM_CHECK_MSG(f.empty(), f);
}

AFM_TEST_CASE(test_geometry_nearly_collinear_and_offset)
{
  for(double eps : {1e-9, 1e-12, 0.0}) {
    const Poly_data pd = afm_geometry::nearly_collinear_boundary(eps);
    const std::string p = pslg_problem(pd, 0);
    AFM_CHECK_MSG(p.empty(), "eps " << eps << ": " << p);
  }
  const Poly_data far = afm_geometry::offset(afm_geometry::nearly_collinear_boundary(1e-9), 1e6, 1e6);
  const std::string p = pslg_problem(far, 0);
  AFM_CHECK_MSG(p.empty(), p);
  const Poly_data base = afm_geometry::multi_element_airfoil();
  const Poly_data moved = afm_geometry::offset(base, 1e6, -1e6);
  const std::string q = pslg_problem(moved, 4);
  AFM_CHECK_MSG(q.empty(), q);
  AFM_CHECK(moved.holes[2][0] == base.holes[2][0] + 1e6);
}

AFM_TEST_CASE(test_geometry_polygon_with_holes)
{
  // Clockwise outer and counter-clockwise, non-convex (C-shaped) hole whose
  // centroid is outside it: orientations are fixed, the seed is inside.
  const Loop outer = {{0, 0}, {0, 10}, {10, 10}, {10, 0}, {0, 0}}; // repeated closing point
  const Loop c_hole = {{2, 2}, {8, 2}, {8, 3}, {3, 3}, {3, 7}, {8, 7}, {8, 8}, {2, 8}};
  const Poly_data pd = afm_geometry::polygon_with_holes({outer, c_hole});
  const std::string p = pslg_problem(pd, 1);
  AFM_CHECK_MSG(p.empty(), p);
  AFM_CHECK(pd.points.size() == 4 + 8);
  AFM_CHECK(afm_geometry::point_in_polygon(pd.holes[0], c_hole));
  bool threw = false;
  try { afm_geometry::polygon_with_holes({outer, {{20, 20}, {21, 20}, {21, 21}}}); }
  catch(const std::invalid_argument&) { threw = true; }
  AFM_CHECK(threw);
}

// --- shared data -------------------------------------------------------------------

AFM_TEST_CASE(test_geometry_shared_30p30n)
{
  const std::string dir = afm_test::shared_data_dir();
  if(dir.empty())
    return;
  std::vector<std::string> fixes;
  const Poly_data pd = afm_shared_data::thirty_p_thirty_n(dir, 20, 96, &fixes);
  const std::string p = pslg_problem(pd, 3);
  AFM_CHECK_MSG(p.empty(), p);
  AFM_CHECK(pd.points.size() == 96 + 200 + 220 + 242);
  // The only repair is closing the open flap contour.
  AFM_CHECK(fixes.size() == 1);
  AFM_CHECK(fixes[0].find("flap") != std::string::npos && fixes[0].find("open") != std::string::npos);
  const std::vector<Loop> loops = afm_geometry::extract_loops(pd);
  for(std::size_t i = 1; i < loops.size(); ++i)
    for(std::size_t j = i + 1; j < loops.size(); ++j)
      AFM_CHECK(afm_geometry::loop_clearance(loops[i], loops[j]) > 0.01);
}

AFM_TEST_CASE(test_geometry_shared_nlr7301)
{
  const std::string dir = afm_test::shared_data_dir();
  if(dir.empty())
    return;
  const Poly_data pd = afm_shared_data::nlr7301_with_flap(dir);
  const std::string p = pslg_problem(pd, 2);
  AFM_CHECK_MSG(p.empty(), p);
  AFM_CHECK(pd.points.size() == 96 + 247 + 159);
}

AFM_TEST_CASE(test_geometry_shared_read_xy_dat)
{
  const std::string dir = afm_test::shared_data_dir();
  if(dir.empty())
    return;
  const Loop main = afm_shared_data::read_xy_dat(dir + "/nlr7301_viiflow/NLR7301.dat", true);
  AFM_CHECK(main.size() == 247);
  const Loop flap = afm_shared_data::read_xy_dat(dir + "/30p30n_linuxguy123/30P-30N-Flap-raw.dat", false);
  AFM_CHECK(flap.size() == 242);
  const Loop ls417 = afm_shared_data::read_xy_dat(dir + "/uiuc_airfoils/ls417.dat", true);
  AFM_CHECK(ls417.size() == 75);

  // Missing file and malformed line: the message names the file (and line).
  std::string msg;
  try { afm_shared_data::read_xy_dat(dir + "/no_such_file.dat", false); }
  catch(const std::runtime_error& e) { msg = e.what(); }
  AFM_CHECK_MSG(msg.find("no_such_file.dat") != std::string::npos, msg);
}

AFM_TEST_CASE(test_geometry_loader_errors)
{
  // Does not need the shared data: writes small broken files.
  const std::string path = (std::filesystem::temp_directory_path() / "afm_test_geometry_broken.tmp").string();
  {
    std::ofstream f(path);
    f << "name\n0 0\n1 0\n1 x\n0 1\n";
  }
  std::string msg;
  try { afm_shared_data::read_xy_dat(path, true); }
  catch(const std::runtime_error& e) { msg = e.what(); }
  AFM_CHECK_MSG(msg.find(path + ":4:") != std::string::npos, msg);
  {
    std::ofstream f(path);
    f << "# c\nmshid=1\nndims=2\npoint=3\n0;0;0\n1;0;0\n0;1;0\nedge2=3\n0;1;0\n1;2;0\n2;3;0\n";
  }
  msg.clear();
  try { afm_shared_data::mesh2d_jigsaw(path); }
  catch(const std::runtime_error& e) { msg = e.what(); }
  AFM_CHECK_MSG(msg.find(path + ":11:") != std::string::npos, msg);
  {
    std::ofstream f(path);
    f << "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n3 0\n1 1 2\n2 2 3\n3 3 4\n0\n";
  }
  msg.clear();
  try { afm_shared_data::triangle_poly(path); }
  catch(const std::runtime_error& e) { msg = e.what(); }
  AFM_CHECK_MSG(msg.find(path + ":8:") != std::string::npos, msg);
  std::remove(path.c_str());
}

AFM_TEST_CASE(test_geometry_shared_jigsaw)
{
  const std::string dir = afm_test::shared_data_dir();
  if(dir.empty())
    return;
  const Poly_data lake = afm_shared_data::mesh2d_jigsaw(dir + "/mesh2d/lake.msh");
  std::string p = pslg_problem(lake, 6);
  AFM_CHECK_MSG(p.empty(), p);
  AFM_CHECK(loop_count(lake) == 7 && lake.points.size() == 303);

  const Poly_data airfoil = afm_shared_data::mesh2d_jigsaw(dir + "/mesh2d/airfoil.msh");
  p = pslg_problem(airfoil, 3);
  AFM_CHECK_MSG(p.empty(), p);

  const Poly_data river = afm_shared_data::mesh2d_jigsaw(dir + "/mesh2d/river.msh");
  p = pslg_problem(river, 1);
  AFM_CHECK_MSG(p.empty(), p);

  // 277 loops, 329 isolated points (all of them in the sea, so kept).
  const Poly_data islands = afm_shared_data::mesh2d_jigsaw(dir + "/mesh2d/islands.msh");
  p = pslg_problem(islands, 276);
  AFM_CHECK_MSG(p.empty(), p);
  AFM_CHECK(islands.segments.size() == 6742);
  AFM_CHECK(islands.points.size() <= 7071);
}

AFM_TEST_CASE(test_geometry_shared_triangle_poly)
{
  const std::string dir = afm_test::shared_data_dir();
  if(dir.empty())
    return;
  const Poly_data a = afm_shared_data::triangle_poly(dir + "/triangle_drufat/A.poly");
  AFM_CHECK(a.points.size() == 29 && a.segments.size() == 29 && a.holes.size() == 1);
  std::string p = pslg_problem(a, 1, false);
  AFM_CHECK_MSG(p.empty(), p);
  const Poly_data hex = afm_shared_data::triangle_poly(dir + "/triangle_drufat/double_hex.poly");
  AFM_CHECK(hex.points.size() == 96 && hex.segments.size() == 96);
  p = pslg_problem(hex, 2, false);
  AFM_CHECK_MSG(p.empty(), p);
  const Poly_data face = afm_shared_data::triangle_poly(dir + "/triangle_drufat/face.poly");
  AFM_CHECK(face.points.size() == 26 && face.segments.size() == 22 && face.holes.size() == 3);
  AFM_CHECK(afm_geometry::is_simple_pslg(face));
}
