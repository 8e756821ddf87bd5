// Quality where the size varies: this package against Gmsh's Frontal-Delaunay
// and CGAL Mesh_2 on graded real cases, in one run, before and after
// smoothing. Prints a Markdown report; every mesh is checked by the
// independent checker (constrained Delaunay included for ours and Mesh_2's;
// Gmsh's smoothing does not keep its meshes Delaunay, so for Gmsh the
// checker's verdict is only reported).
//
// The cases:
// - the paper's Fig. 12 field (the four-element airfoil with its point
//   sources, diffused by the Poisson solve): every mesher gets the same
//   field, Gmsh and Mesh_2 through a size callback scaled until their
//   triangle count matches ours within 2%;
// - real airfoils and coasts from ../shared/data with the size taken from
//   the boundary spacing and bounded above by H, as afmesh_2 makes it
//   without sources: the same field for every mesher, matched counts; and
//   Gmsh with its own default extension of the boundary's sizes into the
//   domain (Mesh.MeshSizeExtendFromBoundary, MeshSizeMax = H), at its own
//   count;
// - the uniform square with a hole, where nothing may get worse;
// - the four elements under radial fields, steep and gentle (d: the
//   distance from the main element's mid-chord).
//
// Our rows: raw, after 1 and N passes of each smoother, and after CGAL's
// Lloyd iterations followed by N quality passes.
//
// Gmsh smooths its meshes by default (Mesh.Smoothing = 1, one pass of its
// vertex relocation): its rows are given without ("raw") and with it
// ("default"), so that each of ours compares with the like.
//
//   graded_quality --data ../shared/data [--smooth N] [--cases a,b,...] [--figures DIR] [--ours-only]
// (cases: square, radial, holes, fig12, 30p30n, nlr, airfoil, lake; --ours-only
// skips Gmsh and Mesh_2, for quick iterations on the mesher)
#include "bench_common.h"
#ifdef AFM_WITH_GMSH
#include "gmsh_runner.h"
#endif

#include "afm_geometries.h"
#include "afm_paper_sources.h"
#include "afm_shared_data.h"
#include "afm_test_mesh.h"

#include <CGAL/Advancing_front_mesh_2/IO/write_SVG.h>
#include <CGAL/Advancing_front_mesh_2/Poisson_sizing_field_2.h>
#include <CGAL/Advancing_front_mesh_2/Sizing_field_mesh_criteria_2.h>
#include <CGAL/Advancing_front_mesh_2/laplacian_smooth_mesh_2.h>
#include <CGAL/Advancing_front_mesh_2/quality_smooth_mesh_2.h>
#include <CGAL/Advancing_front_mesher_2.h>
#include <CGAL/Delaunay_mesh_vertex_base_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/lloyd_optimize_mesh_2.h>

#include <array>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
// Lloyd needs Mesh_2's vertex base; the advancing front works on it too.
typedef CGAL::Triangulation_data_structure_2<CGAL::Delaunay_mesh_vertex_base_2<K>, CGAL::Delaunay_mesh_face_base_2<K> >
  Tds;
typedef CGAL::Constrained_Delaunay_triangulation_2<K, Tds> CDT;
typedef K::Point_2 Point;
namespace AFM = CGAL::Advancing_front_mesh_2;
typedef AFM::Poisson_sizing_field_2<K> Field;
typedef afm_test::Poly_data Poly_data;
typedef std::function<double(double, double)> Size_function;

struct Options
{
  std::string data;
  int smooth = 5;
  std::string cases; // empty: all
  std::string figures;
  bool ours_only = false;
};

// A close-up picture of our mesh, raw and smoothed, coloured by quality.
struct Figure
{
  std::string raw, smoothed; // file names without extension; empty: none
  double xmin, ymin, xmax, ymax;
};

bool wanted(const Options& o, const std::string& key)
{
  return o.cases.empty() || ("," + o.cases + ",").find("," + key + ",") != std::string::npos;
}

double seconds_since(std::chrono::steady_clock::time_point t)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

