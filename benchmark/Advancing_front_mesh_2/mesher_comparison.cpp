// This package's advancing-front mesher against CGAL Mesh_2, Gmsh
// (Frontal-Delaunay and Delaunay) and CGAL's bulk Delaunay insertion, in
// one process and on the same input PSLGs, at matched triangle counts.
//
// For every case our mesher runs first at the case's nominal size; its
// triangle count is the target. Mesh_2's size bound (or the scale of the
// sizing field) and Gmsh's mesh size (or field scale) are then tuned so that
// their counts agree with ours within 2% where possible (5% at most; rows
// outside are marked), using count ~ size^-2 and, over the square series,
// the constant of the previous size. The reported row of each mesher is a
// tuned run. Timed: building the triangulation or the Gmsh model from the
// in-memory PSLG, and meshing. Not timed: quality (radius ratio, computed
// by the same code for every mesher), the independent validity checker
// (CGAL meshes only) and reading Gmsh's mesh back. Peak memory is the heap
// high-water mark above the state before the run, measured by interposing
// malloc in this executable (heap_meter.h), which counts Gmsh as well.
//
// Writes OUT_DIR/benchmark_results.md, OUT_DIR/benchmark_time.svg and
// OUT_DIR/benchmark_memory.svg; tuning runs and progress go to stderr.
//
//   mesher_comparison [--quick] [--max-triangles N] [--square-sizes N1,N2,...]
//                     [--gmsh-max-triangles N] [--no-gmsh]
//                     [--data SHARED_DATA_DIR] [--out OUT_DIR] [SHARED_DATA_DIR [OUT_DIR]]
//
// --quick: square at 1e4 and 1e5 triangles and small other cases (a smoke
// run); --max-triangles caps the square series (default 1e7); Gmsh runs up
// to --gmsh-max-triangles (default 1.5e6). The shared data directory
// defaults to AFM_SHARED_DATA_DIR (CMake), the output directory to ".".
#include "bench_common.h" // first: it defines the allocation functions (heap_meter.h)
#include "boundary_graded_size_tree.h"
#include "svg_plot.h"
#ifdef AFM_WITH_GMSH
#include "gmsh_runner.h"
#endif

#include "afm_geometries.h"
#include "afm_paper_sources.h"
#include "afm_shared_data.h"
#include "afm_test_mesh.h"

#include <CGAL/Advancing_front_mesh_2/Kd_tree_point_index.h>

#include <CGAL/Advancing_front_mesh_2/Poisson_sizing_field_2.h>
#include <CGAL/Advancing_front_mesh_2/Sizing_field_mesh_criteria_2.h>
#include <CGAL/Advancing_front_mesher_2.h>
#include <CGAL/Delaunay_mesh_size_criteria_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/version.h>

#include <sys/utsname.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <random>
#include <sstream>
#include <string>
#include <type_traits>
#include <thread>
#include <unordered_map>
#include <vector>

#ifndef AFM_SHARED_DATA_DIR
#define AFM_SHARED_DATA_DIR ""
#endif
#ifndef AFM_BENCH_BUILD_TYPE
#define AFM_BENCH_BUILD_TYPE "unknown"
#endif
#ifndef AFM_BENCH_CXX_FLAGS
#define AFM_BENCH_CXX_FLAGS ""
#endif

std::string afm_test::shared_data_dir() { return AFM_SHARED_DATA_DIR; }

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef afm_test::Types<K>::CDT CDT;
typedef K::Point_2 Point;
typedef afm_test::Poly_data Poly_data;
namespace AFM = CGAL::Advancing_front_mesh_2;
typedef AFM::Poisson_sizing_field_2<K> Poisson_field;
using afm_bench::Run;
using afm_bench::Meter;

const char* const ours_name = "ours (advancing front)";
const char* const ours_kd_tree_name = "ours, Kd_tree point index";
const char* const mesh2_name = "CGAL Mesh_2";
const char* const gmsh6_name = "Gmsh Frontal-Delaunay (6)";
const char* const gmsh5_name = "Gmsh Delaunay (5)";

struct Options
{
  bool quick = false;
  bool gmsh = true;
  double max_triangles = 1e7;
  // Gmsh makes about 20k triangles/s at 1e6 here: 1e7 would take ~10 minutes per run
  double gmsh_max_triangles = 1.5e6;
  // the square series; 3e6 is left out by default to keep scripts/benchmark.sh
  // within 15 minutes on 2 cores (--square-sizes 1e4,1e5,3e5,1e6,3e6,1e7)
  std::vector<double> square_sizes{1e4, 1e5, 3e5, 1e6, 1e7};
  std::string data_dir = AFM_SHARED_DATA_DIR;
  std::string out_dir = ".";
};


// ---------------------------------------------------------------------------
// One mesher run: the figures, and what is needed to evaluate it afterwards
// (the triangulation, or Gmsh's mesh already read back).
// ---------------------------------------------------------------------------

struct Outcome
{
  Run run;
  double parameter = 0;
  std::shared_ptr<CDT> cdt;
  std::shared_ptr<afm_check::Mesh> mesh;
  std::uint64_t allocations = 0;
  double meshing_time = 0; // ours: statistics().meshing_time
};

std::size_t in_domain_faces(const CDT& cdt)
{
  std::size_t n = 0;
  for(auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) n += f->is_in_domain();
  return n;
}

struct Phase_record
{
  bool measured = false;
  AFM::Phase_times times;
  double meshing_time = 0, init_time = 0, untimed_meshing_time = 0, run_time = 0, untimed_run_time = 0;
};

