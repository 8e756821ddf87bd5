// The background size field (Poisson_sizing_field_2): exact at sources,
// bounded, continuous, gradation limited; meshes from sharp and smooth
// fields; the Mesh_2 criteria; the sources file reader.
#include "afm_test_mesh.h"
#include "afm_geometries.h"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Advancing_front_mesh_2/IO/insert_poly.h>
#include <CGAL/Advancing_front_mesh_2/IO/markers_and_regions.h>
#include <CGAL/Advancing_front_mesh_2/IO/read_size_sources.h>
#include <CGAL/Advancing_front_mesh_2/Markers_and_regions_2.h>
#include <CGAL/Advancing_front_mesh_2/Poisson_sizing_field_2.h>
#include <CGAL/Advancing_front_mesh_2/Region_sizing_field_2.h>
#include <CGAL/Advancing_front_mesh_2/Sampled_sizing_field_2.h>
#include <CGAL/Advancing_front_mesh_2/Sizing_field_mesh_criteria_2.h>
#include <CGAL/Delaunay_mesher_2.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>
#include <sstream>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef afm_test::Types<K>::CDT CDT;
typedef K::Point_2 Point;
namespace AFM = CGAL::Advancing_front_mesh_2;
typedef AFM::Poisson_sizing_field_2<K> Field;
typedef AFM::Size_source_2<K> Source;
typedef std::vector<std::pair<Point, K::FT> > Spacing;
using afm_test::mesh_and_check;

// Random sources in the unit square, sizes log-uniform in [lo, hi].
std::vector<Source> random_sources(std::mt19937& rng, std::size_t n, double lo, double hi)
{
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<Source> s;
  for(std::size_t i = 0; i < n; ++i)
    s.emplace_back(Point(u(rng), u(rng)), lo * std::pow(hi / lo, u(rng)));
  return s;
}

template <class Kernel = K>
AFM::Poisson_sizing_field_2<Kernel> field_for(const afm_test::Poly_data& in,
                                              const std::vector<AFM::Size_source_2<Kernel> >& sources,
                                              const AFM::Poisson_sizing_field_options& o)
{
  typename afm_test::Types<Kernel>::CDT cdt;
  afm_test::build_cdt(cdt, in);
  std::vector<std::pair<typename Kernel::Point_2, typename Kernel::FT> > spacing;
  AFM::boundary_spacing_2(cdt, std::back_inserter(spacing));
  return AFM::Poisson_sizing_field_2<Kernel>(spacing, sources, o);
}

AFM::Poisson_sizing_field_options no_gradation(bool logarithmic = true)
{
  AFM::Poisson_sizing_field_options o;
  o.limit_gradation = false;
  o.logarithmic = logarithmic;
  // with nothing to grow at, the boundary spacing is diffused (the paper's field)
  o.boundary_spacing = AFM::Poisson_sizing_field_options::DIFFUSE_WITH_SOURCES;
  return o;
}

// Largest ratio |f(p) - f(q)| / |p - q| over random pairs at distance up to
// `reach`, with points also outside the unit square.
double largest_slope(const Field& f, std::mt19937& rng, std::size_t pairs, double reach)
{
  std::uniform_real_distribution<double> u(-0.2, 1.2), v(-1, 1);
  double slope = 0;
  for(std::size_t i = 0; i < pairs; ++i) {
    const Point p(u(rng), u(rng));
    const Point q(p.x() + reach * v(rng), p.y() + reach * v(rng));
    const double d = std::sqrt(CGAL::squared_distance(p, q));
    if(d > 0) slope = (std::max)(slope, std::abs(f(p) - f(q)) / d);
  }
  return slope;
}

} // namespace

