// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESHER_2_H
#define CGAL_ADVANCING_FRONT_MESHER_2_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <CGAL/Advancing_front_mesh_2/Checkpoint_error.h>
#include <CGAL/Advancing_front_mesh_2/Default_visitor.h>
#include <CGAL/Advancing_front_mesh_2/Mesh_return_code.h>
#include <CGAL/Advancing_front_mesh_2/Mesh_sink_2.h>
#include <CGAL/Advancing_front_mesh_2/Sizing_fields.h>
#include <CGAL/Advancing_front_mesh_2/Statistics.h>
#include <CGAL/Advancing_front_mesh_2/internal/Binary_io.h>
#include <CGAL/Advancing_front_mesh_2/internal/Compact_id_list.h>
#include <CGAL/Advancing_front_mesh_2/internal/Dynamic_point_quadtree.h>
#include <CGAL/Advancing_front_mesh_2/internal/Flat_hash_map.h>
#include <CGAL/Advancing_front_mesh_2/internal/Front_predicates.h>
#include <CGAL/Advancing_front_mesh_2/internal/Lifted_circle_octree.h>

#include <CGAL/Delaunay_mesh_criteria_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/assertions.h>
#include <CGAL/number_utils.h>


#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <functional>
#include <iterator>
#include <limits>
#include <list>
#include <queue>
#include <sstream>
#include <stdexcept>
#include <string>
#include <typeinfo>
#include <type_traits>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

namespace CGAL {

/*!
\ingroup PkgAdvancingFrontMesh2Ref

Generates a mesh of the domain of a constrained Delaunay triangulation with
the advancing-front Delaunay algorithm of D. J. Mavriplis, "An Advancing
Front Delaunay Triangulation Algorithm Designed for Robustness" (1992).

The boundary edges form the initial front. The shortest front edge is taken
first; either an existing front point closes a Delaunay triangle on it within
the local size bound, or a new point is placed ahead of the front along the
edge's perpendicular bisector and all Delaunay triangles it forms with nearby
front points are built at once. Triangles exist only behind the front, every
operation is local, and every combinatorial decision uses the traits' exact
predicates. Input constraints are never split, and the result is a
constrained Delaunay triangulation of its vertices.

The mesh is built directly in the triangulation data structure of `cdt`:
the in-domain faces are removed, the front advances over the emptied region,
and at the end the triangulation is complete and valid again, its in-domain
faces flagged with `set_in_domain(true)`, exactly like the result of
`CGAL::Delaunay_mesher_2`.

\tparam CDT a `Constrained_Delaunay_triangulation_2` or a
  `Constrained_triangulation_plus_2` of one, whose face base models
  `DelaunayMeshFaceBase_2` (for example `Delaunay_mesh_face_base_2`).
\tparam SizingField a model of `AdvancingFrontSizingField_2`: callable as
  `FT(const Point_2&)`, returning the target edge length `h` at a point.
\tparam Visitor a model of `AdvancingFrontMeshVisitor_2`.

<b>Sizes.</b> The paper bounds triangle circumradii by rho(x); users think in
edge lengths. The sizing field gives the target edge length h(x) and the
mesher uses rho(x) = h(x) / sqrt(3), the circumradius of the equilateral
triangle of side h.
*/
template <class CDT_,
          class SizingField_ = Advancing_front_mesh_2::Uniform_sizing_field_2<typename CDT_::Geom_traits>,
          class Visitor_ = Advancing_front_mesh_2::Default_visitor>
class Advancing_front_mesher_2
{
public:
  typedef CDT_ CDT;
  typedef CDT_ Triangulation;
  typedef SizingField_ Sizing_field;
  typedef Visitor_ Visitor;
  typedef typename CDT::Geom_traits Geom_traits;
  typedef typename Geom_traits::FT FT;
  typedef typename CDT::Point Point;
  typedef typename CDT::Vertex_handle Vertex_handle;
  typedef typename CDT::Face_handle Face_handle;
  typedef typename CDT::Triangulation_data_structure Tds;
  typedef std::list<Point> Seeds;
  typedef typename Seeds::const_iterator Seeds_const_iterator;
  typedef Advancing_front_mesh_2::Mesh_sink_2<Point> Mesh_sink;

private:
  typedef std::uint32_t Vid;
  typedef std::uint64_t Edge_key;
  static constexpr Vid no_vertex = (std::numeric_limits<Vid>::max)();

  struct Handle_hash
  {
    template <class H>
    std::size_t operator()(const H& h) const { return std::hash<const void*>()(&*h); }
  };

  // A front edge is directed with the unmeshed region on its left.
  struct Front_edge
  {
    Face_handle behind;  // face on the meshed side (mesh or outside face), null on a virgin side of a constraint
    int behind_index = -1;
    bool constrained = false;
    std::uint16_t level = 0; // pockets within pockets: see mark_pockets()
    std::uint32_t version = 0;
  };

  struct Face_record
  {
    std::size_t circle_item;
    int front_edges;
  };

  struct Queue_entry
  {
    Queue_entry(double len, Edge_key k, std::uint32_t v, std::uint16_t l)
      : length(len), key(k), version(v), level(l) {}
    double length;
    Edge_key key;
    std::uint32_t version;
    std::uint16_t level;
    bool operator<(const Queue_entry& o) const
    {
      // std::priority_queue is a max-heap: invert to pop the shortest edge,
      // the edges of the innermost pockets first; ties broken by age
      // (versions grow with creation, and when an edge is found on a
      // pocket), which does not depend on the reuse of vertex ids, so that
      // runs are deterministic
      if(level != o.level) return level < o.level;
      if(length != o.length) return length > o.length;
      return version > o.version;
    }
  };

  // A front edge near the neighbourhood's disk, with its end points'
  // coordinates copied once, so that the many box tests of the visibility
  // checks read them from one small array.
  struct Near_edge
  {
    Edge_key key;
    double x0, y0, x1, y1;
  };

  struct Neighbourhood
  {
    double cx = 0, cy = 0, radius = 0;
    std::vector<std::size_t> vertices;           // active vertices in the disk
    std::vector<std::array<double, 2> > vertex_xy; // their coordinates, in the same order
    std::vector<Near_edge> edges;                // front edges meeting the disk when gathered
    std::vector<Edge_key> new_edges;             // front edges created since
    std::vector<Edge_key> removed_edges;         // front edges removed since
  };

  struct Circle
  {
    double cx, cy, r;
  };

  typedef Advancing_front_mesh_2::internal::Lifted_circle_octree<Face_handle> Triangle_octree;
  // an input constraint, by its end vertices (which may become inactive)
  typedef std::pair<Vertex_handle, Vertex_handle> Constraint;
  typedef Advancing_front_mesh_2::internal::Lifted_circle_octree<Constraint> Constraint_octree;

public:
  /// \name Creation
  /// @{

  /*!
  Creates a mesher for `cdt`. The triangulation must stay alive and must not
  be modified by anything else while the mesher works on it.
  */
  explicit Advancing_front_mesher_2(CDT& cdt,
                                    const Sizing_field& sizing = Sizing_field(),
                                    const Visitor& visitor = Visitor())
    : cdt_(cdt), sizing_(sizing), visitor_(visitor), pred_(cdt.geom_traits())
  {}

  /// @}

  /// \name Domain
  /// @{

  /*!
  Sets the seeds, exactly as `Delaunay_mesher_2::set_seeds()`: with
  `mark == false` (default) the connected components (bounded by
  constraints) containing a seed are holes; with `mark == true` they are the
  domain. The unbounded component is never meshed. Without seeds every
  bounded component is meshed.
  */
  template <class InputIterator>
  void set_seeds(InputIterator b, InputIterator e, bool mark = false)
  {
    seeds_.assign(b, e);
    seeds_mark_ = mark;
    initialized_ = false;
  }

  void clear_seeds()
  {
    seeds_.clear();
    seeds_mark_ = false;
    initialized_ = false;
  }

  Seeds_const_iterator seeds_begin() const { return seeds_.begin(); }
  Seeds_const_iterator seeds_end() const { return seeds_.end(); }

  /// @}

  /// \name Limits
  /// @{

  /// Stops after `n` front edges have been processed (0: no limit).
  void set_iteration_limit(std::size_t n) { iteration_limit_ = n; }
  /// Stops after `seconds` seconds of meshing (0: no limit).
  void set_time_limit(double seconds) { time_limit_ = seconds; }

  /// Measures the time of each phase into `statistics().phase_times`
  /// (off by default: it reads the clock at every phase change).
  void set_phase_timing(bool on) { phase_timing_ = on; }

  /// Meshes the pockets of the front first (on by default): regions of the
  /// unmeshed domain that the front closes off from the rest are meshed as
  /// soon as they form, instead of when their edges come up in the
  /// shortest-first order. With uniform sizes this keeps the front, and
  /// the memory and trees that follow it, smaller (on the benchmark's square
  /// at 1M triangles: 10.6k front edges at most instead of 39.7k), at the
  /// cost of a little quality where patches of triangles meet (share of
  /// radius ratios above 0.9: 99.1% instead of 99.6% on average over four
  /// sizes near 1M triangles). A change during
  /// meshing applies to the pockets that form afterwards.
  void set_pocket_priority(bool on) { pocket_priority_ = on; }
  bool pocket_priority() const { return pocket_priority_; }

  /// @}

  /// \name Streaming
  /// @{

  /*!
  Switches on streaming mode: finished triangles, those whose circumcircles
  lie so far behind the front that no later point is expected to break
  them, are handed to `sink` (with the mesher's own vertex numbering, see
  `Advancing_front_mesh_2::Mesh_sink_2`) and removed from the triangulation
  as meshing goes, so that memory holds only the triangles near the front
  (Mavriplis 1992, section 4). The visitor's `on_face_finished()` sees each
  of them first. At the end every triangle has gone to the sink and `cdt` is
  left empty (`clear()`ed): the mesh is wherever the sink put it.
  A later point whose cavity would reach a finished triangle all the same
  is refused (the edge is closed on an existing point, as for any refused
  point), so the mesh stays a constrained Delaunay triangulation; the
  statistic `points_refused_for_finished_triangles` counts such points, and
  with it at 0 the triangles are exactly those of the same run without
  streaming.

  Must be called before meshing starts; `nullptr` switches streaming off.
  The sink must outlive the meshing.
  */
  void set_output_sink(Mesh_sink* sink)
  {
    sink_ = sink;
    initialized_ = false;
  }
  Mesh_sink* output_sink() const { return sink_; }

  /// In streaming mode, the triangles in memory are searched for finished
  /// ones after `n` new triangles (default 4096), or after as many as
  /// stayed in memory at the previous search if that is more: smaller
  /// values hold fewer triangles in memory and search more often.
  void set_sweep_interval(std::size_t n) { minimum_sweep_ = (std::max)(n, std::size_t(1)); }

  /*!
  Streaming mode only: writes a checkpoint to `file_name` each time at least
  `every` more triangles have gone to the sink (0 switches checkpoints off),
  the restart facility of Mavriplis (1992, section 4). A checkpoint holds the
  state of the mesher (the front, the triangles still in memory, the trees,
  the queue) and `sink->checkpoint_state()`, so that `resume()` in a later
  run goes on exactly where this one was: the final mesh and output are
  those of an uninterrupted run. It is written to `file_name.tmp` and
  renamed, so a run killed while writing leaves the previous checkpoint.
  `user_data` is stored with it (the command-line tool stores its options).
  With `stop == true`, `refine_mesh()` returns `STOPPED_AT_CHECKPOINT` after
  the first checkpoint.

  The checkpoint file is in the machine's native binary layout, for the same
  kernel and build; it holds coordinates as doubles, so the points must be
  representable as doubles (always true for `Epick`, and for the other
  kernels when the input was given in doubles).
  */
  void set_checkpoint(std::size_t every, const std::string& file_name, const std::string& user_data = std::string(),
                      bool stop = false)
  {
    checkpoint_every_ = every;
    checkpoint_file_ = file_name;
    checkpoint_user_data_ = user_data;
    checkpoint_stop_ = stop;
    next_checkpoint_ = triangles_output_ + every;
  }

  /// What `read_checkpoint_info()` and `resume()` return.
  struct Checkpoint_info
  {
    std::string user_data;     ///< as given to `set_checkpoint()`
    std::string sink_state;    ///< what the sink's `checkpoint_state()` returned
    std::size_t vertices_written = 0, triangles_written = 0; ///< given to the sink before the checkpoint
  };

  /*!
  Reads the beginning of a checkpoint written by `set_checkpoint()`: what a
  program needs to prepare a resumed run (its options in `user_data`, a sink
  made from `sink_state`).

  The kernel is not checked here (`resume()` does), so that a program can
  read the kernel it must use from its `user_data`.

  \throws std::runtime_error "FILE: ..." if the file cannot be read or is
  not a checkpoint of this mesher.
  */
  static Checkpoint_info read_checkpoint_info(const std::string& file_name)
  {
    std::istringstream is(verified_checkpoint(file_name));
    Advancing_front_mesh_2::internal::Binary_reader r(is, file_name);
    return read_checkpoint_header(r, false);
  }

  /*!
  Continues the run whose checkpoint is `file_name`. The triangulation must
  be empty and the output sink already set (made from the `sink_state` of
  `read_checkpoint_info()`: for `Streaming_mesh_writer`, with its `resume()`),
  and the sizing field must be the one of the interrupted run. Then
  `refine_mesh()` (or `step_by_step_refine_mesh()`) meshes the rest; the
  triangles and vertices the sink receives, their numbers and their order
  are exactly those the interrupted run would have given after its
  checkpoint. The sweep interval and the pocket priority are restored from
  the checkpoint (set after `resume()`, they apply from then on, and the
  output differs from the uninterrupted run's); limits and checkpoints are
  not restored: set them again. The statistics' counters go on from the
  checkpoint's; their times (`init_time`, `meshing_time`, `phase_times`)
  are those of the resumed run alone, so that a checkpoint does not depend
  on how fast it was made: two runs write the same bytes.

  \throws std::logic_error if the triangulation is not empty or no sink is set
  \throws std::runtime_error "FILE: ..." if the file cannot be read, is
  corrupt (its checksum is checked) or was written with another kernel.
  */
  Checkpoint_info resume(const std::string& file_name)
  {
    if(sink_ == nullptr)
      throw std::logic_error("Advancing_front_mesher_2::resume(): set the output sink first");
    if(cdt_.number_of_vertices() != 0 || cdt_.dimension() != -1)
      throw std::logic_error("Advancing_front_mesher_2::resume(): the triangulation must be empty");
    std::istringstream is(verified_checkpoint(file_name));
    Advancing_front_mesh_2::internal::Binary_reader r(is, file_name);
    clear_state();
    try {
      const Checkpoint_info info = read_checkpoint_header(r);
      vertices_output_ = info.vertices_written;
      triangles_output_ = info.triangles_written;
      read_checkpoint_state(r);
      r.check_checksum();
      initialized_ = true;
      finished_ = false;
      return info;
    } catch(...) {
      // nothing half-loaded may stay behind
      clear_state();
      cdt_.clear();
      initialized_ = false;
      throw;
    }
  }

  /*!
  Writes a checkpoint now (streaming mode, between steps); see `set_checkpoint()`.

  \throws Advancing_front_mesh_2::Checkpoint_error if the file or the
  sink's state cannot be written; nothing else changes then.
  \throws std::logic_error without streaming mode, after the end, or when a
  coordinate is not a double.
  */
  void write_checkpoint(const std::string& file_name, const std::string& user_data = std::string())
  {
    if(sink_ == nullptr) throw std::logic_error("Advancing_front_mesher_2: checkpoints need streaming mode");
    if(!initialized_) init();
    if(finished_) throw std::logic_error("Advancing_front_mesher_2: the mesh is complete, there is nothing to checkpoint");
    const std::string tmp = file_name + ".tmp";
    std::string sink_state;
    try {
      sink_state = sink_->checkpoint_state();
    } catch(const std::exception& e) {
      throw Advancing_front_mesh_2::Checkpoint_error(file_name + ": the output's state for the checkpoint: " +
                                                     e.what());
    }
    // counted in the state it writes: a resumed run counts on from there
    ++stats_.checkpoints_written;
    try {
      std::ofstream os(tmp.c_str(), std::ios::out | std::ios::binary | std::ios::trunc);
      if(!os) throw Advancing_front_mesh_2::Checkpoint_error(tmp + ": cannot write the checkpoint");
      Advancing_front_mesh_2::internal::Binary_writer w(os);
      write_checkpoint_state(w, user_data, sink_state);
      w.write_checksum();
      os.flush();
      if(!os) throw Advancing_front_mesh_2::Checkpoint_error(tmp + ": cannot write the checkpoint");
      os.close();
      if(!os) throw Advancing_front_mesh_2::Checkpoint_error(tmp + ": cannot write the checkpoint");
      if(std::rename(tmp.c_str(), file_name.c_str()) != 0)
        throw Advancing_front_mesh_2::Checkpoint_error(tmp + ": cannot rename it to " + file_name);
    } catch(...) {
      --stats_.checkpoints_written;
      std::remove(tmp.c_str()); // a partial file would only mislead
      throw;
    }
  }