// ours with the default search structures, or with `PointIndex` (the
// Kd_tree model) for the close points
template <class Sizing, class PointIndex = CGAL::Default>
Outcome run_ours(const Poly_data& in, const Sizing& sizing, Phase_record* phases = nullptr)
{
  const auto seeds = afm_test::seeds_of<CDT>(in);
  Outcome o;
  o.cdt = std::make_shared<CDT>();
  const std::uint64_t a0 = heap_meter::allocations();
  Meter meter;
  meter.start();
  afm_test::build_cdt(*o.cdt, in);
  CGAL::Advancing_front_mesher_2<CDT, Sizing, AFM::Default_visitor, PointIndex> mesher(*o.cdt, sizing);
  // the paper's mode, in which the manual's figures were measured (these
  // inputs' boundaries are at the size)
  mesher.set_constraint_splitting(false);
  if(phases != nullptr) {
    mesher.set_phase_timing(true);
    phases->measured = true;
  }
  mesher.set_seeds(seeds.begin(), seeds.end());
  const AFM::Mesh_return_code rc = mesher.refine_mesh();
  meter.stop();
  o.allocations = heap_meter::allocations() - a0;
  o.run.mesher = std::is_same<PointIndex, CGAL::Default>::value ? ours_name : ours_kd_tree_name;
  o.run.seconds = meter.seconds();
  o.run.peak_bytes = meter.peak_bytes();
  o.run.triangles = in_domain_faces(*o.cdt);
  o.run.vertices = o.cdt->number_of_vertices();
  const auto& st = mesher.statistics();
  o.meshing_time = st.meshing_time;
  if(phases != nullptr) {
    phases->times = st.phase_times;
    phases->meshing_time = st.meshing_time;
    phases->init_time = st.init_time;
  }
  // anything but a complete, flip-free run is reported as invalid
  if(rc != AFM::MESH_COMPLETE) o.run.checker = "INVALID: meshing stopped early";
  else if(st.delaunay_repair_flips != 0)
    o.run.checker = "INVALID: " + std::to_string(st.delaunay_repair_flips) + " Delaunay repair flips";
  else o.run.checker.clear();
  return o;
}

template <class Criteria>
Outcome run_mesh2(const Poly_data& in, const Criteria& criteria)
{
  const auto seeds = afm_test::seeds_of<CDT>(in);
  Outcome o;
  o.cdt = std::make_shared<CDT>();
  const std::uint64_t a0 = heap_meter::allocations();
  Meter meter;
  meter.start();
  afm_test::build_cdt(*o.cdt, in);
  CGAL::refine_Delaunay_mesh_2(*o.cdt, seeds.begin(), seeds.end(), criteria);
  meter.stop();
  o.allocations = heap_meter::allocations() - a0;
  o.run.mesher = mesh2_name;
  o.run.seconds = meter.seconds();
  o.run.peak_bytes = meter.peak_bytes();
  o.run.triangles = in_domain_faces(*o.cdt);
  o.run.vertices = o.cdt->number_of_vertices();
  o.run.checker.clear();
  return o;
}

// afm_test::extract_mesh() with a hash map instead of std::map: the same
// mesh (vertices numbered in order of appearance), but Mesh_2's vertices are
// scattered in memory and the tree lookups took 53 s at 1e7 triangles.
// evaluate() compares both on the smaller meshes.
afm_check::Mesh extract_mesh_fast(const CDT& cdt)
{
  afm_check::Mesh m;
  std::unordered_map<const void*, std::size_t> ids;
  ids.reserve(cdt.number_of_vertices());
  for(auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if(!f->is_in_domain()) continue;
    std::array<std::size_t, 3> t;
    for(int i = 0; i < 3; ++i) {
      const auto v = f->vertex(i);
      const auto it = ids.emplace(&*v, m.vertices.size());
      if(it.second) m.vertices.push_back({{CGAL::to_double(v->point().x()), CGAL::to_double(v->point().y())}});
      t[i] = it.first->second;
    }
    m.triangles.push_back(t);
  }
  return m;
}

// Quality for every mesher; the validity checker for the CGAL meshes.
void evaluate(Outcome& o, const Poly_data& in)
{
  auto now = [] { return std::chrono::steady_clock::now(); };
  auto since = [](auto t) { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count(); };
  const auto t0 = now();
  std::ostringstream times;
  if(o.cdt) {
    const afm_check::Mesh m = extract_mesh_fast(*o.cdt);
    times << "extract " << since(t0) << " s";
    if(m.triangles.size() <= 200000) {
      const afm_check::Mesh reference = afm_test::extract_mesh(*o.cdt);
      if(reference.vertices != m.vertices || reference.triangles != m.triangles)
        throw std::logic_error("extract_mesh_fast() differs from afm_test::extract_mesh()");
    }
    o.run.vertices = m.vertices.size();
    o.run.quality = afm_bench::quality(m);
    if(o.run.checker.empty()) {
      auto t = now();
      // every mesher here may split the segments: covered by chains of edges
      const afm_check::Pslg pslg = afm_check::split_at_mesh_vertices(afm_test::to_pslg(in), m);
      times << ", PSLG " << since(t) << " s";
      t = now();
      const afm_check::Report r = afm_check::check_mesh(pslg, m);
      times << ", checker " << since(t) << " s";
      std::string s = r.summary();
      if(s.size() > 120) s = s.substr(0, 117) + "...";
      o.run.checker = r.ok ? "valid" : "INVALID: " + s;
    }
  } else if(o.mesh) {
    o.run.vertices = o.mesh->vertices.size();
    o.run.quality = afm_bench::quality(*o.mesh);
    o.run.checker = "not checked";
  }
  o.run.evaluated = true;
  std::cerr << "    evaluated " << o.run.mesher << " in " << since(t0) << " s (" << times.str() << ")\n";
}

// ---------------------------------------------------------------------------
// Tuning a size parameter p so that a mesher's triangle count n matches a
// target: n ~ C p^e, e = -2 at first (count ~ size^-2) and afterwards the
// slope of the last two runs (graded fields with a fixed boundary are
// flatter), C carried over between the sizes of a series.
// ---------------------------------------------------------------------------

struct Calibration
{
  double constant = 0; // C, 0 while unknown
  double exponent = -2;
};

// Runs above this many seconds are accepted within 5% instead of 2%: a
// second run of a large case costs more than the 3% are worth.
constexpr double expensive_run_seconds = 8;

// Our mesher and Mesh_2 are timed as the fastest of 3 runs up to 1.5M
// triangles (the larger runs last long enough to vary less, and Mesh_2's
// 1e7 run alone takes 3 minutes).
int timing_repeats(double triangles) { return triangles <= 1.5e6 ? 3 : 1; }