AFM_TEST_CASE(test_poisson_field_exact_at_sources)
{
  std::mt19937 rng(7);
  for(bool logarithmic : {true, false}) {
    for(int trial = 0; trial < 5; ++trial) {
      const auto sources = random_sources(rng, 20, 1e-3, 1.0);
      const Field f(Spacing(), sources, no_gradation(logarithmic));
      for(const Source& s : sources)
        AFM_CHECK_MSG(f(s.point) == s.size, "source at " << s.point << " of size " << s.size << " gives "
                                                          << f(s.point) << (logarithmic ? " (log)" : ""));
    }
  }
  // With boundary points: a source on the square's boundary overrides it,
  // the others still hold exactly.
  const auto in = afm_geometry::square_with_circular_hole(1.0, 0.25, 0.02);
  const std::vector<Source> sources{Source(Point(0, 0), 0.003), Source(Point(0.2, 0.2), 0.05),
                                    Source(Point(0.9, 0.1), 0.01)};
  const Field f = field_for(in, sources, no_gradation());
  for(const Source& s : sources) AFM_CHECK_MSG(f(s.point) == s.size, "source " << s.point << ": " << f(s.point));
  // The gradation limit only lowers: at a source the field is at most its size.
  AFM::Poisson_sizing_field_options graded;
  const Field g = field_for(in, sources, graded);
  for(const Source& s : sources) AFM_CHECK(g(s.point) <= s.size);
  AFM_CHECK(g(Point(0, 0)) == 0.003); // the smallest source is never lowered
}

AFM_TEST_CASE(test_poisson_field_bounded_by_sources)
{
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-0.5, 1.5);
  for(bool logarithmic : {true, false}) {
    for(int trial = 0; trial < 5; ++trial) {
      const auto sources = random_sources(rng, 2 + 10 * trial, 1e-3, 10.0);
      double lo = 1e300, hi = 0;
      for(const Source& s : sources) { lo = (std::min)(lo, s.size); hi = (std::max)(hi, s.size); }
      for(bool graded : {false, true}) {
        AFM::Poisson_sizing_field_options o = no_gradation(logarithmic);
        o.limit_gradation = graded;
        const Field f(Spacing(), sources, o);
        for(int i = 0; i < 20000; ++i) {
          const double v = f(Point(u(rng), u(rng)));
          AFM_CHECK_MSG(v >= lo && v <= hi, "field " << v << " outside [" << lo << ", " << hi << "]");
        }
        AFM_CHECK(f.statistics().smallest_size >= lo && f.statistics().largest_size <= hi);
      }
    }
  }
  // Boundary spacing counts as prescribed sizes too.
  const auto in = afm_geometry::square_with_circular_hole(1.0, 0.25, 0.02);
  const Field f = field_for(in, {Source(Point(0.5, 0.1), 0.002)}, no_gradation());
  for(int i = 0; i < 20000; ++i) {
    const double v = f(Point(u(rng), u(rng)));
    AFM_CHECK(v >= 0.002 && v <= 0.0211);
  }
}

// A discontinuity (a hanging corner not matching its side) would show as a
// jump at vanishing distance; a Lipschitz bound at every scale rules it out.
AFM_TEST_CASE(test_poisson_field_continuous)
{
  std::mt19937 rng(3);
  const auto in = afm_geometry::square_with_circular_hole(1.0, 0.25, 0.02);
  // Several configurations: CGAL 5.5's single grade() pass leaves some trees
  // unbalanced (found by review), which shows as jumps across leaf sides.
  for(int trial = 0; trial < 12; ++trial) {
    const auto sources = random_sources(rng, 2 + trial, 1e-3, 0.1);
    const Field f = field_for(in, sources, no_gradation(trial % 2 == 0));
    // at a distance of 1e-12 the field changes by far less than 1e-6 of
    // itself, unless it jumps (the jumps found by review were 3% to 7%)
    std::uniform_real_distribution<double> u(-0.2, 1.2), v(-1, 1);
    for(int i = 0; i < 50000; ++i) {
      const Point p(u(rng), u(rng)), q(p.x() + 1e-12 * v(rng), p.y() + 1e-12 * v(rng));
      const double a = f(p), b = f(q);
      AFM_CHECK_MSG(std::abs(a - b) <= 1e-6 * a, "jump from " << a << " to " << b << " at " << p);
    }
    // Across the sides of the leaves, explicitly: values on both sides agree.
    std::vector<CGAL::Bbox_2> boxes;
    f.leaf_boxes(std::back_inserter(boxes));
    AFM_CHECK(boxes.size() == f.statistics().number_of_leaves);
    double worst = 0;
    for(const CGAL::Bbox_2& b : boxes) {
      const double eps = 1e-9 * (b.xmax() - b.xmin());
      for(double t : {0.125, 0.25, 0.5, 0.75, 0.875}) {
        const double x = b.xmin() + t * (b.xmax() - b.xmin()), y = b.ymin() + t * (b.ymax() - b.ymin());
        const double v = f(Point(x, b.ymax() - eps));
        worst = (std::max)(worst, std::abs(v - f(Point(x, b.ymax() + eps))) / v);
        const double w = f(Point(b.xmax() - eps, y));
        worst = (std::max)(worst, std::abs(w - f(Point(b.xmax() + eps, y))) / w);
      }
    }
    AFM_CHECK_MSG(worst < 1e-6, "trial " << trial << ": relative jump " << worst << " across a leaf side");
  }
}

