// Streaming (Advancing_front_mesher_2::set_output_sink()) against meshing in
// memory and against CGAL Mesh_2, measured in the same run on the
// benchmark's square with a circular hole at uniform size h = sqrt(1.87 / N)
// for N triangles: wall time, peak heap above the state before the run
// (heap_meter.h, every allocation of the process), triangles, and for
// streaming the largest number of triangles in memory. The streamed
// triangles go to a sink that counts them: writing them to files
// (IO::Streaming_mesh_writer) adds buffers of constant size, not memory
// that grows with the mesh. Mesh_2 runs with B = 0.125 and the size bound
// S = 1.4737 h, which matched our counts within 0.5% in mesher_comparison.
//
//   streaming_memory [--sizes 1e5,1e6,1e7] [--out DIR]
//
// Writes DIR/streaming_results.md (default DIR: the current directory).
#include "bench_common.h" // first: it defines the allocation functions (heap_meter.h)

#include "afm_geometries.h"
#include "afm_test_mesh.h"

#include <CGAL/Advancing_front_mesher_2.h>
#include <CGAL/Delaunay_mesh_size_criteria_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

std::string afm_test::shared_data_dir() { return ""; }

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef afm_test::Types<K>::CDT CDT;
namespace AFM = CGAL::Advancing_front_mesh_2;
using afm_bench::Meter;

struct Counting_sink : AFM::Mesh_sink_2<K::Point_2>
{
  std::size_t vertices = 0, triangles = 0;
  void add_vertex(std::size_t, const K::Point_2&) override { ++vertices; }
  void add_triangle(std::size_t, std::size_t, std::size_t) override { ++triangles; }
};

struct Row
{
  double nominal = 0, h = 0;
  std::size_t in_core_triangles = 0, streamed_triangles = 0, mesh2_triangles = 0;
  double in_core_seconds = 0, streamed_seconds = 0, mesh2_seconds = 0;
  std::size_t in_core_peak = 0, streamed_peak = 0, mesh2_peak = 0;
  std::size_t in_memory = 0, refused = 0;
};

std::size_t in_domain_faces(const CDT& cdt)
{
  std::size_t n = 0;
  for(auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) n += f->is_in_domain();
  return n;
}

Row measure(double nominal)
{
  Row row;
  row.nominal = nominal;
  row.h = std::sqrt(1.87 / nominal);
  const afm_test::Poly_data in = afm_geometry::square_with_circular_hole(1.0, 0.25, row.h);
  const auto seeds = afm_test::seeds_of<CDT>(in);
  const AFM::Uniform_sizing_field_2<K> size(row.h);
  Meter meter;
  {
    meter.start();
    CDT cdt;
    afm_test::build_cdt(cdt, in);
    CGAL::Advancing_front_mesher_2<CDT> mesher(cdt, size);
    // the paper's mode, in which the manual's figures were measured (these
    // inputs' boundaries are at the size)
    mesher.set_constraint_splitting(false);
    mesher.set_seeds(seeds.begin(), seeds.end());
    mesher.refine_mesh();
    meter.stop();
    row.in_core_triangles = in_domain_faces(cdt);
    row.in_core_seconds = meter.seconds();
    row.in_core_peak = meter.peak_bytes();
  }
  std::cerr << "  in memory: " << row.in_core_triangles << " triangles, " << row.in_core_seconds << " s\n";
  {
    meter.start();
    CDT cdt;
    afm_test::build_cdt(cdt, in);
    Counting_sink sink;
    CGAL::Advancing_front_mesher_2<CDT> mesher(cdt, size);
    // the paper's mode, in which the manual's figures were measured (these
    // inputs' boundaries are at the size)
    mesher.set_constraint_splitting(false);
    mesher.set_seeds(seeds.begin(), seeds.end());
    mesher.set_output_sink(&sink);
    mesher.refine_mesh();
    meter.stop();
    row.streamed_triangles = sink.triangles;
    row.streamed_seconds = meter.seconds();
    row.streamed_peak = meter.peak_bytes();
    row.in_memory = mesher.statistics().largest_triangles_in_memory;
    row.refused = mesher.statistics().points_refused_for_finished_triangles;
  }
  std::cerr << "  streamed: " << row.streamed_triangles << " triangles, " << row.streamed_seconds << " s\n";
  {
    meter.start();
    CDT cdt;
    afm_test::build_cdt(cdt, in);
    CGAL::refine_Delaunay_mesh_2(cdt, seeds.begin(), seeds.end(),
                                 CGAL::Delaunay_mesh_size_criteria_2<CDT>(0.125, 1.4737 * row.h));
    meter.stop();
    row.mesh2_triangles = in_domain_faces(cdt);
    row.mesh2_seconds = meter.seconds();
    row.mesh2_peak = meter.peak_bytes();
  }
  std::cerr << "  Mesh_2: " << row.mesh2_triangles << " triangles, " << row.mesh2_seconds << " s\n";
  return row;
}

