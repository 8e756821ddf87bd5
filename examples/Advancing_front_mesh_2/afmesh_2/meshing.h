// afmesh_2: the mesher set up from the options and run, in memory or
// streaming to the outputs, and the smoothing after it.
#ifndef AFMESH_2_MESHING_H
#define AFMESH_2_MESHING_H

#include "input.h"
#include "options.h"
#include "resume.h"

#include <CGAL/Advancing_front_mesher_2.h>
#include <CGAL/Advancing_front_mesh_2/IO/Streaming_mesh_writer.h>
#include <CGAL/Advancing_front_mesh_2/IO/Streaming_tagging_sink_2.h>
#include <CGAL/Advancing_front_mesh_2/laplacian_smooth_mesh_2.h>
#include <CGAL/Advancing_front_mesh_2/mesh_in_parallel_2.h>
#include <CGAL/Advancing_front_mesh_2/quality_smooth_mesh_2.h>
#include <CGAL/Advancing_front_mesh_2/refine_to_minimum_angle_2.h>

#include <boost/property_map/function_property_map.hpp>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <set>
#include <string>
#include <unistd.h>
#include <vector>

namespace afmesh_2 {

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
    std::cerr << "\r[" << std::string(filled, '#') << std::string(width - filled, ' ') << "] " << std::fixed
              << std::setprecision(1) << 100 * fraction << "%" << std::flush;
  }
  void done()
  {
    if(enabled) std::cerr << "\r" << std::string(50, ' ') << "\r" << std::flush;
  }
};

template <class K>
using Mesher = CGAL::Advancing_front_mesher_2<typename Types<K>::CDT, Cli_sizing_field<K>, Progress_visitor>;

// The input read and inserted, and the size field made, with their times.
template <class K>
void load_input(const Options& opt, Input<K>& in)
{
  const auto t_start = std::chrono::steady_clock::now();
  in.poly = read_input(opt.input);
  in.times.read = seconds_since(t_start);
  check_same_inputs(opt);
  const auto t_cdt = std::chrono::steady_clock::now();
  insert_boundary(opt, in);
  in.times.boundary = seconds_since(t_cdt);
  const auto t_field = std::chrono::steady_clock::now();
  make_size_field(opt, in);
  in.times.size_field = seconds_since(t_field);
  const auto t_split = std::chrono::steady_clock::now();
  split_boundary(opt, in);
  in.times.boundary_split = seconds_since(t_split);
}

// A checkpoint that cannot be written must show before any output is
// touched, not after the first K triangles.
inline void check_checkpoint_writable(const Options& opt)
{
  if(opt.checkpoint_every == 0) return;
  const std::string tmp = opt.checkpoint_file + ".tmp";
  if(!std::ofstream(tmp.c_str(), std::ios::out | std::ios::binary | std::ios::app))
    throw Input_error(tmp + ": cannot write the checkpoint here");
  std::remove(tmp.c_str());
}

template <class K>
using Tagging_sink = AFM::IO::Streaming_tagging_sink_2<typename Types<K>::CDT>;