  /// @}

  /// \name Meshing
  /// @{

  /*!
  Meshes the domain. Returns `MESH_COMPLETE`, or the limit that stopped the
  advancing front; in every case the triangulation is a valid mesh of the
  whole domain (see `Advancing_front_mesh_2::Mesh_return_code`).

  \throws std::invalid_argument if the sizing field returns a value that is
  not a positive finite number (the front is closed first, so the
  triangulation is valid).
  \throws Advancing_front_mesh_2::Checkpoint_error if a checkpoint cannot be
  written: then nothing is closed, and calling `refine_mesh()` again goes on.
  */
  Advancing_front_mesh_2::Mesh_return_code refine_mesh()
  {
    if(!initialized_) init();
    const auto start = std::chrono::steady_clock::now();
    // initialisation is timed separately (init_time)
    phase_seconds_.fill(0);
    phase_start_ = Clock::now();
    phase_ = FRONT_SELECTION;
    Advancing_front_mesh_2::Mesh_return_code rc = Advancing_front_mesh_2::MESH_COMPLETE;
    std::size_t steps = 0;
    while(!queue_.empty()) {
      if(iteration_limit_ != 0 && steps >= iteration_limit_) {
        rc = Advancing_front_mesh_2::ITERATION_LIMIT_REACHED;
        break;
      }
      if(time_limit_ > 0 && (steps & 63) == 0 &&
         seconds_since(start) > time_limit_) {
        rc = Advancing_front_mesh_2::TIME_LIMIT_REACHED;
        break;
      }
      try {
        if(!step()) break;
      } catch(const Advancing_front_mesh_2::Checkpoint_error&) {
        // the state is the one before the checkpoint: a caller may retry
        enter_phase(FRONT_SELECTION);
        store_phase_times();
        stats_.meshing_time += seconds_since(start);
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
        rc = Advancing_front_mesh_2::STOPPED_AT_CHECKPOINT;
        break;
      }
    }
    if(rc == Advancing_front_mesh_2::STOPPED_AT_CHECKPOINT) {
      // what the sink has so far
      stats_.number_of_faces = triangles_output_;
      stats_.number_of_vertices = vertices_output_;
      enter_phase(FRONT_SELECTION);
      store_phase_times();
      stats_.meshing_time += seconds_since(start);
      return rc;
    }
    if(rc != Advancing_front_mesh_2::MESH_COMPLETE) close_remaining_front();
    finish();
    enter_phase(FRONT_SELECTION);
    store_phase_times();
    stats_.meshing_time += seconds_since(start);
    return rc;
  }

  /*!
  Marks the domain from the seeds, removes the in-domain faces and builds
  the initial front from the constrained edges that bound the domain.
  Called by `refine_mesh()` and `step_by_step_refine_mesh()` when needed.
  */
  void init()
  {
    const auto start = std::chrono::steady_clock::now();
    clear_state();
    initialized_ = true;
    finished_ = false;
    if(cdt_.dimension() < 2) {
      finished_ = true;
      return;
    }
    CGAL::Delaunay_mesher_2<CDT, CGAL::Delaunay_mesh_criteria_2<CDT> >::mark_facets(
      cdt_, seeds_.begin(), seeds_.end(), seeds_mark_);
    exponent_ = choose_exponent();
    build_front();
    if(sink_ != nullptr && !finished_) {
      // the face that stands for faces gone to the sink: not in the domain,
      // so cavities stop at it as at the outside
      ghost_ = tds().create_face();
      ghost_->set_in_domain(false);
    }
    step_edges_.clear(); // only the edges of one step are of interest
    visitor_.on_init(*this);
    stats_.init_time += seconds_since(start);
  }

  /*!
  Processes one front edge. Returns `false` when the mesh is complete
  (then the triangulation is valid again). Between two calls the
  triangulation data structure is partial: only the faces behind the front
  exist, so it must not be used through the triangulation's own functions
  (locate, insert, is_valid) before this function has returned `false`.
  */
  bool step_by_step_refine_mesh()
  {
    if(!initialized_) init();
    if(finished_) return false;
    stop_now_ = false; // a stop after a checkpoint concerns refine_mesh() only
    try {
      if(step()) return true;
    } catch(const Advancing_front_mesh_2::Checkpoint_error&) {
      throw; // the state is the one before the checkpoint
    } catch(...) {
      close_remaining_front();
      finish();
      throw;
    }
    finish();
    return false;
  }

  /// Returns `true` when the front is empty and the mesh complete.
  bool is_refinement_done() const { return initialized_ && finished_; }

  /// @}

  /// \name Access
  /// @{

  const CDT& triangulation() const { return cdt_; }
  const Sizing_field& sizing_field() const { return sizing_; }
  const Visitor& visitor() const { return visitor_; }
  Visitor& visitor() { return visitor_; }
  const Advancing_front_mesh_2::Statistics& statistics() const { return stats_; }
  /// number of front edges now
  std::size_t front_size() const { return front_.size(); }

  /*!
  Checks the front invariants (for tests and debugging, O(front size)):
  every front vertex has as many incoming as outgoing front edges, every
  front edge is recorded at both end points, and every front edge's face on
  the meshed side really has that edge; and the records of the active
  vertices (which are renumbered when memory is released) agree: every id
  not free names a vertex that maps back to it, with its coordinates and a
  place in the point quadtree.
  */
  bool is_front_valid() const
  {
    std::vector<bool> is_free(vertex_.size(), false);
    for(Vid v : free_ids_) is_free[v] = true;
    for(Vid v : released_ids_) is_free[v] = true;
    std::size_t active = 0;
    for(Vid v = 0; v < vertex_.size(); ++v) {
      if(is_free[v]) continue;
      ++active;
      const Vid* id = vid_.find(&*vertex_[v]);
      if(id == nullptr || *id != v || !index_.contains(v)) return false;
      if(xy_[v][0] != ix(vertex_[v]->point()) || xy_[v][1] != iy(vertex_[v]->point()))
        return false;
    }
    if(active != vid_.size()) return false;
    std::size_t counted = 0;
    for(Vid v = 0; v < out_.size(); ++v) {
      if(out_[v].size() != in_[v].size()) return false;
      if(is_free[v] && !out_[v].empty()) return false;
      for(Vid w : out_[v]) {
        const Front_edge* it = front_.find(key(v, w));
        if(it == nullptr) return false;
        if(std::find(in_[w].begin(), in_[w].end(), v) == in_[w].end()) return false;
        const Front_edge& fe = *it;
        if(fe.behind != Face_handle() && fe.behind != ghost_) {
          const int i = fe.behind_index;
          if(fe.behind->vertex(cw(i)) != vertex_[v] || fe.behind->vertex(ccw(i)) != vertex_[w])
            return false;
          if(fe.behind->neighbor(i) != Face_handle()) return false;
        }
        ++counted;
      }
    }
    return counted == front_.size();
  }

  /// @}

private:
  // ------------------------------------------------------- phase timing
  enum Phase { FRONT_SELECTION, CLOSE_POINT_SEARCH, DELAUNAY_CLOSURE, PLACEMENT, CIRCLE_OCTREE,
               CAVITY, VISIBILITY, FRONT_UPDATE, OUTPUT };
  typedef std::chrono::steady_clock Clock;

  // Charges the time since the last phase change to the current phase and
  // makes `p` current; returns the phase it replaces.
  Phase enter_phase(Phase p) const
  {
    const Phase previous = phase_;
    if(phase_timing_) {
      const Clock::time_point now = Clock::now();
      phase_seconds_[previous] += std::chrono::duration<double>(now - phase_start_).count();
      phase_start_ = now;
    }
    phase_ = p;
    return previous;
  }

  // The phase of a scope; the enclosing phase resumes when it ends.
  class Phase_scope
  {
  public:
    Phase_scope(const Advancing_front_mesher_2* m, Phase p) : m_(m), previous_(m->enter_phase(p)) {}
    ~Phase_scope() { m_->enter_phase(previous_); }
    Phase_scope(const Phase_scope&) = delete;
    Phase_scope& operator=(const Phase_scope&) = delete;
  private:
    const Advancing_front_mesher_2* m_;
    Phase previous_;
  };

  void store_phase_times()
  {
    Advancing_front_mesh_2::Phase_times& t = stats_.phase_times;
    t.front_selection = phase_seconds_[FRONT_SELECTION];
    t.close_point_search = phase_seconds_[CLOSE_POINT_SEARCH];
    t.delaunay_closure = phase_seconds_[DELAUNAY_CLOSURE];
    t.placement = phase_seconds_[PLACEMENT];
    t.circle_octree = phase_seconds_[CIRCLE_OCTREE];
    t.cavity = phase_seconds_[CAVITY];
    t.visibility = phase_seconds_[VISIBILITY];
    t.front_update = phase_seconds_[FRONT_UPDATE];
    t.output = phase_seconds_[OUTPUT];
  }

  // ---------------------------------------------------------------- basics
  static int ccw(int i) { return (i + 1) % 3; }
  static int cw(int i) { return (i + 2) % 3; }
  static Edge_key key(Vid u, Vid v) { return (Edge_key(u) << 32) | Edge_key(v); }
  static Vid source(Edge_key k) { return Vid(k >> 32); }
  static Vid target(Edge_key k) { return Vid(k & 0xffffffffu); }

  // std::hypot without its cost where the plain formula cannot overflow or
  // underflow (hypot was 4% of the meshing time)
  static double length(double dx, double dy)
  {
    const double s = dx * dx + dy * dy;
    if(s > 1e-280 && s < 1e280) return std::sqrt(s);
    return std::hypot(dx, dy);
  }

  template <class T>
  static double seconds_since(const T& start)
  {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }

  Tds& tds() { return cdt_.tds(); }
  const Point& pt(Vid v) const { return vertex_[v]->point(); }
  // the stored coordinates xy_ are exact (the kernel's number type is double)
  static constexpr bool double_coordinates = std::is_same<FT, double>::value;
  double x(Vid v) const { return xy_[v][0]; }
  double y(Vid v) const { return xy_[v][1]; }

  // Internal coordinates and sizes are the user's divided by 2^exponent_,
  // chosen so that a domain near 1e+300 or 1e-300 is meshed near 1: squared
  // lengths and circle radii then neither overflow nor underflow, and the
  // mesh is the one the same domain gets at unit scale. A power of two
  // scales every double exactly, so the internal coordinates stay exact.
  double to_internal(const FT& v) const
  {
    const double d = CGAL::to_double(v);
    return exponent_ == 0 ? d : std::ldexp(d, -exponent_);
  }
  double ix(const Point& p) const { return to_internal(p.x()); }
  double iy(const Point& p) const { return to_internal(p.y()); }
  Point to_user_point(double px, double py) const
  {
    if(exponent_ == 0) return Point(px, py);
    return Point(std::ldexp(px, exponent_), std::ldexp(py, exponent_));
  }

  // The exponent for the input's largest coordinate magnitude m: 0 while
  // m lies within 2^(+-100) of 1, where nothing can overflow, and otherwise
  // the one that brings m to [1, 2), unless some input coordinate would not
  // survive the scaling exactly (a domain spanning 1e-300 to 1e+300).
  int choose_exponent() const
  {
    double m = 0;
    for(auto v = cdt_.finite_vertices_begin(); v != cdt_.finite_vertices_end(); ++v)
      m = (std::max)({m, std::abs(CGAL::to_double(v->point().x())), std::abs(CGAL::to_double(v->point().y()))});
    if(!(m > 0) || !std::isfinite(m) || (m < std::ldexp(1., 100) && m > std::ldexp(1., -100))) return 0;
    const int e = std::ilogb(m);
    for(auto v = cdt_.finite_vertices_begin(); v != cdt_.finite_vertices_end(); ++v)
      for(const double c : {CGAL::to_double(v->point().x()), CGAL::to_double(v->point().y())})
        if(std::ldexp(std::ldexp(c, -e), e) != c) return 0;
    return e;
  }

  void clear_state()
  {
    front_.clear();
    out_.clear();
    in_.clear();
    vertex_.clear();
    xy_.clear();
    vid_.clear();
    free_ids_.clear();
    released_ids_.clear();
    face_records_.clear();
    queue_ = std::priority_queue<Queue_entry>();
    step_level_ = 0;
    loops_changed_ = false;
    step_edges_.clear();
    walks_.clear();
    index_.clear();
    stats_ = Advancing_front_mesh_2::Statistics();
    phase_seconds_.fill(0);
    phase_start_ = Clock::now();
    meshed_area_ = 0;
    domain_area_ = 0;
    ghost_ = Face_handle();
    ghost_apex_.clear();
    live_faces_.clear();
    output_id_.clear();
    vertices_output_ = 0;
    triangles_output_ = 0;
    triangles_in_memory_ = 0;
    created_since_sweep_ = 0;
    sweep_after_ = minimum_sweep_;
  }

  // ------------------------------------------------------ vertex records
  // Only the active vertices have a record: an id, their coordinates, their
  // front edges and a place in the point quadtree. A vertex is active while
  // it has front edges, or while no triangle touches it (a free point, or
  // a vertex whose triangles were all removed by a cavity). Behind the front
  // a vertex needs nothing, so its record is released and its id reused:
  // the records and the lookup of ids by vertex hold O(front) memory
  // instead of O(mesh), which was 60 bytes per triangle at 1M triangles.
  //
  // No triangle count is needed to tell the two kinds of vertices without
  // front edges apart: a vertex that loses its last front edge to a new
  // triangle belongs to that triangle (behind the front), and one that
  // loses it to a removed triangle keeps no triangle at all (a removed
  // triangle's edges at a vertex either become front edges, when a
  // triangle lies beyond them, or vanish, when the vertex's fan was that
  // triangle alone).

  // The id of a vertex, which becomes active if it was not.
  Vid acquire(Vertex_handle vh)
  {
    if(const Vid* known = vid_.find(&*vh)) return *known;
    const std::array<double, 2> xy = {{ix(vh->point()), iy(vh->point())}};
    Vid id;
    if(!free_ids_.empty()) {
      id = free_ids_.back();
      free_ids_.pop_back();
      vertex_[id] = vh;
      xy_[id] = xy;
      CGAL_assertion(out_[id].empty() && in_[id].empty());
    } else {
      if(vertex_.size() >= std::size_t(no_vertex) - 1)
        throw std::length_error("Advancing_front_mesher_2: too many active vertices");
      id = static_cast<Vid>(vertex_.size());
      vertex_.push_back(vh);
      xy_.push_back(xy);
      out_.emplace_back();
      in_.emplace_back();
    }
    vid_.insert(&*vh, id);
    index_.insert(id, xy[0], xy[1]);
    stats_.largest_active_vertices = (std::max)(stats_.largest_active_vertices, vid_.size());
    return id;
  }

  // Releases the record of a vertex that now lies behind the front. Its id
  // is reused from the next step on, not before: ids gathered in this step
  // (the neighbourhood, the cavity) must keep naming the same vertex.
  void release(Vid v)
  {
    CGAL_precondition(out_[v].empty() && in_[v].empty());
    index_.remove(v);
    vid_.erase(&*vertex_[v]);
    released_ids_.push_back(v);
  }

  void recycle_released_ids()
  {
    free_ids_.insert(free_ids_.end(), released_ids_.begin(), released_ids_.end());
    released_ids_.clear();
  }

  // ------------------------------------------------------------- memory
  // The front rises and falls: with uniform sizes it grows to about 1% of
  // the mesh's edges and shrinks to nothing at the end, when the
  // triangulation is largest. Containers keep their capacity, so without
  // this the run's peak would be the triangulation plus the structures of
  // the largest front (4 bytes per triangle at 1M triangles). Each
  // structure is rebuilt at its current size once it uses less than a
  // quarter (hash tables: an eighth) of what it holds; the rebuilds cost
  // O(front) and come at geometrically spaced sizes.
  void release_unused_memory()
  {
    if(vertex_.size() >= 64 && 4 * vid_.size() < vertex_.size()) compact_vertex_ids();
    front_.shrink_if_sparse();
    face_records_.shrink_if_sparse();
    if(triangle_octree_.is_sparse())
      triangle_octree_.rebuild([this](Face_handle f, std::size_t item) {
        Face_record* r = face_records_.find(&*f);
        CGAL_assertion(r != nullptr);
        r->circle_item = item;
      });
  }

