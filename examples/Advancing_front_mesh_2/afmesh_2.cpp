// afmesh_2: the command-line front end of Advancing_front_mesh_2.
//
//   afmesh_2 INPUT.poly [--size H] [--sources FILE] [--grading G|off]
//            -o OUT.off [-o OUT.vtu] [-o OUT.svg]
//            [--smooth N] [--svg-color plain|quality] [--histogram OUT.svg]
//            [--kernel epick|epeck|exact-rational] [--stats] [--report]
//
// --size alone meshes with the uniform target edge length H. Otherwise the
// size field is a Poisson_sizing_field_2 made from the boundary spacing and
// the sources of FILE (one "x y h" per line), limited by the gradation G
// (default 0.2) and, with --size, bounded above by H.
//
// Streaming (meshes larger than memory): --stream hands finished triangles
// to the output files while meshing, so that memory holds only the part
// near the front; --checkpoint-every K FILE also writes the mesher's state
// to FILE after every K more triangles, and --resume FILE continues such a
// run later (with the options stored in FILE), giving the same files as an
// uninterrupted run.
//
// Exit codes: 0 success; 1 invalid input (one line "afmesh_2: error:
// FILE[:LINE]: what is wrong" on stderr); 2 bad usage; 3 an output or
// checkpoint that could not be written, or an internal error.

#include <CGAL/Advancing_front_mesher_2.h>
#include <CGAL/Advancing_front_mesh_2/IO/read_poly.h>
#include <CGAL/Advancing_front_mesh_2/IO/insert_poly.h>
#include <CGAL/Advancing_front_mesh_2/IO/read_size_sources.h>
#include <CGAL/Advancing_front_mesh_2/Poisson_sizing_field_2.h>
#include <CGAL/Advancing_front_mesh_2/IO/write_quality_histogram.h>
#include <CGAL/Advancing_front_mesh_2/laplacian_smooth_mesh_2.h>
#include <CGAL/Advancing_front_mesh_2/IO/write_mesh.h>
#include <CGAL/Advancing_front_mesh_2/IO/Streaming_mesh_writer.h>
#include <CGAL/Advancing_front_mesh_2/Mesh_quality.h>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Exact_rational.h>
#include <CGAL/Simple_cartesian.h>

#include <boost/program_options.hpp>
#include <boost/property_map/function_property_map.hpp>

#include <chrono>
#include <memory>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <set>
#include <iostream>
#include <list>
#include <sstream>
#include <string>
#include <sys/resource.h>
#include <unistd.h>
#include <vector>

namespace po = boost::program_options;
namespace AFM = CGAL::Advancing_front_mesh_2;

