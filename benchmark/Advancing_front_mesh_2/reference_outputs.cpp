// Writes the outputs that prove a refactoring a pure move: for every
// geometry of the test catalogue (afm_robustness::catalogue(), the shared
// data meshed by the tests) and for the benchmark inputs, the OFF file of
// the mesh made in memory (Epick, and Epeck for the catalogue), the mesher's
// counters, and in streaming mode the streamed OFF file and every checkpoint
// file written along the way (about four per run). Two builds of this
// program, before and after a change, must write byte-identical files:
// scripts/compare_reference_outputs.sh builds it at two commits and compares.
//
// Usage: reference_outputs OUT_DIR [SHARED_DATA_DIR] [--quick]
// (--quick leaves out the 1M-triangle square).
#include "afm_geometries.h"
#include "afm_paper_sources.h"
#include "afm_robustness_catalogue.h"
#include "afm_shared_data.h"
#include "afm_test_mesh.h"

#include <CGAL/Advancing_front_mesh_2/IO/Streaming_mesh_writer.h>
#include <CGAL/Advancing_front_mesh_2/IO/write_mesh.h>
#include <CGAL/Advancing_front_mesh_2/Poisson_sizing_field_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cstdio>
#include <fstream>
#include <functional>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace AFM = CGAL::Advancing_front_mesh_2;
typedef CGAL::Exact_predicates_inexact_constructions_kernel Epick;
typedef CGAL::Exact_predicates_exact_constructions_kernel Epeck;
typedef afm_test::Poly_data Poly_data;

std::string out_dir;

std::string file_name(const std::string& label)
{
  std::string s;
  for(char c : label) s += (std::isalnum(static_cast<unsigned char>(c)) ? c : '_');
  return out_dir + "/" + s;
}

// every counter of the statistics, not the times
std::string counters(const AFM::Statistics& s)
{
  std::ostringstream os;
  os << s.front_edges_processed << ' ' << s.points_inserted << ' ' << s.triangles_closed_on_existing_points << ' '
     << s.forced_closures << ' ' << s.rejected_points << ' ' << s.triangles_around_new_points << ' '
     << s.triangles_removed << ' ' << s.size_bound_raised << ' ' << s.broken_circle_queries << ' '
     << s.point_search_queries << ' ' << s.incircle_tests << ' ' << s.largest_front << ' ' << s.pockets << ' '
     << s.memory_compactions << ' ' << s.largest_active_vertices << ' ' << s.largest_live_triangles << ' '
     << s.delaunay_repair_flips << ' ' << s.stream_sweeps << ' ' << s.largest_triangles_in_memory << ' '
     << s.points_refused_for_finished_triangles << ' ' << s.finished_triangles_broken << ' '
     << s.checkpoints_written << ' ' << s.number_of_vertices << ' ' << s.number_of_faces << '\n';
  return os.str();
}

void copy_file(const std::string& from, const std::string& to)
{
  std::ifstream in(from.c_str(), std::ios::binary);
  std::ofstream out(to.c_str(), std::ios::binary);
  out << in.rdbuf();
  if(!in || !out) throw std::runtime_error("cannot copy " + from + " to " + to);
}

template <class K, class Sizing>
std::size_t mesh_in_memory(const std::string& label, const Poly_data& in, const Sizing& sizing, bool pockets)
{
  typedef typename afm_test::Types<K>::CDT CDT;
  CDT cdt;
  afm_test::build_cdt(cdt, in);
  const auto seeds = afm_test::seeds_of<CDT>(in);
  CGAL::Advancing_front_mesher_2<CDT, Sizing> mesher(cdt, sizing);
  // the paper's mode, in which the manual's figures were measured (these
  // inputs' boundaries are at the size)
  mesher.set_constraint_splitting(false);
  mesher.set_seeds(seeds.begin(), seeds.end());
  mesher.set_pocket_priority(pockets);
  if(mesher.refine_mesh() != AFM::MESH_COMPLETE) throw std::runtime_error(label + ": not complete");
  const std::string base = file_name(label);
  std::ofstream os((base + ".off").c_str());
  AFM::IO::write_OFF(os, cdt);
  std::ofstream((base + ".counters").c_str()) << counters(mesher.statistics());
  return mesher.statistics().number_of_faces;
}