  // Renumbers the active vertices 0..n-1 (keeping their order, so that
  // nothing that depends on ids changes order) and rebuilds everything
  // indexed or keyed by vertex ids. Only between steps: ids gathered
  // during a step must keep naming the same vertex.
  void compact_vertex_ids()
  {
    CGAL_precondition(released_ids_.empty());
    std::vector<Vid> new_id(vertex_.size(), no_vertex);
    for(Vid v : free_ids_) new_id[v] = 0; // marks the free ids
    Vid n = 0;
    for(Vid v = 0; v < new_id.size(); ++v) new_id[v] = (new_id[v] == no_vertex) ? n++ : no_vertex;
    CGAL_assertion(n == vid_.size());

    std::vector<Vertex_handle> vertex(n);
    std::vector<std::array<double, 2> > xy(n);
    std::vector<Advancing_front_mesh_2::internal::Compact_id_list> out(n), in(n);
    for(Vid v = 0; v < new_id.size(); ++v) {
      const Vid w = new_id[v];
      if(w == no_vertex) continue;
      vertex[w] = vertex_[v];
      xy[w] = xy_[v];
      for(Vid t : out_[v]) out[w].push_back(new_id[t]);
      for(Vid s : in_[v]) in[w].push_back(new_id[s]);
    }
    vertex_.swap(vertex);
    xy_.swap(xy);
    out_.swap(out);
    in_.swap(in);
    std::vector<Vid>().swap(free_ids_);

    Advancing_front_mesh_2::internal::Flat_hash_map<const Tds_vertex*, Vid> vid(nullptr);
    vid.reserve(n);
    for(Vid w = 0; w < n; ++w) vid.insert(&*vertex_[w], w);
    vid_ = std::move(vid);

    Advancing_front_mesh_2::internal::Flat_hash_map<Edge_key, Front_edge> front(~Edge_key(0));
    front.reserve(front_.size());
    front_.for_each([&](Edge_key k, const Front_edge& fe) {
      front.insert(key(new_id[source(k)], new_id[target(k)]), fe);
    });
    front_ = std::move(front);

    index_.rebuild(new_id);
    compact_queue(); // the queue's keys name vertices too
    ++stats_.memory_compactions;
  }

  static Circle circle_of(double ax, double ay, double bx, double by, double cx, double cy)
  {
    // circumcircle relative to a, which keeps the rounding error small for
    // coordinates far from the origin
    // and in a frame scaled to unit size, so that the cubic terms neither
    // overflow nor underflow for very large or very small coordinates
    const double scale = (std::max)({std::abs(bx - ax), std::abs(by - ay), std::abs(cx - ax), std::abs(cy - ay)});
    if(!(scale > 0) || !std::isfinite(scale))
      return Circle{ax, ay, std::numeric_limits<double>::infinity()};
    const double bax = (bx - ax) / scale, bay = (by - ay) / scale, cax = (cx - ax) / scale, cay = (cy - ay) / scale;
    const double d = 2 * (bax * cay - bay * cax);
    const double b2 = bax * bax + bay * bay, c2 = cax * cax + cay * cay;
    const double ux = (cay * b2 - bay * c2) / d, uy = (bax * c2 - cax * b2) / d;
    return Circle{ax + ux * scale, ay + uy * scale, length(ux, uy) * scale};
  }

  Circle circle_of(Vid a, Vid b, Vid c) const
  {
    return circle_of(x(a), y(a), x(b), y(b), x(c), y(c));
  }

  // the face's vertices need not be active: their coordinates are read
  // through the face
  Circle circle_of(Face_handle f) const
  {
    auto X = [this, &f](int i) { return ix(f->vertex(i)->point()); };
    auto Y = [this, &f](int i) { return iy(f->vertex(i)->point()); };
    return circle_of(X(0), Y(0), X(1), Y(1), X(2), Y(2));
  }

  // (`phase`: where the time of the sizing field goes)
  double target_circumradius(double mx, double my, Phase phase_of_call = FRONT_SELECTION)
  {
    Phase_scope phase(this, phase_of_call);
    const Point m = to_user_point(mx, my);
    const FT h = sizing_(m);
    const double user_h = CGAL::to_double(h);
    if(!(user_h > 0) || !std::isfinite(user_h)) {
      std::ostringstream os;
      os.precision(17);
      os << "Advancing_front_mesher_2: the sizing field returned " << CGAL::to_double(h) << " at ("
         << CGAL::to_double(m.x()) << ", " << CGAL::to_double(m.y()) << "); sizes must be positive finite numbers";
      throw std::invalid_argument(os.str());
    }
    // a size far beyond the domain's scale may leave the doubles once
    // scaled: it bounds nothing, as 1e300 does not at unit scale
    const double hd = (std::max)((std::min)(to_internal(h), 1e300), (std::numeric_limits<double>::min)());
    return hd / std::sqrt(3.);
  }

  // ------------------------------------------------------------ the front
  // `apex`, when known, is the vertex of `behind` opposite the edge: it
  // spares the lookups of the face's vertex ids.
  void add_front_edge(Vid u, Vid v, Face_handle behind, int behind_index, bool constrained,
                      Vid apex = no_vertex)
  {
    CGAL_assertion(!front_.contains(key(u, v)));
    Front_edge fe;
    fe.behind = behind;
    fe.behind_index = behind_index;
    fe.constrained = constrained;
    fe.level = step_level_;
    fe.version = ++version_counter_;
    const double len = length(x(v) - x(u), y(v) - y(u));
    front_.insert(key(u, v), fe);
    nbh_.new_edges.push_back(key(u, v));
    step_edges_.push_back(key(u, v));
    out_[u].push_back(v);
    in_[v].push_back(u);
    if(!(len <= index_.reach(u))) index_.set_reach(u, len);
    if(behind != Face_handle() && behind->is_in_domain()) add_front_edge_to_face(behind, v, apex, u);
    queue_.push(Queue_entry{len, key(u, v), fe.version, fe.level});
    if(queue_.size() > 2 * front_.size() + 1024) compact_queue();
    stats_.largest_front = (std::max)(stats_.largest_front, front_.size());
  }

  // The queue keeps an entry of every front edge until it is popped, also
  // of those closed before their turn (it cannot erase): rebuilt from the
  // front when those are the majority, it holds O(front) entries instead of
  // 15 bytes per triangle of the mesh.
  void compact_queue()
  {
    std::vector<Queue_entry> live;
    live.reserve(front_.size());
    front_.for_each([this, &live](Edge_key k, const Front_edge& fe) {
      const Vid u = source(k), v = target(k);
      live.push_back(Queue_entry{length(x(v) - x(u), y(v) - y(u)), k, fe.version, fe.level});
    });
    queue_ = std::priority_queue<Queue_entry>(std::less<Queue_entry>(), std::move(live));
    ++queue_compactions_;
  }

  void remove_front_edge(Vid u, Vid v)
  {
    const Front_edge* it = front_.find(key(u, v));
    CGAL_assertion(it != nullptr);
    const Front_edge fe = *it;
    front_.erase(key(u, v));
    // beyond 8 removals still_on_front() probes the table: no need to list more
    if(nbh_.removed_edges.size() <= 8) nbh_.removed_edges.push_back(key(u, v));
    out_[u].erase_value(v);
    in_[v].erase_value(u);
    update_reach(u);
    if(fe.behind != Face_handle() && fe.behind->is_in_domain()) remove_front_edge_from_face(fe.behind);
  }

  // A front vertex's reach in the point quadtree is the length of its
  // longest outgoing front edge: a front edge meeting a disk of radius s
  // about q has its source within s + its length of q, so the vertices
  // found within s plus their reach lead, through their outgoing edges, to
  // every front edge near the disk (see gather()).
  void update_reach(Vid u)
  {
    double reach = 0;
    for(Vid w : out_[u]) {
      const double l = length(x(w) - x(u), y(w) - y(u));
      reach = std::isnan(l) ? l : (std::max)(reach, l);
      if(std::isnan(reach)) break;
    }
    index_.set_reach(u, reach);
  }

  // A face enters the circle octree with its first front edge and leaves
  // it with its last: the octree holds exactly the front triangles.
  void add_front_edge_to_face(Face_handle f, Vid a = no_vertex, Vid b = no_vertex, Vid c_ = no_vertex)
  {
    Face_record* it = face_records_.find(&*f);
    if(it != nullptr) {
      ++it->front_edges;
      return;
    }
    Phase_scope phase(this, CIRCLE_OCTREE);
    const Circle c = (a != no_vertex && b != no_vertex && c_ != no_vertex) ? circle_of(a, b, c_) : circle_of(f);
    face_records_.insert(&*f, Face_record{triangle_octree_.insert(c.cx, c.cy, c.r, f), 1});
    stats_.largest_live_triangles = (std::max)(stats_.largest_live_triangles, face_records_.size());
  }

  void remove_front_edge_from_face(Face_handle f)
  {
    Face_record* it = face_records_.find(&*f);
    CGAL_assertion(it != nullptr);
    if(--it->front_edges == 0) {
      Phase_scope phase(this, CIRCLE_OCTREE);
      triangle_octree_.remove(it->circle_item);
      face_records_.erase(&*f);
    }
  }

  void build_front()
  {
    std::vector<Face_handle> domain_faces;
    double xmin = (std::numeric_limits<double>::max)(), ymin = xmin;
    double xmax = -xmin, ymax = -xmin;
    for(auto f = cdt_.finite_faces_begin(); f != cdt_.finite_faces_end(); ++f) {
      if(!f->is_in_domain()) continue;
      domain_faces.push_back(f);
      for(int i = 0; i < 3; ++i) {
        const double vx = ix(f->vertex(i)->point()), vy = iy(f->vertex(i)->point());
        xmin = (std::min)(xmin, vx); xmax = (std::max)(xmax, vx);
        ymin = (std::min)(ymin, vy); ymax = (std::max)(ymax, vy);
      }
    }
    if(domain_faces.empty()) {
      finished_ = true;
      return;
    }
    // The octrees' root box: circles of triangles that will ever exist lie
    // near the domain; generous padding keeps the overflow list short.
    // Leaf sizes (32 circles, 16 points) measured best among 8 to 64 on the
    // benchmark's square: fewer, fuller leaves cost less to descend than
    // they add to the scans (2% fewer instructions than 16 and 8).
    const double span = (std::max)(xmax - xmin, ymax - ymin);
    triangle_octree_.reset(xmin - span, ymin - span, xmax + span, ymax + span, 2 * span, 32);
    index_.reset(xmin, ymin, xmax, ymax, 16);
    // every vertex of the domain starts active: on the front, or free
    for(Face_handle f : domain_faces)
      for(int i = 0; i < 3; ++i) acquire(f->vertex(i));

    struct Pending { Vid u, v; Face_handle behind; int index; bool constrained; };
    std::vector<Pending> pending;
    for(Face_handle f : domain_faces) {
      domain_area_ += std::abs(triangle_area(f));
      for(int i = 0; i < 3; ++i) {
        Face_handle g = f->neighbor(i);
        // edge i of f, directed with f (soon unmeshed) on its left
        const Vid u = acquire(f->vertex(ccw(i))), v = acquire(f->vertex(cw(i)));
        if(!g->is_in_domain()) {
          // the boundary of the domain: the mesh marking guarantees it is constrained
          CGAL_assertion(f->is_constrained(i));
          pending.push_back(Pending{u, v, g, g->index(f), true});
        } else if(f->is_constrained(i)) {
          // an interior constraint: both of its sides are front edges
          pending.push_back(Pending{u, v, Face_handle(), -1, true});
        }
      }
    }
    for(Face_handle f : domain_faces) {
      for(int i = 0; i < 3; ++i) {
        Face_handle g = f->neighbor(i);
        if(!g->is_in_domain()) g->set_neighbor(g->index(f), Face_handle());
      }
    }
    for(Face_handle f : domain_faces) tds().delete_face(f);
    // the input constraints never change: a static index of them answers
    // the visibility questions of the circle search
    constraint_octree_.reset(xmin - span, ymin - span, xmax + span, ymax + span, 2 * span);
    for(const Pending& p : pending) {
      if(p.u > p.v && p.behind == Face_handle()) continue; // interior constraint: once
      const double dx = x(p.v) - x(p.u), dy = y(p.v) - y(p.u);
      constraint_octree_.insert(0.5 * (x(p.u) + x(p.v)), 0.5 * (y(p.u) + y(p.v)),
                                0.5 * length(dx, dy), std::make_pair(vertex_[p.u], vertex_[p.v]));
    }
    constraint_octree_.shrink_to_fit();
    for(const Pending& p : pending) add_front_edge(p.u, p.v, p.behind, p.index, p.constrained);
    if(front_.empty()) finished_ = true;
  }

  double triangle_area(Face_handle f) const
  {
    const double ax = ix(f->vertex(0)->point()), ay = iy(f->vertex(0)->point());
    const double bx = ix(f->vertex(1)->point()), by = iy(f->vertex(1)->point());
    const double cx = ix(f->vertex(2)->point()), cy = iy(f->vertex(2)->point());
    return 0.5 * ((bx - ax) * (cy - ay) - (by - ay) * (cx - ax));
  }

  // ------------------------------------------------- creating and removing
  // Creates the triangle (a, b, c), counter-clockwise, in the unmeshed
  // region. Each of its edges either closes the front edge that faces it or
  // becomes a new front edge facing the other way. Appends new front edges
  // to `created` when given.
  Face_handle make_triangle(Vid a, Vid b, Vid c, std::vector<Edge_key>* created = nullptr)
  {
    CGAL_precondition(pred_.orientation(pt(a), pt(b), pt(c)) == LEFT_TURN);
    Phase_scope phase(this, FRONT_UPDATE);
    Face_handle f = tds().create_face(vertex_[a], vertex_[b], vertex_[c]);
    f->set_in_domain(true);
    ++triangles_in_memory_;
    stats_.largest_triangles_in_memory = (std::max)(stats_.largest_triangles_in_memory, triangles_in_memory_);
    if(sink_ != nullptr) {
      ++created_since_sweep_;
      for(Vid v : {a, b, c})
        if(std::uint32_t* n = live_faces_.find(&*vertex_[v])) ++*n;
    }
    const std::array<Vid, 3> vs = {{a, b, c}};
    // The triangle splits or joins loops of the front when it meets the
    // front in more than one piece: the pieces are its front edges, joined
    // through their end points, and the front vertices off those edges.
    std::array<bool, 3> on_front, consumed;
    for(int k = 0; k < 3; ++k) on_front[k] = !out_[vs[k]].empty() || !in_[vs[k]].empty();
    for(int k = 0; k < 3; ++k) {
      // edge k of f is opposite vertex k, directed vs[k+1] -> vs[k+2] with f on its left
      const Vid s = vs[ccw(k)], t = vs[cw(k)];
      const Front_edge* it = front_.find(key(s, t));
      consumed[k] = it != nullptr;
      if(it != nullptr) {
        const Front_edge fe = *it;
        f->set_constraint(k, fe.constrained);
        if(fe.behind != Face_handle()) {
          f->set_neighbor(k, fe.behind);
          if(fe.behind != ghost_) fe.behind->set_neighbor(fe.behind_index, f);
        } else {
          f->set_neighbor(k, Face_handle());
          // a virgin side of a constraint: the other side now faces f
          Front_edge* rev = front_.find(key(t, s));
          if(rev != nullptr) {
            rev->behind = f;
            rev->behind_index = k;
            add_front_edge_to_face(f);
          }
        }
        remove_front_edge(s, t);
      } else {
        f->set_constraint(k, false);
        f->set_neighbor(k, Face_handle());
        add_front_edge(t, s, f, k, false, vs[k]);
        if(created) created->push_back(key(t, s));
      }
    }
    const int edges_met = int(consumed[0]) + int(consumed[1]) + int(consumed[2]);
    int pieces = (edges_met > 0) ? 1 : 0;
    for(int k = 0; k < 3; ++k)
      // vertex k is off the met edges when the edges at it (k+1 and k+2) were not met
      if(on_front[k] && !consumed[ccw(k)] && !consumed[cw(k)]) ++pieces;
    if(pieces > 1) loops_changed_ = true;
    for(Vid v : vs) {
      vertex_[v]->set_face(f);
      // a vertex left without front edges now lies behind the front
      if(out_[v].empty() && in_[v].empty()) release(v);
    }
    meshed_area_ += std::abs(triangle_area(f));
    visitor_.on_face_created(f);
    return f;
  }

