// afmesh_2_mpi: what a run reports, from rank 0: the JSON object of --stats
// and the readable summary of --report, with the quality figures of the
// whole mesh (quality.h) as afmesh_2 gives them, and each rank's figures.
#ifndef AFMESH_2_MPI_REPORT_H
#define AFMESH_2_MPI_REPORT_H

#include "../afmesh_2/report.h"
#include "min_angle.h"
#include "parts.h"

#include <CGAL/Advancing_front_mesh_2/Mesh_quality.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

namespace afmesh_2_mpi {

// What a rank's share and its interfaces came to.
struct Share_figures
{
  std::uint64_t triangles = 0, owned_vertices = 0, band_triangles = 0, flips = 0, seam_vertices = 0, widenings = 0,
                band_bytes_sent = 0, held_triangles = 0;
};

template <class Work>
Share_figures share_figures(const Work& w, std::uint64_t triangles, std::uint64_t owned_vertices)
{
  Share_figures f;
  f.triangles = triangles;
  f.owned_vertices = owned_vertices;
  f.band_triangles = w.merge.band_triangles;
  f.flips = w.merge.flips;
  f.seam_vertices = w.merge.seam_vertices;
  f.widenings = w.widenings;
  f.band_bytes_sent = w.bytes_sent;
  return f;
}

// One rank's figures, gathered to rank 0.
struct Rank_figures
{
  double meshing, interfaces, writing, peak_memory_mb;
  Share_figures share;
  int code;
  bool resumed, from_checkpoint;
  std::uint64_t checkpoints;
  double smoothing;
  std::uint64_t smoothing_passes, smoothing_moves, smoothing_rejected_moves, smoothing_flips;
};

// What rank 0 reports on: the run's decomposition, the ranks' figures, and
// the quality of the whole mesh (null when it was not computed: --stream).
template <class K>
struct Run_summary
{
  const afmesh_2::Options& opt;
  const Decomposition<K>& d;
  std::string fewer_parts_reason;
  const std::vector<Rank_figures>& ranks;
  const AFM::Mesh_quality* quality;
  double decomposition_time, quality_time, total_time;
  const Min_angle_figures* min_angle; // null without --min-angle