std::string fixed(double v, int digits)
{
  std::ostringstream os;
  os << std::fixed << std::setprecision(digits) << v;
  return os.str();
}

std::string grouped(std::size_t n)
{
  std::string s = std::to_string(n);
  for(int i = int(s.size()) - 3; i > 0; i -= 3) s.insert(std::size_t(i), ",");
  return s;
}

} // namespace

int main(int argc, char* argv[])
{
  std::vector<double> sizes{1e5, 1e6, 1e7};
  std::string out_dir = ".";
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if(a == "--sizes" && i + 1 < argc) {
      sizes.clear();
      std::istringstream is(argv[++i]);
      for(std::string t; std::getline(is, t, ',');) sizes.push_back(std::stod(t));
    } else if(a == "--out" && i + 1 < argc) {
      out_dir = argv[++i];
    } else {
      std::cerr << "usage: streaming_memory [--sizes 1e5,1e6,1e7] [--out DIR]\n";
      return 2;
    }
  }
  std::vector<Row> rows;
  for(double n : sizes) {
    std::cerr << "== square with a hole, ~" << n << " triangles\n";
    rows.push_back(measure(n));
  }
  std::ostringstream os;
  const double MB = 1e6;
  os << "# Streaming: peak memory against meshing in memory and CGAL Mesh_2\n\n"
     << "Square with a circular hole, uniform size, all three measured in the same run by "
        "`benchmark/Advancing_front_mesh_2/streaming_memory` (Release; peak heap above the state before "
        "the run, every allocation counted; the streamed triangles go to a sink that counts them).\n\n"
     << "| triangles (in memory / streamed / Mesh_2) | streamed = in memory | time in memory / streamed / Mesh_2 (s) "
        "| peak heap in memory / streamed / Mesh_2 (MB) | streamed / Mesh_2 heap | streamed / in memory heap "
        "| most triangles in memory while streaming |\n"
     << "|---|---|--:|--:|--:|--:|--:|\n";
  for(const Row& r : rows) {
    os << "| " << grouped(r.in_core_triangles) << " / " << grouped(r.streamed_triangles) << " / "
       << grouped(r.mesh2_triangles) << " | "
       << (r.streamed_triangles == r.in_core_triangles && r.refused == 0 ? "yes" : "NO (" + grouped(r.refused) +
                                                                                      " points refused)")
       << " | " << fixed(r.in_core_seconds, 2) << " / " << fixed(r.streamed_seconds, 2) << " / "
       << fixed(r.mesh2_seconds, 2) << " | " << fixed(double(r.in_core_peak) / MB, 1) << " / "
       << fixed(double(r.streamed_peak) / MB, 1) << " / " << fixed(double(r.mesh2_peak) / MB, 1) << " | "
       << fixed(double(r.streamed_peak) / double(r.mesh2_peak), 3) << " | "
       << fixed(double(r.streamed_peak) / double(r.in_core_peak), 3) << " | " << grouped(r.in_memory) << " ("
       << fixed(100. * double(r.in_memory) / double(r.streamed_triangles), 1) << "%) |\n";
  }
  std::cout << os.str();
  const std::string file = out_dir + "/streaming_results.md";
  std::ofstream f(file);
  f << os.str();
  f.close();
  if(!f) {
    std::cerr << "streaming_memory: cannot write " << file << "\n";
    return 1;
  }
  return 0;
}