  // Removes a mesh face whose circle was broken. Its edges facing the
  // remaining mesh (or the outside) become front edges; the front edges it
  // had disappear into the unmeshed region, except constraints, which stay
  // front edges on both sides.
  void remove_triangle(Face_handle f, std::vector<Edge_key>* created)
  {
    Phase_scope phase(this, FRONT_UPDATE);
    visitor_.on_face_removed(f);
    std::array<Vid, 3> vs;
    for(int k = 0; k < 3; ++k) vs[k] = acquire(f->vertex(k));
    --triangles_in_memory_;
    if(sink_ != nullptr)
      for(int k = 0; k < 3; ++k)
        if(std::uint32_t* n = live_faces_.find(&*f->vertex(k))) --*n;
    for(int k = 0; k < 3; ++k) {
      const Vid s = vs[ccw(k)], t = vs[cw(k)];
      Face_handle g = f->neighbor(k);
      const bool constrained = f->is_constrained(k);
      if(g == Face_handle()) {
        // the unmeshed region is beyond: front edge t -> s has f behind it
        CGAL_assertion(front_.contains(key(t, s)));
        if(constrained) {
          Front_edge* rev = front_.find(key(t, s));
          rev->behind = Face_handle();
          rev->behind_index = -1;
          remove_front_edge_from_face(f);
          add_front_edge(s, t, Face_handle(), -1, true);
          if(created) created->push_back(key(s, t));
        } else {
          remove_front_edge(t, s);
        }
      } else if(sink_ != nullptr && g == ghost_) {
        // beyond lies the outside after a restart, or a finished triangle
        // (then the cavity is put back, see insert_point())
        add_front_edge(s, t, ghost_, -1, constrained);
        if(created) created->push_back(key(s, t));
      } else {
        const int j = g->index(f);
        g->set_neighbor(j, Face_handle());
        add_front_edge(s, t, g, j, constrained);
        if(created) created->push_back(key(s, t));
      }
    }
    meshed_area_ -= std::abs(triangle_area(f));
    tds().delete_face(f);
    // a vertex left without front edges has no triangle left either: it
    // stays active, as a free point
    ++stats_.triangles_removed;
  }

  // -------------------------------------------------- the neighbourhood
  void gather(double cx, double cy, double radius, Neighbourhood& n)
  {
    n.cx = cx;
    n.cy = cy;
    n.radius = radius;
    n.vertices.clear();
    n.vertex_xy.clear();
    n.edges.clear();
    n.new_edges.clear();
    n.removed_edges.clear();
    // One search finds the active vertices in the disk and, through the
    // vertices within their reach, the front edges whose diametral disk
    // meets it (they may pass through the disk with both end points far
    // away; the padding is the trees' own).
    Phase_scope phase(this, CLOSE_POINT_SEARCH);
    const double pad = 1e-12 * (std::abs(cx) + std::abs(cy));
    index_.query_with_reach(cx, cy, radius, [this, &n, cx, cy, radius, pad](std::size_t id, double px, double py,
                                                                           bool in_disk) {
      if(in_disk) {
        n.vertices.push_back(id);
        n.vertex_xy.push_back({{px, py}});
      }
      for(Vid h : out_[Vid(id)]) {
        const double hx = x(h), hy = y(h);
        const double dx = 0.5 * (px + hx) - cx, dy = 0.5 * (py + hy) - cy;
        const double reach = (0.5 * length(hx - px, hy - py) + radius) * (1 + 1e-9) + pad +
                             1e-12 * (std::abs(px) + std::abs(py) + std::abs(hx) + std::abs(hy));
        // written so that an edge whose test cannot be computed is kept
        if(!(dx * dx + dy * dy > reach * reach)) n.edges.push_back(Near_edge{key(Vid(id), h), px, py, hx, hy});
      }
    });
    ++stats_.point_search_queries;
    ++stats_.edge_octree_queries;
  }

  // Is k, a front edge of n.edges or n.new_edges, still on the front? It
  // is unless it was removed since n was gathered (and not created again);
  // the few removals since are scanned instead of probing the front's hash
  // table, whose probes miss the cache on large fronts.
  bool still_on_front(Edge_key k, const Neighbourhood& n) const
  {
    if(n.removed_edges.size() > 8) return front_.contains(k);
    for(Edge_key r : n.removed_edges)
      if(r == k) return front_.contains(k);
    return true;
  }

  // Is the direction from front vertex v towards q inside the unmeshed
  // region at v? The unmeshed sectors at v run counter-clockwise from each
  // outgoing front edge to the first incoming one. Directions strictly
  // inside a sector qualify, and so do the sector's own bounding front
  // edges when q is their other end point (vertex id qid): the segment is
  // then that front edge, which a triangle may close.
  bool in_free_sector(Vid v, const Point& q, Vid qid = no_vertex) const
  {
    if(out_[v].empty()) return in_[v].empty();
    const Point& pv = pt(v);
    for(Vid o : out_[v]) {
      Vid closing = no_vertex;
      for(Vid i : in_[v])
        if(closing == no_vertex || pred_.turns_before(pv, pt(o), pt(i), pt(closing))) closing = i;
      if(closing == no_vertex) continue;
      if(qid != no_vertex && (qid == o || qid == closing)) return true;
      if(pred_.turn_region(pv, pt(o), q) == 3) continue;
      if(pred_.turns_before(pv, pt(o), q, pt(closing))) return true;
    }
    return false;
  }

  // Is the segment u-v (vertex ids, or no_vertex for the new point) a
  // front edge, in either direction?
  bool is_front_segment(Vid u, Vid v) const
  {
    if(u == no_vertex || v == no_vertex) return false;
    for(Vid w : out_[u]) if(w == v) return true;
    for(Vid w : in_[u]) if(w == v) return true;
    return false;
  }

  // Does front edge (g, h) block the segment s-t (s, t given as vertex ids,
  // or no_vertex for the new point), which is not a front edge and leaves
  // its end points strictly inside free sectors (in_free_sector() passed)?
  // An edge sharing an end point with the segment could only block it by
  // running along it, and no front edge enters the inside of a free sector
  // (around a vertex, the front's edges alternate between leaving and
  // entering it, and a free sector runs from a leaving edge to the next
  // entering one): such an edge never blocks, without a predicate.
  bool edge_blocks(Vid g, Vid h, Vid s, const Point& ps, Vid t, const Point& pt_) const
  {
    const bool gs = (g == s), gt = (g == t), hs = (h == s), ht = (h == t);
    if(gs || hs || gt || ht) {
      CGAL_assertion(((gs && ht) || (gt && hs)) ||
                     !((gs || hs) ? pred_.overlap_from_shared_end(ps, pt(gs ? h : g), pt_)
                                  : pred_.overlap_from_shared_end(pt_, pt(gt ? h : g), ps)));
      return false;
    }
    return pred_.closed_segments_meet(ps, pt_, pt(g), pt(h));
  }

  // A segment's bounding box in doubles, padded by more than the rounding
  // of the coordinates: most front edges and vertices of a neighbourhood are
  // far from a segment, and this test skips their exact tests.
  struct Segment_box
  {
    // doubles are exact; CGAL promises to_double of other number types (a
    // lazy exact number) only to a relative precision of 1e-5
    static constexpr double relative_pad = double_coordinates ? 1e-14 : 1e-5;
    double x0, y0, x1, y1;
    double magnitude; // of the end points' coordinates

    // the end points' internal coordinates
    Segment_box(double sx, double sy, double tx, double ty)
    {
      magnitude = (std::max)({std::abs(sx), std::abs(sy), std::abs(tx), std::abs(ty)});
      const double pad = relative_pad * magnitude;
      x0 = (std::min)(sx, tx) - pad; x1 = (std::max)(sx, tx) + pad;
      y0 = (std::min)(sy, ty) - pad; y1 = (std::max)(sy, ty) + pad;
    }

    // the box of the segment (or point) g-h does not meet this one
    bool apart(double gx, double gy, double hx, double hy) const
    {
      const double gpad = relative_pad * (std::max)({std::abs(gx), std::abs(gy), std::abs(hx), std::abs(hy)});
      return (std::max)(gx, hx) + gpad < x0 || (std::min)(gx, hx) - gpad > x1 ||
             (std::max)(gy, hy) + gpad < y0 || (std::min)(gy, hy) - gpad > y1;
    }
  };

  // The union of two segment boxes with a fixed pad, a cheaper first test
  // for the many far edges: whatever is apart from it is apart from both
  // boxes. (The pad of Segment_box::apart() grows with the tested edge's
  // magnitude G; for G <= 2 M, M the boxes' magnitude, it is at most the
  // 2 relative_pad M added here, and for larger G the edge lies more than
  // G - M >= G / 2 away from the boxes in some coordinate, beyond both
  // pads.)
  struct Union_box
  {
    double x0, y0, x1, y1;

    Union_box(const Segment_box& b1, const Segment_box& b2)
    {
      const double pad = 2 * Segment_box::relative_pad * (std::max)(b1.magnitude, b2.magnitude);
      x0 = (std::min)(b1.x0, b2.x0) - pad; x1 = (std::max)(b1.x1, b2.x1) + pad;
      y0 = (std::min)(b1.y0, b2.y0) - pad; y1 = (std::max)(b1.y1, b2.y1) + pad;
    }

    bool apart(double gx, double gy, double hx, double hy) const
    {
      return (std::max)(gx, hx) < x0 || (std::min)(gx, hx) > x1 ||
             (std::max)(gy, hy) < y0 || (std::min)(gy, hy) > y1;
    }
  };

  // Are the open segments s1-t and s2-t inside the unmeshed region: leaving
  // their end points into free sectors, crossing no front edge and passing
  // through no vertex? (s1, s2, t are vertex ids, or no_vertex for the new
  // point.) Complete when the segments lie in the neighbourhood's disk. Both
  // segments are tested in one pass over the neighbourhood: the callers
  // always need both (an apex seen from a and b, a new point seen from a and
  // b).
  bool visible_from_both(Vid s1, const Point& ps1, Vid s2, const Point& ps2, Vid t, const Point& pt_,
                         const Neighbourhood& n, bool sectors_tested = false) const
  {
    Phase_scope phase(this, VISIBILITY);
    if(!sectors_tested) {
      if(s1 != no_vertex && !in_free_sector(s1, pt_, t)) return false;
      if(t != no_vertex && !in_free_sector(t, ps1, s1)) return false;
      if(s2 != no_vertex && !in_free_sector(s2, pt_, t)) return false;
      if(t != no_vertex && !in_free_sector(t, ps2, s2)) return false;
    }
    // A segment that is a front edge itself (the apex is the next vertex
    // along the front, the most common closure) crosses no front edge and
    // holds no vertex, the front being a planar straight-line graph: only
    // its end points' sectors, tested above, matter.
    const bool open1 = !is_front_segment(s1, t), open2 = !is_front_segment(s2, t);
    if(!open1 && !open2) return true;
    const double tx = ix(pt_), ty = iy(pt_);
    const Segment_box box1(ix(ps1), iy(ps1), tx, ty), box2(ix(ps2), iy(ps2), tx, ty);
    const Union_box both(box1, box2);
    // every front edge that can block: those near the disk when it was
    // gathered, and those created since
    auto blocks = [&](Vid g, Vid h, double gx, double gy, double hx, double hy, Edge_key k) {
      if(both.apart(gx, gy, hx, hy)) return false;
      const bool near1 = open1 && !box1.apart(gx, gy, hx, hy), near2 = open2 && !box2.apart(gx, gy, hx, hy);
      if(!(near1 || near2) || !still_on_front(k, n)) return false;
      return (near1 && edge_blocks(g, h, s1, ps1, t, pt_)) || (near2 && edge_blocks(g, h, s2, ps2, t, pt_));
    };
    for(const Near_edge& e : n.edges)
      if(blocks(source(e.key), target(e.key), e.x0, e.y0, e.x1, e.y1, e.key)) return false;
    for(Edge_key k : n.new_edges) {
      const Vid g = source(k), h = target(k);
      if(blocks(g, h, x(g), y(g), x(h), y(h), k)) return false;
    }
    for(std::size_t i = 0; i < n.vertices.size(); ++i) {
      const std::size_t z = n.vertices[i];
      if(z == t) continue;
      const double zx = n.vertex_xy[i][0], zy = n.vertex_xy[i][1];
      if(both.apart(zx, zy, zx, zy)) continue;
      if(open1 && z != s1 && !box1.apart(zx, zy, zx, zy) && pred_.in_open_segment(ps1, pt_, pt(Vid(z))))
        return false;
      if(open2 && z != s2 && !box2.apart(zx, zy, zx, zy) && pred_.in_open_segment(ps2, pt_, pt(Vid(z))))
        return false;
    }
    return true;
  }

  // Step 5, Merriam's iteration: the Delaunay apex of front edge a -> b
  // among the neighbourhood's vertices visible from both end points, i.e.
  // the candidate whose circle through a and b contains no other candidate.
  //
  // When the caller has no use for an apex whose circle's centre lies at
  // `max_centre_height` or more above the edge (such a triangle is too
  // large to be built, and the new point would lie inside its circle), the
  // candidates surely beyond that height are dropped before their costly
  // tests; since they lie outside the circles of all lower candidates, the
  // answer among the others is unchanged, and no_vertex means "no apex
  // below".
  Vid delaunay_apex(Vid a, Vid b, const Neighbourhood& n,
                    double max_centre_height = std::numeric_limits<double>::infinity())
  {
    Phase_scope phase(this, DELAUNAY_CLOSURE);
    const Point& pa = pt(a);
    const Point& pb = pt(b);
    // Candidates are taken in the order of their circles' approximate
    // centre heights over the edge: the Delaunay apex is then nearly always
    // the first candidate that qualifies, so the costly free-sector tests run
    // for few candidates. The exact in-circle iteration decides; the order
    // only saves work.
    const double mx = 0.5 * (x(a) + x(b)), my = 0.5 * (y(a) + y(b));
    const double tx = x(b) - x(a), ty = y(b) - y(a);
    const double quarter_l2 = 0.25 * (tx * tx + ty * ty);
    // heights below are centre heights in units of half the edge length
    const double half_length = std::sqrt(quarter_l2);
    // With other number types than double, the stored coordinates are only
    // approximations (to_double of a lazy number may be off by 1e-5), so no
    // candidate is dropped on their account.
    const double cutoff = double_coordinates ? max_centre_height / half_length
                                             : std::numeric_limits<double>::infinity();
    candidates_.clear();
    dropped_.clear();
    // Error bounds of the double computation below (a few units in the last
    // place of every term, generously): each candidate's true height lies in
    // [low, high]. A candidate is dropped only if its low bound is above the
    // cut-off; if a kept one may lie above it (its high bound is), the
    // dropped ones it might not exclude are taken back, so the answer among
    // the kept candidates is the answer among all.
    const double eps = 1e-15;
    const double e_t = eps * (std::abs(x(a)) + std::abs(y(a)) + std::abs(x(b)) + std::abs(y(b)));
    double straddle = -std::numeric_limits<double>::infinity();
    for(std::size_t z : n.vertices) {
      const Vid c = Vid(z);
      if(c == a || c == b) continue;
      // Points in line with an axis-parallel edge (boundary points on the
      // sides of a box) are exactly collinear, where the filtered predicate
      // falls back to exact arithmetic: with double coordinates, equal
      // coordinates decide it at once.
      if(double_coordinates && ((y(a) == y(b) && y(c) == y(a)) || (x(a) == x(b) && x(c) == x(a)))) continue;
      if(pred_.orientation(pa, pb, pt(c)) != LEFT_TURN) continue;
      // with half the edge's length as unit: the circle through a, b and c
      // has its centre at height num / v over the midpoint
      const double dx = x(c) - mx, dy = y(c) - my;
      const double u = dx * tx + dy * ty, v = dy * tx - dx * ty;
      const double along2 = u * u / (4 * quarter_l2), across2 = v * v / (4 * quarter_l2);
      const double num = along2 + across2 - quarter_l2;
      const double e_d = eps * (std::abs(x(c)) + std::abs(y(c)) + std::abs(mx) + std::abs(my));
      const double e_uv = e_d * (std::abs(tx) + std::abs(ty)) + e_t * (std::abs(dx) + std::abs(dy)) +
                          eps * (std::abs(dx * tx) + std::abs(dy * ty) + std::abs(dy * tx) + std::abs(dx * ty));
      const double e_num = (2 * (std::abs(u) + std::abs(v)) * e_uv + e_uv * e_uv) / (4 * quarter_l2) +
                           eps * (along2 + across2 + quarter_l2) + 4 * eps * quarter_l2;
      const double height = v > 0 ? num / v : 0;
      const double low = (v + e_uv > 0 && num - e_num > 0) ? (num - e_num) / (v + e_uv)
                                                          : -std::numeric_limits<double>::infinity();
      const double high = (v - e_uv > 0) ? (num + e_num) / (v - e_uv) : std::numeric_limits<double>::infinity();
      const Candidate cand{std::isfinite(height) ? height : 0., c, UNTESTED, low};
      if(low > cutoff && std::isfinite(low)) {
        dropped_.push_back(cand);
      } else {
        candidates_.push_back(cand);
        if(!(high <= cutoff)) straddle = (std::max)(straddle, std::isnan(high) ? std::numeric_limits<double>::infinity() : high);
      }
    }
    if(straddle > cutoff)
      for(const Candidate& d : dropped_)
        if(!(d.low > straddle)) candidates_.push_back(d);
    std::sort(candidates_.begin(), candidates_.end(),
              [](const Candidate& p, const Candidate& q) { return p.height < q.height; });
    auto qualifies = [&](Candidate& cand) {
      if(cand.state == UNTESTED) {
        const Vid c = cand.vertex;
        const Point& pc = pt(c);
        const bool ok = in_free_sector(a, pc, c) && in_free_sector(b, pc, c) && in_free_sector(c, pa, a) &&
                        in_free_sector(c, pb, b);
        cand.state = ok ? QUALIFIES : REJECTED;
      }
      return cand.state == QUALIFIES;
    };
    for(;;) {
      // Merriam's iteration over the qualifying candidates: the one whose
      // circle through a and b holds no other
      std::size_t best = candidates_.size();
      for(std::size_t i = 0; i < candidates_.size(); ++i) {
        Candidate& cand = candidates_[i];
        if(cand.state == REJECTED) continue;
        if(best == candidates_.size()) {
          if(qualifies(cand)) best = i;
          continue;
        }
        ++stats_.incircle_tests;
        if(pred_.strictly_inside_circle(pa, pb, pt(candidates_[best].vertex), pt(cand.vertex)) && qualifies(cand))
          best = i;
      }
      if(best == candidates_.size()) return no_vertex;
      const Vid c = candidates_[best].vertex;
      // the winner qualified: its four free-sector tests are done
      if(visible_from_both(a, pa, b, pb, c, pt(c), n, true)) return c;
      candidates_[best].state = REJECTED;
    }
  }