// Whatever the scale, the field is the same up to scaling (the Laplacian is
// assembled in cells of the tree, not in coordinates).
AFM_TEST_CASE(test_poisson_field_scale_invariant)
{
  std::mt19937 rng(13);
  const auto sources = random_sources(rng, 12, 1e-3, 0.1);
  const Field unit(Spacing(), sources);
  std::uniform_real_distribution<double> u(0, 1);
  for(double scale : {1e-170, 1e-20, 1e20, 1e160}) {
    std::vector<Source> scaled;
    for(const Source& s : sources) scaled.emplace_back(Point(scale * s.point.x(), scale * s.point.y()), scale * s.size);
    AFM::Poisson_sizing_field_options o;
    o.gradation = 0.2; // dimensionless: the same limit at every scale
    const Field f(Spacing(), scaled, o);
    for(const Source& s : scaled) AFM_CHECK(f(s.point) <= s.size);
    for(int i = 0; i < 2000; ++i) {
      const double x = u(rng), y = u(rng);
      const double a = unit(Point(x, y)), b = f(Point(scale * x, scale * y)) / scale;
      AFM_CHECK_MSG(std::abs(a - b) <= 1e-6 * a, "scale " << scale << ": " << a << " vs " << b);
    }
  }
  auto throws = [](double x) {
    try {
      Field(Spacing(), std::vector<Source>{Source(Point(-x, 0), 1.), Source(Point(x, 0), 1.)});
    } catch(const std::invalid_argument&) {
      return true;
    }
    return false;
  };
  AFM_CHECK(throws(1e308));
  AFM_CHECK(!throws(1e300));
}

AFM_TEST_CASE(test_poisson_field_gradation_limit)
{
  std::mt19937 rng(5);
  for(double g : {0.05, 0.2, 1.0}) {
    AFM::Poisson_sizing_field_options o;
    o.gradation = g;
    const Field f(Spacing(), random_sources(rng, 30, 1e-4, 1.0), o);
    AFM_CHECK(f.gradation() == g);
    // |grad h| <= sqrt(2) G, with a little slack for rounding.
    const double slope = (std::max)(largest_slope(f, rng, 100000, 1e-2), largest_slope(f, rng, 100000, 0.3));
    AFM_CHECK_MSG(slope <= std::sqrt(2.) * g * (1 + 1e-9), "slope " << slope << " > sqrt(2) * " << g);
    AFM_CHECK(f.statistics().corners_lowered_by_gradation > 0);
  }
  // max_size and min_size bound the result.
  AFM::Poisson_sizing_field_options o;
  o.max_size = 0.05;
  o.min_size = 0.01;
  const Field f(Spacing(), random_sources(rng, 10, 1e-4, 1.0), o);
  std::uniform_real_distribution<double> u(0, 1);
  for(int i = 0; i < 10000; ++i) {
    const double v = f(Point(u(rng), u(rng)));
    AFM_CHECK(v >= 0.01 && v <= 0.05);
  }
}

