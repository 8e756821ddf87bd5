// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_ADVANCING_FRONT_REFINER_H
#define CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_ADVANCING_FRONT_REFINER_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <CGAL/Advancing_front_mesh_2/Checkpoint_error.h>
#include <CGAL/Advancing_front_mesh_2/Checkpoint_info.h>
#include <CGAL/Advancing_front_mesh_2/Mesh_return_code.h>
#include <CGAL/Advancing_front_mesh_2/internal/Cavity.h>
#include <CGAL/Advancing_front_mesh_2/internal/Checkpoint_io.h>
#include <CGAL/Advancing_front_mesh_2/internal/Delaunay_apex.h>
#include <CGAL/Advancing_front_mesh_2/internal/Front_2.h>
#include <CGAL/Advancing_front_mesh_2/internal/Front_triangles.h>
#include <CGAL/Advancing_front_mesh_2/internal/Front_visibility.h>
#include <CGAL/Advancing_front_mesh_2/internal/Initial_front.h>
#include <CGAL/Advancing_front_mesh_2/split_constraints_to_size_2.h>
#include <CGAL/Advancing_front_mesh_2/internal/Lawson_flips.h>
#include <CGAL/Advancing_front_mesh_2/internal/Neighbourhood.h>
#include <CGAL/Advancing_front_mesh_2/internal/Pockets.h>
#include <CGAL/Advancing_front_mesh_2/internal/Point_placement.h>
#include <CGAL/Advancing_front_mesh_2/internal/Refinement_context.h>
#include <CGAL/Advancing_front_mesh_2/internal/Size_bound.h>
#include <CGAL/Advancing_front_mesh_2/internal/Streaming_output.h>
#include <CGAL/Advancing_front_mesh_2/internal/Streaming_state.h>