  // ------------------------------------------------------------ pockets
  // With a uniform size, the lengths of the front edges differ by rounding
  // only, and shortest-first grows the mesh like a crystal: patches advance
  // as spikes that close around pockets of unmeshed region, whose slightly
  // longer edges wait. Left alone, the pockets pile up behind the advancing
  // spikes and the front grows in proportion to the mesh (40k edges at 1M
  // triangles), not to its perimeter. After a step that split or joined
  // loops of the front (see make_triangle()), the loops through the edges
  // it created are walked in step, at most `pocket_walk_limit` edges each;
  // those that close within the limit are taken for pockets (also a loop
  // just joined from two small ones, or the whole front near the end: the
  // order within them is unchanged). Their edges, and the
  // edges created while processing them, go one level up in the queue:
  // before all edges of lower levels, so that a pocket is meshed soon after
  // it forms (and a pocket within it sooner still). Only the order changes:
  // every edge is still processed by the same rules.
  static constexpr std::size_t pocket_walk_limit = 1024;

  void mark_pockets()
  {
    walks_.clear();
    auto start_walk = [this](Edge_key k) {
      for(const Pocket_walk& w : walks_)
        if(w.start == k) return;
      walks_.push_back(Pocket_walk{k, target(k), 1, 0});
    };
    for(Edge_key k : step_edges_) {
      if(!front_.contains(k)) continue;
      start_walk(k);
      // A walk stops at a vertex where loops meet, so the loop that leaves
      // such a vertex is walked from there: after a closure of a -> b on a
      // vertex c of its own loop, the loop through the new edge a -> c is
      // walked from c's older edge, and closes back at c.
      const Vid v = target(k);
      if(out_[v].size() > 1)
        for(Vid w : out_[v]) start_walk(key(v, w));
    }
    std::size_t walking = walks_.size();
    while(walking > 0) {
      for(Pocket_walk& w : walks_) {
        if(w.state != 0) continue;
        if(w.at == source(w.start)) w.state = 1;
        // a vertex where loops meet: its successor depends on the geometry;
        // the walk gives up and the loop counts as open
        else if(out_[w.at].size() != 1 || w.length >= pocket_walk_limit) w.state = 2;
        else {
          // a walk that starts here is on this walk's loop: it can stop
          for(Pocket_walk& o : walks_)
            if(o.state == 0 && source(o.start) == w.at) {
              o.state = 3;
              --walking;
            }
          w.at = out_[w.at].begin()[0];
          ++w.length;
          continue;
        }
        --walking;
      }
    }
    // Every loop that closed is promoted, also when no walk found a larger
    // one (a loop just joined, a small front at the end): requiring a larger
    // loop beside it measured a little worse on the benchmark's square (share
    // of radius ratios above 0.9), for the same front size.
    const std::uint16_t level = (step_level_ < (std::numeric_limits<std::uint16_t>::max)()) ? step_level_ + 1 : step_level_;
    for(const Pocket_walk& walk : walks_) {
      if(walk.state != 1) continue;
      Front_edge* first = front_.find(walk.start);
      if(first->level >= level) continue; // the loop of an earlier walk
      ++stats_.pockets;
      Vid u = source(walk.start), w = target(walk.start);
      do {
        Front_edge* fe = front_.find(key(u, w));
        CGAL_assertion(fe != nullptr);
        fe->level = level;
        // a new version makes the edge's old queue entry stale
        fe->version = ++version_counter_;
        queue_.push(Queue_entry{length(x(w) - x(u), y(w) - y(u)), key(u, w), fe->version, level});
        u = w;
        w = out_[u].begin()[0];
      } while(u != source(walk.start));
    }
  }

  // ------------------------------------------------------------- one step
  bool step()
  {
    recycle_released_ids();
    release_unused_memory();
    if(sink_ != nullptr && created_since_sweep_ >= sweep_after_) {
      sweep_finished_faces(false);
      // right after a sweep the state is smallest
      if(checkpoint_every_ != 0 && triangles_output_ >= next_checkpoint_) {
        write_checkpoint(checkpoint_file_, checkpoint_user_data_);
        next_checkpoint_ = triangles_output_ + checkpoint_every_;
        if(checkpoint_stop_) {
          // before the next edge: the state in memory is the checkpoint's
          stop_now_ = true;
          return true;
        }
      }
    }
    while(!queue_.empty()) {
      const Queue_entry e = queue_.top();
      queue_.pop();
      const Front_edge* it = front_.find(e.key);
      if(it == nullptr || it->version != e.version) continue;
      ++stats_.front_edges_processed;
      const std::size_t compactions = queue_compactions_;
      // what an edge of a pocket creates lies in the pocket
      step_level_ = it->level;
      step_edges_.clear();
      loops_changed_ = false;
      {
        Phase_scope phase(this, PLACEMENT);
        process_edge(source(e.key), target(e.key));
      }
      if(loops_changed_ && pocket_priority_) mark_pockets();
      step_level_ = 0;
      // A new point may leave the edge open (its apex after the cavity was
      // another point): the edge stays on the front and must be queued
      // again, unless a compaction of the queue, a new version (the edge
      // was removed and created again, or found on a pocket) already did so.
      const Front_edge* left = front_.find(e.key);
      if(left != nullptr && compactions == queue_compactions_ && left->version == e.version)
        queue_.push(Queue_entry{e.length, e.key, left->version, left->level});
      visitor_.on_progress(domain_area_ > 0 ? (std::min)(1., meshed_area_ / domain_area_) : 1.);
      return true;
    }
    return false;
  }

  void process_edge(Vid a, Vid b)
  {
    const double ax = x(a), ay = y(a), bx = x(b), by = y(b);
    const double L = length(bx - ax, by - ay);
    const double mx = 0.5 * (ax + bx), my = 0.5 * (ay + by);
    const double nx = -(by - ay) / L, ny = (bx - ax) / L; // unit normal towards the unmeshed side
    const double rho = target_circumradius(mx, my);       // step 3
    const double accept = closure_tolerance * rho;

    // step 6's ideal distance from the midpoint along the bisector: the
    // point making a triangle of circumradius rho, or the diametral circle
    // when rho is smaller than half the edge
    const double d_target = (rho >= 0.5 * L) ? rho + std::sqrt(rho * rho - 0.25 * L * L) : 0.5 * L;
    // The search covers every circle through a and b that matters: those
    // small enough to accept, and those whose centre lies before d_target
    // (which limit the new point's position, Fig. 7).
    const double radius = (std::max)(2 * accept, d_target + std::sqrt(d_target * d_target + 0.25 * L * L));
    // The gathered disk is made large enough to also hold, in most steps,
    // the disk of the new point's star (see insert_point), which then needs
    // no search of its own: the new point lies at most d_target from m, and
    // its star reaches 2 * 1.25 * max(rho, r) from it, where the circle
    // through a, b and the point has a radius r of at most 0.57 L (at the
    // placement floor) or rho.
    const double star_reach = d_target + 2 * closure_tolerance * (std::max)(rho, 0.57 * L);
    gather(mx, my, (std::max)(radius, star_reach) * (1 + 1e-6), nbh_); // step 4
    // an apex whose circle's centre lies at d_target or higher can neither
    // be accepted (its radius exceeds 1.41 rho) nor limit the new point
    const Vid w = delaunay_apex(a, b, nbh_, d_target);            // step 5
    double d = d_target;
    if(w != no_vertex) {
      const Circle c = circle_of(a, b, w);
      const double centre_offset = length(c.cx - mx, c.cy - my);
      const bool complete = centre_offset + c.r <= radius;
      if(complete && c.r <= accept) {                             // step 6: close
        close_on_existing_point(a, b, w);
        return;
      }
      const double h_w = (c.cx - mx) * nx + (c.cy - my) * ny;     // signed height of its centre
      if(h_w < d_target) {
        if(!(h_w >= placement_floor * L)) {
          // No room for a point between the edge and the circle: close. On
          // w only if its circle lies in the searched disk (then no front
          // point outside can be in it); otherwise the closure searches on.
          ++stats_.forced_closures;
          if(complete) close_on_existing_point(a, b, w);
          else forced_closure(a, b, radius);
          return;
        }
        d = h_w;                                                  // upper clamp (Fig. 7)
      }
    }
    const double px = mx + d * nx, py = my + d * ny;
    if(insert_point(a, b, px, py, d, rho, w)) return;
    ++stats_.rejected_points;
    ++stats_.forced_closures;
    forced_closure(a, b, radius);
  }

  void close_on_existing_point(Vid a, Vid b, Vid c)
  {
    ++stats_.triangles_closed_on_existing_points;
    make_triangle(a, b, c);
  }

  // Closes a -> b on its constrained Delaunay apex whatever its size. The
  // unmeshed region is a polygonal region bounded by the front, so the apex
  // exists; the search grows until the apex's circle lies in the searched
  // disk, which makes it the true apex.
  void forced_closure(Vid a, Vid b, double radius)
  {
    const double mx = 0.5 * (x(a) + x(b)), my = 0.5 * (y(a) + y(b));
    const double L = length(x(b) - x(a), y(b) - y(a));
    double r = (std::max)(radius, L);
    for(;;) {
      gather(mx, my, r, nbh_);
      // the search is exhaustive once it holds every active vertex (or its
      // radius stopped being a number): the loop ends on that, not on a count
      const bool everything = nbh_.vertices.size() >= index_.size() || !std::isfinite(r);
      const Vid w = delaunay_apex(a, b, nbh_);
      if(w != no_vertex) {
        const Circle c = circle_of(a, b, w);
        const double needed = length(c.cx - mx, c.cy - my) + c.r;
        if(needed <= r || everything) {
          close_on_existing_point(a, b, w);
          return;
        }
        r = (std::max)(2 * r, needed * (1 + 1e-9));
      } else {
        if(everything) {
          throw std::logic_error("Advancing_front_mesher_2: internal error: a front edge has no "
                                 "visible apex (the front is inconsistent)");
        }
        r *= 2;
      }
    }
  }

  // The circle of face f contains p and p can see f, as constrained
  // Delaunay insertion requires: p is inside f, or the segment from p to a
  // point of f (its centroid, or the midpoint of one of its front edges)
  // crosses no input constraint. Non-constraint front edges do not hide
  // anything: they are not edges of the final triangulation's constraints.
  // Faces reached only through the mesh are found by the neighbour walk
  // (Fig. 6). Without this test, a triangle whose circle reaches across a
  // thin wall (a plate, a hole) would be removed for a point that cannot
  // see it, opening a cavity that point cannot fill.
  bool is_broken(Face_handle f, const Point& p, double px, double py)
  {
    ++stats_.incircle_tests;
    if(!pred_.strictly_inside_circle(f->vertex(0)->point(), f->vertex(1)->point(),
                                     f->vertex(2)->point(), p))
      return false;
    // f's vertices need not be active: coordinates are read through f
    auto X = [this, &f](int i) { return ix(f->vertex(i)->point()); };
    auto Y = [this, &f](int i) { return iy(f->vertex(i)->point()); };
    bool inside = true;
    for(int i = 0; i < 3; ++i)
      if(pred_.orientation(f->vertex(ccw(i))->point(), f->vertex(cw(i))->point(), p) == RIGHT_TURN)
        inside = false;
    if(inside) return true;
    if(sees_point(p, px, py, (X(0) + X(1) + X(2)) / 3, (Y(0) + Y(1) + Y(2)) / 3)) return true;
    for(int i = 0; i < 3; ++i) {
      if(f->neighbor(i) != Face_handle()) continue;
      const int g = ccw(i), h = cw(i);
      if(sees_point(p, px, py, 0.5 * (X(g) + X(h)), 0.5 * (Y(g) + Y(h)))) return true;
    }
    return false;
  }

  // Does the segment from p to (qx, qy) cross no input constraint? The end
  // point is rounded; this only selects which triangles are removed.
  bool sees_point(const Point& p, double px, double py, double qx, double qy)
  {
    Phase_scope phase(this, VISIBILITY);
    const Point q = to_user_point(qx, qy);
    bool blocked = false;
    ++stats_.edge_octree_queries;
    constraint_octree_.query(0.5 * (px + qx), 0.5 * (py + qy), 0.5 * length(qx - px, qy - py),
                             [&](const Constraint& c) {
      if(blocked) return;
      const Point& pu = c.first->point();
      const Point& pv = c.second->point();
      // a proper crossing only: touching an end point does not hide
      const Orientation o1 = pred_.orientation(p, q, pu), o2 = pred_.orientation(p, q, pv);
      if(o1 == COLLINEAR || o2 == COLLINEAR || o1 == o2) return;
      const Orientation o3 = pred_.orientation(pu, pv, p), o4 = pred_.orientation(pu, pv, q);
      if(o3 == COLLINEAR || o4 == COLLINEAR || o3 == o4) return;
      blocked = true;
    });
    return !blocked;
  }