double smallest_angle_degrees(const afm_check::Mesh& m)
{
  double smallest = 180;
  for(const auto& t : m.triangles)
    for(int i = 0; i < 3; ++i) {
      const auto& a = m.vertices[t[i]];
      const auto& b = m.vertices[t[(i + 1) % 3]];
      const auto& c = m.vertices[t[(i + 2) % 3]];
      const double ux = b[0] - a[0], uy = b[1] - a[1], vx = c[0] - a[0], vy = c[1] - a[1];
      smallest = (std::min)(smallest, std::atan2(std::abs(ux * vy - uy * vx), ux * vx + uy * vy) * 180 / CGAL_PI);
    }
  return smallest;
}

void row(const std::string& name, const std::string& mesher, const afm_check::Mesh& m, double seconds,
         const std::string& checker)
{
  const afm_bench::Quality q = afm_bench::quality(m);
  std::cout << "| " << name << " | " << mesher << " | " << m.triangles.size() << " | " << std::fixed
            << std::setprecision(3) << seconds << " | " << std::setprecision(4) << q.mean << " | "
            << std::setprecision(1) << 100 * q.share_above_0_9 << "% | " << std::setprecision(4) << q.min << " | "
            << std::setprecision(2) << smallest_angle_degrees(m) << " | " << checker << " |\n"
            << std::defaultfloat << std::flush;
}

std::string verdict(const afm_check::Report& r)
{
  return r.ok ? std::string("valid") : "INVALID: " + r.summary().substr(0, 80);
}

void figure(const Options& o, const std::string& file, const CDT& cdt, const Figure& w)
{
  if(o.figures.empty() || file.empty()) return;
  AFM::IO::SVG_options so;
  so.width_px = 1000;
  so.color_by_quality = true;
  so.has_window = true;
  so.xmin = w.xmin;
  so.ymin = w.ymin;
  so.xmax = w.xmax;
  so.ymax = w.ymax;
  std::ofstream os(o.figures + "/" + file + ".svg");
  AFM::IO::write_SVG(os, cdt, so);
}

// Ours, then ours smoothed; returns the triangle count.
std::size_t run_ours(const std::string& name, const Poly_data& in, const Size_function& size, const Options& o,
                     const Figure& fig = Figure())
{
  auto sizing = [&size](const Point& p) { return K::FT(size(CGAL::to_double(p.x()), CGAL::to_double(p.y()))); };
  CDT cdt;
  afm_test::build_cdt(cdt, in);
  auto seeds = afm_test::seeds_of<CDT>(in);
  CGAL::Advancing_front_mesher_2<CDT, decltype(sizing)> mesher(cdt, sizing);
  // the paper's mode, in which the manual's figures were measured (these
  // inputs' boundaries are at the size)
  mesher.set_constraint_splitting(false);
  mesher.set_seeds(seeds.begin(), seeds.end());
  auto t = std::chrono::steady_clock::now();
  mesher.refine_mesh();
  const double seconds = seconds_since(t);
  auto check = [&]() { return verdict(afm_check::check_mesh(afm_test::to_pslg(in), afm_test::extract_mesh(cdt))); };
  const afm_check::Mesh m = afm_test::extract_mesh(cdt);
  row(name, "ours", m, seconds, check());
  figure(o, fig.raw, cdt, fig);
  if(o.smooth > 0) {
    const CDT raw = cdt;
    for(const int passes : {1, o.smooth}) {
      for(const bool quality : {false, true}) {
        cdt = raw;
        t = std::chrono::steady_clock::now();
        const auto np = CGAL::parameters::number_of_iterations(std::size_t(passes));
        if(quality) CGAL::quality_smooth_mesh_2(cdt, np);
        else CGAL::laplacian_smooth_mesh_2(cdt, np);
        row(name, std::string("ours + ") + (quality ? "quality" : "Laplacian") + " smoothing (" +
                    std::to_string(passes) + (passes == 1 ? " pass)" : " passes)"),
            afm_test::extract_mesh(cdt), seconds + seconds_since(t), check());
        if(quality && passes == o.smooth) figure(o, fig.smoothed, cdt, fig);
      }
      if(o.smooth == 1) break;
    }
    // CGAL's Lloyd iterations (unguarded, they also change the topology
    // through the Delaunay flips of the moved points) before our guarded
    // passes: the best the two together reach, at Lloyd's cost
    cdt = raw;
    t = std::chrono::steady_clock::now();
    CGAL::lloyd_optimize_mesh_2(cdt, CGAL::parameters::max_iteration_number = 10,
                                CGAL::parameters::seeds_begin = seeds.begin(), CGAL::parameters::seeds_end = seeds.end());
    CGAL::quality_smooth_mesh_2(cdt, CGAL::parameters::number_of_iterations(std::size_t(o.smooth)));
    row(name, "ours + Lloyd (10 iterations) + quality smoothing (" + std::to_string(o.smooth) + " passes)",
        afm_test::extract_mesh(cdt), seconds + seconds_since(t), check());
  }
  return m.triangles.size();
}