#include <CGAL/Delaunay_mesh_criteria_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/assertions.h>

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <list>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Advancing_front_mesh_2 {
namespace internal {

// The engine of `Advancing_front_mesher_2`: it owns the state and the
// components, runs the step loop of Mavriplis (1992) and finishes the mesh.
// One step takes the next front edge (step 2) and dispatches it: the size
// bound (3), the close points (4), the Delaunay apex (5), then a closure on
// it or a new point (6) with its cavity (7-12).
//
// `PointIndex` models AdvancingFrontPointIndex_2; `CircleIndex` models
// AdvancingFrontCircleIndex_2 and is rebound to the two payloads it holds.
template <class Tr, class SizingField, class Visitor, class PointIndex, class CircleIndex>
class Advancing_front_refiner
{
public:
  typedef Refinement_context<Tr> Context;
  typedef typename Context::Point Point;
  typedef typename Context::Vertex_handle Vertex_handle;
  typedef typename Context::Face_handle Face_handle;
  typedef typename Context::Phase_scope Phase_scope;
  typedef typename CircleIndex::template Rebind_payload<Face_handle>::Other Face_circle_index;
  typedef typename CircleIndex::template Rebind_payload<std::pair<Vertex_handle, Vertex_handle> >::Other
    Constraint_circle_index;
  typedef Front_2<Context, PointIndex, Face_circle_index> Front;
  typedef typename Front::Vid Vid;
  typedef typename Front::Edge_key Edge_key;
  typedef typename Front::Front_edge Front_edge;
  typedef typename Front::Queue_entry Queue_entry;
  typedef internal::Size_bound<Context, SizingField> Size_bound;
  typedef internal::Neighbourhood<Front> Neighbourhood;
  typedef Front_visibility<Front, Constraint_circle_index> Visibility;
  typedef internal::Front_triangles<Front, Visitor> Triangles;
  typedef internal::Delaunay_apex<Front, Visibility> Apex;
  typedef internal::Pockets<Front> Pockets;
  typedef internal::Point_placement<Front, Visibility, Triangles, Size_bound> Placement;
  typedef internal::Cavity<Front, Visibility, Triangles, Placement, Visitor> Cavity;
  typedef internal::Initial_front<Front, Visibility, Triangles> Initial_front;
  typedef Streaming_state<Context> Stream;
  typedef internal::Streaming_output<Front, Size_bound, Visitor> Streaming_output;
  typedef internal::Checkpoint_io<Front, Visibility, Triangles> Checkpoint_io;
  typedef typename Stream::Mesh_sink Mesh_sink;
  typedef std::list<Point> Seeds;
  static constexpr Vid no_vertex = Front::no_vertex;
  static constexpr bool supports_checkpoints = Checkpoint_io::is_supported;

  Advancing_front_refiner(Tr& tr, const SizingField& sizing, const Visitor& visitor)
    : ctx_(tr), visitor_(visitor), size_(ctx_, sizing), front_(ctx_), neighbourhood_(ctx_, front_),
      visibility_(ctx_, front_), triangles_(ctx_, front_, stream_, visitor_), apex_(ctx_, front_, visibility_),
      pockets_(ctx_, front_),
      placement_(ctx_, front_, neighbourhood_, apex_, visibility_, triangles_, size_),
      cavity_(ctx_, front_, stream_, neighbourhood_, apex_, visibility_, triangles_, placement_, visitor_),
      initial_front_(ctx_, front_, visibility_, triangles_),
      streaming_output_(ctx_, front_, stream_, size_, visitor_),
      checkpoint_io_(ctx_, front_, stream_, triangles_, visibility_, pocket_priority_)
  {}

  // The components refer to each other: a copy or a move would leave the new
  // object's components pointing into the old one.
  Advancing_front_refiner(const Advancing_front_refiner&) = delete;
  Advancing_front_refiner& operator=(const Advancing_front_refiner&) = delete;

  // ---------------------------------------------------------- settings
  Seeds seeds;
  bool seeds_mark = false;
  // the domain is the faces marked when meshing starts (no seeds)
  bool keep_domain_marks = false;
  // the boundary discretisation before the front is built (off: the paper's
  // mode, every input segment one front edge)
  bool split_constraints = true;
  Constraint_split_statistics split_statistics;
  std::size_t iteration_limit = 0;
  double time_limit = 0;
  bool pocket_priority() const { return pocket_priority_; }
  void set_pocket_priority(bool on) { pocket_priority_ = on; }
  void set_phase_timing(bool on) { ctx_.timer.set_enabled(on); }
  void invalidate() { initialized_ = false; }
  void set_output_sink(Mesh_sink* sink)
  {
    stream_.sink = sink;
    initialized_ = false;
  }
  Mesh_sink* output_sink() const { return stream_.sink; }
  void set_sweep_interval(std::size_t n) { stream_.minimum_sweep = (std::max)(n, std::size_t(1)); }
  void set_checkpoint(std::size_t every, const std::string& file_name, const std::string& user_data, bool stop);

  // ---------------------------------------------------------- meshing
  template <class On_init>
  void init(On_init on_init);
  bool is_initialized() const { return initialized_; }
  bool is_finished() const { return finished_; }
  template <class On_init>
  Mesh_return_code refine_mesh(On_init on_init);
  template <class On_init>
  bool step_by_step(On_init on_init);

  // ------------------------------------------------------- checkpoints
  static Checkpoint_info read_checkpoint_info(const std::string& file_name);
  Checkpoint_info resume(const std::string& file_name);
  template <class On_init>
  void write_checkpoint(const std::string& file_name, const std::string& user_data, On_init on_init);

  // ------------------------------------------------------------ access
  Tr& triangulation() const { return ctx_.tr; }
  const SizingField& sizing_field() const { return size_.sizing_field(); }
  Visitor& visitor() { return visitor_; }
  const Visitor& visitor() const { return visitor_; }
  const Statistics& statistics() const { return ctx_.stats; }
  std::size_t front_size() const { return front_.size(); }
  bool is_front_valid() const { return front_.is_valid(stream_.ghost) && front_.reach_covers_edges(); }

private:
  void clear_state();
  void require_checkpoint_support(const char* what) const;
  bool sweep_and_checkpoint();
  bool step();
  void process_edge(Vid a, Vid b);
  void close_remaining_front();
  void finish();
  void finish_triangulation();
  void stop_clock(const std::chrono::steady_clock::time_point& start);
  static double seconds_since(const std::chrono::steady_clock::time_point& start)
  {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }

  // the components, in the order they are built (each refers to earlier ones)
  Context ctx_;
  Visitor visitor_;
  Size_bound size_;
  Front front_;
  Stream stream_;
  Neighbourhood neighbourhood_;
  Visibility visibility_;
  Triangles triangles_;
  Apex apex_;
  Pockets pockets_;
  Placement placement_;
  Cavity cavity_;
  Initial_front initial_front_;
  Streaming_output streaming_output_;
  Checkpoint_io checkpoint_io_;

  bool initialized_ = false;
  bool finished_ = false;
  bool pocket_priority_ = true;
  std::size_t checkpoint_every_ = 0, next_checkpoint_ = 0;
  std::string checkpoint_file_, checkpoint_user_data_;
  bool checkpoint_stop_ = false, stop_now_ = false;
};

template <class Tr, class S, class V, class P, class C>
void Advancing_front_refiner<Tr, S, V, P, C>::clear_state()
{
  front_.clear();
  pockets_.clear();
  ctx_.stats = Statistics();
  ctx_.timer.clear();
  triangles_.meshed_area = 0;
  triangles_.domain_area = 0;
  stream_.clear();
}

// Marks the domain from the seeds, removes the in-domain faces and builds
// the initial front from the constrained edges that bound the domain.
template <class Tr, class S, class V, class P, class C>
template <class On_init>
void Advancing_front_refiner<Tr, S, V, P, C>::init(On_init on_init)
{
  const auto start = std::chrono::steady_clock::now();
  clear_state();
  initialized_ = true;
  finished_ = false;
  if(ctx_.tr.dimension() < 2) {
    finished_ = true;
    return;
  }
  typedef CGAL::Delaunay_mesher_2<Tr, CGAL::Delaunay_mesh_criteria_2<Tr> > Mesh_2_mesher;
  if(!keep_domain_marks) Mesh_2_mesher::mark_facets(ctx_.tr, seeds.begin(), seeds.end(), seeds_mark);
  split_statistics = Constraint_split_statistics();
  // (with the domain given by marks, the faces a split makes could not be
  // marked again: the caller splits)
  if(split_constraints && !keep_domain_marks) {
    // the constraints that bound or cross the domain, to the size field;
    // the faces the splits made are marked again, even when no point went
    // in: a cut left out may have taken its constraint out and put it back
    split_statistics = split_constraints_to_size_2(ctx_.tr, size_.sizing_field(),
                                                   Constraint_touches_domain<Tr>{&ctx_.tr},
                                                   internal::No_split_callback());
    Mesh_2_mesher::mark_facets(ctx_.tr, seeds.begin(), seeds.end(), seeds_mark);
  }
  ctx_.set_scaling(Coordinate_scaling<Point>::for_triangulation(ctx_.tr));
  finished_ = !initial_front_.build();
  if(stream_.is_streaming() && !finished_) {
    // the face that stands for faces gone to the sink: not in the domain,
    // so cavities stop at it as at the outside
    stream_.ghost = ctx_.tds().create_face();
    stream_.ghost->set_in_domain(false);
  }
  front_.created_this_step.clear(); // only the edges of one step are of interest
  on_init();
  ctx_.stats.init_time += seconds_since(start);
}

template <class Tr, class S, class V, class P, class C>
template <class On_init>
Mesh_return_code Advancing_front_refiner<Tr, S, V, P, C>::refine_mesh(On_init on_init)
{
  if(!initialized_) init(on_init);
  const auto start = std::chrono::steady_clock::now();
  // initialisation is timed separately (init_time)
  ctx_.timer.restart(FRONT_SELECTION);
  Mesh_return_code rc = MESH_COMPLETE;
  std::size_t steps = 0;
  while(!front_.queue.empty()) {
    if(iteration_limit != 0 && steps >= iteration_limit) {
      rc = ITERATION_LIMIT_REACHED;
      break;
    }
    if(time_limit > 0 && (steps & 63) == 0 && seconds_since(start) > time_limit) {
      rc = TIME_LIMIT_REACHED;
      break;
    }
    try {
      if(!step()) break;
    } catch(const Checkpoint_error&) {
      // the state is the one before the checkpoint: a caller may retry
      stop_clock(start);
      throw;
    } catch(...) {
      // leave a valid triangulation behind before reporting the error
      close_remaining_front();
      finish();
      throw;
    }
    ++steps;
    if(stop_now_) {
      stop_now_ = false;
      rc = STOPPED_AT_CHECKPOINT;
      break;
    }
  }
  if(rc == STOPPED_AT_CHECKPOINT) {
    // what the sink has so far
    ctx_.stats.number_of_faces = stream_.triangles_output;
    ctx_.stats.number_of_vertices = stream_.vertices_output;
  } else {
    if(rc != MESH_COMPLETE) close_remaining_front();
    finish();
  }
  stop_clock(start);
  return rc;
}

template <class Tr, class S, class V, class P, class C>
void Advancing_front_refiner<Tr, S, V, P, C>::stop_clock(const std::chrono::steady_clock::time_point& start)
{
  ctx_.timer.enter(FRONT_SELECTION);
  ctx_.timer.store(ctx_.stats.phase_times);
  ctx_.stats.meshing_time += seconds_since(start);
}

template <class Tr, class S, class V, class P, class C>
template <class On_init>
bool Advancing_front_refiner<Tr, S, V, P, C>::step_by_step(On_init on_init)
{
  if(!initialized_) init(on_init);
  if(finished_) return false;
  stop_now_ = false; // a stop after a checkpoint concerns refine_mesh() only
  try {
    if(step()) return true;
  } catch(const Checkpoint_error&) {
    throw; // the state is the one before the checkpoint
  } catch(...) {
    close_remaining_front();
    finish();
    throw;
  }
  finish();
  return false;
}

// Streaming: drops the finished triangles when a sweep is due, and writes
// a checkpoint right after it when one is due (the state is smallest then).
// Returns true when the run is to stop at that checkpoint.
template <class Tr, class S, class V, class P, class C>
bool Advancing_front_refiner<Tr, S, V, P, C>::sweep_and_checkpoint()
{
  if(!stream_.is_streaming() || !streaming_output_.is_due()) return false;
  streaming_output_.sweep(false);
  if(checkpoint_every_ == 0 || stream_.triangles_output < next_checkpoint_) return false;
  write_checkpoint(checkpoint_file_, checkpoint_user_data_, [] {});
  next_checkpoint_ = stream_.triangles_output + checkpoint_every_;
  // before the next edge: the state in memory is the checkpoint's
  return checkpoint_stop_;
}

// Step 2: the next front edge from the queue, dispatched; false when the
// front is empty.
template <class Tr, class S, class V, class P, class C>
bool Advancing_front_refiner<Tr, S, V, P, C>::step()
{
  front_.reuse_released_ids();
  front_.release_unused_memory();
  if(sweep_and_checkpoint()) {
    stop_now_ = true;
    return true;
  }
  while(!front_.queue.empty()) {
    const Queue_entry e = front_.queue.top();
    front_.queue.pop();
    const Front_edge* it = front_.find(e.key);
    if(it == nullptr || it->version != e.version) continue;
    ++ctx_.stats.front_edges_processed;
    const std::size_t compactions = front_.queue_compactions;
    // what an edge of a pocket creates lies in the pocket
    front_.level = it->level;
    front_.created_this_step.clear();
    front_.loops_changed = false;
    {
      Phase_scope phase(ctx_.timer, PLACEMENT);
      front_.defer_queueing = true;
      process_edge(Front::source(e.key), Front::target(e.key));
      front_.queue_created_edges();
    }
    if(front_.loops_changed && pocket_priority_) pockets_.mark();
    front_.level = 0;
    // A new point may leave the edge open (its apex after the cavity was
    // another point): the edge stays on the front and must be queued again,
    // unless a compaction of the queue, a new version (the edge was removed
    // and created again, or found on a pocket) already did so.
    const Front_edge* left = front_.find(e.key);
    if(left != nullptr && compactions == front_.queue_compactions && left->version == e.version)
      front_.queue.push(Queue_entry{e.length, e.key, left->version, left->level});
    const double meshed = triangles_.meshed_area, domain = triangles_.domain_area;
    visitor_.on_progress(domain > 0 ? (std::min)(1., meshed / domain) : 1.);
    return true;
  }
  return false;
}

// One front edge a -> b, steps 3-12.
template <class Tr, class S, class V, class P, class C>
void Advancing_front_refiner<Tr, S, V, P, C>::process_edge(Vid a, Vid b)
{
  const Edge_frame e = placement_.frame(a, b);                                     // steps 3 and 6
  neighbourhood_.gather(e.mx, e.my, (std::max)(e.radius, e.star_reach) * (1 + 1e-6)); // step 4
  // an apex whose circle's centre lies at d_target or higher can neither be
  // accepted (its radius exceeds 1.41 rho) nor limit the new point
  const Vid w = apex_(a, b, neighbourhood_, e.d_target);                           // step 5
  double d;
  if(placement_.close_or_clamp(a, b, w, e, d)) return;                             // step 6
  if(cavity_.insert_point(a, b, e.mx + d * e.nx, e.my + d * e.ny, d, e.rho, w)) return; // steps 7-12
  ++ctx_.stats.rejected_points;
  ++ctx_.stats.forced_closures;
  placement_.forced_closure(a, b);
}

// Used when a limit stops the run: closes the remaining front on existing
// points only, which always terminates and leaves a valid mesh.
template <class Tr, class S, class V, class P, class C>
void Advancing_front_refiner<Tr, S, V, P, C>::close_remaining_front()
{
  // every front edge gets a fresh queue entry, so none can be missed
  front_.edges.for_each([this](Edge_key k, const Front_edge& fe) { front_.push(k, fe); });
  while(!front_.queue.empty()) {
    const Queue_entry e = front_.queue.top();
    front_.queue.pop();
    const Front_edge* it = front_.find(e.key);
    if(it == nullptr || it->version != e.version) continue;
    const Vid a = Front::source(e.key), b = Front::target(e.key);
    front_.created_this_step.clear();
    placement_.forced_closure(a, b);
  }
}

template <class Tr, class S, class V, class P, class C>
void Advancing_front_refiner<Tr, S, V, P, C>::finish()
{
  if(finished_) return;
  {
    Phase_scope phase(ctx_.timer, OUTPUT);
    finished_ = true;
    CGAL_assertion(stream_.is_streaming() || front_.empty());
    if(!front_.empty()) close_remaining_front(); // never expected; keeps the result valid
    if(stream_.is_streaming()) streaming_output_.finish();
    else finish_triangulation();
  }
  ctx_.timer.store(ctx_.stats.phase_times);
}

// The triangulation is complete again: checked with Lawson's flips (the
// advancing front builds a constrained Delaunay triangulation by itself, so
// they find nothing to flip; the tests assert it), its vertices pointing at
// live faces.
template <class Tr, class S, class V, class P, class C>
void Advancing_front_refiner<Tr, S, V, P, C>::finish_triangulation()
{
  ctx_.stats.delaunay_repair_flips += restore_constrained_delaunay(ctx_.tr);
  // vertices may still point at faces deleted during meshing
  for(auto f = ctx_.tr.all_faces_begin(); f != ctx_.tr.all_faces_end(); ++f)
    for(int i = 0; i < 3; ++i) f->vertex(i)->set_face(f);
  std::size_t faces = 0;
  for(auto f = ctx_.tr.finite_faces_begin(); f != ctx_.tr.finite_faces_end(); ++f)
    if(f->is_in_domain()) ++faces;
  ctx_.stats.number_of_faces = faces;
  ctx_.stats.number_of_vertices = ctx_.tr.number_of_vertices();
  CGAL_expensive_postcondition(ctx_.tr.is_valid());
}

// ------------------------------------------------------------- checkpoints

template <class Tr, class S, class V, class P, class C>
void Advancing_front_refiner<Tr, S, V, P, C>::require_checkpoint_support(const char* what) const
{
  if(!supports_checkpoints)
    throw std::logic_error(std::string("Advancing_front_mesher_2::") + what +
                           ": checkpoints need search structures that can be saved and loaded (save() and load()), "
                           "and this mesher's point index or circle index cannot");
}

template <class Tr, class S, class V, class P, class C>
void Advancing_front_refiner<Tr, S, V, P, C>::set_checkpoint(std::size_t every, const std::string& file_name,
                                                             const std::string& user_data, bool stop)
{
  if(every != 0) require_checkpoint_support("set_checkpoint()");
  checkpoint_every_ = every;
  checkpoint_file_ = file_name;
  checkpoint_user_data_ = user_data;
  checkpoint_stop_ = stop;
  next_checkpoint_ = stream_.triangles_output + every;
}

template <class Tr, class S, class V, class P, class C>
Checkpoint_info Advancing_front_refiner<Tr, S, V, P, C>::read_checkpoint_info(const std::string& file_name)
{
  std::istringstream is(Checkpoint_io::verified_content(file_name));
  Binary_reader r(is, file_name);
  return Checkpoint_io::read_header(r, false);
}

template <class Tr, class S, class V, class P, class C>
Checkpoint_info Advancing_front_refiner<Tr, S, V, P, C>::resume(const std::string& file_name)
{
  require_checkpoint_support("resume()");
  if(stream_.sink == nullptr)
    throw std::logic_error("Advancing_front_mesher_2::resume(): set the output sink first");
  if(ctx_.tr.number_of_vertices() != 0 || ctx_.tr.dimension() != -1)
    throw std::logic_error("Advancing_front_mesher_2::resume(): the triangulation must be empty");
  const std::string content = Checkpoint_io::verified_content(file_name);
  clear_state();
  try {
    const Checkpoint_info info = checkpoint_io_.read(content, file_name);
    initialized_ = true;
    finished_ = false;
    return info;
  } catch(...) {
    // nothing half-loaded may stay behind
    clear_state();
    ctx_.tr.clear();
    initialized_ = false;
    throw;
  }
}

template <class Tr, class S, class V, class P, class C>
template <class On_init>
void Advancing_front_refiner<Tr, S, V, P, C>::write_checkpoint(const std::string& file_name,
                                                               const std::string& user_data, On_init on_init)
{
  require_checkpoint_support("write_checkpoint()");
  if(stream_.sink == nullptr) throw std::logic_error("Advancing_front_mesher_2: checkpoints need streaming mode");
  if(!initialized_) init(on_init);
  if(finished_) throw std::logic_error("Advancing_front_mesher_2: the mesh is complete, there is nothing to checkpoint");
  std::string sink_state;
  try {
    sink_state = stream_.sink->checkpoint_state();
  } catch(const std::exception& e) {
    throw Checkpoint_error(file_name + ": the output's state for the checkpoint: " + e.what());
  }
  // counted in the state it writes: a resumed run counts on from there
  ++ctx_.stats.checkpoints_written;
  try {
    checkpoint_io_.write(file_name, user_data, sink_state);
  } catch(...) {
    --ctx_.stats.checkpoints_written;
    throw;
  }
}

} // namespace internal
} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_ADVANCING_FRONT_REFINER_H