  // Steps 6-12 for a new point p = (px, py) ahead of front edge a -> b.
  // Returns false (leaving the mesh unchanged) when p is not acceptable.
  bool insert_point(Vid a, Vid b, double px, double py, double d, double rho, Vid apex_before)
  {
    if(!std::isfinite(px) || !std::isfinite(py)) return false;
    const Point p = to_user_point(px, py);
    // the point as stored (scaling back may round, where a tiny domain's
    // points come near the subnormal numbers)
    px = ix(p);
    py = iy(p);
    if(pred_.orientation(pt(a), pt(b), p) != LEFT_TURN) return false;
    Phase_scope cavity_phase(this, CAVITY);

    // steps 7-8: broken front triangles from the circle octree, interior
    // ones by walking across unconstrained edges
    broken_.clear();
    broken_set_.clear();
    ++stats_.triangle_octree_queries;
    {
      Phase_scope phase(this, CIRCLE_OCTREE);
      triangle_octree_.query(px, py, 0., [this, &p, px, py](Face_handle f) {
        Phase_scope cavity(this, CAVITY);
        if(broken_set_.find(f) == broken_set_.end() && is_broken(f, p, px, py)) {
          broken_set_.insert(f);
          broken_.push_back(f);
        }
      });
    }
    // finished triangles (gone to the sink) next to the cavity, and those p breaks
    bool reaches_finished = false;
    std::size_t finished_broken = 0;
    for(std::size_t i = 0; i < broken_.size(); ++i) {
      Face_handle f = broken_[i];
      for(int k = 0; k < 3; ++k) {
        Face_handle g = f->neighbor(k);
        if(sink_ != nullptr && g == ghost_) {
          if(is_finished_face_beyond(f, k, p, finished_broken)) reaches_finished = true;
          continue;
        }
        if(f->is_constrained(k)) continue;
        if(g == Face_handle() || !g->is_in_domain() || broken_set_.count(g)) continue;
        ++stats_.incircle_tests;
        if(pred_.strictly_inside_circle(g->vertex(0)->point(), g->vertex(1)->point(),
                                        g->vertex(2)->point(), p)) {
          broken_set_.insert(g);
          broken_.push_back(g);
        }
      }
    }
    // step 10: the size bound grows to the largest broken circle
    const Circle cp = circle_of(x(a), y(a), x(b), y(b), px, py);
    double rho_new = (std::max)(rho, cp.r);
    for(Face_handle f : broken_) rho_new = (std::max)(rho_new, circle_of(f).r);
    if(rho_new > (std::max)(rho, cp.r)) ++stats_.size_bound_raised;

    // step 9: remove them, remembering them to restore them if p is rejected
    removed_.clear();
    cavity_edges_.clear();
    for(Face_handle f : broken_) {
      removed_.push_back({{acquire(f->vertex(0)), acquire(f->vertex(1)), acquire(f->vertex(2))}});
      remove_triangle(f, &cavity_edges_);
    }

    // Triangles about p are accepted up to the local bound, and up to the
    // raised bound of step 10 when they are not needles: a large cavity is
    // reconnected to p as the paper does (which is what lets fronts of very
    // different sizes merge, Fig. 9), but a cavity vertex nearly in line
    // with p and a short cavity edge is left to later steps instead of
    // making a sliver. Every accepted circle passes through p with radius
    // at most `accept_raised`, so the disk of twice that about p holds
    // every point that matters.
    const double accept = closure_tolerance * (std::max)(rho, cp.r);
    const double accept_raised = closure_tolerance * rho_new;
    const double star_radius = (std::max)({2 * accept_raised, length(px - x(a), py - y(a)),
                                           length(px - x(b), py - y(b))}) * (1 + 1e-9);
    // Without a cavity the front is as it was when the edge's neighbourhood
    // was gathered; if that disk holds the star's disk it serves as it is.
    const bool no_cavity = broken_.empty();
    if(!no_cavity || length(px - nbh_.cx, py - nbh_.cy) + star_radius > nbh_.radius)
      gather(px, py, star_radius, nbh_);
    // A point the run without streaming rejects is rejected here too, for
    // the same reasons, before reaching a finished triangle is held against
    // it.
    const bool acceptable = is_acceptable_point(a, b, p, px, py, d);
    if(!acceptable || reaches_finished) {
      for(const std::array<Vid, 3>& t : removed_) make_triangle(t[0], t[1], t[2]);
      stats_.triangles_removed -= removed_.size();
      if(acceptable) {
        // The cavity would break a triangle already given to the sink, or
        // leave its edge on the front, where the run without streaming
        // would put its circle back in the octree for later points to
        // break: the sink could follow neither. The point is refused, and
        // the edge is closed on an existing point instead, as for any
        // refused point. The mesh stays a constrained Delaunay
        // triangulation; it differs from the run without streaming here,
        // which the statistics count.
        ++stats_.points_refused_for_finished_triangles;
        stats_.finished_triangles_broken += finished_broken;
      }
      return false;
    }

    // p is inside the unmeshed region: insert it
    Vertex_handle vh = tds().create_vertex();
    vh->set_point(p);
    const Vid pid = acquire(vh);
    // the vertices the mesher creates are removed once their last triangle
    // has gone to the sink; the input's stay (constraints refer to them)
    if(sink_ != nullptr) live_faces_.insert(&*vh, 0);
    ++stats_.points_inserted;
    visitor_.on_point_inserted(vh);

    // steps 11-12: the Delaunay triangles about p within the size bound,
    // found by closing, with Merriam's iteration, the front edges that can
    // reach p: the current edge, the cavity's boundary, and then each front
    // edge at p in turn, which turns the fan about p in both directions.
    // Since the neighbourhood was gathered only p has been added.
    nbh_.vertices.push_back(pid);
    nbh_.vertex_xy.push_back({{px, py}});
    work_.clear();
    std::vector<Edge_key>& created = created_;
    created.clear();
    if(no_cavity &&
       (apex_before == no_vertex || pred_.strictly_inside_circle(pt(a), pt(b), pt(apex_before), p))) {
      // The apex of a -> b among the old front points was apex_before and p
      // lies inside its circle: p is the apex now (it is visible from a and
      // b, is_acceptable_point checked that), no search needed.
      make_triangle(a, b, pid, &created);
      ++stats_.triangles_around_new_points;
      for(Edge_key e : created) work_.push_back(e);
    } else {
      work_.push_back(key(a, b));
    }
    for(Edge_key k : cavity_edges_) work_.push_back(k);
    while(!work_.empty()) {
      const Edge_key k = work_.back();
      work_.pop_back();
      if(!front_.contains(k)) continue;
      const Vid u = source(k), v = target(k);
      const bool at_p = (u == pid || v == pid);
      if(!at_p && pred_.orientation(pt(u), pt(v), p) != LEFT_TURN) continue;
      if(length(x(u) - px, y(u) - py) > star_radius || length(x(v) - px, y(v) - py) > star_radius)
        continue;
      // apart from a -> b, triangles whose circle is larger than the raised
      // bound are not built: their apex need not be found
      const double luv2 = (x(v) - x(u)) * (x(v) - x(u)) + (y(v) - y(u)) * (y(v) - y(u));
      const double max_height = (u == a && v == b) ? std::numeric_limits<double>::infinity()
                              : std::sqrt((std::max)(0., accept_raised * accept_raised - 0.25 * luv2));
      const Vid w = delaunay_apex(u, v, nbh_, max_height);
      if(w == no_vertex) continue;
      if(!at_p && w != pid) continue;
      const Circle c = circle_of(u, v, w);
      // written so that a circle that could not be computed (NaN) is rejected
      if(!(length(c.cx - px, c.cy - py) + c.r <= star_radius)) continue;
      if(!(c.r <= accept) && !(u == a && v == b) &&
         (!(c.r <= accept_raised) || !(radius_ratio(u, v, w) >= raised_bound_min_quality)))
        continue;
      created.clear();
      make_triangle(u, v, w, &created);
      ++stats_.triangles_around_new_points;
      for(Edge_key e : created)
        if(source(e) == pid || target(e) == pid) work_.push_back(e);
    }
    return true;
  }

  // A placed point is kept only if it lies strictly inside the unmeshed
  // region (seen from a and b through the region, so not across the front
  // or a constraint) and not too close to any front point or edge: such a
  // point would make a needle, and the closure fallback does better there.
  bool is_acceptable_point(Vid a, Vid b, const Point& p, double px, double py, double d) const
  {
    Phase_scope phase(this, PLACEMENT);
    const double min_dist = point_clearance * d;
    for(std::size_t i = 0; i < nbh_.vertices.size(); ++i) {
      if(length(nbh_.vertex_xy[i][0] - px, nbh_.vertex_xy[i][1] - py) < min_dist) return false;
      if(pt(Vid(nbh_.vertices[i])) == p) return false;
    }
    // the clearance tests first: plain arithmetic, they reject most points
    // that fail at all before the exact visibility tests run
    for(const Near_edge& e : nbh_.edges)
      if(segment_distance(px, py, e.x0, e.y0, e.x1, e.y1) < min_dist && still_on_front(e.key, nbh_)) return false;
    for(Edge_key k : nbh_.new_edges) {
      const Vid g = source(k), h = target(k);
      if(segment_distance(px, py, x(g), y(g), x(h), y(h)) < min_dist && still_on_front(k, nbh_)) return false;
    }
    return visible_from_both(a, pt(a), b, pt(b), no_vertex, p, nbh_);
  }

  double radius_ratio(Vid a, Vid b, Vid c) const
  {
    const double l0 = length(x(b) - x(c), y(b) - y(c)), l1 = length(x(a) - x(c), y(a) - y(c)),
                 l2 = length(x(a) - x(b), y(a) - y(b));
    const double area = 0.5 * std::abs((x(b) - x(a)) * (y(c) - y(a)) - (y(b) - y(a)) * (x(c) - x(a)));
    const double s = 0.5 * (l0 + l1 + l2);
    return 8 * area * area / (s * l0 * l1 * l2);
  }

  static double segment_distance(double px, double py, double ax, double ay, double bx, double by)
  {
    const double dx = bx - ax, dy = by - ay;
    const double l2 = dx * dx + dy * dy;
    double t = l2 > 0 ? ((px - ax) * dx + (py - ay) * dy) / l2 : 0;
    t = (std::max)(0., (std::min)(1., t));
    return length(px - (ax + t * dx), py - (ay + t * dy));
  }

  // ---------------------------------------------------------- finishing
  // Used when a limit stops the run: closes the remaining front on
  // existing points only, which always terminates and leaves a valid mesh.
  void close_remaining_front()
  {
    // every front edge gets a fresh queue entry, so none can be missed
    front_.for_each([this](Edge_key k, const Front_edge& fe) {
      const Vid u = source(k), v = target(k);
      const double dx = x(v) - x(u), dy = y(v) - y(u);
      queue_.push(Queue_entry{length(dx, dy), k, fe.version, fe.level});
    });
    while(!queue_.empty()) {
      const Queue_entry e = queue_.top();
      queue_.pop();
      const Front_edge* it = front_.find(e.key);
      if(it == nullptr || it->version != e.version) continue;
      const Vid a = source(e.key), b = target(e.key);
      step_edges_.clear();
      forced_closure(a, b, length(x(b) - x(a), y(b) - y(a)));
    }
  }

  void finish()
  {
    if(finished_) return;
    {
      Phase_scope phase(this, OUTPUT);
      if(sink_ != nullptr) finish_stream();
      else finish_triangulation();
    }
    store_phase_times();
  }

  // ---------------------------------------------------------- streaming
  // A triangle can only be broken by a point inside its circle. Points are
  // placed ahead of the front, but a point's cavity may remove the front
  // triangles behind a thin unmeshed gap, and the point then lands where
  // the mesh was: up to about the placement distance (at most twice the
  // target circumradius) behind the front. A triangle is taken for
  // finished (see sweep_finished_faces()) when the disk about its
  // circumcentre of radius `finished_margin` times its circumradius plus
  // `placement_margin` times the target circumradius at its centroid meets
  // no front edge and holds no free point, and its neighbours' disks are as
  // clear. (With the first term alone, a 100M-triangle run had 2 points
  // inside finished triangles' circles, both placed past a thin gap.) A
  // point whose cavity reaches a finished triangle all the same is refused
  // (insert_point()).
  static constexpr double finished_margin = 2.0;
  static constexpr double placement_margin = 2.0;

  // Is any front edge or active vertex within `radius` of (cx, cy)?
  bool front_meets_disk(double cx, double cy, double radius) const
  {
    bool meets = false;
    const double pad = 1e-9 * radius + 1e-12 * (std::abs(cx) + std::abs(cy));
    index_.query_with_reach(cx, cy, radius, [&](std::size_t id, double px, double py, bool in_disk) {
      if(meets) return;
      if(in_disk) {
        meets = true;
        return;
      }
      for(Vid h : out_[Vid(id)])
        if(!(segment_distance(cx, cy, px, py, x(h), y(h)) > radius + pad)) {
          meets = true;
          return;
        }
    });
    return meets;
  }

  bool is_clear_of_front(Face_handle f)
  {
    if(face_records_.find(&*f) != nullptr) return false; // a front triangle
    const Circle c = circle_of(f);
    if(!(std::isfinite(c.cx) && std::isfinite(c.cy) && std::isfinite(c.r))) return false;
    // at the centroid, which lies in the domain (the circumcentre may not)
    double gx = 0, gy = 0;
    for(int i = 0; i < 3; ++i) {
      gx += ix(f->vertex(i)->point()) / 3;
      gy += iy(f->vertex(i)->point()) / 3;
    }
    return !front_meets_disk(c.cx, c.cy, finished_margin * c.r + placement_margin * target_circumradius(gx, gy, OUTPUT));
  }

  // Is a finished face beyond edge k of f, a face of p's cavity? (Not the
  // outside, which stands behind the ghost after a restart.) Counts in
  // `broken` the finished faces the mesher without streaming would have
  // broken: their circle holds p and the walk would cross the edge.
  bool is_finished_face_beyond(Face_handle f, int k, const Point& p, std::size_t& broken)
  {
    const Vertex_handle s = f->vertex(ccw(k)), t = f->vertex(cw(k));
    const auto it = ghost_apex_.find(std::make_pair(&*s, &*t));
    if(it == ghost_apex_.end()) return false;
    if(!f->is_constrained(k)) {
      ++stats_.incircle_tests;
      if(pred_.strictly_inside_circle(t->point(), s->point(), it->second, p)) ++broken;
    }
    return true;
  }

  std::size_t output_vertex(Vertex_handle v)
  {
    if(const std::uint64_t* id = output_id_.find(&*v)) return std::size_t(*id);
    const std::size_t id = vertices_output_++;
    output_id_.insert(&*v, id);
    sink_->add_vertex(id, v->point());
    return id;
  }

  // Hands the finished faces to the sink, in an order that depends only on
  // their coordinates (not on addresses), and removes them and the vertices
  // left without triangles.
  void drop_finished_faces(std::vector<Face_handle>& faces)
  {
    struct Keyed
    {
      std::array<double, 6> key;
      Face_handle face;
      int first;
    };
    std::vector<Keyed> keyed;
    keyed.reserve(faces.size());
    for(Face_handle f : faces) {
      // rotated to start at the lexicographically smallest vertex
      int first = 0;
      for(int i = 1; i < 3; ++i) {
        const Point& p = f->vertex(i)->point();
        const Point& q = f->vertex(first)->point();
        if(ix(p) < ix(q) || (ix(p) == ix(q) && iy(p) < iy(q))) first = i;
      }
      Keyed k;
      k.face = f;
      k.first = first;
      for(int i = 0; i < 3; ++i) {
        k.key[2 * i] = ix(f->vertex((first + i) % 3)->point());
        k.key[2 * i + 1] = iy(f->vertex((first + i) % 3)->point());
      }
      keyed.push_back(k);
    }
    std::sort(keyed.begin(), keyed.end(), [](const Keyed& a, const Keyed& b) { return a.key < b.key; });
    for(const Keyed& k : keyed) {
      visitor_.on_face_finished(k.face);
      std::array<std::size_t, 3> ids;
      for(int i = 0; i < 3; ++i) ids[i] = output_vertex(k.face->vertex((k.first + i) % 3));
      sink_->add_triangle(ids[0], ids[1], ids[2]);
      ++triangles_output_;
    }
    batch_.clear();
    for(Face_handle f : faces) batch_.insert(&*f, true);
    // all links to the batch are cut before any face is deleted (a deleted
    // face's slot is reused, and a stale link could then name a new face)
    for(Face_handle f : faces) {
      for(int k = 0; k < 3; ++k) {
        Face_handle g = f->neighbor(k);
        if(g == ghost_) {
          ghost_apex_.erase(std::make_pair(&*f->vertex(ccw(k)), &*f->vertex(cw(k))));
        } else if(g == Face_handle() || batch_.find(&*g) != nullptr) {
          continue;
        } else if(g->is_in_domain()) {
          // a face that stays: its edge now faces a finished triangle, whose
          // apex is kept to tell whether a cavity reaches it
          const int j = g->index(f);
          g->set_neighbor(j, ghost_);
          ghost_apex_[std::make_pair(&*g->vertex(ccw(j)), &*g->vertex(cw(j)))] = f->vertex(k)->point();
        } else {
          // a face outside the domain: it never links to the mesh again
          g->set_neighbor(g->index(f), Face_handle());
        }
      }
    }
    batch_.clear();
    batch_.shrink_if_sparse();
    for(Face_handle f : faces) {
      std::array<Vertex_handle, 3> vs = {{f->vertex(0), f->vertex(1), f->vertex(2)}};
      tds().delete_face(f);
      --triangles_in_memory_;
      for(Vertex_handle v : vs) {
        std::uint32_t* n = live_faces_.find(&*v);
        if(n == nullptr || --*n != 0 || vid_.find(&*v) != nullptr) continue;
        live_faces_.erase(&*v);
        output_id_.erase(&*v);
        tds().delete_vertex(v);
      }
    }
    live_faces_.shrink_if_sparse();
    output_id_.shrink_if_sparse();
  }