// A secant search for the factor on the size that gives `target`
// triangles within 2%: `count(f)` meshes with the size times f.
double matched_factor(const std::function<std::size_t(double)>& count, std::size_t target)
{
  double f = 1, prev_f = 0, prev_n = 0, best_f = 1, best_err = 1e300;
  for(int it = 0; it < 6; ++it) {
    const double n = double(count(f));
    const double err = std::abs(n / double(target) - 1);
    if(err < best_err) {
      best_err = err;
      best_f = f;
    }
    if(err < 0.02) break;
    // n ~ f^-2; a secant step on the logarithms once there are two
    double slope = -2;
    if(prev_n > 0 && std::abs(std::log(f / prev_f)) > 1e-9) slope = std::log(n / prev_n) / std::log(f / prev_f);
    if(!(slope < -0.5)) slope = -2;
    prev_f = f;
    prev_n = n;
    f *= std::exp(std::log(double(target) / n) / slope);
  }
  return best_f;
}

std::string factor_text(double f)
{
  std::ostringstream os;
  os << "size x " << std::setprecision(3) << f;
  return os.str();
}

// Mesh_2 on the same field scaled to our count, then Lloyd.
void run_mesh_2(const std::string& name, const Poly_data& in, const Size_function& size, std::size_t target,
                const Options& o)
{
  auto seeds = afm_test::seeds_of<CDT>(in);
  auto mesh = [&](CDT& cdt, double f) {
    afm_test::build_cdt(cdt, in);
    auto scaled = [&size, f](const Point& p) { return K::FT(f * size(CGAL::to_double(p.x()), CGAL::to_double(p.y()))); };
    CGAL::refine_Delaunay_mesh_2(cdt, seeds.begin(), seeds.end(),
                                 AFM::Sizing_field_mesh_criteria_2<CDT, decltype(scaled)>(scaled));
  };
  const double f = matched_factor(
    [&](double g) {
      CDT cdt;
      mesh(cdt, g);
      return afm_test::extract_mesh(cdt).triangles.size();
    },
    target);
  CDT cdt;
  auto t = std::chrono::steady_clock::now();
  mesh(cdt, f);
  const double seconds = seconds_since(t);
  auto check = [&]() { return verdict(afm_test::check_split_mesh(in, afm_test::extract_mesh(cdt))); };
  row(name, "Mesh_2, same field (" + factor_text(f) + ")", afm_test::extract_mesh(cdt), seconds, check());
  t = std::chrono::steady_clock::now();
  CGAL::lloyd_optimize_mesh_2(cdt, CGAL::parameters::max_iteration_number = 10,
                              CGAL::parameters::seeds_begin = seeds.begin(), CGAL::parameters::seeds_end = seeds.end());
  const double lloyd = seconds_since(t);
  row(name, "Mesh_2 + Lloyd (10 iterations)", afm_test::extract_mesh(cdt), seconds + lloyd, check());
  if(o.smooth > 0) {
    t = std::chrono::steady_clock::now();
    CGAL::quality_smooth_mesh_2(cdt, CGAL::parameters::number_of_iterations(std::size_t(o.smooth)));
    row(name, "Mesh_2 + Lloyd + our quality smoothing (" + std::to_string(o.smooth) + " passes)",
        afm_test::extract_mesh(cdt), seconds + lloyd + seconds_since(t), check());
  }
}