AFM_TEST_CASE(test_poisson_field_invalid_input)
{
  auto throws = [](auto make) {
    try {
      make();
    } catch(const std::invalid_argument& e) {
      return std::string(e.what()).find("background size field") != std::string::npos;
    }
    return false;
  };
  AFM_CHECK(throws([] { Field(Spacing(), std::vector<Source>()); }));
  AFM_CHECK(throws([] { Field(Spacing(), std::vector<Source>{Source(Point(0, 0), 0.)}); }));
  AFM_CHECK(throws([] { Field(Spacing(), std::vector<Source>{Source(Point(0, 0), -1.)}); }));
  AFM_CHECK(throws([] { Field(Spacing(), std::vector<Source>{Source(Point(0, 0), std::nan(""))}); }));
  AFM_CHECK(throws([] {
    Field(Spacing(), std::vector<Source>{Source(Point(std::numeric_limits<double>::infinity(), 0), 1.)});
  }));
  AFM_CHECK(throws([] { Field(Spacing{{Point(0, 0), K::FT(-2)}}, std::vector<Source>()); }));
  AFM_CHECK(throws([] {
    AFM::Poisson_sizing_field_options o;
    o.gradation = 0;
    Field(Spacing(), std::vector<Source>{Source(Point(0, 0), 1.)}, o);
  }));
  AFM_CHECK(throws([] { // growing the boundary spacing needs the gradation limit
    AFM::Poisson_sizing_field_options o;
    o.limit_gradation = false;
    Field(Spacing(), std::vector<Source>{Source(Point(0, 0), 1.)}, o);
  }));
  AFM_CHECK(throws([] {
    AFM::Poisson_sizing_field_options o;
    o.max_size = 0.1;
    o.min_size = 0.2;
    Field(Spacing(), std::vector<Source>{Source(Point(0, 0), 1.)}, o);
  }));
  // One point, or several at the same place: a constant field, the smallest size.
  const Field one(Spacing(), std::vector<Source>{Source(Point(1, 1), 0.3), Source(Point(1, 1), 0.2)});
  AFM_CHECK(one(Point(5, -3)) == 0.2 && one(Point(1, 1)) == 0.2);
  // Coincident sources merge, the smaller wins; a copy shares the field.
  const Field two(Spacing(), std::vector<Source>{Source(Point(0, 0), 0.3), Source(Point(0, 0), 0.1),
                                                 Source(Point(1, 0), 0.5)},
                  no_gradation());
  const Field copy = two;
  AFM_CHECK(two.statistics().number_of_sources == 2);
  AFM_CHECK(copy(Point(0, 0)) == 0.1 && copy(Point(1, 0)) == 0.5);
}

AFM_TEST_CASE(test_boundary_spacing)
{
  // The square with a hole of afm_geometry is subdivided at spacing close to
  // 0.05 on the square and 2 pi 0.25 / n on the circle.
  const auto in = afm_geometry::square_with_circular_hole(1.0, 0.25, 0.05);
  CDT cdt;
  afm_test::build_cdt(cdt, in);
  Spacing spacing;
  AFM::boundary_spacing_2(cdt, std::back_inserter(spacing));
  AFM_CHECK(spacing.size() == in.points.size());
  for(const auto& s : spacing) AFM_CHECK_MSG(s.second > 0.035 && s.second < 0.06, "spacing " << s.second);
}