template <class Attempt>
Outcome tune(const std::string& label, double target, double guess, Calibration& cal, Attempt attempt)
{
  double p = cal.constant > 0 ? std::pow(target / cal.constant, 1 / cal.exponent) : guess;
  std::vector<std::pair<double, double> > history; // (p, n)
  Outcome best;
  bool have = false;
  double exponent = cal.exponent;
  for(int k = 0; k < 4; ++k) {
    Outcome o = attempt(p);
    o.parameter = p;
    const double n = double(o.run.triangles);
    o.run.off_target = n / target - 1;
    std::cerr << "  tuning " << label << ": parameter " << std::setprecision(6) << p << " -> " << o.run.triangles
              << " triangles (" << std::showpos << std::fixed << std::setprecision(2) << 100 * o.run.off_target
              << std::noshowpos << "% of target " << std::setprecision(0) << target << ", " << std::setprecision(2)
              << o.run.seconds << " s)\n"
              << std::defaultfloat;
    const double seconds = o.run.seconds;
    const double off = std::abs(o.run.off_target);
    if(!have || off < std::abs(best.run.off_target)) {
      best = std::move(o);
      have = true;
    }
    if(n <= 0) break; // a failed run; nothing to tune on
    history.push_back({p, n});
    if(off <= 0.02 || (off <= 0.05 && seconds > expensive_run_seconds)) break;
    if(history.size() >= 2) {
      const auto& a = history[history.size() - 2];
      const auto& b = history.back();
      if(std::abs(std::log(a.first / b.first)) > 1e-3 && a.second != b.second)
        exponent = std::max(-3., std::min(-0.7, std::log(b.second / a.second) / std::log(b.first / a.first)));
    }
    p *= std::pow(target / n, 1 / exponent);
  }
  if(best.run.triangles > 0) {
    cal.exponent = exponent;
    cal.constant = double(best.run.triangles) / std::pow(best.parameter, exponent);
  }
  return best;
}

// ---------------------------------------------------------------------------
// Cases
// ---------------------------------------------------------------------------

struct Case_result
{
  std::string group, name;
  std::string label; // short name for the summary tables
  double nominal_triangles = 0; // the square series' size class (1e4, 1e5, ...)
  std::vector<Run> runs;
  std::string gmsh_note; // why Gmsh did not run
  // CGAL bulk Delaunay insertion of our output vertices
  std::size_t bulk_points = 0;
  double bulk_seconds = 0;
  std::size_t bulk_peak_bytes = 0;
  Phase_record phases;

  const Run* find(const std::string& mesher) const
  {
    for(const Run& r : runs)
      if(r.mesher == mesher) return &r;
    return nullptr;
  }
};

/// A sizing field multiplied by a factor: the tuning knob of the graded
/// cases for Mesh_2 and Gmsh.
template <class Field>
struct Scaled_field
{
  Field field;
  double scale;
  K::FT operator()(const Point& p) const { return K::FT(scale * CGAL::to_double(field(p))); }
};

struct Series_calibration
{
  Calibration mesh2, gmsh6, gmsh5;
};

std::string number_text(double v, int digits = 6)
{
  std::ostringstream os;
  os << std::setprecision(digits) << v;
  return os.str();
}

// 1e4, 3e5, ...: the size classes of the square series
std::string size_class_text(double n)
{
  const int e = int(std::floor(std::log10(n) + 1e-9));
  return number_text(n / std::pow(10., e), 2) + "e" + std::to_string(e);
}

// Ours with CGAL's Kd_tree as the close-point index instead of our quadtree
// (the design card's "CGAL spatial-searching structure"): same checks, the
// fastest of as many runs as ours.
template <class Sizing>
void run_ours_with_kd_tree(Case_result& cr, const Poly_data& in, const Sizing& sizing, const Run& ours, int repeats)
{
  Outcome kd = run_ours<Sizing, AFM::Kd_tree_point_index>(in, sizing);
  kd.run.parameter = ours.parameter;
  kd.run.off_target = double(kd.run.triangles) / double(ours.triangles) - 1;
  evaluate(kd, in);
  kd.cdt.reset();
  for(int r = 1; r < repeats; ++r) kd.run.seconds = (std::min)(kd.run.seconds, run_ours<Sizing, AFM::Kd_tree_point_index>(in, sizing).run.seconds);
  kd.run.runs = repeats;
  kd.run.allocations = kd.allocations;
  std::cerr << "  " << ours_kd_tree_name << ": " << kd.run.triangles << " triangles, " << kd.run.seconds << " s ("
            << kd.run.seconds / ours.seconds << " times ours)\n";
  cr.runs.push_back(kd.run);
}

struct Bench
{
  Options opt;
  std::vector<Case_result> results;
  std::string gmsh_version = "not built with Gmsh";
  double poisson_field_seconds = 0;