// --stream: the writer of the outputs with the markers and regions of the
// input (found on a copy of it before meshing), new or resumed from the
// checkpoint, becomes the mesher's sink; a resumed run loads the checkpoint.
template <class K>
std::unique_ptr<Tagging_sink<K> > start_streaming(const Options& opt, Input<K>& in, Mesher<K>& mesher)
{
  typedef AFM::IO::Streaming_mesh_writer<typename K::Point_2> Writer;
  check_checkpoint_writable(opt);
  std::unique_ptr<Tagging_sink<K> > sink;
  try {
    if(opt.resume.empty()) {
      std::vector<std::string> outputs = opt.outputs;
      // the writer's state in a checkpoint names them
      if(opt.checkpoint_every > 0)
        for(std::string& out : outputs) out = absolute_path(out);
      sink.reset(new Tagging_sink<K>(in.cdt, in.tags));
      sink->set_writer(std::unique_ptr<Writer>(new Writer(outputs, sink->writer_options(!opt.vtu_ascii))));
    } else {
      sink = Tagging_sink<K>::resume(Mesher<K>::read_checkpoint_info(opt.resume).sink_state, in.cdt, in.tags);
    }
  } catch(const std::exception& e) {
    throw Input_error((opt.resume.empty() ? std::string("output") : opt.resume) + ": " + e.what());
  }
  mesher.set_output_sink(sink.get());
  if(!opt.resume.empty()) {
    try {
      mesher.resume(opt.resume);
    } catch(const std::runtime_error& e) {
      throw Input_error(e.what());
    }
  }
  if(opt.checkpoint_every > 0)
    mesher.set_checkpoint(opt.checkpoint_every, opt.checkpoint_file, opt.arguments, opt.stop_after_checkpoint);
  return sink;
}

template <class K>
void configure(const Options& opt, const Input<K>& in, Mesher<K>& mesher)
{
  mesher.set_seeds(in.seeds.begin(), in.seeds.end());
  // the boundary was split (or kept) by load_input(), with the markers
  mesher.set_constraint_splitting(false);
  mesher.set_pocket_priority(!opt.no_pocket_priority);
  mesher.set_time_limit(opt.time_limit);
  mesher.set_iteration_limit(opt.max_steps);
}

// Runs the mesher; false (after saying why on stderr) when a checkpoint
// could not be written: the outputs stay as they are, and a resume from the
// previous checkpoint cuts them back to it.
template <class K>
bool run_mesher(const Options& opt, Mesher<K>& mesher, AFM::Mesh_return_code& rc)
{
  try {
    rc = mesher.refine_mesh();
  } catch(const AFM::Checkpoint_error& e) {
    mesher.visitor().done();
    std::cerr << program << ": error: " << e.what() << "; the outputs are incomplete";
    if(mesher.statistics().checkpoints_written > 0)
      std::cerr << "; afmesh_2 --resume " << opt.checkpoint_file << " goes on from the previous checkpoint";
    std::cerr << "\n";
    return false;
  }
  if(rc == AFM::TIME_LIMIT_REACHED || rc == AFM::ITERATION_LIMIT_REACHED)
    std::cerr << "afmesh_2: note: " << opt.input << ": "
              << (rc == AFM::TIME_LIMIT_REACHED ? "--time-limit" : "--max-steps")
              << " reached: the rest of the front was closed on existing points (valid, coarser there)\n";
  mesher.visitor().done();
  return true;
}

// --threads N above 1: the domain in N parts meshed at once and merged
// (mesh_in_parallel_2); the markers follow the segments the cuts split.
// The boundary was split (or kept) by load_input(), with the markers.
template <class K>
AFM::Mesh_return_code mesh_in_parts(const Options& opt, Input<K>& in, AFM::Parallel_mesh_statistics& parallel)
{
  typedef typename Types<K>::CDT CDT;
  auto on_split = [&in](typename CDT::Vertex_handle a, typename CDT::Vertex_handle b, typename CDT::Vertex_handle v) {
    in.tags.split_constraint(a, b, v);
  };
  return AFM::mesh_in_parallel_2(in.cdt, in.seeds.begin(), in.seeds.end(), in.sizing, false, opt.threads, parallel,
                                 false, on_split, !opt.no_pocket_priority);
}