  void sweep_finished_faces(bool everything)
  {
    Phase_scope phase(this, OUTPUT);
    ++stats_.stream_sweeps;
    std::vector<Face_handle> kept, finished;
    near_front_.clear();
    // the container itself: faces_begin() is empty below dimension 2, which a
    // resumed run's triangulation keeps
    for(auto f = tds().faces().begin(); f != tds().faces().end(); ++f) {
      Face_handle fh = f;
      if(fh == ghost_ || !fh->is_in_domain()) continue;
      kept.push_back(fh);
      if(!everything && !is_clear_of_front(fh)) near_front_.insert(&*fh, true);
    }
    // A triangle goes only when its neighbours are clear of the front too:
    // a cavity can only open a triangle next to one whose circle a new point
    // breaks, and a neighbour with a large circle (a closure that the size
    // bound could not prevent) reaches far ahead.
    for(Face_handle f : kept) {
      bool done = near_front_.find(&*f) == nullptr;
      for(int k = 0; done && k < 3; ++k) {
        Face_handle g = f->neighbor(k);
        if(g != Face_handle() && g != ghost_ && g->is_in_domain() && near_front_.find(&*g) != nullptr) done = false;
      }
      if(done) finished.push_back(f);
    }
    near_front_.clear();
    near_front_.shrink_if_sparse();
    drop_finished_faces(finished);
    created_since_sweep_ = 0;
    // after as many new triangles as stayed in memory, so that each is tested
    // a bounded number of times on average
    sweep_after_ = (std::max)(triangles_in_memory_, minimum_sweep_);
  }

  // --------------------------------------------------------- checkpoints
  // The state is written as it is in memory, trees included (their query
  // order decides ties), so that a resumed run repeats the decisions of an
  // uninterrupted one exactly. Handles become indices: vertices and faces
  // are numbered in the file.
  static constexpr std::uint32_t checkpoint_version = 1;
  static constexpr std::uint32_t null_face = 0xffffffffu, ghost_face = 0xfffffffeu, no_index = 0xffffffffu;

  typedef Advancing_front_mesh_2::internal::Binary_writer Binary_writer;
  typedef Advancing_front_mesh_2::internal::Binary_reader Binary_reader;

  static std::string checkpoint_magic() { return "Advancing_front_mesh_2 checkpoint"; }