// A field varying by 10^4 over a short distance, gradation limit off: the
// mesher must still produce a valid mesh (quality may suffer near the jump).
AFM_TEST_CASE(test_mesh_sharp_field_without_gradation)
{
  const auto in = afm_geometry::square_with_circular_hole(1.0, 0.25, 0.02);
  const std::vector<Source> sources{Source(Point(0.1, 0.1), 1e-4), Source(Point(0.16, 0.1), 1.0),
                                    Source(Point(0.85, 0.85), 2e-4), Source(Point(0.85, 0.9), 1.0)};
  const Field f = field_for(in, sources, no_gradation());
  AFM_CHECK(f(Point(0.1, 0.1)) == 1e-4 && f(Point(0.16, 0.1)) == 1.0);
  const auto r = mesh_and_check<CDT>(in, f, "square with hole, field 1e-4..1 without gradation");
  AFM_CHECK(r.report.n_triangles > 1000);
  // the same with the default gradation limit, and with a linear-h solve
  mesh_and_check<CDT>(in, field_for(in, sources, AFM::Poisson_sizing_field_options()),
                      "square with hole, field 1e-4..1 with gradation 0.2");
  mesh_and_check<CDT>(in, field_for(in, sources, no_gradation(false)),
                      "square with hole, field 1e-4..1, linear solve, no gradation");
  // Without the limit, a harmonic field's small sizes cover a vanishing area
  // about a point source, which the front may step over (it evaluates the
  // field at its edges' midpoints). A discontinuous user field at a small
  // hole makes the front meet a jump by 10^4: 1e-3 within 0.01 of the hole
  // (whose boundary has that spacing), 10 beyond.
  const auto hole = afm_geometry::polygon_with_holes(
    {afm_geometry::subdivided_polygon({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 0.02),
     afm_geometry::circle({0.2, 0.2}, 0.005, 31, false)});
  auto step = [](const Point& p) {
    return K::FT(CGAL::squared_distance(p, Point(0.2, 0.2)) < 0.01 * 0.01 ? 1e-3 : 10.0);
  };
  const auto s = mesh_and_check<CDT>(hole, step, "small hole, step field 1e-3 | 10");
  AFM_CHECK_MSG(s.report.n_triangles > 400, s.report.n_triangles << " triangles: the jump was not met");
}

// Sources with sharp variation on the four-element airfoil, exact kernel.
AFM_TEST_CASE(test_mesh_sharp_field_exact_kernel)
{
  typedef CGAL::Exact_predicates_exact_constructions_kernel EK;
  const auto in = afm_geometry::multi_element_airfoil(4, 48);
  std::vector<AFM::Size_source_2<EK> > sources{
    AFM::Size_source_2<EK>(EK::Point_2(0.5, 0.2), 0.0005), AFM::Size_source_2<EK>(EK::Point_2(0.5, 0.3), 0.3)};
  const auto f = field_for<EK>(in, sources, no_gradation());
  mesh_and_check<afm_test::Types<EK>::CDT>(in, f, "four-element airfoil, Epeck, sharp sources");
}

// On a smooth field, edges away from the boundary have the requested
// length: at least 90% of them within [0.7, 1.4] h at their midpoint.
AFM_TEST_CASE(test_mesh_size_conformity_smooth_field)
{
  struct Case { std::string name; afm_test::Poly_data in; std::vector<Source> sources; };
  std::vector<Case> cases;
  cases.push_back({"square with hole, 3 sources", afm_geometry::square_with_circular_hole(1.0, 0.25, 0.02),
                   {Source(Point(0.1, 0.1), 0.01), Source(Point(0.8, 0.5), 0.04), Source(Point(0.5, 0.9), 0.02)}});
  cases.push_back({"four-element airfoil, boundary spacing only", afm_geometry::multi_element_airfoil(4, 128), {}});
  for(const Case& c : cases) {
    const Field f = field_for(c.in, c.sources, AFM::Poisson_sizing_field_options());
    const auto r = mesh_and_check<CDT>(c.in, f, c.name);
    const afm_check::Mesh& m = r.mesh;
    // boundary vertices: those at an input point
    std::set<std::pair<double, double> > input_points;
    for(const auto& p : c.in.points) input_points.insert({p[0], p[1]});
    std::set<std::pair<std::size_t, std::size_t> > edges;
    for(const auto& t : m.triangles)
      for(int i = 0; i < 3; ++i)
        edges.insert(std::minmax(t[i], t[(i + 1) % 3]));
    std::size_t counted = 0, conforming = 0;
    for(const auto& e : edges) {
      const auto& a = m.vertices[e.first];
      const auto& b = m.vertices[e.second];
      if(input_points.count({a[0], a[1]}) || input_points.count({b[0], b[1]})) continue;
      const Point mid(0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1]));
      const double h = f(mid);
      // away from the boundary: two sizes from every input segment
      bool near = false;
      for(const auto& s : c.in.segments) {
        const auto& p = c.in.points[s[0]];
        const auto& q = c.in.points[s[1]];
        if(afm_geometry::detail::squared_distance_point_segment({mid.x(), mid.y()}, p, q) < 4 * h * h) {
          near = true;
          break;
        }
      }
      if(near) continue;
      ++counted;
      const double ratio = std::hypot(b[0] - a[0], b[1] - a[1]) / h;
      conforming += (ratio >= 0.7 && ratio <= 1.4);
    }
    const double share = double(conforming) / double(counted);
    std::cout << "  " << c.name << ": " << counted << " interior edges, " << 100 * share
              << "% with length/h in [0.7, 1.4]\n";
    AFM_CHECK(counted > 1000);
    AFM_CHECK_MSG(share >= 0.9, c.name << ": " << 100 * share << "% conforming");
  }
}