  // One case: ours at its nominal size, then the others tuned to our count.
  // `uniform_h` > 0: uniform size; else `sizing` is the graded field.
  template <class Sizing>
  void run_case(const std::string& group, const std::string& name, const std::string& label, const Poly_data& in,
                const Sizing& sizing,
                double uniform_h, Series_calibration& cal, double nominal_triangles = 0,
                bool phase_timing = false)
  {
    std::cerr << "== " << group << ": " << name << "\n";
    Case_result cr;
    cr.group = group;
    cr.name = name;
    cr.label = label;
    cr.nominal_triangles = nominal_triangles;
    const bool uniform = uniform_h > 0;

    // 1. ours, at the nominal size: the target count
    Outcome ours = run_ours(in, sizing);
    ours.run.allocations = ours.allocations;
    std::cerr << "  " << ours_name << ": " << ours.run.triangles << " triangles, " << ours.run.seconds << " s, "
              << ours.allocations << " allocations\n";
    const double target = double(ours.run.triangles);
    ours.run.parameter = uniform ? "h = " + number_text(uniform_h) : "field";
    evaluate(ours, in);
    // 4. CGAL bulk Delaunay insertion of our output vertices (now, while
    // our triangulation is alive; it is freed before the other meshers run)
    {
      std::vector<Point> points;
      points.reserve(ours.cdt->number_of_vertices());
      for(auto v = ours.cdt->finite_vertices_begin(); v != ours.cdt->finite_vertices_end(); ++v)
        points.push_back(v->point());
      ours.cdt.reset();
      Meter meter;
      meter.start();
      {
        CGAL::Delaunay_triangulation_2<K> dt(points.begin(), points.end());
        meter.stop();
        cr.bulk_points = dt.number_of_vertices();
      }
      cr.bulk_seconds = meter.seconds();
      cr.bulk_peak_bytes = meter.peak_bytes();
      std::cerr << "  bulk Delaunay of " << cr.bulk_points << " points: " << cr.bulk_seconds << " s\n";
    }
    // the fastest of a few runs, for ours as for Mesh_2: single runs of the
    // 1M case varied by 20% between benchmark runs
    const int repeats = timing_repeats(target);
    for(int r = 1; r < repeats; ++r) {
      const Outcome again = run_ours(in, sizing);
      ours.run.seconds = (std::min)(ours.run.seconds, again.run.seconds);
      ours.meshing_time = (std::min)(ours.meshing_time, again.meshing_time);
    }
    ours.run.runs = repeats;
    cr.runs.push_back(ours.run);
    run_ours_with_kd_tree(cr, in, sizing, ours.run, repeats);
    if(phase_timing) {
      Outcome timed = run_ours(in, sizing, &cr.phases);
      cr.phases.untimed_meshing_time = ours.meshing_time;
      cr.phases.run_time = timed.run.seconds;
      cr.phases.untimed_run_time = ours.run.seconds;
      std::cerr << "  phase-timed run: " << timed.run.seconds << " s\n";
    }

    // 2. Mesh_2: size bound S on the longest edge (B = 0.125), or the field scaled
    {
      auto attempt = [&](double p) {
        if(uniform) return run_mesh2(in, CGAL::Delaunay_mesh_size_criteria_2<CDT>(0.125, p));
        return run_mesh2(in, AFM::Sizing_field_mesh_criteria_2<CDT, Scaled_field<Sizing> >(
                               Scaled_field<Sizing>{sizing, p}));
      };
      Outcome m = tune(std::string(mesh2_name) + (uniform ? " S" : " field scale"), target,
                       uniform ? uniform_h / 0.7 : 1., cal.mesh2, attempt);
      m.run.parameter = uniform ? "B = 0.125, S = " + number_text(m.parameter)
                                : "B = 0.125, field x " + number_text(m.parameter, 4) + " / 0.7";
      for(int r = 1; r < repeats; ++r)
        m.run.seconds = (std::min)(m.run.seconds, attempt(m.parameter).run.seconds);
      m.run.runs = repeats;
      m.run.allocations = m.allocations;
      evaluate(m, in);
      cr.runs.push_back(m.run);
    }

    // 3. Gmsh, both algorithms
#ifdef AFM_WITH_GMSH
    if(!opt.gmsh) {
      cr.gmsh_note = "Gmsh switched off (--no-gmsh)";
    } else if(target > opt.gmsh_max_triangles) {
      cr.gmsh_note = "Gmsh not run above " + number_text(opt.gmsh_max_triangles, 3) +
                     " triangles (--gmsh-max-triangles): at its 16k-22k triangles/s of the 1e6 case, a run "
                     "would take about 10 minutes";
    } else {
      const afm_bench::Gmsh_geometry geometry(in);
      for(int algorithm : {6, 5}) {
        Calibration& c = algorithm == 6 ? cal.gmsh6 : cal.gmsh5;
        const std::string label = algorithm == 6 ? gmsh6_name : gmsh5_name;
        auto attempt = [&](double p) {
          Outcome o;
          o.run.mesher = label;
          const std::uint64_t a0 = heap_meter::allocations();
          try {
            afm_bench::Gmsh_outcome g;
            if(uniform) {
              g = afm_bench::run_gmsh(geometry, algorithm, p, {});
            } else {
              g = afm_bench::run_gmsh(geometry, algorithm, 0, [&](double x, double y) {
                return p * CGAL::to_double(sizing(Point(x, y)));
              });
            }
            o.run.seconds = g.seconds;
            o.run.peak_bytes = g.peak_bytes;
            o.run.triangles = g.mesh->triangles.size();
            o.run.vertices = g.mesh->vertices.size();
            o.mesh = g.mesh;
          } catch(...) {
            std::string why;
            gmsh::logger::getLastError(why);
            std::cerr << "  Gmsh failed: " << why << "\n";
            o.run.checker = "Gmsh failed: " + why;
            gmsh::clear();
          }
          o.allocations = heap_meter::allocations() - a0;
          return o;
        };
        Outcome g = tune(label + (uniform ? " h" : " field scale"), target, uniform ? uniform_h : 1., c, attempt);
        g.run.parameter = uniform ? "h = " + number_text(g.parameter) : "field x " + number_text(g.parameter, 4);
        g.run.allocations = g.allocations;
        if(g.mesh) evaluate(g, in);
        cr.runs.push_back(g.run);
      }
    }
#else
    cr.gmsh_note = "not built with Gmsh (gmsh.h or libgmsh not found by CMake)";
#endif
    results.push_back(cr);
  }
};

// ---------------------------------------------------------------------------
// Report
// ---------------------------------------------------------------------------

std::string read_first_line_with(const std::string& file, const std::string& key)
{
  std::ifstream is(file);
  std::string line;
  while(std::getline(is, line))
    if(line.compare(0, key.size(), key) == 0) return line;
  return "";
}

std::string after_colon(const std::string& s)
{
  const auto p = s.find(':');
  if(p == std::string::npos) return s;
  auto r = s.substr(p + 1);
  while(!r.empty() && (r[0] == ' ' || r[0] == '\t')) r.erase(0, 1);
  return r;
}

std::string with_commas(std::size_t n)
{
  std::string s = std::to_string(n), r;
  for(std::size_t i = 0; i < s.size(); ++i) {
    if(i > 0 && (s.size() - i) % 3 == 0) r += ',';
    r += s[i];
  }
  return r;
}

std::string fixed(double v, int digits)
{
  std::ostringstream os;
  os << std::fixed << std::setprecision(digits) << v;
  return os.str();
}

std::string seconds_text(double s) { return s < 0.1 ? fixed(s, 4) : s < 10 ? fixed(s, 3) : fixed(s, 2); }

std::string mb(std::size_t bytes) { return fixed(double(bytes) / 1048576., bytes < 10 * 1048576 ? 2 : 1); }

std::string vm_status(const std::string& key)
{
  return after_colon(read_first_line_with("/proc/self/status", key + ":"));
}