  // The file's content, once its checksum is verified: nothing is built
  // from a damaged checkpoint, which is refused as a whole.
  static std::string verified_checkpoint(const std::string& file_name)
  {
    std::ifstream file(file_name.c_str(), std::ios::in | std::ios::binary);
    if(!file) throw std::runtime_error(file_name + ": cannot read the checkpoint");
    std::string content((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
    std::istringstream is(content);
    Binary_reader r(is, file_name);
    if(content.size() < sizeof(std::uint64_t)) r.fail("truncated");
    std::vector<char> buffer(std::size_t(1) << 16);
    for(std::size_t left = content.size() - sizeof(std::uint64_t); left > 0;) {
      const std::size_t n = (std::min)(left, buffer.size());
      r.read_bytes(buffer.data(), n);
      left -= n;
    }
    r.check_checksum();
    return content;
  }
  static std::string traits_name() { return typeid(Geom_traits).name(); }

  static Checkpoint_info read_checkpoint_header(Binary_reader& r, bool check_traits = true)
  {
    if(r.read_string(64) != checkpoint_magic()) r.fail("not a checkpoint of Advancing_front_mesher_2");
    if(r.read<std::uint32_t>() != checkpoint_version) r.fail("a checkpoint of another version of the mesher");
    if(r.read_string(4096) != traits_name() && check_traits) r.fail("a checkpoint written with another kernel");
    Checkpoint_info info;
    info.user_data = r.read_string(std::uint64_t(1) << 24);
    info.sink_state = r.read_string(std::uint64_t(1) << 24);
    info.vertices_written = std::size_t(r.read<std::uint64_t>());
    info.triangles_written = std::size_t(r.read<std::uint64_t>());
    return info;
  }

  static double exact_double(const FT& v)
  {
    const double d = CGAL::to_double(v);
    if(!(FT(d) == v))
      throw std::logic_error("Advancing_front_mesher_2: a checkpoint needs coordinates that are doubles");
    return d;
  }

  void write_checkpoint_state(Binary_writer& w, const std::string& user_data, const std::string& sink_state)
  {
    w.write_string(checkpoint_magic());
    w.write(checkpoint_version);
    w.write_string(traits_name());
    w.write_string(user_data);
    w.write_string(sink_state);
    w.write(std::uint64_t(vertices_output_));
    w.write(std::uint64_t(triangles_output_));

    // the vertices anything refers to, and the faces in memory
    std::unordered_map<const Tds_vertex*, std::uint32_t> vindex;
    std::vector<Vertex_handle> vertices;
    auto number = [&](Vertex_handle v) {
      if(vindex.emplace(&*v, std::uint32_t(vertices.size())).second) vertices.push_back(v);
    };
    std::vector<bool> is_free(vertex_.size(), false);
    for(Vid v : free_ids_) is_free[v] = true;
    for(Vid v : released_ids_) is_free[v] = true;
    for(Vid v = 0; v < vertex_.size(); ++v)
      if(!is_free[v]) number(vertex_[v]);
    std::unordered_map<const Tds_face*, std::uint32_t> findex;
    std::vector<Face_handle> faces;
    for(auto f = tds().faces().begin(); f != tds().faces().end(); ++f) {
      Face_handle fh = f;
      if(fh == ghost_ || !fh->is_in_domain()) continue;
      findex.emplace(&*fh, std::uint32_t(faces.size()));
      faces.push_back(fh);
      for(int i = 0; i < 3; ++i) number(fh->vertex(i));
    }
    constraint_octree_.for_each_payload([&](const Constraint& c) {
      number(c.first);
      number(c.second);
    });
    auto face_code = [&](Face_handle f) -> std::uint32_t {
      if(f == Face_handle()) return null_face;
      const auto it = findex.find(&*f);
      // the ghost, or a face outside the domain: after a restart both are
      // the ghost, which the mesher treats alike
      return it == findex.end() ? ghost_face : it->second;
    };
    auto vertex_code = [&](Vertex_handle v) { return vindex.at(&*v); };

    w.write(exponent_);
    w.write(domain_area_);
    w.write(meshed_area_);
    w.write(version_counter_);
    w.write(std::uint64_t(queue_compactions_));
    w.write(static_cast<std::uint8_t>(pocket_priority_));
    // the counters without the times, which are this session's: a
    // checkpoint depends on the input and the options only, and two runs
    // write the same bytes
    Advancing_front_mesh_2::Statistics counters = stats_;
    counters.init_time = counters.meshing_time = 0;
    counters.phase_times = Advancing_front_mesh_2::Phase_times();
    w.write(counters);
    for(std::size_t n : {triangles_in_memory_, created_since_sweep_, sweep_after_, minimum_sweep_})
      w.write(std::uint64_t(n));

    w.write(std::uint64_t(vertices.size()));
    for(Vertex_handle v : vertices) {
      w.write(exact_double(v->point().x()));
      w.write(exact_double(v->point().y()));
      const std::uint64_t* out = output_id_.find(&*v);
      w.write(out != nullptr ? *out : ~std::uint64_t(0));
      w.write(static_cast<std::uint8_t>(live_faces_.find(&*v) != nullptr));
    }

    w.write(std::uint64_t(vertex_.size()));
    for(Vid v = 0; v < vertex_.size(); ++v) {
      w.write(is_free[v] ? no_index : vertex_code(vertex_[v]));
      w.write(xy_[v]);
      w.write_vector(std::vector<Vid>(out_[v].begin(), out_[v].end()));
      w.write_vector(std::vector<Vid>(in_[v].begin(), in_[v].end()));
    }
    w.write_vector(free_ids_);
    w.write_vector(released_ids_);

    w.write(std::uint64_t(faces.size()));
    for(Face_handle f : faces) {
      for(int i = 0; i < 3; ++i) w.write(vertex_code(f->vertex(i)));
      for(int i = 0; i < 3; ++i) w.write(face_code(f->neighbor(i)));
      for(int i = 0; i < 3; ++i) w.write(static_cast<std::uint8_t>(f->is_constrained(i)));
      const Face_record* rec = face_records_.find(&*f);
      w.write(static_cast<std::uint8_t>(rec != nullptr));
      if(rec != nullptr) {
        w.write(std::uint64_t(rec->circle_item));
        w.write(rec->front_edges);
      }
    }

    w.write(std::uint64_t(front_.size()));
    front_.for_each([&](Edge_key k, const Front_edge& fe) {
      w.write(k);
      w.write(face_code(fe.behind));
      w.write(fe.behind_index);
      w.write(static_cast<std::uint8_t>(fe.constrained));
      w.write(fe.level);
      w.write(fe.version);
    });

    std::priority_queue<Queue_entry> q = queue_;
    w.write(std::uint64_t(q.size()));
    for(; !q.empty(); q.pop()) {
      const Queue_entry& e = q.top();
      w.write(e.length);
      w.write(e.key);
      w.write(e.version);
      w.write(e.level);
    }

    index_.save(w);
    triangle_octree_.save(w, [&](Binary_writer& bw, const Face_handle& f) { bw.write(face_code(f)); });
    constraint_octree_.save(w, [&](Binary_writer& bw, const Constraint& c) {
      bw.write(vertex_code(c.first));
      bw.write(vertex_code(c.second));
    });

    // in the order of the vertices' numbers, not the hash table's, which
    // depends on addresses
    std::vector<std::pair<std::array<std::uint32_t, 2>, Point> > ghosts;
    ghosts.reserve(ghost_apex_.size());
    for(const auto& g : ghost_apex_)
      ghosts.emplace_back(std::array<std::uint32_t, 2>{{vindex.at(g.first.first), vindex.at(g.first.second)}}, g.second);
    std::sort(ghosts.begin(), ghosts.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    w.write(std::uint64_t(ghosts.size()));
    for(const auto& g : ghosts) {
      w.write(g.first[0]);
      w.write(g.first[1]);
      w.write(exact_double(g.second.x()));
      w.write(exact_double(g.second.y()));
    }
  }

  void read_checkpoint_state(Binary_reader& r)
  {
    const std::uint64_t big = std::uint64_t(1) << 40;
    auto check = [&r](bool ok, const char* what) {
      if(!ok) r.fail(std::string("corrupt checkpoint: ") + what);
    };
    exponent_ = r.read<int>();
    domain_area_ = r.read<double>();
    meshed_area_ = r.read<double>();
    version_counter_ = r.read<std::uint32_t>();
    queue_compactions_ = std::size_t(r.read<std::uint64_t>());
    pocket_priority_ = r.read<std::uint8_t>() != 0;
    stats_ = r.read<Advancing_front_mesh_2::Statistics>();
    triangles_in_memory_ = std::size_t(r.read<std::uint64_t>());
    created_since_sweep_ = std::size_t(r.read<std::uint64_t>());
    sweep_after_ = std::size_t(r.read<std::uint64_t>());
    minimum_sweep_ = std::size_t(r.read<std::uint64_t>());

    const std::uint64_t nv = r.read<std::uint64_t>();
    check(nv < big, "vertex count");
    std::vector<Vertex_handle> vertices;
    vertices.reserve(std::size_t((std::min)(nv, std::uint64_t(1) << 20)));
    for(std::uint64_t i = 0; i < nv; ++i) {
      const double px = r.read<double>(), py = r.read<double>();
      check(std::isfinite(px) && std::isfinite(py), "vertex coordinates");
      const std::uint64_t out = r.read<std::uint64_t>();
      const bool created = r.read<std::uint8_t>() != 0;
      Vertex_handle v = tds().create_vertex();
      v->set_point(Point(px, py));
      vertices.push_back(v);
      if(out != ~std::uint64_t(0)) output_id_.insert(&*v, out);
      if(created) live_faces_.insert(&*v, 0);
    }
    auto vertex_at = [&](std::uint32_t i) {
      check(i < vertices.size(), "vertex index");
      return vertices[i];
    };

    const std::uint64_t nids = r.read<std::uint64_t>();
    check(nids < no_vertex, "number of vertex ids");
    std::vector<bool> is_free; // grown per record: nids is not trusted yet
    for(std::uint64_t v = 0; v < nids; ++v) {
      is_free.push_back(true);
      const std::uint32_t code = r.read<std::uint32_t>();
      vertex_.push_back(code == no_index ? Vertex_handle() : vertex_at(code));
      xy_.push_back(r.read<std::array<double, 2> >());
      std::vector<Vid> ids;
      out_.emplace_back();
      in_.emplace_back();
      r.read_vector(ids, nids);
      for(Vid w : ids) { check(w < nids, "front edge"); out_.back().push_back(w); }
      r.read_vector(ids, nids);
      for(Vid w : ids) { check(w < nids, "front edge"); in_.back().push_back(w); }
      if(code != no_index) {
        check(vid_.find(&*vertex_.back()) == nullptr, "vertex ids");
        is_free[std::size_t(v)] = false;
        vid_.insert(&*vertex_.back(), Vid(v));
      }
    }
    r.read_vector(free_ids_, nids);
    r.read_vector(released_ids_, nids);
    // every id without a vertex is free or released, once
    std::vector<bool> listed(is_free.size(), false);
    for(Vid v : free_ids_) {
      check(v < nids && is_free[v] && !listed[v], "free vertex id");
      listed[v] = true;
    }
    for(Vid v : released_ids_) {
      check(v < nids && is_free[v] && !listed[v], "released vertex id");
      listed[v] = true;
    }
    check(std::count(is_free.begin(), is_free.end(), true) == std::ptrdiff_t(free_ids_.size() + released_ids_.size()),
          "free vertex ids");

    ghost_ = tds().create_face();
    ghost_->set_in_domain(false);
    const std::uint64_t nf = r.read<std::uint64_t>();
    check(nf < big, "face count");
    std::vector<Face_handle> faces;
    std::vector<std::array<std::uint32_t, 3> > neighbours;
    for(std::uint64_t i = 0; i < nf; ++i) {
      std::array<std::uint32_t, 3> vs;
      for(int k = 0; k < 3; ++k) vs[k] = r.read<std::uint32_t>();
      check(vs[0] != vs[1] && vs[1] != vs[2] && vs[2] != vs[0], "face vertices");
      Face_handle f = tds().create_face(vertex_at(vs[0]), vertex_at(vs[1]), vertex_at(vs[2]));
      f->set_in_domain(true);
      faces.push_back(f);
      std::array<std::uint32_t, 3> ns;
      for(int k = 0; k < 3; ++k) ns[k] = r.read<std::uint32_t>();
      neighbours.push_back(ns);
      for(int k = 0; k < 3; ++k) f->set_constraint(k, r.read<std::uint8_t>() != 0);
      for(int k = 0; k < 3; ++k) {
        vertex_at(vs[k])->set_face(f);
        if(std::uint32_t* n = live_faces_.find(&*vertex_at(vs[k]))) ++*n;
      }
      if(r.read<std::uint8_t>() != 0) {
        Face_record rec;
        rec.circle_item = std::size_t(r.read<std::uint64_t>());
        rec.front_edges = r.read<int>();
        check(rec.front_edges > 0 && rec.front_edges <= 3, "face record");
        face_records_.insert(&*f, rec);
      }
    }
    auto face_at = [&](std::uint32_t code) {
      if(code == null_face) return Face_handle();
      if(code == ghost_face) return ghost_;
      check(code < faces.size(), "face index");
      return faces[code];
    };
    for(std::size_t i = 0; i < faces.size(); ++i)
      for(int k = 0; k < 3; ++k) faces[i]->set_neighbor(k, face_at(neighbours[i][k]));
    // two faces in memory see each other across the same edge
    for(Face_handle f : faces)
      for(int k = 0; k < 3; ++k) {
        Face_handle g = f->neighbor(k);
        if(g == Face_handle() || g == ghost_) continue;
        int j = 0;
        while(j < 3 && g->neighbor(j) != f) ++j;
        check(j < 3 && g->vertex(cw(j)) == f->vertex(ccw(k)) && g->vertex(ccw(j)) == f->vertex(cw(k)) &&
                g->is_constrained(j) == f->is_constrained(k), "face neighbours");
      }

    const std::uint64_t ne = r.read<std::uint64_t>();
    check(ne < big, "front size");
    for(std::uint64_t i = 0; i < ne; ++i) {
      const Edge_key k = r.read<Edge_key>();
      check(source(k) < nids && target(k) < nids && source(k) != target(k), "front edge key");
      Front_edge fe;
      fe.behind = face_at(r.read<std::uint32_t>());
      fe.behind_index = r.read<int>();
      check(fe.behind_index >= -1 && fe.behind_index < 3, "front edge");
      if(fe.behind == ghost_) fe.behind_index = -1;
      check(fe.behind == Face_handle() || fe.behind == ghost_ || fe.behind_index >= 0, "front edge");
      check(front_.find(k) == nullptr, "front edge twice");
      fe.constrained = r.read<std::uint8_t>() != 0;
      fe.level = r.read<std::uint16_t>();
      fe.version = r.read<std::uint32_t>();
      front_.insert(k, fe);
    }

    const std::uint64_t nq = r.read<std::uint64_t>();
    check(nq < big, "queue size");
    std::vector<Queue_entry> entries;
    for(std::uint64_t i = 0; i < nq; ++i) {
      const double length = r.read<double>();
      const Edge_key k = r.read<Edge_key>();
      const std::uint32_t version = r.read<std::uint32_t>();
      const std::uint16_t level = r.read<std::uint16_t>();
      check(source(k) < nids && target(k) < nids, "queue entry");
      entries.push_back(Queue_entry{length, k, version, level});
    }
    queue_ = std::priority_queue<Queue_entry>(std::less<Queue_entry>(), std::move(entries));

    index_.load(r);
    triangle_octree_.load(r, [&](Binary_reader& br) { return face_at(br.read<std::uint32_t>()); });
    constraint_octree_.load(r, [&](Binary_reader& br) {
      const std::uint32_t a = br.read<std::uint32_t>();
      const std::uint32_t b = br.read<std::uint32_t>();
      check(a != b, "constraint");
      return std::make_pair(vertex_at(a), vertex_at(b));
    });

    const std::uint64_t ng = r.read<std::uint64_t>();
    check(ng < big, "ghost count");
    for(std::uint64_t i = 0; i < ng; ++i) {
      const Vertex_handle a = vertex_at(r.read<std::uint32_t>());
      const Vertex_handle b = vertex_at(r.read<std::uint32_t>());
      const double px = r.read<double>(), py = r.read<double>();
      ghost_apex_[std::make_pair(&*a, &*b)] = Point(px, py);
    }
    // what the mesher cross-checks in every step must hold
    for(Vid v = 0; v < nids; ++v)
      if(!is_free[v]) check(index_.contains(v), "point quadtree");
    front_.for_each([&](Edge_key k, const Front_edge&) { check(!is_free[source(k)] && !is_free[target(k)], "front edge"); });
    check(index_.size() == vid_.size(), "point quadtree");
    // the circle octree holds exactly the circles of the face records, and a
    // record counts the front edges its face is behind
    std::size_t circles = 0;
    bool circles_ok = true;
    triangle_octree_.for_each_payload([&](const Face_handle& f) {
      ++circles;
      if(f == Face_handle() || f == ghost_ || face_records_.find(&*f) == nullptr) circles_ok = false;
    });
    check(circles_ok && circles == face_records_.size(), "circle octree");
    std::unordered_map<const Tds_face*, int> edges_behind;
    front_.for_each([&](Edge_key, const Front_edge& fe) {
      if(fe.behind != Face_handle() && fe.behind != ghost_) ++edges_behind[&*fe.behind];
    });
    check(edges_behind.size() == face_records_.size(), "face records");
    face_records_.for_each([&](const Tds_face* f, const Face_record& rec) {
      check(triangle_octree_.is_alive(rec.circle_item) && &*triangle_octree_.payload(rec.circle_item) == f,
            "circle octree");
      const auto it = edges_behind.find(f);
      check(it != edges_behind.end() && it->second == rec.front_edges, "face records");
    });
    check(is_front_valid(), "front");
  }

  void finish_stream()
  {
    finished_ = true;
    if(!front_.empty()) close_remaining_front(); // never expected
    sweep_finished_faces(true);
    ghost_apex_.clear();
    live_faces_.clear();
    output_id_.clear();
    ghost_ = Face_handle();
    cdt_.clear();
    stats_.number_of_faces = triangles_output_;
    stats_.number_of_vertices = vertices_output_;
  }

  void finish_triangulation()
  {
    finished_ = true;
    CGAL_assertion(front_.empty());
    if(!front_.empty()) close_remaining_front(); // never expected; keeps the result valid
    restore_delaunay_property();
    // vertices may still point at faces deleted during meshing
    for(auto f = cdt_.all_faces_begin(); f != cdt_.all_faces_end(); ++f)
      for(int i = 0; i < 3; ++i) f->vertex(i)->set_face(f);
    std::size_t faces = 0;
    for(auto f = cdt_.finite_faces_begin(); f != cdt_.finite_faces_end(); ++f)
      if(f->is_in_domain()) ++faces;
    stats_.number_of_faces = faces;
    stats_.number_of_vertices = cdt_.number_of_vertices();
    CGAL_expensive_postcondition(cdt_.is_valid());
  }

  // Lawson's flips on unconstrained in-domain edges. The advancing front
  // builds a constrained Delaunay triangulation by itself, so this finds
  // nothing to flip (the tests assert it); it is kept as a guarantee.
  void restore_delaunay_property()
  {
    // Each edge is tested once, from the face with the smaller address; a
    // flip pushes the edges of its two new faces on a stack, so the memory
    // is that of the flips, not of the mesh (a stack of every edge was 48
    // bytes per triangle, the largest allocation of a whole run).
    std::vector<std::pair<Face_handle, int> > stack;
    auto needs_flip = [this](Face_handle f, int i) {
      if(f->is_constrained(i)) return false;
      Face_handle g = f->neighbor(i);
      if(!f->is_in_domain() || !g->is_in_domain() || cdt_.is_infinite(g) || cdt_.is_infinite(f)) return false;
      const int j = g->index(f);
      return pred_.strictly_inside_circle(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point(),
                                          g->vertex(j)->point());
    };
    for(auto fit = cdt_.finite_faces_begin(); fit != cdt_.finite_faces_end(); ++fit) {
      Face_handle start = fit;
      if(!start->is_in_domain()) continue;
      for(int i0 = 0; i0 < 3; ++i0) {
        if(&*start->neighbor(i0) < &*start || !needs_flip(start, i0)) continue;
        stack.emplace_back(start, i0);
        while(!stack.empty()) {
          Face_handle f = stack.back().first;
          const int i = stack.back().second;
          stack.pop_back();
          if(!needs_flip(f, i)) continue;
          Face_handle g = f->neighbor(i);
          // the triangulation's flip keeps the constraint flags right
          cdt_.flip(f, i);
          ++stats_.delaunay_repair_flips;
          for(int k = 0; k < 3; ++k) {
            stack.emplace_back(f, k);
            stack.emplace_back(g, k);
          }
        }
      }
    }
  }

  // ------------------------------------------------------------ tuning
  // A triangle on an existing point is accepted up to this factor over
  // the size bound rho; a little slack avoids placing a point next to an
  // existing one when the closing triangle is barely too large.
  static constexpr double closure_tolerance = 1.25;
  // A new point clamped closer than this fraction of the edge length is not
  // placed: the existing apex is used instead.
  static constexpr double placement_floor = 0.3;
  // A new point must keep this fraction of its distance to the edge from
  // every other front point and edge.
  static constexpr double point_clearance = 0.5;
  // Triangles about a new point larger than the local bound (allowed by the
  // raised bound of step 10) must have at least this radius ratio.
  static constexpr double raised_bound_min_quality = 0.25;

  // ------------------------------------------------------------ members
  CDT& cdt_;
  Sizing_field sizing_;
  Visitor visitor_;
  Advancing_front_mesh_2::internal::Front_predicates<Geom_traits> pred_;
  Seeds seeds_;
  bool seeds_mark_ = false;
  bool initialized_ = false;
  bool finished_ = false;
  std::size_t iteration_limit_ = 0;
  double time_limit_ = 0;
  bool phase_timing_ = false;
  mutable Phase phase_ = FRONT_SELECTION;
  mutable Clock::time_point phase_start_;
  mutable std::array<double, 9> phase_seconds_ = {{0, 0, 0, 0, 0, 0, 0, 0, 0}};

  // keyed by (source, target); the empty key is no real edge
  Advancing_front_mesh_2::internal::Flat_hash_map<Edge_key, Front_edge> front_{~Edge_key(0)};
  std::vector<Advancing_front_mesh_2::internal::Compact_id_list> out_, in_;
  std::vector<Vertex_handle> vertex_;
  std::vector<std::array<double, 2> > xy_;
  std::vector<Vid> free_ids_, released_ids_;
  typedef typename Tds::Vertex Tds_vertex;
  typedef typename Tds::Face Tds_face;
  Advancing_front_mesh_2::internal::Flat_hash_map<const Tds_vertex*, Vid> vid_{nullptr};
  Advancing_front_mesh_2::internal::Flat_hash_map<const Tds_face*, Face_record> face_records_{nullptr};
  std::priority_queue<Queue_entry> queue_;
  std::uint32_t version_counter_ = 0;
  // pockets (see mark_pockets())
  // a walk along a loop of the front: state 0 walking, 1 closed, 2 open (or
  // unknown), 3 stopped on the loop of another walk
  struct Pocket_walk { Edge_key start; Vid at; std::size_t length; int state; };
  std::uint16_t step_level_ = 0;      // the level of the edge being processed
  bool pocket_priority_ = true;
  bool loops_changed_ = false;        // this step split or joined loops of the front
  std::vector<Edge_key> step_edges_;  // the front edges this step created
  std::vector<Pocket_walk> walks_;
  std::size_t queue_compactions_ = 0;
  Advancing_front_mesh_2::internal::Dynamic_point_quadtree index_;
  Triangle_octree triangle_octree_;
  Constraint_octree constraint_octree_;
  double meshed_area_ = 0, domain_area_ = 0;
  int exponent_ = 0; // internal coordinates are the user's divided by 2^exponent_

  // streaming (see set_output_sink())
  struct Vertex_pair_hash
  {
    std::size_t operator()(const std::pair<const Tds_vertex*, const Tds_vertex*>& e) const
    {
      return std::hash<const void*>()(e.first) * 31 + std::hash<const void*>()(e.second);
    }
  };
  Mesh_sink* sink_ = nullptr;
  Face_handle ghost_; // stands for the finished faces beyond an edge
  // the apex of the finished face beyond each edge of a face in memory, by
  // the edge's end points as they run in that face
  std::unordered_map<std::pair<const Tds_vertex*, const Tds_vertex*>, Point, Vertex_pair_hash> ghost_apex_;
  // the vertices the mesher created, with their number of faces in memory
  Advancing_front_mesh_2::internal::Flat_hash_map<const Tds_vertex*, std::uint32_t> live_faces_{nullptr};
  // the sink's numbers of the vertices already written that are still in memory
  Advancing_front_mesh_2::internal::Flat_hash_map<const Tds_vertex*, std::uint64_t> output_id_{nullptr};
  std::size_t vertices_output_ = 0, triangles_output_ = 0;
  std::size_t triangles_in_memory_ = 0;
  std::size_t minimum_sweep_ = 4096;
  std::size_t checkpoint_every_ = 0, next_checkpoint_ = 0;
  std::string checkpoint_file_, checkpoint_user_data_;
  bool checkpoint_stop_ = false, stop_now_ = false;
  Advancing_front_mesh_2::internal::Flat_hash_map<const Tds_face*, bool> near_front_{nullptr}, batch_{nullptr};
  std::size_t created_since_sweep_ = 0, sweep_after_ = 4096;
  Advancing_front_mesh_2::Statistics stats_;

  // scratch space reused across steps
  Neighbourhood nbh_;
  enum Candidate_state : unsigned char { UNTESTED, QUALIFIES, REJECTED };
  struct Candidate
  {
    double height;         // approximate circle-centre height, for the order
    Vid vertex;
    Candidate_state state;
    double low;            // a lower bound of the true height
  };
  std::vector<Candidate> candidates_, dropped_;
  std::vector<Face_handle> broken_;
  std::unordered_set<Face_handle, Handle_hash> broken_set_;
  std::vector<std::array<Vid, 3> > removed_;
  std::vector<Edge_key> cavity_edges_;
  std::vector<Edge_key> work_;
  std::vector<Edge_key> created_;
};

namespace Advancing_front_mesh_2 {
namespace internal {

template <class T, class = void>
struct Has_size_bound : std::false_type {};
template <class T>
struct Has_size_bound<T, decltype(void(std::declval<const T&>().size_bound()))> : std::true_type {};

// Turns what the user passed as "size" into a sizing field: a number is a
// uniform target edge length, a Mesh_2 size criteria object gives its
// size bound, anything else must be callable as FT(const Point_2&).
template <class Gt, class T, class = void>
struct Sizing_field_maker
{
  typedef T type;
  static const T& make(const T& t) { return t; }
};
template <class Gt, class T>
struct Sizing_field_maker<Gt, T, std::enable_if_t<std::is_arithmetic<T>::value ||
                                                  std::is_same<T, typename Gt::FT>::value> >
{
  typedef Uniform_sizing_field_2<Gt> type;
  static type make(const T& t)
  {
    // checked before the triangulation is touched
    const double h = CGAL::to_double(t);
    if(!(h > 0) || !std::isfinite(h))
      throw std::invalid_argument("advancing_front_mesh_2: the target edge length must be a positive finite number");
    return type(typename Gt::FT(t));
  }
};
template <class Gt, class T>
struct Sizing_field_maker<Gt, T, std::enable_if_t<Has_size_bound<T>::value> >
{
  typedef Size_criteria_sizing_field_2<T, Gt> type;
  static type make(const T& t)
  {
    if(!(t.size_bound() > 0))
      throw std::invalid_argument("advancing_front_mesh_2: the Mesh_2 criteria have no size bound "
                                  "(size_bound() == 0); an advancing front needs a size");
    return type(t);
  }
};

} // namespace internal
} // namespace Advancing_front_mesh_2

/*!
\ingroup PkgAdvancingFrontMesh2Ref

Meshes the domain of `cdt` (seeds as in `refine_Delaunay_mesh_2()`: with
`mark == false` the components containing a seed are holes).

\param cdt the constrained Delaunay triangulation holding the constraints
\param seeds_begin, seeds_end the seeds
\param size either a number (the uniform target edge length `h`), a sizing
  field callable as `FT(const Point_2&)` returning `h` at a point (a lambda,
  Mesh_2's `Lipschitz_sizing_field_2`, ...), or a Mesh_2 size criteria object
  such as `Delaunay_mesh_size_criteria_2` (see
  `Advancing_front_mesh_2::Size_criteria_sizing_field_2` for the mapping)
\param mark the meaning of the seeds
\param np optional named parameters among:
\cgalNamedParamsBegin
  \cgalParamNBegin{visitor}
    \cgalParamDescription{a model of `AdvancingFrontMeshVisitor_2`}
    \cgalParamDefault{`Advancing_front_mesh_2::Default_visitor()`}
  \cgalParamNEnd
  \cgalParamNBegin{number_of_iterations}
    \cgalParamDescription{stop after this many front edges (0: no limit)}
    \cgalParamDefault{0}
  \cgalParamNEnd
  \cgalParamNBegin{maximum_running_time}
    \cgalParamDescription{stop after this many seconds (0: no limit)}
    \cgalParamDefault{0}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns how the run ended; the triangulation is a valid mesh in every case.
\throws std::invalid_argument when the size is not a positive finite number
  (or the sizing field returns one that is not)
*/
template <class CDT, class InputIterator, class Size,
          class NamedParameters = parameters::Default_named_parameters>
Advancing_front_mesh_2::Mesh_return_code
advancing_front_mesh_2(CDT& cdt, InputIterator seeds_begin, InputIterator seeds_end,
                       const Size& size, bool mark = false,
                       const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  typedef typename CDT::Geom_traits Gt;
  typedef Advancing_front_mesh_2::internal::Sizing_field_maker<Gt, Size> Maker;
  typedef typename internal_np::Lookup_named_param_def<internal_np::visitor_t, NamedParameters,
                                                       Advancing_front_mesh_2::Default_visitor>::type Visitor;
  Visitor visitor = choose_parameter<Advancing_front_mesh_2::Default_visitor>(get_parameter(np, internal_np::visitor));
  Advancing_front_mesher_2<CDT, typename Maker::type, Visitor> mesher(cdt, Maker::make(size), visitor);
  mesher.set_seeds(seeds_begin, seeds_end, mark);
  mesher.set_iteration_limit(choose_parameter(get_parameter(np, internal_np::number_of_iterations), std::size_t(0)));
  mesher.set_time_limit(choose_parameter(get_parameter(np, internal_np::maximum_running_time), 0.));
  return mesher.refine_mesh();
}

/*!
\ingroup PkgAdvancingFrontMesh2Ref
Same as above without seeds: every bounded component is meshed.
*/
template <class CDT, class Size, class NamedParameters = parameters::Default_named_parameters>
Advancing_front_mesh_2::Mesh_return_code
advancing_front_mesh_2(CDT& cdt, const Size& size,
                       const NamedParameters& np = parameters::default_values())
{
  std::list<typename CDT::Point> no_seeds;
  return advancing_front_mesh_2(cdt, no_seeds.begin(), no_seeds.end(), size, false, np);
}

} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESHER_2_H