// Streams the mesh to OFF, stopping at each checkpoint to keep a copy of it.
template <class K, class Sizing>
void mesh_streaming(const std::string& label, const Poly_data& in, const Sizing& sizing, std::size_t triangles)
{
  typedef typename afm_test::Types<K>::CDT CDT;
  const std::string base = file_name(label) + ".stream";
  CDT cdt;
  afm_test::build_cdt(cdt, in);
  const auto seeds = afm_test::seeds_of<CDT>(in);
  AFM::IO::Streaming_mesh_writer<typename CDT::Point> writer(std::vector<std::string>{base + ".off"});
  CGAL::Advancing_front_mesher_2<CDT, Sizing> mesher(cdt, sizing);
  // the paper's mode, in which the manual's figures were measured (these
  // inputs' boundaries are at the size)
  mesher.set_constraint_splitting(false);
  mesher.set_seeds(seeds.begin(), seeds.end());
  mesher.set_output_sink(&writer);
  // small sweeps and checkpoints: a few of them even on small meshes
  mesher.set_sweep_interval(std::max<std::size_t>(8, triangles / 32));
  mesher.set_checkpoint(std::max<std::size_t>(8, triangles / 8), base + ".checkpoint", "reference", true);
  int k = 0;
  for(;;) {
    const AFM::Mesh_return_code rc = mesher.refine_mesh();
    if(rc == AFM::MESH_COMPLETE) break;
    if(rc != AFM::STOPPED_AT_CHECKPOINT) throw std::runtime_error(label + ": streaming stopped early");
    copy_file(base + ".checkpoint", base + ".checkpoint." + std::to_string(k++));
  }
  std::remove((base + ".checkpoint").c_str());
  writer.close();
  std::ofstream((base + ".counters").c_str()) << counters(mesher.statistics());
  std::cout << label << ": " << triangles << " triangles, " << k << " checkpoints\n";
}

template <class Sizing>
void run(const std::string& label, const Poly_data& in, const Sizing& sizing, bool stream = true)
{
  const std::size_t n = mesh_in_memory<Epick>(label, in, sizing, true);
  if(stream) mesh_streaming<Epick>(label, in, sizing, n);
  else std::cout << label << ": " << n << " triangles\n";
}

} // namespace

int main(int argc, char* argv[])
{
  if(argc < 2) {
    std::cerr << "usage: reference_outputs OUT_DIR [SHARED_DATA_DIR] [--quick]\n";
    return 1;
  }
  out_dir = argv[1];
  std::string data = argc > 2 && std::string(argv[2]) != "--quick" ? argv[2] : "";
  bool quick = false;
  for(int i = 2; i < argc; ++i) quick = quick || std::string(argv[i]) == "--quick";
  try {
    // the test catalogue, with both kinds of kernels
    for(const afm_robustness::Case& c : afm_robustness::catalogue()) {
      const afm_robustness::Case_size<Epick> size(c);
      run("catalogue " + c.name, c.in, size);
      mesh_in_memory<Epeck>("catalogue Epeck " + c.name, c.in, afm_robustness::Case_size<Epeck>(c), true);
    }
    mesh_in_memory<Epick>("square without pocket priority",
                          afm_geometry::square_with_circular_hole(1, 0.25, 0.01),
                          afm_test::uniform<Epick>(0.01), false);
    // the benchmark's inputs
    for(double n : quick ? std::vector<double>{1e5} : std::vector<double>{1e5, 1e6}) {
      const double h = std::sqrt(1.87 / n);
      run("benchmark square " + std::to_string(int(n)), afm_geometry::square_with_circular_hole(1.0, 0.25, h),
          afm_test::uniform<Epick>(h), n <= 1e5);
    }
    {
      const Poly_data in = afm_geometry::multi_element_airfoil(15, 64);
      typename afm_test::Types<Epick>::CDT cdt;
      afm_test::build_cdt(cdt, in);
      std::vector<std::pair<Epick::Point_2, Epick::FT> > spacing;
      AFM::boundary_spacing_2(cdt, std::back_inserter(spacing));
      AFM::Poisson_sizing_field_options paper; // the field the reference outputs were made with
      paper.boundary_spacing = AFM::Poisson_sizing_field_options::DIFFUSE_WITH_SOURCES;
      const AFM::Poisson_sizing_field_2<Epick> field(
        spacing, afm_paper::figure_12_sources<Epick>(Epick::Point_2(0.5, 0), 15, 2 * CGAL_PI * 15 / 64), paper);
      run("benchmark four-element airfoil Poisson field", in, field);
    }
    run("benchmark many holes", afm_geometry::many_holes(40, 1), afm_test::uniform<Epick>(0.004));
    if(!data.empty()) {
      const Poly_data lake = afm_shared_data::mesh2d_jigsaw(data + "/mesh2d/lake.msh");
      run("benchmark MESH2D lake", lake, afm_test::uniform<Epick>(0.03));
      run("test MESH2D lake", lake, afm_test::uniform<Epick>(0.1));
      const Poly_data islands = afm_shared_data::mesh2d_jigsaw(data + "/mesh2d/islands.msh");
      run("MESH2D islands", islands, afm_test::Boundary_graded_size<Epick>(islands, 0.2, 0.25));
      const Poly_data p30 = afm_shared_data::thirty_p_thirty_n(data, 20, 96);
      run("30P-30N", p30, afm_test::Boundary_graded_size<Epick>(p30, 0.2));
      const Poly_data nlr = afm_shared_data::nlr7301_with_flap(data);
      run("NLR 7301 with flap", nlr, afm_test::Boundary_graded_size<Epick>(nlr, 0.2));
      for(const char* f : {"A", "double_hex"}) {
        const Poly_data t = afm_shared_data::triangle_poly(data + "/triangle_drufat/" + f + ".poly");
        run(std::string("Triangle ") + f, t, afm_test::uniform<Epick>(0.02));
      }
    }
  } catch(const std::exception& e) {
    std::cerr << "reference_outputs: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