std::string machine_header(const Bench& b)
{
  std::ostringstream os;
  std::string cpu = after_colon(read_first_line_with("/proc/cpuinfo", "model name"));
  if(cpu.empty()) cpu = "unknown";
  std::string mem = after_colon(read_first_line_with("/proc/meminfo", "MemTotal"));
  std::size_t mem_kb = std::strtoull(mem.c_str(), nullptr, 10);
  utsname u;
  std::string os_name = uname(&u) == 0 ? std::string(u.sysname) + " " + u.release + " " + u.machine : "unknown";
  char date[64];
  const std::time_t now = std::time(nullptr);
  std::strftime(date, sizeof date, "%Y-%m-%d %H:%M UTC", std::gmtime(&now));
#if defined(__clang__)
  const std::string compiler = std::string("Clang ") + __clang_version__;
#elif defined(__GNUC__)
  const std::string compiler = std::string("GCC ") + __VERSION__;
#else
  const std::string compiler = "unknown";
#endif
  os << "# Mesher comparison\n\n"
     << "Generated by `benchmark/Advancing_front_mesh_2/mesher_comparison` (`scripts/benchmark.sh`)"
     << (b.opt.quick ? ", **quick run**" : "") << ".\n\n"
     << "| | |\n|---|---|\n"
     << "| date | " << date << " |\n"
     << "| CPU | " << cpu << " |\n"
     << "| cores | " << std::thread::hardware_concurrency() << " (every mesher runs on one thread) |\n"
     << "| memory | " << fixed(double(mem_kb) / 1048576., 1) << " GiB |\n"
     << "| system | " << os_name << " |\n"
     << "| compiler | " << compiler << " |\n"
     << "| build type | " << AFM_BENCH_BUILD_TYPE << " (`" << AFM_BENCH_CXX_FLAGS << "`)"
#ifdef NDEBUG
     << ", NDEBUG"
#else
     << ", **assertions on (not NDEBUG)**"
#endif
     << " |\n"
     << "| CGAL | " << CGAL_VERSION_STR << " |\n"
     << "| Gmsh | " << b.gmsh_version << " |\n"
     << "| kernel | `Exact_predicates_inexact_constructions_kernel` |\n\n";
  return os.str();
}

void write_group_table(std::ostream& os, const Bench& b, const std::string& group)
{
  os << "| case | mesher | triangles | time (s) | triangles/s | ratio to Mesh_2 throughput | peak memory (MB) |"
        " bytes/triangle | mean radius ratio | min radius ratio | share > 0.9 | checker |\n"
     << "|---|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|---|\n";
  bool footnote = false;
  for(const Case_result& c : b.results) {
    if(c.group != group) continue;
    const Run* m2 = c.find(mesh2_name);
    for(const Run& r : c.runs) {
      std::string tri = with_commas(r.triangles);
      if(r.mesher != ours_name && r.triangles > 0) {
        tri += " (" + std::string(r.off_target >= 0 ? "+" : "") + fixed(100 * r.off_target, 1) + "%)";
        if(std::abs(r.off_target) > 0.05) {
          tri += " **†**";
          footnote = true;
        }
      }
      os << "| " << c.name << " | " << r.mesher << " <br><sub>" << r.parameter << "</sub> | " << tri << " | "
         << seconds_text(r.seconds) << " | " << with_commas(std::size_t(r.triangles_per_second() + 0.5)) << " | "
         << (m2 && m2->triangles_per_second() > 0 ? fixed(r.triangles_per_second() / m2->triangles_per_second(), 2)
                                                   : "-")
         << " | " << mb(r.peak_bytes) << " | " << fixed(r.bytes_per_triangle(), 0) << " | "
         << fixed(r.quality.mean, 4) << " | " << fixed(r.quality.min, 4) << " | "
         << fixed(100 * r.quality.share_above_0_9, 1) << "% | " << r.checker << " |\n";
    }
    if(!c.gmsh_note.empty())
      os << "| " << c.name << " | Gmsh | - | - | - | - | - | - | - | - | - | " << c.gmsh_note << " |\n";
  }
  os << "\n";
  if(footnote) os << "**†** triangle count more than 5% away from ours.\n\n";
}