#ifdef AFM_WITH_GMSH
std::string gmsh_verdict(const afm_check::Mesh& m, const Poly_data& in)
{
  const afm_check::Report r = afm_check::check_mesh(afm_test::to_pslg(in), m);
  return r.ok ? std::string("valid") : r.summary().substr(0, 60);
}

// Gmsh's Frontal-Delaunay on `size` scaled to our count, without and with
// its default smoothing.
void gmsh_matched(const std::string& name, const Poly_data& in, const Size_function& size, std::size_t target)
{
  const afm_bench::Gmsh_geometry g(in);
  auto run = [&](double f, int smoothing) {
    auto scaled = [&size, f](double x, double y) { return f * size(x, y); };
    return afm_bench::run_gmsh(g, 6, 0, scaled, 0, smoothing);
  };
  const double f = matched_factor([&](double h) { return run(h, 0).mesh->triangles.size(); }, target);
  for(const int smoothing : {0, 1}) {
    const afm_bench::Gmsh_outcome out = run(f, smoothing);
    row(name, std::string("Gmsh Frontal-Delaunay ") + (smoothing == 0 ? "raw" : "default (1 smoothing pass)") +
                ", same field (" + factor_text(f) + ")",
        *out.mesh, out.seconds, gmsh_verdict(*out.mesh, in));
  }
}

// Gmsh with its own extension of the boundary's sizes, bounded by h_max.
void gmsh_own_extension(const std::string& name, const Poly_data& in, double h_max)
{
  const afm_bench::Gmsh_geometry g(in);
  for(const int smoothing : {0, 1}) {
    const afm_bench::Gmsh_outcome out = afm_bench::run_gmsh(g, 6, 0, nullptr, h_max, smoothing);
    std::ostringstream label;
    label << "Gmsh Frontal-Delaunay " << (smoothing == 0 ? "raw" : "default") << ", its own size from the boundary, max "
          << h_max;
    row(name, label.str(), *out.mesh, out.seconds, gmsh_verdict(*out.mesh, in));
  }
}
#endif

void compare(const std::string& name, const Poly_data& in, const Size_function& size, double h_max,
             const Options& o, const Figure& fig = Figure())
{
  std::cerr << "== " << name << "\n";
  const std::size_t n = run_ours(name, in, size, o, fig);
  if(o.ours_only) return;
#ifdef AFM_WITH_GMSH
  gmsh_matched(name, in, size, n);
  if(h_max > 0) gmsh_own_extension(name, in, h_max);
#endif
  run_mesh_2(name, in, size, n, o);
}

Size_function as_function(const std::shared_ptr<Field>& field)
{
  return [field](double x, double y) { return CGAL::to_double((*field)(Point(x, y))); };
}

// The paper's Fig. 12 field on the four-element airfoil.
void fig12(const Options& o)
{
  const auto four = afm_geometry::multi_element_airfoil(15, 64);
  const auto s = afm_paper::figure_12_sources<K>(Point(0.5, 0), 15, 2 * CGAL_PI * 15 / 64);
  CDT cdt;
  afm_test::build_cdt(cdt, four);
  std::vector<std::pair<Point, K::FT> > spacing;
  AFM::boundary_spacing_2(cdt, std::back_inserter(spacing));
  AFM::Poisson_sizing_field_options opt;
  opt.boundary_spacing = AFM::Poisson_sizing_field_options::DIFFUSE_WITH_SOURCES; // the paper's field
  compare("four-element airfoil, Fig. 12 field", four, as_function(std::make_shared<Field>(spacing, s, opt)), 0, o,
          Figure());
}

// afmesh_2's field without sources: the boundary spacing grown from the
// boundary at the gradation rate, bounded above by h_max.
void boundary_case(const std::string& name, const Poly_data& in, double h_max, const Options& o,
                   const Figure& fig = Figure())
{
  CDT cdt;
  afm_test::build_cdt(cdt, in);
  std::vector<std::pair<Point, K::FT> > spacing;
  AFM::boundary_spacing_2(cdt, std::back_inserter(spacing));
  AFM::Poisson_sizing_field_options opt;
  opt.max_size = h_max;
  compare(name, in, as_function(std::make_shared<Field>(spacing, std::vector<AFM::Size_source_2<K> >(), opt)), h_max,
          o, fig);
}

} // namespace