// The same field drives CGAL Mesh_2 through Sizing_field_mesh_criteria_2.
AFM_TEST_CASE(test_mesh_2_criteria_with_poisson_field)
{
  const auto in = afm_geometry::square_with_circular_hole(1.0, 0.25, 0.02);
  const std::vector<Source> sources{Source(Point(0.1, 0.1), 0.005), Source(Point(0.8, 0.5), 0.05)};
  // The paper's field, which diffuses the boundary spacing into the domain:
  // the grown one takes the sources' field right up to the boundary, finer
  // than the boundary spacing on the side near the fine source, where Mesh_2
  // then splits input segments, which the checker does not accept (yet).
  AFM::Poisson_sizing_field_options diffused;
  diffused.boundary_spacing = AFM::Poisson_sizing_field_options::DIFFUSE_WITH_SOURCES;
  const Field f = field_for(in, sources, diffused);
  typedef AFM::Sizing_field_mesh_criteria_2<CDT, Field> Criteria;
  CDT cdt;
  afm_test::build_cdt(cdt, in);
  auto seeds = afm_test::seeds_of<CDT>(in);
  CGAL::refine_Delaunay_mesh_2(cdt, seeds.begin(), seeds.end(), Criteria(f));
  const afm_check::Mesh m = afm_test::extract_mesh(cdt);
  const afm_check::Report rep = afm_test::check_split_mesh(in, m);
  std::cout << "  Mesh_2 with the Poisson field: " << rep.summary() << "\n";
  AFM_CHECK_MSG(rep.ok, rep.summary());
  // every triangle meets the size bound at its centroid: longest edge <= h / 0.7
  std::size_t too_long = 0;
  for(const auto& t : m.triangles) {
    double x = 0, y = 0, longest = 0;
    for(int i = 0; i < 3; ++i) {
      const auto& a = m.vertices[t[i]];
      const auto& b = m.vertices[t[(i + 1) % 3]];
      x += a[0] / 3;
      y += a[1] / 3;
      longest = (std::max)(longest, std::hypot(b[0] - a[0], b[1] - a[1]));
    }
    too_long += longest > f(Point(x, y)) / 0.7 * (1 + 1e-12);
  }
  AFM_CHECK_MSG(too_long == 0, too_long << " triangles longer than the field allows");
  // and our mesher with the same field makes a mesh of comparable size
  const auto r = mesh_and_check<CDT>(in, f, "advancing front with the same field");
  const double ratio = double(r.report.n_triangles) / double(rep.n_triangles);
  std::cout << "  triangles: advancing front " << r.report.n_triangles << ", Mesh_2 " << rep.n_triangles << "\n";
  AFM_CHECK_MSG(ratio > 0.5 && ratio < 2, "triangle count ratio " << ratio);
}