namespace {

const char* const program = "afmesh_2";

struct Usage_error : std::runtime_error { using std::runtime_error::runtime_error; };
struct Input_error : std::runtime_error { using std::runtime_error::runtime_error; };

struct Options
{
  std::string input;
  double size = 0;
  bool has_size = false;
  std::string sources;
  std::string grading = "0.2";
  double gradation = AFM::Poisson_sizing_field_options::default_gradation; // 0: off
  std::vector<std::string> outputs;
  std::string kernel = "epick";
  bool stats = false;
  bool report = false;
  bool no_pocket_priority = false;
  double time_limit = 0;     // seconds of meshing, 0: none
  std::size_t max_steps = 0; // front edges processed, 0: none
  std::size_t smooth = 0;
  std::string svg_color = "plain";
  std::string histogram;
  bool stream = false;
  std::size_t checkpoint_every = 0; // triangles, 0: no checkpoints
  std::string checkpoint_file;
  bool stop_after_checkpoint = false;
  std::string resume;               // checkpoint to resume from
  std::string arguments;            // the run's own arguments, '\0'-separated, stored in checkpoints
  std::string input_checksum, sources_checksum; // of the files a checkpointed run read
};

// An absolute name, so that a checkpointed run can be resumed from another
// directory.
std::string absolute_path(const std::string& name)
{
  std::error_code ec;
  const std::filesystem::path p = std::filesystem::absolute(name, ec);
  return ec ? name : p.lexically_normal().string();
}

// FNV-1a over the file's bytes, in hexadecimal ("" if it cannot be read):
// a resumed run must read the same input as the interrupted one.
std::string file_checksum(const std::string& name)
{
  std::ifstream is(name.c_str(), std::ios::in | std::ios::binary);
  if(!is) return std::string();
  // the hash the checkpoints themselves are checked with
  namespace AFMI = CGAL::Advancing_front_mesh_2::internal;
  std::uint64_t h = AFMI::fnv1a_offset_basis;
  char buffer[1 << 16];
  while(is.read(buffer, sizeof buffer) || is.gcount() > 0) {
    h = AFMI::fnv1a_update(h, buffer, std::size_t(is.gcount()));
    if(!is) break;
  }
  std::ostringstream os;
  os << std::hex << std::setw(16) << std::setfill('0') << h;
  return os.str();
}

// peak resident memory of the process, in bytes
double peak_rss_bytes()
{
  struct rusage u;
  if(getrusage(RUSAGE_SELF, &u) != 0) return std::nan("");
#ifdef __APPLE__
  return double(u.ru_maxrss); // bytes on macOS
#else
  return 1024. * double(u.ru_maxrss); // kilobytes on Linux and the BSDs
#endif
}

double seconds_since(std::chrono::steady_clock::time_point t)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

// A progress bar on stderr, only when stderr is a terminal, redrawn at most
// ten times a second.
struct Progress_visitor : AFM::Default_visitor
{
  bool enabled = false;
  std::chrono::steady_clock::time_point last = std::chrono::steady_clock::now();
  void on_progress(double fraction)
  {
    if(!enabled || seconds_since(last) < 0.1) return;
    last = std::chrono::steady_clock::now();
    const int width = 40, filled = int(fraction * width);
    std::cerr << "\r[" << std::string(filled, '#') << std::string(width - filled, ' ') << "] "
              << std::fixed << std::setprecision(1) << 100 * fraction << "%" << std::flush;
  }
  void done()
  {
    if(enabled) std::cerr << "\r" << std::string(50, ' ') << "\r" << std::flush;
  }
};

template <class K>
struct Types
{
  typedef CGAL::Triangulation_vertex_base_2<K> Vb;
  typedef CGAL::Delaunay_mesh_face_base_2<K> Fb;
  typedef CGAL::Triangulation_data_structure_2<Vb, Fb> Tds;
  // legal input has no crossing segments: refuse them instead of splitting
  typedef CGAL::Constrained_Delaunay_triangulation_2<
    K, Tds, CGAL::No_constraint_intersection_requiring_constructions_tag> CDT;
};

// Either a uniform size or a background field, so that one mesher type
// serves both.
template <class K>
struct Cli_sizing_field
{
  typedef AFM::Poisson_sizing_field_2<K> Background;
  double uniform = 0;
  std::shared_ptr<const Background> background;
  typename K::FT operator()(const typename K::Point_2& p) const
  {
    return background ? (*background)(p) : typename K::FT(uniform);
  }
};

void json_number(std::ostream& os, const char* name, double v, bool comma = true)
{
  os << "\"" << name << "\": ";
  if(std::isfinite(v)) os << v; else os << "null";
  if(comma) os << ", ";
}

template <class K>
int run(const Options& opt)
{
  typedef typename Types<K>::CDT CDT;
  typedef typename K::Point_2 Point;
  const auto t_start = std::chrono::steady_clock::now();

  AFM::IO::Poly_data in;
  try {
    in = AFM::IO::read_poly(opt.input);
  } catch(const AFM::IO::Poly_read_error& e) {
    throw Input_error(e.what());
  }
  const double t_read = seconds_since(t_start);
  if(!opt.resume.empty()) {
    // the size field is made again from the input: it must be the same
    if(!opt.input_checksum.empty() && file_checksum(opt.input) != opt.input_checksum)
      throw Input_error(opt.input + ": not the file the checkpoint " + opt.resume +
                        " was made from (its content changed)");
    if(!opt.sources_checksum.empty() && file_checksum(opt.sources) != opt.sources_checksum)
      throw Input_error(opt.sources + ": not the file the checkpoint " + opt.resume +
                        " was made from (its content changed)");
  }

  // The boundary, checked on the way (crossings, overlaps, open
  // boundaries, misplaced hole seeds: one line naming the file and line).
  const auto t_cdt = std::chrono::steady_clock::now();
  CDT cdt;
  AFM::IO::Poly_insertion<CDT> inserted;
  try {
    inserted = AFM::IO::insert_poly(cdt, in);
  } catch(const AFM::IO::Poly_read_error& e) {
    throw Input_error(e.what());
  }
  const std::vector<typename CDT::Vertex_handle>& vh = inserted.vertices;
  const std::list<Point> seeds(inserted.hole_seeds.begin(), inserted.hole_seeds.end());
  if(inserted.merged_points + inserted.duplicate_segments + inserted.points_on_segments > 0)
    std::cerr << "afmesh_2: note: " << opt.input << ": " << inserted.merged_points << " duplicate points merged, "
              << inserted.duplicate_segments << " duplicate segments dropped, " << inserted.points_on_segments
              << " points inside segments (split there)\n";
  const double t_boundary = seconds_since(t_cdt);

  const auto t_field = std::chrono::steady_clock::now();
  Cli_sizing_field<K> sizing;
  sizing.uniform = opt.size;
  if(!opt.has_size || !opt.sources.empty()) {
    std::vector<AFM::Size_source_2<K> > sources;
    if(!opt.sources.empty()) {
      try {
        for(const auto& s : AFM::IO::read_size_sources(opt.sources))
          sources.emplace_back(Point(s[0], s[1]), s[2]);
      } catch(const AFM::IO::Poly_read_error& e) {
        throw Input_error(e.what());
      }
    }
    std::vector<std::pair<Point, typename K::FT> > spacing;
    AFM::boundary_spacing_2(cdt, std::back_inserter(spacing));
    if(spacing.empty() && sources.empty())
      throw Input_error(opt.input + ": no segments to derive a size from; give --size or --sources");
    AFM::Poisson_sizing_field_options field_options;
    field_options.limit_gradation = opt.gradation > 0;
    if(opt.gradation > 0) field_options.gradation = opt.gradation;
    if(opt.has_size) field_options.max_size = opt.size;
    sizing.background = std::make_shared<AFM::Poisson_sizing_field_2<K> >(spacing, sources, field_options);
  }
  const double t_size_field = seconds_since(t_field);

  Progress_visitor progress;
  progress.enabled = isatty(2) != 0;
  // a resumed run meshes in an empty triangulation: the state comes from
  // the checkpoint; the input was read again for the size field only
  CDT resumed_cdt;
  CGAL::Advancing_front_mesher_2<CDT, Cli_sizing_field<K>, Progress_visitor> mesher(
    opt.resume.empty() ? cdt : resumed_cdt, sizing, progress);
  mesher.set_seeds(seeds.begin(), seeds.end());
  mesher.set_pocket_priority(!opt.no_pocket_priority);
  mesher.set_time_limit(opt.time_limit);
  mesher.set_iteration_limit(opt.max_steps);
  std::unique_ptr<AFM::IO::Streaming_mesh_writer<Point> > writer;
  if(opt.stream) {
    if(opt.checkpoint_every > 0) {
      // before any output is touched: a checkpoint that cannot be written
      // would otherwise only show after the first K triangles
      const std::string tmp = opt.checkpoint_file + ".tmp";
      if(!std::ofstream(tmp.c_str(), std::ios::out | std::ios::binary | std::ios::app))
        throw Input_error(tmp + ": cannot write the checkpoint here");
      std::remove(tmp.c_str());
    }
    try {
      if(opt.resume.empty()) {
        std::vector<std::string> outputs = opt.outputs;
        // the writer's state in a checkpoint names them
        if(opt.checkpoint_every > 0)
          for(std::string& out : outputs) out = absolute_path(out);
        writer.reset(new AFM::IO::Streaming_mesh_writer<Point>(outputs));
      } else {
        typedef CGAL::Advancing_front_mesher_2<CDT, Cli_sizing_field<K>, Progress_visitor> Mesher;
        writer = AFM::IO::Streaming_mesh_writer<Point>::resume(Mesher::read_checkpoint_info(opt.resume).sink_state);
      }
    } catch(const std::exception& e) {
      throw Input_error((opt.resume.empty() ? std::string("output") : opt.resume) + ": " + e.what());
    }
    mesher.set_output_sink(writer.get());
    if(!opt.resume.empty()) {
      try {
        mesher.resume(opt.resume);
      } catch(const std::runtime_error& e) {
        throw Input_error(e.what());
      }
    }
    if(opt.checkpoint_every > 0)
      mesher.set_checkpoint(opt.checkpoint_every, opt.checkpoint_file, opt.arguments, opt.stop_after_checkpoint);
  }
  const auto t_mesh = std::chrono::steady_clock::now();
  AFM::Mesh_return_code rc;
  try {
    rc = mesher.refine_mesh();
  } catch(const AFM::Checkpoint_error& e) {
    // the outputs stay as they are: a resume from the previous checkpoint
    // cuts them back to it
    mesher.visitor().done();
    std::cerr << program << ": error: " << e.what() << "; the outputs are incomplete";
    if(mesher.statistics().checkpoints_written > 0)
      std::cerr << "; afmesh_2 --resume " << opt.checkpoint_file << " goes on from the previous checkpoint";
    std::cerr << "\n";
    return 3;
  }
  if(rc == AFM::TIME_LIMIT_REACHED || rc == AFM::ITERATION_LIMIT_REACHED)
    std::cerr << "afmesh_2: note: " << opt.input << ": "
              << (rc == AFM::TIME_LIMIT_REACHED ? "--time-limit" : "--max-steps")
              << " reached: the rest of the front was closed on existing points (valid, coarser there)\n";
  mesher.visitor().done();
  const double t_meshing = seconds_since(t_mesh);
  const AFM::Statistics& st = mesher.statistics();
  if(rc != AFM::STOPPED_AT_CHECKPOINT && st.number_of_faces == 0)
    throw Input_error(opt.input + ": nothing to mesh: no bounded region is left once the holes are removed");
  if(rc == AFM::STOPPED_AT_CHECKPOINT) {
    std::cerr << "afmesh_2: note: stopped after writing the checkpoint " << opt.checkpoint_file << " ("
              << st.number_of_faces << " triangles written so far); continue with: afmesh_2 --resume "
              << opt.checkpoint_file << "\n";
  } else if(writer) {
    try {
      writer->close();
    } catch(const std::exception& e) {
      std::cerr << program << ": error: " << e.what() << "\n";
      return 3;
    }
  }
  if(opt.stream) {
    // the mesh is in the files: no quality figures, no pictures
    if(opt.report)
      (opt.stats ? std::cerr : std::cout)
        << (opt.resume.empty() ? opt.input : opt.resume) << ": " << st.number_of_vertices << " vertices, "
        << st.number_of_faces << " triangles streamed in " << t_meshing << " s; at most "
        << st.largest_triangles_in_memory << " triangles in memory, peak memory "
        << peak_rss_bytes() / 1048576 << " MiB\n";
    if(opt.stats) {
      std::ostringstream os;
      os.precision(6);
      os << "{\"input\": \"" << opt.input << "\", \"kernel\": \"" << opt.kernel << "\", \"streamed\": true, "
         << "\"mesh_return_code\": \""
         << (rc == AFM::MESH_COMPLETE ? "MESH_COMPLETE"
             : rc == AFM::TIME_LIMIT_REACHED ? "TIME_LIMIT_REACHED"
             : rc == AFM::ITERATION_LIMIT_REACHED ? "ITERATION_LIMIT_REACHED" : "STOPPED_AT_CHECKPOINT")
         << "\", \"vertices\": " << st.number_of_vertices << ", \"triangles\": " << st.number_of_faces << ", ";
      json_number(os, "mesh_time", t_meshing);
      json_number(os, "total_time", seconds_since(t_start));
      json_number(os, "peak_rss_bytes", peak_rss_bytes());
      os << "\"statistics\": {\"front_edges_processed\": " << st.front_edges_processed
         << ", \"points_inserted\": " << st.points_inserted << ", \"forced_closures\": " << st.forced_closures
         << ", \"largest_front\": " << st.largest_front
         << ", \"largest_triangles_in_memory\": " << st.largest_triangles_in_memory
         << ", \"stream_sweeps\": " << st.stream_sweeps
         << ", \"points_refused_for_finished_triangles\": " << st.points_refused_for_finished_triangles
         << ", \"finished_triangles_broken\": " << st.finished_triangles_broken
         << ", \"checkpoints_written\": " << st.checkpoints_written << "}}";
      std::cout << os.str() << std::endl;
    }
    return 0;
  }
  if(st.number_of_faces == 0) {
    throw Input_error(opt.input + ": nothing to mesh: no bounded region is left once the holes are removed");
  }

  // Smoothing moves mesher points only: the input's points (isolated ones
  // included) are held.
  AFM::Smoothing_statistics smoothing;
  const bool want_quality = opt.stats || opt.report || !opt.histogram.empty();
  AFM::Mesh_quality unsmoothed;
  if(want_quality) unsmoothed = AFM::mesh_quality(cdt, sizing);
  const auto t_smooth = std::chrono::steady_clock::now();
  if(opt.smooth > 0) {
    std::set<typename CDT::Vertex_handle> input_vertices(vh.begin(), vh.end());
    auto held = boost::make_function_property_map<typename CDT::Vertex_handle>(
      [&](typename CDT::Vertex_handle v) { return input_vertices.count(v) > 0; });
    smoothing = CGAL::laplacian_smooth_mesh_2(
      cdt, CGAL::parameters::number_of_iterations(opt.smooth).vertex_is_constrained_map(held));
  }
  const double t_smoothing = seconds_since(t_smooth);
  const AFM::Mesh_quality q = want_quality && opt.smooth > 0 ? AFM::mesh_quality(cdt, sizing) : unsmoothed;

  const auto t_write = std::chrono::steady_clock::now();
  auto write_failed = [&](const std::string& out, const std::exception& e) {
    std::cerr << program << ": error: " << out << ": " << e.what() << "\n";
    return 3;
  };
  for(const std::string& out : opt.outputs) {
    try {
      if(out.size() >= 4 && out.compare(out.size() - 4, 4, ".svg") == 0) {
        std::ofstream os(out);
        AFM::IO::SVG_options svg;
        svg.title = opt.input;
        svg.color_by_quality = opt.svg_color == "quality";
        AFM::IO::write_SVG(os, cdt, svg);
        os.close();
        if(os.fail()) throw std::runtime_error("cannot write " + out);
      } else {
        AFM::IO::write_mesh(out, cdt);
      }
    } catch(const std::exception& e) {
      return write_failed(out, e);
    }
  }
  if(!opt.histogram.empty()) {
    std::ofstream os(opt.histogram);
    AFM::IO::write_quality_histogram_SVG(os, q, opt.input);
    os.close();
    if(os.fail()) return write_failed(opt.histogram, std::runtime_error("cannot write " + opt.histogram));
  }
  const double t_writing = seconds_since(t_write);

  if(opt.report) {
    std::ostringstream os;
    os << std::setprecision(4);
    os << opt.input << ": " << st.number_of_vertices << " vertices, " << q.number_of_triangles << " triangles in "
       << t_meshing << " s (" << (t_meshing > 0 ? st.number_of_faces / t_meshing : 0) << " triangles/s)";
    if(opt.smooth > 0)
      os << ", then " << smoothing.passes << " smoothing passes in " << t_smoothing << " s (" << smoothing.moves
         << " moves, " << smoothing.flips << " flips)";
    os << "\n";
    auto line = [&](const char* when, const AFM::Mesh_quality& m) {
      os << "  " << when << "radius ratio 2r/R: min " << m.min_radius_ratio << ", 1% " << m.radius_ratio_p1
         << ", 5% " << m.radius_ratio_p5 << ", median " << m.radius_ratio_median << ", mean "
         << m.mean_radius_ratio << "; " << 100 * m.share_above_0_9 << "% above 0.9\n"
         << "  " << when << "angles: " << m.min_angle_degrees << " to " << m.max_angle_degrees << " degrees, "
         << 100 * m.share_angles_below_30 << "% below 30\n"
         << "  " << when << "edge length / h: " << m.min_edge_over_size << " to " << m.max_edge_over_size
         << ", mean " << m.mean_edge_over_size << ", " << 100 * m.share_edges_within_sqrt2
         << "% within [0.71, 1.41]\n";
    };
    if(opt.smooth > 0) line("before smoothing, ", unsmoothed);
    line("", q);
    // standard output, unless the JSON of --stats must stay alone there
    (opt.stats ? std::cerr : std::cout) << os.str();
  }

  if(opt.stats) {
    std::ostringstream os;
    os.precision(6);
    os << "{\"input\": \"" << opt.input << "\", \"kernel\": \"" << opt.kernel << "\", ";
    json_number(os, "size", opt.has_size ? opt.size : std::nan(""));
    os << "\"size_field\": {";
    if(sizing.background) {
      const auto& fs = sizing.background->statistics();
      os << "\"kind\": \"poisson\", \"sources\": " << fs.number_of_sources
         << ", \"boundary_points\": " << fs.number_of_boundary_points << ", \"quadtree_leaves\": "
         << fs.number_of_leaves << ", \"quadtree_corners\": " << fs.number_of_corners << ", ";
      json_number(os, "gradation", opt.gradation > 0 ? opt.gradation : std::nan(""));
      json_number(os, "smallest", fs.smallest_size);
      json_number(os, "largest", fs.largest_size);
    } else {
      os << "\"kind\": \"uniform\", ";
    }
    json_number(os, "build_time", t_size_field, false);
    os << "}, ";
    os << "\"mesh_return_code\": \""
       << (rc == AFM::MESH_COMPLETE ? "MESH_COMPLETE"
                                    : rc == AFM::TIME_LIMIT_REACHED ? "TIME_LIMIT_REACHED" : "ITERATION_LIMIT_REACHED")
       << "\", ";
    os << "\"input_repairs\": {\"merged_points\": " << inserted.merged_points << ", \"duplicate_segments\": "
       << inserted.duplicate_segments << ", \"points_on_segments\": " << inserted.points_on_segments << "}, ";
    os << "\"vertices\": " << st.number_of_vertices << ", \"triangles\": " << st.number_of_faces << ", ";
    os << "\"time\": {";
    json_number(os, "read", t_read);
    json_number(os, "boundary", t_boundary);
    json_number(os, "size_field", t_size_field);
    json_number(os, "mesh", t_meshing);
    json_number(os, "smooth", t_smoothing);
    json_number(os, "write", t_writing);
    json_number(os, "total", seconds_since(t_start), false);
    os << "}, \"triangles_per_second\": " << (t_meshing > 0 ? st.number_of_faces / t_meshing : 0) << ", ";
    os << "\"statistics\": {"
       << "\"front_edges_processed\": " << st.front_edges_processed
       << ", \"points_inserted\": " << st.points_inserted
       << ", \"triangles_closed_on_existing_points\": " << st.triangles_closed_on_existing_points
       << ", \"forced_closures\": " << st.forced_closures
       << ", \"rejected_points\": " << st.rejected_points
       << ", \"triangles_around_new_points\": " << st.triangles_around_new_points
       << ", \"triangles_removed\": " << st.triangles_removed
       << ", \"size_bound_raised\": " << st.size_bound_raised
       << ", \"triangle_octree_queries\": " << st.triangle_octree_queries
       << ", \"constraint_index_queries\": " << st.constraint_index_queries
       << ", \"edge_octree_queries\": " << st.constraint_index_queries
       << ", \"point_search_queries\": " << st.point_search_queries
       << ", \"incircle_tests\": " << st.incircle_tests
       << ", \"largest_front\": " << st.largest_front
       << ", \"pockets\": " << st.pockets
       << ", \"largest_live_triangles\": " << st.largest_live_triangles
       << ", \"largest_active_vertices\": " << st.largest_active_vertices
       << ", \"memory_compactions\": " << st.memory_compactions
       << ", \"delaunay_repair_flips\": " << st.delaunay_repair_flips << "}, ";
    json_number(os, "peak_rss_bytes", peak_rss_bytes());
    os << "\"quality\": {";
    json_number(os, "min_radius_ratio", q.min_radius_ratio);
    json_number(os, "mean_radius_ratio", q.mean_radius_ratio);
    json_number(os, "share_radius_ratio_above_0_9", q.share_above_0_9);
    json_number(os, "min_angle_degrees", q.min_angle_degrees);
    json_number(os, "max_angle_degrees", q.max_angle_degrees);
    json_number(os, "radius_ratio_p1", q.radius_ratio_p1);
    json_number(os, "radius_ratio_p5", q.radius_ratio_p5);
    json_number(os, "radius_ratio_median", q.radius_ratio_median);
    json_number(os, "share_angles_below_30", q.share_angles_below_30);
    os << "\"radius_ratio_histogram\": [";
    for(std::size_t k = 0; k < q.radius_ratio_histogram.size(); ++k) os << (k ? ", " : "") << q.radius_ratio_histogram[k];
    os << "], \"angle_histogram_10_degrees\": [";
    for(std::size_t k = 0; k < q.angle_histogram.size(); ++k) os << (k ? ", " : "") << q.angle_histogram[k];
    os << "], ";
    json_number(os, "min_edge_over_size", q.min_edge_over_size);
    json_number(os, "max_edge_over_size", q.max_edge_over_size);
    json_number(os, "mean_edge_over_size", q.mean_edge_over_size);
    json_number(os, "share_edges_within_sqrt2", q.share_edges_within_sqrt2, false);
    os << "}, \"smoothing\": {\"passes\": " << smoothing.passes << ", \"moves\": " << smoothing.moves
       << ", \"rejected_moves\": " << smoothing.rejected_moves << ", \"flips\": " << smoothing.flips << "}}";
    std::cout << os.str() << std::endl;
  }
  return 0;
}

// An option taking exactly two values (K FILE): a multitoken option would
// also take the input file given after them.
class Two_tokens : public po::typed_value<std::vector<std::string> >
{
public:
  explicit Two_tokens(std::vector<std::string>* store) : po::typed_value<std::vector<std::string> >(store) {}
  unsigned min_tokens() const override { return 2; }
  unsigned max_tokens() const override { return 2; }
};

void parse_checkpoint(const std::vector<std::string>& checkpoint, Options& opt)
{
  long long every = 0;
  std::size_t used = 0;
  if(checkpoint.size() == 2) {
    try {
      every = std::stoll(checkpoint[0], &used);
    } catch(const std::exception&) {
      used = 0;
    }
  }
  if(checkpoint.size() != 2 || used != checkpoint[0].size() || every < 1 || checkpoint[1].empty())
    throw Usage_error("--checkpoint-every takes a positive number of triangles K and a FILE");
  // Boost hands over the next option when FILE is missing
  if(checkpoint[1][0] == '-')
    throw Usage_error("--checkpoint-every takes a positive number of triangles K and a FILE, not '" + checkpoint[1] +
                      "'");
  opt.checkpoint_every = std::size_t(every);
  opt.checkpoint_file = checkpoint[1];
  opt.stream = true;
}

// The options a checkpoint stores, '\0'-separated: file names made absolute
// (a run may be resumed from another directory) and the checksums of the
// input files (a resumed run must read the same ones).
std::string stored_arguments(const po::parsed_options& parsed, const Options& opt, bool resuming)
{
  std::vector<std::string> out;
  for(const po::option& o : parsed.options) {
    if(o.string_key == "input") {
      out.push_back(absolute_path(o.value.at(0)));
      continue;
    }
    out.push_back("--" + o.string_key);
    for(std::size_t i = 0; i < o.value.size(); ++i) {
      const bool file = o.string_key == "sources" || o.string_key == "output" || o.string_key == "histogram" ||
                        (o.string_key == "checkpoint-every" && i == 1);
      out.push_back(file ? absolute_path(o.value[i]) : o.value[i]);
    }
  }
  if(!resuming) { // a resumed run's stored options hold them already
    out.insert(out.end(), {"--input-checksum", file_checksum(opt.input)});
    if(!opt.sources.empty()) out.insert(out.end(), {"--sources-checksum", file_checksum(opt.sources)});
  }
  std::string joined;
  for(const std::string& a : out) {
    if(!joined.empty()) joined += '\0';
    joined += a;
  }
  return joined;
}

Options parse(const std::vector<std::string>& args, bool resuming = false)
{
  Options opt;
  long long smooth = 0, max_steps = 0;
  std::vector<std::string> checkpoint;
  po::options_description visible("Usage: afmesh_2 INPUT.poly [--size H] [--sources FILE] -o OUT [-o OUT ...] [options]\n\n"
                                  "Meshes the domain of a Triangle .poly file with the advancing-front\n"
                                  "Delaunay algorithm of Mavriplis (1992). With --size alone the target edge\n"
                                  "length is uniform; otherwise it comes from a background field: the boundary\n"
                                  "spacing and the point sources, diffused by a Poisson solve on a quadtree,\n"
                                  "with a gradation limit, and bounded above by --size when given.\n\nOptions");
  visible.add_options()
    ("help,h", "print this help and exit")
    ("size", po::value<double>(&opt.size), "target edge length H: uniform, or the largest size with --sources")
    ("sources", po::value<std::string>(&opt.sources),
     "size sources, one 'x y h' per line ('#' comments): size h prescribed at (x, y)")
    ("grading", po::value<std::string>(&opt.grading)->default_value("0.2"),
     "gradation limit G of the background field: the size changes by at most G per unit length "
     "along each axis; 'off' to switch it off")
    ("output,o", po::value<std::vector<std::string> >(&opt.outputs),
     "output file, format chosen by extension: .off .vtu .node/.ele .msh .svg (repeatable)")
    ("kernel", po::value<std::string>(&opt.kernel)->default_value("epick"),
     "CGAL kernel: epick (default), epeck or exact-rational")
    ("smooth", po::value<long long>(&smooth)->default_value(0),
     "N passes (0 to 1000) of guarded Laplacian smoothing and Delaunay edge swapping after meshing")
    ("svg-color", po::value<std::string>(&opt.svg_color)->default_value("plain"),
     "SVG outputs: 'plain', or 'quality' to colour triangles by radius ratio")
    ("histogram", po::value<std::string>(&opt.histogram), "write the quality histograms as SVG to this file")
    ("no-pocket-priority", po::bool_switch(&opt.no_pocket_priority),
     "mesh the front's pockets in shortest-first order too: a little better quality "
     "where patches meet, a front up to 4 times larger")
    ("time-limit", po::value<double>(&opt.time_limit),
     "stop meshing after this many seconds: the rest of the front is closed on existing points, the "
     "mesh is valid but coarser there, and a note says so (the run ends without it too)")
    ("max-steps", po::value<long long>(&max_steps),
     "stop meshing after this many front edges, as --time-limit does")
    ("stream", po::bool_switch(&opt.stream),
     "write triangles to the outputs while meshing and drop them from memory, for meshes larger than "
     "memory (not with .svg outputs, --smooth or --histogram; no quality figures)")
    ("checkpoint-every", new Two_tokens(&checkpoint),
     "K FILE: with --stream (implied), write the mesher's state to FILE after every K more triangles, "
     "so that --resume FILE can finish an interrupted run")
    ("stop-after-checkpoint", po::bool_switch(&opt.stop_after_checkpoint),
     "stop right after the first checkpoint (to run a large mesh in several sessions)")
    ("resume", po::value<std::string>(&opt.resume),
     "FILE: continue the run whose checkpoint is FILE, with the options stored there; only "
     "--checkpoint-every, --stop-after-checkpoint, --time-limit, --max-steps, --stats and --report may be given")
    ("stats", po::bool_switch(&opt.stats), "print statistics as one JSON object on stdout")
    ("report", po::bool_switch(&opt.report),
     "print a readable quality summary (on stdout; on stderr with --stats)");
  po::options_description hidden;
  hidden.add_options()("input", po::value<std::string>(&opt.input))
    // written into checkpoints only (see stored_arguments())
    ("input-checksum", po::value<std::string>(&opt.input_checksum))
    ("sources-checksum", po::value<std::string>(&opt.sources_checksum));
  po::options_description all;
  all.add(visible).add(hidden);
  po::positional_options_description pos;
  pos.add("input", 1);
  po::variables_map vm;
  po::parsed_options parsed(&all);
  try {
    parsed = po::command_line_parser(args).options(all).positional(pos).run();
    po::store(parsed, vm);
    po::notify(vm);
  } catch(const po::error& e) {
    throw Usage_error(e.what());
  }
  if(!resuming && (vm.count("input-checksum") || vm.count("sources-checksum")))
    throw Usage_error("unrecognised option '--" + std::string(vm.count("input-checksum") ? "input" : "sources") +
                      "-checksum'");
  if(vm.count("help")) {
    std::cout << visible << "\nExit codes: 0 success, 1 invalid input, 2 bad usage, 3 an output or checkpoint that "
                            "could not be written, or an internal error.\n";
    std::exit(EXIT_SUCCESS);
  }
  if(!opt.resume.empty()) {
    if(resuming) throw Usage_error("the checkpoint's stored options hold --resume");
    for(const auto& o : vm)
      if(!o.second.defaulted() && o.first != "resume" && o.first != "checkpoint-every" &&
         o.first != "stop-after-checkpoint" && o.first != "time-limit" && o.first != "max-steps" &&
         o.first != "stats" && o.first != "report")
        throw Usage_error("--resume takes the run's options from the checkpoint; --" + o.first + " cannot be given");
    // the interrupted run's own options, then what this command line adds
    std::string stored;
    try {
      typedef Types<CGAL::Exact_predicates_inexact_constructions_kernel>::CDT CDT;
      stored = CGAL::Advancing_front_mesher_2<CDT>::read_checkpoint_info(opt.resume).user_data;
    } catch(const std::exception& e) {
      throw Input_error(e.what());
    }
    std::vector<std::string> stored_args;
    for(std::size_t b = 0; b < stored.size();) {
      const std::size_t e = stored.find('\0', b);
      stored_args.push_back(stored.substr(b, e == std::string::npos ? std::string::npos : e - b));
      b = (e == std::string::npos) ? stored.size() : e + 1;
    }
    Options resumed;
    try {
      resumed = parse(stored_args, true);
    } catch(const Usage_error& e) {
      throw Input_error(opt.resume + ": the stored options are not valid: " + e.what());
    }
    resumed.resume = opt.resume;
    resumed.stats = opt.stats;
    resumed.report = opt.report;
    resumed.stop_after_checkpoint = opt.stop_after_checkpoint;
    // limits apply to a session: only those given now
    resumed.time_limit = vm.count("time-limit") ? opt.time_limit : 0;
    resumed.max_steps = vm.count("max-steps") ? std::size_t(max_steps) : 0;
    if(!checkpoint.empty()) {
      parse_checkpoint(checkpoint, resumed);
      // the checkpoints of this session store the new file, so that a later
      // resume goes on writing there
      std::vector<std::string> kept;
      for(std::size_t i = 0; i < stored_args.size(); ++i) {
        if(stored_args[i] == "--checkpoint-every") {
          i += 2;
          continue;
        }
        kept.push_back(stored_args[i]);
      }
      kept.insert(kept.end(), {"--checkpoint-every", checkpoint[0], absolute_path(checkpoint[1])});
      resumed.arguments.clear();
      for(const std::string& a : kept) {
        if(!resumed.arguments.empty()) resumed.arguments += '\0';
        resumed.arguments += a;
      }
    }
    if(resumed.stop_after_checkpoint && resumed.checkpoint_every == 0)
      throw Usage_error("--stop-after-checkpoint needs --checkpoint-every (given now or in the interrupted run)");
    if(vm.count("time-limit") && (!(opt.time_limit > 0) || !std::isfinite(opt.time_limit)))
      throw Usage_error("--time-limit must be a positive number of seconds");
    if(vm.count("max-steps") && max_steps < 1) throw Usage_error("--max-steps must be a positive count");
    return resumed;
  }
  if(opt.input.empty()) throw Usage_error("no input file given");
  opt.has_size = vm.count("size") > 0;
  if(opt.has_size && (!(opt.size > 0) || !std::isfinite(opt.size)))
    throw Usage_error("--size must be a positive number");
  // read as a signed number: Boost reads "-1" into an unsigned as its largest value
  if(smooth < 0 || smooth > 1000) throw Usage_error("--smooth must be a number of passes from 0 to 1000");
  opt.smooth = std::size_t(smooth);
  if(vm.count("time-limit") && (!(opt.time_limit > 0) || !std::isfinite(opt.time_limit)))
    throw Usage_error("--time-limit must be a positive number of seconds");
  if(vm.count("max-steps") && max_steps < 1) throw Usage_error("--max-steps must be a positive count");
  opt.max_steps = std::size_t(max_steps);
  if(opt.svg_color != "plain" && opt.svg_color != "quality")
    throw Usage_error("--svg-color must be plain or quality, not '" + opt.svg_color + "'");
  if(opt.grading == "off") {
    opt.gradation = 0;
  } else {
    std::size_t used = 0;
    double g = 0;
    try {
      g = std::stod(opt.grading, &used);
    } catch(const std::exception&) {
      used = 0;
    }
    if(used != opt.grading.size() || !(g > 0) || !std::isfinite(g))
      throw Usage_error("--grading must be a positive number or 'off', not '" + opt.grading + "'");
    opt.gradation = g;
  }
  if(opt.kernel != "epick" && opt.kernel != "epeck" && opt.kernel != "exact-rational")
    throw Usage_error("--kernel must be epick, epeck or exact-rational, not '" + opt.kernel + "'");
  for(const std::string& out : opt.outputs) {
    const std::string ext = out.substr(out.find_last_of('.') == std::string::npos ? out.size()
                                                                                 : out.find_last_of('.'));
    if(ext != ".off" && ext != ".vtu" && ext != ".node" && ext != ".ele" && ext != ".msh" && ext != ".svg")
      throw Usage_error("unknown output format '" + out + "' (use .off, .vtu, .node, .ele, .msh or .svg)");
  }
  if(!checkpoint.empty()) parse_checkpoint(checkpoint, opt);
  if(opt.stop_after_checkpoint && opt.checkpoint_every == 0)
    throw Usage_error("--stop-after-checkpoint needs --checkpoint-every");
  if(opt.stream) {
    if(opt.outputs.empty()) throw Usage_error("--stream needs an output (-o)");
    for(const std::string& out : opt.outputs)
      if(out.size() >= 4 && out.compare(out.size() - 4, 4, ".svg") == 0)
        throw Usage_error("--stream cannot write pictures (.svg): they need the whole mesh");
    if(opt.smooth > 0) throw Usage_error("--stream cannot be combined with --smooth (smoothing needs the whole mesh)");
    if(!opt.histogram.empty()) throw Usage_error("--stream cannot be combined with --histogram");
  }
  if(opt.checkpoint_every > 0) opt.arguments = stored_arguments(parsed, opt, resuming);
  return opt;
}

} // namespace

int main(int argc, char* argv[])
{
  Options opt;
  try {
    opt = parse(std::vector<std::string>(argv + 1, argv + argc));
  } catch(const Usage_error& e) {
    std::cerr << program << ": " << e.what() << "\n" << "Try 'afmesh_2 --help'.\n";
    return 2;
  } catch(const Input_error& e) {
    std::cerr << program << ": error: " << e.what() << "\n";
    return 1;
  }
  try {
    if(opt.kernel == "epeck") return run<CGAL::Exact_predicates_exact_constructions_kernel>(opt);
    if(opt.kernel == "exact-rational") return run<CGAL::Simple_cartesian<CGAL::Exact_rational> >(opt);
    return run<CGAL::Exact_predicates_inexact_constructions_kernel>(opt);
  } catch(const Input_error& e) {
    std::cerr << program << ": error: " << e.what() << "\n";
    return 1;
  } catch(const std::invalid_argument& e) {
    std::cerr << program << ": error: " << opt.input << ": " << e.what() << "\n";
    return 1;
  } catch(const std::exception& e) {
    std::cerr << program << ": internal error: " << e.what() << "\n";
    return 3;
  }
}