std::string afm_test::shared_data_dir() { return ""; }

int main(int argc, char* argv[])
{
  Options o;
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if(a == "--data" && i + 1 < argc) o.data = argv[++i];
    else if(a == "--smooth" && i + 1 < argc) o.smooth = std::atoi(argv[++i]);
    else if(a == "--cases" && i + 1 < argc) o.cases = argv[++i];
    else if(a == "--figures" && i + 1 < argc) o.figures = argv[++i];
    else if(a == "--ours-only") o.ours_only = true;
    else {
      std::cerr << "usage: graded_quality --data DIR [--smooth N] [--cases square,radial,holes,fig12,30p30n,nlr,airfoil,lake]"
                   " [--figures DIR] [--ours-only]\n";
      return 2;
    }
  }
#ifdef AFM_WITH_GMSH
  gmsh::initialize();
  gmsh::option::setNumber("General.Terminal", 0);
  std::cout << "Gmsh " << afm_bench::gmsh_version() << "; CGAL " << CGAL_VERSION_STR << "\n\n";
#else
  std::cout << "built without Gmsh: its rows are missing\n\n";
#endif
  std::cout << "| case | mesher | triangles | seconds | mean radius ratio | share above 0.9 | min radius ratio |"
               " min angle | checker |\n"
            << "| :--- | :----- | --------: | ------: | ----------------: | --------------: | ---------------: |"
               " --------: | :------ |\n";
  if(wanted(o, "square")) {
    const double h = 0.005;
    compare("square with hole, h = 0.005", afm_geometry::square_with_circular_hole(1.0, 0.25, h),
            [h](double, double) { return h; }, 0, o);
  }
  if(wanted(o, "radial")) {
    // The four elements under a size growing with the distance from the
    // main element's mid-chord: steeply, where our frontal pass is on a par
    // with Gmsh's, and gently, where the gap of the Fig. 12 field shows
    // again (the manual's Section on placement)
    const auto four = afm_geometry::multi_element_airfoil(15, 64);
    compare("four-element airfoil, h = 0.01 + 0.1 d", four,
            [](double x, double y) { return 0.01 + 0.1 * std::hypot(x - 0.5, y); }, 0, o);
    compare("four-element airfoil, h = 0.004 + 0.03 d", four,
            [](double x, double y) { return 0.004 + 0.03 * std::hypot(x - 0.5, y); }, 0, o);
  }
  if(wanted(o, "holes")) {
    const auto holes = afm_geometry::many_holes(40, 1);
    compare("many holes (40), h = 0.02", holes, [](double, double) { return 0.02; }, 0, o);
    boundary_case("many holes (40), boundary spacing, max 0.02", holes, 0.02, o);
  }
  if(wanted(o, "fig12")) fig12(o);
  if(!o.data.empty()) {
    if(wanted(o, "30p30n"))
      boundary_case("30P-30N, boundary spacing, max 1", afm_shared_data::thirty_p_thirty_n(o.data), 1.0, o,
                    Figure{"thirty_p_thirty_n_boundary_field_closeup", "thirty_p_thirty_n_boundary_field_smoothed_closeup",
                           -0.15, -0.2, 0.35, 0.12});
    if(wanted(o, "nlr"))
      boundary_case("NLR 7301 with flap, boundary spacing, max 1", afm_shared_data::nlr7301_with_flap(o.data), 1.0, o);
    if(wanted(o, "airfoil"))
      boundary_case("MESH2D airfoil, boundary spacing, max 0.1",
                    afm_shared_data::mesh2d_jigsaw(o.data + "/mesh2d/airfoil.msh"), 0.1, o);
    if(wanted(o, "lake"))
      boundary_case("MESH2D lake, boundary spacing, max 0.1",
                    afm_shared_data::mesh2d_jigsaw(o.data + "/mesh2d/lake.msh"), 0.1, o);
  }
#ifdef AFM_WITH_GMSH
  gmsh::finalize();
#endif
  return 0;
}