void write_report(const Bench& b, const std::string& heap_check)
{
  std::ostringstream os;
  os << machine_header(b);
  os << "Every mesher meshes the same in-memory PSLG in one process. Our mesher runs first at the case's size; its "
        "triangle count is the target, and the size parameter of Mesh_2 and Gmsh (or the scale of the sizing field) "
        "is tuned so that their counts agree with ours (deviation in brackets; tuning runs are not reported). "
        "**Time**: building the constrained Delaunay triangulation (or the Gmsh model) from the PSLG plus "
        "meshing; sizing fields are built beforehand and shared; for ours and Mesh_2 the fastest of 3 runs up "
        "to 1.5M triangles (single runs of the 1M case varied by 20% between benchmark runs), of 1 run above "
        "and for Gmsh. **Peak memory**: the heap high-water mark above "
        "the state before the run (interposed malloc, Gmsh included; " + heap_check + "). **Radius ratio** "
        "2r/R, computed by the same code on every mesher's triangle list. **Checker**: the test suite's "
        "independent validity checker (for Mesh_2 against the input segments as split by Mesh_2); Gmsh meshes are "
        "only counted and measured. Mesh_2 runs with the default shape bound B = 0.125 (about 20.7 degrees) and "
        "splits boundary segments; ours and Gmsh keep every input segment as one edge (Gmsh: transfinite lines of "
        "2 nodes; Mesh.MeshSizeFromPoints = MeshSizeExtendFromBoundary = MeshSizeFromCurvature = 0, other options "
        "at their defaults, one thread). **" + std::string(ours_kd_tree_name) + "**: our mesher with "
        "`Kd_tree_point_index` (CGAL's `Kd_tree` with `Fuzzy_sphere` queries) instead of the default point "
        "quadtree as close-point index, timed the same way; its mesh may differ from the default's where equal "
        "candidates are taken in another order (count deviation in brackets).\n\n";

  std::vector<std::string> groups;
  for(const Case_result& c : b.results)
    if(std::find(groups.begin(), groups.end(), c.group) == groups.end()) groups.push_back(c.group);
  for(const std::string& g : groups) {
    os << "## " << g << "\n\n";
    write_group_table(os, b, g);
  }

  os << "## Our time over CGAL's bulk Delaunay insertion of our vertices\n\n"
     << "`CGAL::Delaunay_triangulation_2<Epick> dt(points.begin(), points.end())` (spatial sort + insertion) of "
        "the vertices of our mesh: the cost of a Delaunay triangulation of the same points, with no point placement, "
        "no constraints and no size field.\n\n"
     << "| case | vertices | our time (s) | bulk insertion (s) | ratio | bulk insertion peak memory (MB) |\n"
     << "|---|--:|--:|--:|--:|--:|\n";
  for(const Case_result& c : b.results) {
    const Run* o = c.find(ours_name);
    if(!o) continue;
    os << "| " << c.label << " | " << with_commas(c.bulk_points) << " | " << seconds_text(o->seconds)
       << " | " << seconds_text(c.bulk_seconds) << " | " << fixed(c.bulk_seconds > 0 ? o->seconds / c.bulk_seconds : 0, 1)
       << " | " << mb(c.bulk_peak_bytes) << " |\n";
  }
  os << "\n";

  // phase breakdown
  std::vector<const Case_result*> phased;
  for(const Case_result& c : b.results)
    if(c.phases.measured) phased.push_back(&c);
  os << "## Where our time goes\n\n";
  if(phased.empty()) {
    os << "No case with phase timing was run.\n\n";
  } else {
    os << "Share of the phase-timed meshing time (`statistics().phase_times`, an extra run with "
          "`set_phase_timing(true)`; the timed runs above keep it off).\n\n| phase |";
    for(const Case_result* c : phased) os << " " << c->label << " |";
    os << "\n|---|";
    for(std::size_t i = 0; i < phased.size(); ++i) os << "--:|";
    os << "\n";
    typedef double AFM::Phase_times::*Field;
    const std::vector<std::pair<const char*, Field> > rows{
      {"front selection (queue, sizing field)", &AFM::Phase_times::front_selection},
      {"close-point search", &AFM::Phase_times::close_point_search},
      {"Delaunay closure", &AFM::Phase_times::delaunay_closure},
      {"placement", &AFM::Phase_times::placement},
      {"circle octree", &AFM::Phase_times::circle_octree},
      {"cavity", &AFM::Phase_times::cavity},
      {"visibility", &AFM::Phase_times::visibility},
      {"front update", &AFM::Phase_times::front_update},
      {"output", &AFM::Phase_times::output}};
    for(const auto& row : rows) {
      os << "| " << row.first << " |";
      for(const Case_result* c : phased) {
        const double total = c->phases.times.total();
        os << " " << fixed(total > 0 ? 100 * (c->phases.times.*(row.second)) / total : 0, 1) << "% |";
      }
      os << "\n";
    }
    os << "| sum of phases (s) |";
    for(const Case_result* c : phased) os << " " << seconds_text(c->phases.times.total()) << " |";
    os << "\n| meshing time (`statistics().meshing_time`), phase timing on (s) |";
    for(const Case_result* c : phased) os << " " << seconds_text(c->phases.meshing_time) << " |";
    os << "\n| meshing time, phase timing off (the reported run) (s) |";
    for(const Case_result* c : phased) os << " " << seconds_text(c->phases.untimed_meshing_time) << " |";
    os << "\n| initialisation (`statistics().init_time`, not in the phases) (s) |";
    for(const Case_result* c : phased) os << " " << seconds_text(c->phases.init_time) << " |";
    os << "\n| whole run incl. CDT construction, phase timing on / off (s) |";
    for(const Case_result* c : phased)
      os << " " << seconds_text(c->phases.run_time) << " / " << seconds_text(c->phases.untimed_run_time) << " |";
    os << "\n\n";
  }

  // scaling summary, square series
  os << "## Scaling (square with a hole)\n\n";
  auto square_at = [&](double nominal) -> const Case_result* {
    for(const Case_result& c : b.results)
      if(c.nominal_triangles == nominal) return &c;
    return nullptr;
  };
  auto per_triangle = [](const Run* r) { return r && r->triangles ? r->seconds / double(r->triangles) : 0.; };
  const Case_result* s5 = square_at(1e5);
  const Case_result* s6 = square_at(1e6);
  const Case_result* s7 = square_at(1e7);
  // the largest square case above 1e5 that was run
  const Case_result* largest = s7 ? s7 : nullptr;
  for(const Case_result& c : b.results)
    if(c.nominal_triangles > 1e5 && (!largest || c.nominal_triangles > largest->nominal_triangles)) largest = &c;
  if(s5 && largest) {
    const double a = per_triangle(largest->find(ours_name)), z = per_triangle(s5->find(ours_name));
    os << "- Our time per triangle at " << size_class_text(largest->nominal_triangles) << " over 1e5: "
       << fixed(a / z, 2) << " (" << fixed(1e6 * a, 2) << " us against " << fixed(1e6 * z, 2) << " us per triangle)"
       << (s7 ? "" : "; 1e7 not run") << ".\n";
  } else {
    os << "- The square series was not run above 1e5 (quick run or --max-triangles).\n";
  }
  for(const Case_result* c : {s6, s7}) {
    if(!c) continue;
    const Run* o = c->find(ours_name);
    const Run* m = c->find(mesh2_name);
    if(o && m)
      os << "- Memory per triangle at " << size_class_text(c->nominal_triangles) << ": ours "
         << fixed(o->bytes_per_triangle(), 0) << " bytes, Mesh_2 " << fixed(m->bytes_per_triangle(), 0)
         << " bytes (ours / Mesh_2 = " << fixed(o->bytes_per_triangle() / m->bytes_per_triangle(), 2) << ").\n";
  }
  if(s6) {
    const Run* o = s6->find(ours_name);
    const Run* m = s6->find(mesh2_name);
    if(o && m)
      os << "- **Headline: at about 1M triangles our throughput (CDT construction + meshing) is "
         << fixed(o->triangles_per_second() / m->triangles_per_second(), 2) << " times Mesh_2's** ("
         << with_commas(std::size_t(o->triangles_per_second())) << " against "
         << with_commas(std::size_t(m->triangles_per_second())) << " triangles/s).\n";
    if(const Run* kd = s6->find(ours_kd_tree_name))
      if(o && o->seconds > 0)
        os << "- With CGAL's `Kd_tree` as close-point index (`Kd_tree_point_index`) instead of our quadtree, the same "
              "case takes " << fixed(kd->seconds / o->seconds, 2) << " times as long (" << seconds_text(kd->seconds)
           << " s against " << seconds_text(o->seconds) << " s).\n";
  }
  if(const Case_result* c = s6 ? s6 : s5) {
    os << "- Heap allocations per triangle at " << size_class_text(c->nominal_triangles) << ":";
    for(const Run& r : c->runs)
      os << " " << r.mesher << " " << fixed(double(r.allocations) / double(std::max<std::size_t>(1, r.triangles)), 1)
         << (&r == &c->runs.back() ? "" : ";");
    os << " (the heap meter adds a few ns per allocation, under 2% of any run).\n";
  }
  os << "- Process peak resident memory (VmHWM) at the end of the benchmark: "
     << fixed(std::strtod(vm_status("VmHWM").c_str(), nullptr) / 1024., 0)
     << " MB (all runs, the evaluations and the validity checks included).\n\n"
     << "Plots (square with a hole): [wall time against triangles](benchmark_time.svg), "
        "[peak heap memory against triangles](benchmark_memory.svg).\n\n"
     << "Notes: the airfoil's Poisson field (built once in " << seconds_text(b.poisson_field_seconds)
     << " s, outside the timings) and the islands' boundary-graded field (evaluated through a k-d tree that returns "
        "exactly the values of the tests' brute-force `Boundary_graded_size`) are shared by all meshers: Mesh_2 "
        "through `Sizing_field_mesh_criteria_2`, Gmsh through a size callback. The Gmsh model's loop nesting is "
        "computed from the PSLG outside the timing, as the hole seeds are for the CGAL meshers.\n";

  std::ofstream f(b.opt.out_dir + "/benchmark_results.md");
  f << os.str();
}

