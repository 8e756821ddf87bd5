// afmesh_2: what a run reports: the readable summary of --report and the
// JSON object of --stats (written by nlohmann::json, which escapes strings).
#ifndef AFMESH_2_REPORT_H
#define AFMESH_2_REPORT_H

#include "input.h"
#include "options.h"

#include <CGAL/Advancing_front_mesh_2/Mesh_quality.h>
#include <CGAL/Advancing_front_mesh_2/Mesh_return_code.h>
#include <CGAL/Advancing_front_mesh_2/Statistics.h>
#include <CGAL/Advancing_front_mesh_2/laplacian_smooth_mesh_2.h>
#include <CGAL/Advancing_front_mesh_2/mesh_in_parallel_2.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <sys/resource.h>

namespace afmesh_2 {

// keys in the order they are set
typedef nlohmann::ordered_json Json;

// peak resident memory of the process, in bytes
inline double peak_rss_bytes()
{
  struct rusage u;
  if(getrusage(RUSAGE_SELF, &u) != 0) return std::nan("");
#ifdef __APPLE__
  return double(u.ru_maxrss); // bytes on macOS
#else
  return 1024. * double(u.ru_maxrss); // kilobytes on Linux and the BSDs
#endif
}

// a number, or null when it is not finite (JSON has no NaN)
inline Json number(double v) { return std::isfinite(v) ? Json(v) : Json(nullptr); }

// The times of a run in memory (seconds).
struct Run_times
{
  double meshing = 0, smoothing = 0, min_angle = 0, writing = 0, total = 0;
};

inline void print_report_text(const Options& opt, const std::string& text)
{
  // standard output, unless the JSON of --stats must stay alone there
  (opt.stats ? std::cerr : std::cout) << text;
}

// The report's lines on the quality `m` (`when`: what they are before,
// or nothing), two spaces in.
inline void print_quality_lines(std::ostream& os, const char* when, const AFM::Mesh_quality& m)
{
  os << "  " << when << "radius ratio 2r/R: min " << m.min_radius_ratio << ", 1% " << m.radius_ratio_p1 << ", 5% "
     << m.radius_ratio_p5 << ", median " << m.radius_ratio_median << ", mean " << m.mean_radius_ratio << "; "
     << 100 * m.share_above_0_9 << "% above 0.9\n"
     << "  " << when << "angles: " << m.min_angle_degrees << " to " << m.max_angle_degrees << " degrees, "
     << 100 * m.share_angles_below_30 << "% below 30\n"
     << "  " << when << "edge length / h: " << m.min_edge_over_size << " to " << m.max_edge_over_size << ", mean "
     << m.mean_edge_over_size << ", " << 100 * m.share_edges_within_sqrt2 << "% within [0.71, 1.41]\n";
}

inline void print_streamed_report(const Options& opt, const AFM::Statistics& st, double t_meshing)
{
  std::ostringstream os;
  os << (opt.resume.empty() ? opt.input : opt.resume) << ": " << st.number_of_vertices << " vertices, "
     << st.number_of_faces << " triangles streamed in " << t_meshing << " s; at most "
     << st.largest_triangles_in_memory << " triangles in memory, peak memory " << peak_rss_bytes() / 1048576
     << " MiB\n";
  print_report_text(opt, os.str());
}

inline void print_report(const Options& opt, const AFM::Statistics& st, const AFM::Mesh_quality& unsmoothed,
                         const AFM::Mesh_quality& q, const AFM::Smoothing_statistics& smoothing, const Run_times& t,
                         const std::string& boundary, const AFM::Minimum_angle_statistics& angle,
                         const AFM::Parallel_mesh_statistics* parallel = nullptr)
{
  std::ostringstream os;
  os << std::setprecision(4);
  os << opt.input << ": " << st.number_of_vertices + angle.points_inserted << " vertices, " << q.number_of_triangles
     << " triangles in "
     << t.meshing << " s (" << (t.meshing > 0 ? st.number_of_faces / t.meshing : 0) << " triangles/s)";
  if(opt.smooth > 0)
    os << ", then " << smoothing.passes << " " << opt.smoother << " smoothing passes in " << t.smoothing << " s (" << smoothing.moves
       << " moves, " << smoothing.flips << " flips)";
  if(opt.min_angle > 0)
    os << ", then the minimum angle raised to " << opt.min_angle << " degrees in " << t.min_angle << " s ("
       << angle.below_before << " triangles below it, " << angle.points_inserted << " points inserted, "
       << angle.triangles_changed << " triangles changed, " << angle.below_after << " left below)";
  os << "\n";
  auto line = [&](const char* when, const AFM::Mesh_quality& m) { print_quality_lines(os, when, m); };
  if(opt.smooth > 0 || opt.min_angle > 0) line(opt.smooth > 0 ? "before smoothing, " : "before refinement, ", unsmoothed);
  line("", q);
  os << "  " << boundary << "\n";
  if(parallel != nullptr) {
    os << "  threads: " << parallel->threads << ", ";
    if(parallel->parts == 1) {
      os << "meshed in one piece (" << parallel->one_piece_reason << ")\n";
    } else {
      os << parallel->parts << " parts cut at " << (parallel->axis == 0 ? "x =" : "y =");
      for(double c : parallel->cuts) os << " " << c;
      os << " (" << parallel->cut_points << " cut points, " << parallel->interface_points << " interface points); "
         << "cutting " << parallel->decomposition_time << " s, parts " << parallel->meshing_time << " s, merge "
         << parallel->merge_time << " s, seams " << parallel->seam_time << " s (" << parallel->seam_vertices
         << " vertices, " << parallel->seam_smoothing.moves << " moves)\n";
    }
  }
  print_report_text(opt, os.str());
}

// The report's line on the boundary discretisation.
template <class K>
std::string boundary_summary(const Options& opt, const Input<K>& in)
{
  std::ostringstream os;
  if(opt.keep_segments)
    os << "boundary: input segments kept (--keep-segments); " << in.long_kept_segments
       << " longer than 1.5 local sizes";
  else
    os << "boundary: " << in.split.edges_split << " segments split to the size field at "
       << in.split.points_inserted << " new points";
  return os.str();
}

inline Json streamed_statistics_json(const Options& opt, AFM::Mesh_return_code rc, const AFM::Statistics& st,
                                     double t_meshing, double t_total)
{
  Json j;
  j["input"] = opt.input;
  j["kernel"] = opt.kernel;
  j["streamed"] = true;
  j["mesh_return_code"] = AFM::to_string(rc);
  j["vertices"] = st.number_of_vertices;
  j["triangles"] = st.number_of_faces;
  j["mesh_time"] = number(t_meshing);
  j["total_time"] = number(t_total);
  j["peak_rss_bytes"] = number(peak_rss_bytes());
  j["statistics"] = Json{{"front_edges_processed", st.front_edges_processed},
                         {"points_inserted", st.points_inserted},
                         {"forced_closures", st.forced_closures},
                         {"largest_front", st.largest_front},
                         {"largest_triangles_in_memory", st.largest_triangles_in_memory},
                         {"stream_sweeps", st.stream_sweeps},
                         {"points_refused_for_finished_triangles", st.points_refused_for_finished_triangles},
                         {"finished_triangles_broken", st.finished_triangles_broken},
                         {"finished_triangles_held", st.finished_triangles_held},
                         {"finished_edges_not_delaunay", st.finished_edges_not_delaunay},
                         {"delaunay_repair_flips", st.delaunay_repair_flips},
                         {"checkpoints_written", st.checkpoints_written}};
  return j;
}

template <class K>
Json size_field_json(const Options& opt, const Input<K>& in)
{
  Json j;
  if(in.sizing.base.background) {
    const auto& fs = in.sizing.base.background->statistics();
    j["kind"] = "poisson";
    j["sources"] = fs.number_of_sources;
    j["boundary_points"] = fs.number_of_boundary_points;
    j["quadtree_leaves"] = fs.number_of_leaves;
    j["quadtree_corners"] = fs.number_of_corners;
    j["boundary_spacing"] = opt.boundary_spacing == "diffuse" ? "diffused" : "grown";
    j["gradation"] = number(opt.gradation > 0 ? opt.gradation : std::nan(""));
    j["smallest"] = number(fs.smallest_size);
    j["largest"] = number(fs.largest_size);
  } else {
    j["kind"] = "uniform";
  }
  j["build_time"] = number(in.times.size_field);
  return j;
}

inline Json mesher_statistics_json(const AFM::Statistics& st)
{
  return Json{{"front_edges_processed", st.front_edges_processed},
              {"points_inserted", st.points_inserted},
              {"triangles_closed_on_existing_points", st.triangles_closed_on_existing_points},
              {"forced_closures", st.forced_closures},
              {"rejected_points", st.rejected_points},
              {"triangles_around_new_points", st.triangles_around_new_points},
              {"triangles_removed", st.triangles_removed},
              {"size_bound_raised", st.size_bound_raised},
              {"broken_circle_queries", st.broken_circle_queries},
              {"constraint_index_queries", st.constraint_index_queries},
              // the keys before 2026-11, with the same counts, for one release:
              // edge_octree_queries counted the front-edge searches too, which
              // are the point searches
              {"triangle_octree_queries", st.broken_circle_queries},
              {"edge_octree_queries", st.constraint_index_queries + st.point_search_queries},
              {"point_search_queries", st.point_search_queries},
              {"incircle_tests", st.incircle_tests},
              {"largest_front", st.largest_front},
              {"pockets", st.pockets},
              {"largest_live_triangles", st.largest_live_triangles},
              {"largest_active_vertices", st.largest_active_vertices},
              {"memory_compactions", st.memory_compactions},
              {"delaunay_repair_flips", st.delaunay_repair_flips}};
}

inline Json quality_json(const AFM::Mesh_quality& q)
{
  Json j;
  j["min_radius_ratio"] = number(q.min_radius_ratio);
  j["mean_radius_ratio"] = number(q.mean_radius_ratio);
  j["share_radius_ratio_above_0_9"] = number(q.share_above_0_9);
  j["min_angle_degrees"] = number(q.min_angle_degrees);
  j["max_angle_degrees"] = number(q.max_angle_degrees);
  j["radius_ratio_p1"] = number(q.radius_ratio_p1);
  j["radius_ratio_p5"] = number(q.radius_ratio_p5);
  j["radius_ratio_median"] = number(q.radius_ratio_median);
  j["share_angles_below_30"] = number(q.share_angles_below_30);
  j["radius_ratio_histogram"] = q.radius_ratio_histogram;
  j["angle_histogram_10_degrees"] = q.angle_histogram;
  j["min_edge_over_size"] = number(q.min_edge_over_size);
  j["max_edge_over_size"] = number(q.max_edge_over_size);
  j["mean_edge_over_size"] = number(q.mean_edge_over_size);
  j["share_edges_within_sqrt2"] = number(q.share_edges_within_sqrt2);
  return j;
}

// What the boundary discretisation did, or with --keep-segments how many
// segments stayed longer than 1.5 local sizes.
template <class K>
Json boundary_discretisation_json(const Options& opt, const Input<K>& in)
{
  return Json{{"keep_segments", opt.keep_segments},
              {"edges_split", in.split.edges_split},
              {"points_inserted", in.split.points_inserted},
              {"points_rounded", in.split.points_rounded},
              {"points_skipped", in.split.points_skipped},
              {"long_kept_segments", in.long_kept_segments},
              {"longest_kept_segment_in_sizes", in.longest_kept_segment_in_sizes}};
}

// --threads: the parts and where the time went (threads 1: the serial mesher)
inline Json parallel_json(const Options& opt, const AFM::Parallel_mesh_statistics* p)
{
  if(p == nullptr) return Json{{"threads", opt.threads}, {"parts", 1}};
  Json j{{"threads", p->threads},
         {"parts", p->parts},
         {"cut_axis", p->axis == 0 ? "x" : "y"},
         {"cuts", p->cuts},
         {"predicted_triangles", p->predicted_triangles},
         {"part_triangles", p->part_triangles},
         {"cut_points", p->cut_points},
         {"interface_points", p->interface_points},
         {"seam_vertices", p->seam_vertices},
         {"seam_moves", p->seam_smoothing.moves},
         {"time", Json{{"cutting", number(p->decomposition_time)},
                       {"parts", number(p->meshing_time)},
                       {"merge", number(p->merge_time)},
                       {"seams", number(p->seam_time)}}}};
  if(!p->one_piece_reason.empty()) j["one_piece_reason"] = p->one_piece_reason;
  return j;
}

template <class K>
Json statistics_json(const Options& opt, const Input<K>& in, AFM::Mesh_return_code rc, const AFM::Statistics& st,
                     const AFM::Mesh_quality& q, const AFM::Smoothing_statistics& smoothing, const Run_times& t,
                     const AFM::Minimum_angle_statistics& angle,
                     const AFM::Parallel_mesh_statistics* parallel = nullptr)
{
  Json j;
  j["input"] = opt.input;
  j["kernel"] = opt.kernel;
  j["size"] = number(opt.has_size ? opt.size : std::nan(""));
  j["size_field"] = size_field_json(opt, in);
  j["mesh_return_code"] = AFM::to_string(rc);
  j["input_repairs"] = Json{{"merged_points", in.inserted.merged_points},
                            {"duplicate_segments", in.inserted.duplicate_segments},
                            {"points_on_segments", in.inserted.points_on_segments}};
  j["boundary_discretisation"] = boundary_discretisation_json(opt, in);
  // the mesh written: with --min-angle, the refinement's points and triangles too
  j["vertices"] = st.number_of_vertices + angle.points_inserted;
  j["triangles"] = st.number_of_faces + angle.triangles_after - angle.triangles_before;
  j["time"] = Json{{"read", number(in.times.read)},       {"boundary", number(in.times.boundary)},
                   {"size_field", number(in.times.size_field)}, {"boundary_split", number(in.times.boundary_split)},
                   {"mesh", number(t.meshing)},
                   {"smooth", number(t.smoothing)},       {"min_angle", number(t.min_angle)},
                   {"write", number(t.writing)},
                   {"total", number(t.total)}};
  j["triangles_per_second"] = t.meshing > 0 ? st.number_of_faces / t.meshing : 0.;
  j["statistics"] = mesher_statistics_json(st);
  j["peak_rss_bytes"] = number(peak_rss_bytes());
  j["quality"] = quality_json(q);
  j["smoothing"] = Json{{"method", opt.smoother},
                        {"passes", smoothing.passes},
                        {"moves", smoothing.moves},
                        {"rejected_moves", smoothing.rejected_moves},
                        {"flips", smoothing.flips}};
  j["min_angle"] = Json{{"bound", number(opt.min_angle)},
                        {"below_before", angle.below_before},
                        {"points_inserted", angle.points_inserted},
                        {"triangles_changed", angle.triangles_changed},
                        {"below_after", angle.below_after},
                        {"completed", angle.completed}};
  j["parallel"] = parallel_json(opt, parallel);
  return j;
}

// one JSON object on one line of standard output; input names that are not
// UTF-8 are written with replacement characters, not refused
inline void print_statistics(const Json& j)
{
  std::cout << j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) << std::endl;
}

} // namespace afmesh_2

#endif // AFMESH_2_REPORT_H