  std::uint64_t triangles() const
  {
    std::uint64_t n = 0;
    for(const Rank_figures& f : ranks) n += f.share.triangles;
    return n;
  }
  std::uint64_t vertices() const
  {
    std::uint64_t n = 0;
    for(const Rank_figures& f : ranks) n += f.share.owned_vertices;
    return n;
  }
};

template <class K>
nlohmann::ordered_json statistics_json(const Run_summary<K>& s)
{
  nlohmann::ordered_json j;
  j["input"] = s.opt.input;
  j["ranks"] = s.ranks.size();
  j["parts"] = s.d.parts;
  if(!s.d.one_part_reason.empty()) j["one_part_reason"] = s.d.one_part_reason;
  if(!s.fewer_parts_reason.empty()) j["fewer_parts_reason"] = s.fewer_parts_reason;
  j["axis"] = s.d.plan.axis;
  std::vector<double> cuts;
  for(const auto& c : s.d.plan.cuts) cuts.push_back(c.position);
  j["cuts"] = cuts;
  j["predicted_triangles"] = s.d.plan.estimated;
  nlohmann::ordered_json per_rank = nlohmann::ordered_json::array();
  for(const Rank_figures& f : s.ranks) {
    const Share_figures& r = f.share;
    per_rank.push_back({{"triangles", r.triangles}, {"owned_vertices", r.owned_vertices},
                        {"meshing_time", f.meshing}, {"interface_time", f.interfaces},
                        {"writing_time", f.writing}, {"band_triangles", r.band_triangles},
                        {"interface_flips", r.flips}, {"seam_vertices", r.seam_vertices},
                        {"band_widenings", r.widenings}, {"band_bytes_sent", r.band_bytes_sent},
                        {"peak_memory_mb", f.peak_memory_mb}, {"return_code", f.code}});
    if(s.opt.smooth > 0) {
      per_rank.back()["smoothing_time"] = f.smoothing;
      per_rank.back()["smoothing_moves"] = f.smoothing_moves;
      per_rank.back()["smoothing_flips"] = f.smoothing_flips;
    }
    if(s.opt.stream) {
      per_rank.back()["held_triangles"] = r.held_triangles;
      per_rank.back()["resumed_part"] = f.resumed;
      per_rank.back()["resumed_from_checkpoint"] = f.from_checkpoint;
      per_rank.back()["checkpoints_written"] = f.checkpoints;
    }
  }
  j["number_of_faces"] = s.triangles();
  j["number_of_vertices"] = s.vertices();
  // afmesh_2's names for the same counts
  j["vertices"] = s.vertices();
  j["triangles"] = s.triangles();
  if(s.opt.smooth > 0) {
    // afmesh_2's keys: the passes done (the most of any part), the moves,
    // refused moves and flips of all parts
    std::uint64_t passes = 0, moves = 0, rejected = 0, flips = 0;
    for(const Rank_figures& f : s.ranks) {
      passes = (std::max)(passes, f.smoothing_passes);
      moves += f.smoothing_moves;
      rejected += f.smoothing_rejected_moves;
      flips += f.smoothing_flips;
    }
    j["smoothing"] = {{"method", s.opt.smoother}, {"passes", passes}, {"moves", moves}, {"rejected_moves", rejected},
                      {"flips", flips}};
  }
  if(s.min_angle != nullptr) {
    // afmesh_2's keys, and the rounds of the ranks
    const AFM::Minimum_angle_statistics& a = s.min_angle->total;
    j["min_angle"] = {{"bound", a.angle},
                      {"below_before", a.below_before},
                      {"points_inserted", a.points_inserted},
                      {"triangles_changed", a.triangles_changed},
                      {"below_after", a.below_after},
                      {"completed", a.completed},
                      {"smallest_angle", a.smallest_angle},
                      {"rounds", s.min_angle->rounds},
                      {"points_on_interfaces", s.min_angle->shared_points},
                      {"interface_edges_made_delaunay", s.min_angle->delaunay_splits},
                      {"time", s.min_angle->time}};
  }
  if(s.quality != nullptr) {
    j["quality"] = afmesh_2::quality_json(*s.quality);
    j["quality_time"] = s.quality_time;
  }
  j["decomposition_time"] = s.decomposition_time;
  j["total_time"] = s.total_time;
  j["per_rank"] = per_rank;
  return j;
}

// The summary of --report; `boundary` is afmesh_2's line on the boundary
// discretisation.
template <class K>
std::string report_text(const Run_summary<K>& s, const std::string& boundary)
{
  double meshing = 0, smoothing = 0, interfaces = 0, writing = 0, least_memory = 0, most_memory = 0;
  std::uint64_t fewest = ~std::uint64_t(0), most = 0, band = 0, flips = 0, seam = 0, held = 0, moves = 0,
                smoothing_flips = 0;
  for(const Rank_figures& f : s.ranks) {
    smoothing = (std::max)(smoothing, f.smoothing);
    moves += f.smoothing_moves;
    smoothing_flips += f.smoothing_flips;
    meshing = (std::max)(meshing, f.meshing);
    interfaces = (std::max)(interfaces, f.interfaces);
    writing = (std::max)(writing, f.writing);
    least_memory = &f == &s.ranks.front() ? f.peak_memory_mb : (std::min)(least_memory, f.peak_memory_mb);
    most_memory = (std::max)(most_memory, f.peak_memory_mb);
    fewest = (std::min)(fewest, f.share.triangles);
    most = (std::max)(most, f.share.triangles);
    band += f.share.band_triangles;
    flips += f.share.flips;
    seam += f.share.seam_vertices;
    held = (std::max)(held, f.share.held_triangles);
  }
  std::ostringstream os;
  os << std::setprecision(4);
  os << s.opt.input << ": " << s.vertices() << " vertices, " << s.triangles() << " triangles"
     << (s.opt.stream ? " streamed" : "") << " on " << s.ranks.size() << " ranks in " << s.total_time
     << " s (slowest rank: meshing " << meshing << " s, ";
  if(s.opt.smooth > 0) os << "smoothing " << smoothing << " s, ";
  os << "interfaces " << interfaces << " s, writing " << writing
     << " s)\n";
  if(s.opt.smooth > 0)
    os << "  each part smoothed before the interfaces were merged: " << s.opt.smooth << " " << s.opt.smoother
       << " passes, " << moves << " moves, " << smoothing_flips << " flips\n";
  if(s.min_angle != nullptr) {
    const AFM::Minimum_angle_statistics& a = s.min_angle->total;
    os << "  the minimum angle raised to " << a.angle << " degrees in " << s.min_angle->time << " s ("
       << a.below_before << " triangles below it, " << a.points_inserted << " points inserted, "
       << a.triangles_changed << " triangles changed, " << a.below_after << " left below; " << s.min_angle->rounds
       << " rounds, " << s.min_angle->shared_points << " points on the interfaces)\n";
  }
  if(s.quality != nullptr) afmesh_2::print_quality_lines(os, "", *s.quality);
  else os << "  no quality figures with --stream (as afmesh_2 --stream)\n";
  os << "  " << boundary << "\n";
  os << "  " << s.d.parts << " parts";
  if(s.d.parts == 1) {
    const std::string& why = !s.d.one_part_reason.empty() ? s.d.one_part_reason : s.fewer_parts_reason;
    os << " (" << (why.empty() ? std::string("one rank") : why) << ")";
  } else {
    os << " cut at " << (s.d.plan.axis == 0 ? "x =" : "y =");
    for(const auto& c : s.d.plan.cuts) os << " " << c.position;
    if(!s.fewer_parts_reason.empty()) os << " (fewer than the ranks: " << s.fewer_parts_reason << ")";
  }
  os << "; " << fewest << " to " << most << " triangles a rank, peak memory " << least_memory << " to "
     << most_memory << " MiB a rank\n";
  os << "  interfaces: " << band << " band triangles merged, " << flips << " flips, " << seam << " seam vertices";
  if(s.opt.stream) os << "; at most " << held << " triangles held near the cuts on a rank";
  os << "\n";
  return os.str();
}

} // namespace afmesh_2_mpi

#endif // AFMESH_2_MPI_REPORT_H