void write_plots(const Bench& b)
{
  struct Style
  {
    const char* mesher;
    const char* color;
    const char* marker;
  };
  const std::vector<Style> styles{{ours_name, "#d62728", "circle"},
                                  {ours_kd_tree_name, "#ff7f0e", "circle"},
                                  {mesh2_name, "#1f77b4", "square"},
                                  {gmsh6_name, "#2ca02c", "triangle"},
                                  {gmsh5_name, "#9467bd", "diamond"}};
  afm_bench::Log_log_plot time, memory;
  time.title = "Square with a hole: wall time (CDT construction + meshing)";
  time.x_label = "triangles";
  time.y_label = "wall time (s)";
  memory.title = "Square with a hole: peak heap memory during the run";
  memory.x_label = "triangles";
  memory.y_label = "peak heap memory (MB)";
  for(const Style& s : styles) {
    afm_bench::Plot_series t{s.mesher, s.color, s.marker, false, {}}, m = t;
    for(const Case_result& c : b.results) {
      if(c.nominal_triangles == 0) continue;
      if(const Run* r = c.find(s.mesher))
        if(r->triangles > 0) {
          t.points.push_back({double(r->triangles), r->seconds});
          m.points.push_back({double(r->triangles), double(r->peak_bytes) / 1048576.});
        }
    }
    if(!t.points.empty()) {
      time.series.push_back(t);
      memory.series.push_back(m);
    }
  }
  afm_bench::Plot_series bt{"CGAL bulk Delaunay of our vertices", "#7f7f7f", "circle", true, {}}, bm = bt;
  for(const Case_result& c : b.results) {
    if(c.nominal_triangles == 0) continue;
    if(const Run* r = c.find(ours_name)) {
      bt.points.push_back({double(r->triangles), c.bulk_seconds});
      bm.points.push_back({double(r->triangles), double(c.bulk_peak_bytes) / 1048576.});
    }
  }
  time.series.push_back(bt);
  memory.series.push_back(bm);
  time.write(b.opt.out_dir + "/benchmark_time.svg");
  memory.write(b.opt.out_dir + "/benchmark_memory.svg");
}

// The heap meter must see a 100 MB vector: a self-test of the interposition.
std::string heap_meter_check()
{
  heap_meter::reset_peak();
  const std::size_t before = heap_meter::current();
  std::size_t seen = 0;
  {
    std::vector<char> v(100 * 1000 * 1000, 1);
    seen = heap_meter::current() - before;
    if(v[v.size() / 2] != 1) std::abort();
  }
  const std::size_t after = heap_meter::current();
  std::ostringstream os;
  os << "self-check: a 100 MB vector was measured as " << fixed(double(seen) / 1e6, 1) << " MB, "
     << fixed(double(after > before ? after - before : 0) / 1e6, 3) << " MB left after freeing it";
#ifdef AFM_BENCH_NO_HEAP_METER
  return "heap meter compiled out (AFM_BENCH_NO_HEAP_METER): memory figures are 0";
#endif
  if(seen < 100000000 || seen > 101000000) {
    std::cerr << "heap meter FAILED its " << os.str() << "\n";
    return "the heap meter FAILED its " + os.str();
  }
  return os.str();
}

bool parse_options(int argc, char* argv[], Options& opt)
{
  std::vector<std::string> positional;
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if(i + 1 >= argc) throw std::invalid_argument(a + " needs a value");
      return argv[++i];
    };
    if(a == "--quick") opt.quick = true;
    else if(a == "--no-gmsh") opt.gmsh = false;
    else if(a == "--max-triangles") opt.max_triangles = std::stod(value());
    else if(a == "--gmsh-max-triangles") opt.gmsh_max_triangles = std::stod(value());
    else if(a == "--square-sizes") {
      opt.square_sizes.clear();
      std::istringstream is(value());
      std::string item;
      while(std::getline(is, item, ',')) opt.square_sizes.push_back(std::stod(item));
    } else if(a == "--data") opt.data_dir = value();
    else if(a == "--out") opt.out_dir = value();
    else if(a == "-h" || a == "--help") return false;
    else if(!a.empty() && a[0] == '-') throw std::invalid_argument("unknown option " + a);
    else positional.push_back(a);
  }
  if(positional.size() > 0) opt.data_dir = positional[0];
  if(positional.size() > 1) opt.out_dir = positional[1];
  if(positional.size() > 2) throw std::invalid_argument("too many arguments");
  return true;
}

} // namespace