AFM_TEST_CASE(test_read_size_sources)
{
  std::istringstream good("# sources\n0 0 0.1\n\n  1.5e0 -2 3e-3   # trailing comment\n");
  const auto s = AFM::IO::read_size_sources(good, "good.txt");
  AFM_CHECK(s.size() == 2 && s[1][0] == 1.5 && s[1][1] == -2 && s[1][2] == 3e-3);
  auto error_of = [](const std::string& text) {
    std::istringstream in(text);
    try {
      AFM::IO::read_size_sources(in, "src.txt");
    } catch(const AFM::IO::Poly_read_error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  AFM_CHECK(error_of("0 0 1\n1 2\n") == "src.txt:2: a source line (x y h) has 2 values, expected 3");
  AFM_CHECK(error_of("0 0 0\n") == "src.txt:1: size '0' is not positive");
  AFM_CHECK(error_of("# c\n0 0 -1\n") == "src.txt:2: size '-1' is not positive");
  AFM_CHECK(error_of("0 x 1\n") == "src.txt:1: 'x' is not a number");
  AFM_CHECK(error_of("0 0 inf\n") == "src.txt:1: size 'inf' is not finite");
  AFM_CHECK(error_of("0 0 1 4\n") == "src.txt:1: a source line (x y h) has 4 values, expected 3");
  std::istringstream empty("# nothing but a comment\n\n");
  AFM_CHECK(AFM::IO::read_size_sources(empty, "empty.txt").empty());
  AFM_CHECK(error_of("0 0 1\n") == "no error");
}

// Per-region area limits (Region_sizing_field_2): the field is bounded in
// the regions with a limit, and only there; the mesh is valid and finer
// where the limit asks for it.
AFM_TEST_CASE(test_region_sizing_field_area_limits)
{
  namespace afm_io = AFM::IO;
  typedef AFM::Uniform_sizing_field_2<K> Uniform;
  // left: limit 2e-4; right: none; inclusion: 2e-3, above what the uniform size gives
  const afm_io::Poly_data in = afm_geometry::tagged_regions(0.01, 2e-4, 2e-3);
  CDT input;
  const auto inserted = afm_io::insert_poly(input, in);
  const AFM::Markers_and_regions_2<CDT> tags = afm_io::markers_and_regions(in, inserted);
  const AFM::Region_sizing_field_2<CDT, Uniform> f(input, tags, Uniform(0.05));
  const double left_h = std::sqrt(4 * 0.8 * 2e-4 / std::sqrt(3.));
  AFM_CHECK_MSG(std::abs(f(Point(0.2, 0.2)) - left_h) < 1e-15, f(Point(0.2, 0.2)));
  AFM_CHECK(f(Point(0.99, 0.99)) == K::FT(left_h));
  AFM_CHECK(f(Point(1.9, 0.1)) == 0.05);   // right: no limit
  AFM_CHECK(f(Point(1.5, 0.5)) == 0.05);   // inclusion: its limit is above the size
  AFM_CHECK(f(Point(0.5, 0.5)) == 0.05);   // in the hole
  AFM_CHECK(f(Point(-1, 3)) == 0.05);      // outside the domain
  // a copy shares the regions and answers alike
  const AFM::Region_sizing_field_2<CDT, Uniform> g = f;
  AFM_CHECK(g(Point(0.3, 0.7)) == K::FT(left_h) && g(Point(1.2, 0.1)) == 0.05);
  bool thrown = false;
  try {
    AFM::Region_sizing_field_2<CDT, Uniform>(input, tags, Uniform(0.05), 0.);
  } catch(const std::invalid_argument&) {
    thrown = true;
  }
  AFM_CHECK(thrown);

  const auto r = mesh_and_check<CDT>(in, f, "tagged regions, area limit 2e-4 on the left");
  double left_area = 0, right_area = 0;
  std::size_t left = 0, right = 0;
  for(const auto& t : r.mesh.triangles) {
    const auto& a = r.mesh.vertices[t[0]];
    const auto& b = r.mesh.vertices[t[1]];
    const auto& c = r.mesh.vertices[t[2]];
    const double area = 0.5 * std::abs((b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]));
    const double cx = (a[0] + b[0] + c[0]) / 3, cy = (a[1] + b[1] + c[1]) / 3;
    if(cx < 1) {
      left_area += area;
      ++left;
    } else if(std::hypot(cx - 1.5, cy - 0.5) > 0.21) {
      right_area += area;
      ++right;
    }
  }
  AFM_CHECK(left > 0 && right > 0);
  AFM_CHECK_MSG(left_area / left < 2e-4, "mean area on the left " << left_area / left);
  AFM_CHECK_MSG(right_area / right > 3 * (left_area / left),
                "the right, without a limit, is not coarser: " << right_area / right << " vs " << left_area / left);
}

// A field sampled from a function evaluated in bulk: exact at its samples,
// close to a smooth function everywhere, a few calls on arrays, bad sizes
// refused with their point, the sample count bounded; a valid mesh from it.
AFM_TEST_CASE(test_sampled_sizing_field)
{
  typedef AFM::Sampled_sizing_field_2<K> Sampled;
  std::size_t calls = 0, points = 0;
  auto h = [](double x, double y) { return 0.01 + 0.1 * std::hypot(x - 0.3, y - 0.2); };
  const Sampled::Bulk_function f = [&](const double* xy, std::size_t n, double* out) {
    ++calls;
    points += n;
    for(std::size_t i = 0; i < n; ++i) out[i] = h(xy[2 * i], xy[2 * i + 1]);
  };
  const Sampled field(f, 0, 0, 1, 1);
  AFM_CHECK(calls == field.number_of_calls() && points == field.number_of_samples());
  AFM_CHECK_MSG(calls > 3 && calls < 20, calls << " calls");
  AFM_CHECK(field.at(0, 0) == h(0, 0) && field.at(1, 1) == h(1, 1) && field.at(0.5, 0.5) == h(0.5, 0.5));
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0, 1);
  double worst = 0;
  for(int i = 0; i < 2000; ++i) {
    const double x = u(rng), y = u(rng);
    worst = (std::max)(worst, std::abs(field(Point(x, y)) - h(x, y)) / h(x, y));
  }
  AFM_CHECK_MSG(worst < 0.05, "relative interpolation error " << worst);
  AFM_CHECK(field(Point(-3, 0.5)) == field(Point(0, 0.5))); // outside: the nearest point of the box

  const auto in = afm_geometry::square_with_circular_hole(1.0, 0.25, 0.02);
  const auto r = mesh_and_check<CDT>(in, field, "square with hole, sampled field");
  AFM_CHECK_MSG(r.report.n_triangles > field.number_of_samples(),
                r.report.n_triangles << " triangles from " << field.number_of_samples() << " samples");

  // the number of leaves is bounded, and a bad size names its point
  const Sampled::Bulk_function tiny = [](const double*, std::size_t n, double* out) {
    for(std::size_t i = 0; i < n; ++i) out[i] = 1e-12;
  };
  AFM_CHECK(Sampled(tiny, 0, 0, 1, 1, 2.0, 1000).number_of_leaves() <= 1000);
  for(double bad : {0., -1., std::nan(""), HUGE_VAL}) {
    const Sampled::Bulk_function g = [bad](const double* xy, std::size_t n, double* out) {
      for(std::size_t i = 0; i < n; ++i) out[i] = xy[2 * i] > 0.7 ? bad : 0.1;
    };
    bool thrown = false;
    try {
      Sampled(g, 0, 0, 1, 1);
    } catch(const std::invalid_argument& e) {
      thrown = std::string(e.what()).find("the size function returned") != std::string::npos;
    }
    AFM_CHECK_MSG(thrown, "size " << bad << " accepted");
  }
  bool thrown = false;
  try {
    Sampled(f, 0, 0, 0, 1);
  } catch(const std::invalid_argument&) {
    thrown = true;
  }
  AFM_CHECK(thrown);
}