// --smooth N with the --smoother: the mesher's points move, the input's
// points (isolated ones included) are held.
template <class K>
AFM::Smoothing_statistics smooth(const Options& opt, Input<K>& in)
{
  typedef typename Types<K>::CDT CDT;
  if(opt.smooth == 0) return AFM::Smoothing_statistics();
  const std::vector<typename CDT::Vertex_handle>& vh = in.inserted.vertices;
  std::set<typename CDT::Vertex_handle> input_vertices(vh.begin(), vh.end());
  auto held = boost::make_function_property_map<typename CDT::Vertex_handle>(
    [&](typename CDT::Vertex_handle v) { return input_vertices.count(v) > 0; });
  const auto np = CGAL::parameters::number_of_iterations(opt.smooth).vertex_is_constrained_map(held);
  return opt.smoother == "laplacian" ? CGAL::laplacian_smooth_mesh_2(in.cdt, np) : CGAL::quality_smooth_mesh_2(in.cdt, np);
}

// A constrained edge (a, b) that the refinement split at midpoints is now a
// chain of constrained edges from a to b: its marker goes to each piece
// (and to the new vertices, by Triangle's rules). The chain is straight up
// to the rounding of the midpoints, so each step takes the constrained
// edge that heads most nearly towards b.
template <class CDT>
void carry_marker_along_chain(const CDT& cdt, AFM::Markers_and_regions_2<CDT>& tags, typename CDT::Vertex_handle a,
                              typename CDT::Vertex_handle b)
{
  typedef typename CDT::Vertex_handle Vertex_handle;
  if(cdt.is_edge(a, b)) return;
  const double bx = CGAL::to_double(b->point().x()), by = CGAL::to_double(b->point().y());
  Vertex_handle at = a, came_from;
  for(std::size_t steps = 0; at != b && steps < cdt.number_of_vertices(); ++steps) {
    Vertex_handle next;
    double best = -2;
    auto e = cdt.incident_edges(at), done = e;
    do {
      if(!cdt.is_constrained(*e)) continue;
      const int i = e->second;
      Vertex_handle w = e->first->vertex(CDT::ccw(i));
      if(w == at) w = e->first->vertex(CDT::cw(i));
      if(w == came_from || cdt.is_infinite(w)) continue;
      const double ax = CGAL::to_double(at->point().x()), ay = CGAL::to_double(at->point().y());
      const double ux = CGAL::to_double(w->point().x()) - ax, uy = CGAL::to_double(w->point().y()) - ay;
      const double vx = bx - ax, vy = by - ay;
      const double cosine = (ux * vx + uy * vy) / (std::hypot(ux, uy) * std::hypot(vx, vy));
      if(cosine > best) {
        best = cosine;
        next = w;
      }
    } while(++e != done);
    if(next == Vertex_handle()) return;
    if(next != b) tags.split_constraint(at, b, next);
    came_from = at;
    at = next;
  }
}

// --min-angle A after the smoothing: Mesh_2's refinement of the triangles
// below A (splitting segments unless --keep-segments), markers carried over
// the segments it splits; a note when the safeguard stopped it.
template <class K>
AFM::Minimum_angle_statistics raise_minimum_angle(const Options& opt, Input<K>& in)
{
  typedef typename Types<K>::CDT CDT;
  typedef typename CDT::Vertex_handle Vertex_handle;
  if(opt.min_angle == 0) return AFM::Minimum_angle_statistics();
  std::vector<std::pair<Vertex_handle, Vertex_handle> > constrained;
  if(in.tags.has_markers() && !opt.keep_segments)
    for(const auto& e : in.cdt.constrained_edges())
      constrained.emplace_back(e.first->vertex(CDT::ccw(e.second)), e.first->vertex(CDT::cw(e.second)));
  const AFM::Minimum_angle_statistics st = AFM::refine_to_minimum_angle_2(in.cdt, opt.min_angle, !opt.keep_segments);
  for(const auto& ab : constrained) carry_marker_along_chain(in.cdt, in.tags, ab.first, ab.second);
  if(!st.completed)
    std::cerr << "afmesh_2: warning: " << opt.input << ": --min-angle " << opt.min_angle
              << ": the refinement stopped at its limit of insertions with " << st.below_after
              << " triangles below the bound (the mesh is valid)\n";
  return st;
}

} // namespace afmesh_2

#endif // AFMESH_2_MESHING_H