int main(int argc, char* argv[])
{
  Bench b;
  try {
    if(!parse_options(argc, argv, b.opt)) {
      std::cout << "mesher_comparison [--quick] [--max-triangles N] [--square-sizes N1,N2,...]\n"
                   "                  [--gmsh-max-triangles N] [--no-gmsh]\n"
                   "                  [--data SHARED_DATA_DIR] [--out OUT_DIR] [SHARED_DATA_DIR [OUT_DIR]]\n";
      return EXIT_SUCCESS;
    }
  } catch(const std::exception& e) {
    std::cerr << "mesher_comparison: " << e.what() << "\n";
    return EXIT_FAILURE;
  }
  const Options& opt = b.opt;
  const std::string heap_check = heap_meter_check();
  std::cerr << "heap meter " << heap_check << "\n";
#ifdef AFM_WITH_GMSH
  gmsh::initialize(0, nullptr, false);
  gmsh::option::setNumber("General.Terminal", 0);
  b.gmsh_version = afm_bench::gmsh_version();
#else
  std::cerr << "built without Gmsh: Gmsh rows are skipped\n";
#endif

  // Square with a hole: uniform h, about 1.87 / h^2 triangles.
  {
    Series_calibration cal;
    const std::vector<double> sizes = opt.quick ? std::vector<double>{1e4, 1e5} : opt.square_sizes;
    // the phase breakdown at the largest size up to 1e6
    double phase_size = 0;
    for(double n : sizes)
      if(n <= opt.max_triangles && n <= 1e6) phase_size = n;
    for(double n : sizes) {
      if(n > opt.max_triangles) {
        std::cerr << "square with hole: " << n << " triangles skipped (--max-triangles)\n";
        continue;
      }
      const double h = std::sqrt(1.87 / n);
      const auto in = afm_geometry::square_with_circular_hole(1.0, 0.25, h);
      b.run_case("Square with a circular hole (uniform size)", "~" + size_class_text(n) + ", h = " + number_text(h, 4),
                 "square ~" + size_class_text(n), in, AFM::Uniform_sizing_field_2<K>(h), h, cal, n, n == phase_size);
    }
  }

  // Four-element airfoil, the Poisson field of the paper's Fig. 12.
  {
    const auto in = afm_geometry::multi_element_airfoil(15, 64);
    CDT cdt;
    afm_test::build_cdt(cdt, in);
    const auto t = std::chrono::steady_clock::now();
    std::vector<std::pair<Point, K::FT> > spacing;
    AFM::boundary_spacing_2(cdt, std::back_inserter(spacing));
    AFM::Poisson_sizing_field_options paper; // the boundary spacing diffused with the sources, as in the paper
    paper.boundary_spacing = AFM::Poisson_sizing_field_options::DIFFUSE_WITH_SOURCES;
    const Poisson_field field(spacing, afm_paper::figure_12_sources<K>(Point(0.5, 0), 15, 2 * CGAL_PI * 15 / 64),
                              paper);
    b.poisson_field_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
    Series_calibration cal;
    b.run_case("Four-element airfoil (Poisson field with the sources of the paper's Fig. 12)",
               "far field r = 15, 64 points", "four-element airfoil", in, field, 0, cal, 0, true);
  }

  // Many holes, uniform size (the square's spacing 0.02 is coarser).
  {
    const double h = opt.quick ? 0.01 : 0.004;
    Series_calibration cal;
    b.run_case("Many holes", "40 holes, h = " + number_text(h), "many holes", afm_geometry::many_holes(40, 1),
               AFM::Uniform_sizing_field_2<K>(h), h, cal);
  }

  // MESH2D lake (uniform) and islands (boundary-graded), shared data.
  if(opt.data_dir.empty()) {
    std::cerr << "no shared data directory: MESH2D cases skipped\n";
  } else {
    try {
      const double lake_h = opt.quick ? 0.1 : 0.03;
      Series_calibration lake_cal;
      b.run_case("MESH2D geometries (shared data)", "lake, h = " + number_text(lake_h), "MESH2D lake",
                 afm_shared_data::mesh2d_jigsaw(opt.data_dir + "/mesh2d/lake.msh"), AFM::Uniform_sizing_field_2<K>(lake_h),
                 lake_h, lake_cal);
      // geometry_table.cpp's size already gives 1.1e5 triangles: the 6,700
      // boundary edges set most of the mesh
      const double island_max = 0.25;
      const auto isl = afm_shared_data::mesh2d_jigsaw(opt.data_dir + "/mesh2d/islands.msh");
      const afm_test::Boundary_graded_size<K> brute_force(isl, 0.2, island_max);
      const afm_bench::Boundary_graded_size_tree<K> graded(brute_force);
      {
        // the tree must return exactly the brute-force values
        std::mt19937 rng(7);
        std::uniform_real_distribution<double> u(0, 1);
        double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
        for(const auto& p : isl.points) {
          x0 = std::min(x0, p[0]); x1 = std::max(x1, p[0]);
          y0 = std::min(y0, p[1]); y1 = std::max(y1, p[1]);
        }
        std::size_t differ = 0;
        for(int i = 0; i < 2000; ++i) {
          const Point p(x0 + (x1 - x0) * (1.2 * u(rng) - 0.1), y0 + (y1 - y0) * (1.2 * u(rng) - 0.1));
          differ += brute_force(p) != graded(p);
        }
        std::cerr << "boundary-graded size: the k-d tree differs from the brute force at " << differ
                  << " of 2000 random points\n";
        if(differ != 0) throw std::runtime_error("Boundary_graded_size_tree differs from Boundary_graded_size");
      }
      Series_calibration isl_cal;
      b.run_case("MESH2D geometries (shared data)",
                 "islands, boundary-graded g = 0.2, max " + number_text(island_max), "MESH2D islands", isl, graded, 0, isl_cal);
    } catch(const std::exception& e) {
      std::cerr << "MESH2D cases skipped: " << e.what() << "\n";
    }
  }

#ifdef AFM_WITH_GMSH
  gmsh::finalize();
#endif
  write_report(b, heap_check);
  write_plots(b);
  std::cerr << "wrote " << opt.out_dir << "/benchmark_results.md, benchmark_time.svg, benchmark_memory.svg\n"
            << "process VmHWM " << vm_status("VmHWM") << ", VmRSS " << vm_status("VmRSS") << "\n";
  return EXIT_SUCCESS;
}
