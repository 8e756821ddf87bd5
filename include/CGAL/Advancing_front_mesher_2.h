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
#include <CGAL/Advancing_front_mesh_2/Checkpoint_info.h>
#include <CGAL/Advancing_front_mesh_2/Default_visitor.h>
#include <CGAL/Advancing_front_mesh_2/Mesh_return_code.h>
#include <CGAL/Advancing_front_mesh_2/Mesh_sink_2.h>
#include <CGAL/Advancing_front_mesh_2/refine_to_minimum_angle_2.h>
#include <CGAL/Advancing_front_mesh_2/Sizing_fields.h>
#include <CGAL/Advancing_front_mesh_2/Statistics.h>
#include <CGAL/Advancing_front_mesh_2/internal/Advancing_front_refiner.h>
#include <CGAL/Advancing_front_mesh_2/internal/Dynamic_point_quadtree.h>
#include <CGAL/Advancing_front_mesh_2/internal/Lifted_circle_octree.h>
#include <CGAL/Advancing_front_mesh_2/internal/Sizing_field_maker.h>

#include <CGAL/Default.h>
#include <CGAL/Named_function_parameters.h>

#include <cstddef>
#include <list>
#include <string>

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
predicates. The result is a constrained Delaunay triangulation of its
vertices.

Before the front is built, constraints longer than the local size are split
to the sizing field (`set_constraint_splitting()`, the boundary
discretisation of `split_constraints_to_size_2()`); the paper takes the
boundary discretisation as given, and with splitting off every input
segment stays one edge.

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
\tparam PointIndex a model of `AdvancingFrontPointIndex_2`, the search for
  the front points close to an edge (step 4); `CGAL::Default` is the
  package's dynamic point quadtree, `Advancing_front_mesh_2::Kd_tree_point_index`
  builds on CGAL's `Kd_tree`.
\tparam CircleIndex a model of `AdvancingFrontCircleIndex_2`, the search for
  the circles a new point breaks (step 7) and for the input constraints near
  a segment; `CGAL::Default` is the package's lifted circle octree (Fig. 11 of
  the paper).

<b>Sizes.</b> The paper bounds triangle circumradii by rho(x); users think in
edge lengths. The sizing field gives the target edge length h(x) and the
mesher uses rho(x) = h(x) / sqrt(3), the circumradius of the equilateral
triangle of side h.

The mesher is neither copyable nor movable (its parts refer to each other);
build it where it is used, or hold it by pointer.
*/
template <class CDT_,
          class SizingField_ = Advancing_front_mesh_2::Uniform_sizing_field_2<typename CDT_::Geom_traits>,
          class Visitor_ = Advancing_front_mesh_2::Default_visitor,
          class PointIndex_ = Default,
          class CircleIndex_ = Default>
class Advancing_front_mesher_2
{
public:
  typedef CDT_ CDT;
  typedef CDT_ Triangulation;
  typedef SizingField_ Sizing_field;
  typedef Visitor_ Visitor;
  typedef typename Default::Get<PointIndex_, Advancing_front_mesh_2::internal::Dynamic_point_quadtree>::type
    Point_index;
  typedef typename Default::Get<CircleIndex_, Advancing_front_mesh_2::internal::Lifted_circle_octree<> >::type
    Circle_index;
  typedef typename CDT::Geom_traits Geom_traits;
  typedef typename Geom_traits::FT FT;
  typedef typename CDT::Point Point;
  typedef typename CDT::Vertex_handle Vertex_handle;
  typedef typename CDT::Face_handle Face_handle;
  typedef typename CDT::Triangulation_data_structure Tds;
  typedef std::list<Point> Seeds;
  typedef typename Seeds::const_iterator Seeds_const_iterator;
  typedef Advancing_front_mesh_2::Mesh_sink_2<Point> Mesh_sink;
  /// What `read_checkpoint_info()` and `resume()` return.
  typedef Advancing_front_mesh_2::Checkpoint_info Checkpoint_info;

private:
  typedef Advancing_front_mesh_2::internal::Advancing_front_refiner<CDT, Sizing_field, Visitor, Point_index,
                                                                    Circle_index>
    Refiner;

public:
  /// Whether the search structures can be saved, which checkpoints need
  /// (true with the default ones).
  static constexpr bool supports_checkpoints = Refiner::supports_checkpoints;

  /// \name Creation
  /// @{

  /*!
  Creates a mesher for `cdt`. The triangulation must stay alive and must not
  be modified by anything else while the mesher works on it.
  */
  explicit Advancing_front_mesher_2(CDT& cdt, const Sizing_field& sizing = Sizing_field(),
                                    const Visitor& visitor = Visitor())
    : refiner_(cdt, sizing, visitor)
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
    refiner_.seeds.assign(b, e);
    refiner_.seeds_mark = mark;
    refiner_.keep_domain_marks = false;
    refiner_.invalidate();
  }

  void clear_seeds()
  {
    refiner_.seeds.clear();
    refiner_.seeds_mark = false;
    refiner_.keep_domain_marks = false;
    refiner_.invalidate();
  }

  /*!
  Takes the domain from the faces' in-domain marks (`is_in_domain()`) as
  they are when meshing starts, instead of from the seeds: for a domain that
  no set of seeds describes, such as one part of a decomposed domain
  (`advancing_front_mesh_2_in_parallel()` marks each part so). The marked
  faces must be bounded by constrained edges. The constraints are then not
  split to the size field (`set_constraint_splitting()` is ignored: the
  faces a split makes could not be marked again); split them beforehand
  with `split_constraints_to_size_2()` and mark the domain afterwards (the
  split may replace faces even where it inserts no point). `set_seeds()`
  and `clear_seeds()` turn it off.
  */
  void use_domain_marks()
  {
    refiner_.seeds.clear();
    refiner_.seeds_mark = false;
    refiner_.keep_domain_marks = true;
    refiner_.invalidate();
  }

  Seeds_const_iterator seeds_begin() const { return refiner_.seeds.begin(); }
  Seeds_const_iterator seeds_end() const { return refiner_.seeds.end(); }

  /// @}

  /// \name Limits
  /// @{

  /// Stops after `n` front edges have been processed (0: no limit).
  void set_iteration_limit(std::size_t n) { refiner_.iteration_limit = n; }
  /// Stops after `seconds` seconds of meshing (0: no limit).
  void set_time_limit(double seconds) { refiner_.time_limit = seconds; }

  /// Measures the time of each phase into `statistics().phase_times`
  /// (off by default: it reads the clock at every phase change).
  void set_phase_timing(bool on) { refiner_.set_phase_timing(on); }

  /*!
  Splits the constraints that bound or cross the domain to the sizing field
  before the front is built (on by default): the boundary discretisation of
  `split_constraints_to_size_2()`, so that a boundary given by a few long
  segments is meshed at the size asked for. Off, every input segment is one
  edge of the initial front, as in the paper, and the mesh is coarse and
  poor wherever segments are much longer than the local size. The splits
  made are in `constraint_split_statistics()`.
  */
  void set_constraint_splitting(bool on)
  {
    refiner_.split_constraints = on;
    refiner_.invalidate();
  }
  bool constraint_splitting() const { return refiner_.split_constraints; }
  /// what the boundary discretisation of the last `init()` did
  const Advancing_front_mesh_2::Constraint_split_statistics& constraint_split_statistics() const
  {
    return refiner_.split_statistics;
  }

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
  void set_pocket_priority(bool on) { refiner_.set_pocket_priority(on); }
  bool pocket_priority() const { return refiner_.pocket_priority(); }

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
  void set_output_sink(Mesh_sink* sink) { refiner_.set_output_sink(sink); }
  Mesh_sink* output_sink() const { return refiner_.output_sink(); }

  /// In streaming mode, the triangles in memory are searched for finished
  /// ones after `n` new triangles (default 4096), or after as many as
  /// stayed in memory at the previous search if that is more: smaller
  /// values hold fewer triangles in memory and search more often.
  void set_sweep_interval(std::size_t n) { refiner_.set_sweep_interval(n); }

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

  \throws std::logic_error if `every != 0` and the search structures cannot
  be saved (`supports_checkpoints` is false).
  */
  void set_checkpoint(std::size_t every, const std::string& file_name, const std::string& user_data = std::string(),
                      bool stop = false)
  {
    refiner_.set_checkpoint(every, file_name, user_data, stop);
  }

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
    return Refiner::read_checkpoint_info(file_name);
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

  \throws std::logic_error if the triangulation is not empty, no sink is set,
  or the search structures cannot be saved (`supports_checkpoints` is false)
  \throws std::runtime_error "FILE: ..." if the file cannot be read, is
  corrupt (its checksum is checked) or was written with another kernel.
  */
  Checkpoint_info resume(const std::string& file_name) { return refiner_.resume(file_name); }

  /*!
  Writes a checkpoint now (streaming mode, between steps); see `set_checkpoint()`.

  \throws Advancing_front_mesh_2::Checkpoint_error if the file or the
  sink's state cannot be written; nothing else changes then.
  \throws std::logic_error without streaming mode, after the end, when a
  coordinate is not a double, or when the search structures cannot be saved.
  */
  void write_checkpoint(const std::string& file_name, const std::string& user_data = std::string())
  {
    refiner_.write_checkpoint(file_name, user_data, on_init());
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
  Advancing_front_mesh_2::Mesh_return_code refine_mesh() { return refiner_.refine_mesh(on_init()); }

  /*!
  Marks the domain from the seeds, removes the in-domain faces and builds
  the initial front from the constrained edges that bound the domain.
  Called by `refine_mesh()` and `step_by_step_refine_mesh()` when needed.
  */
  void init() { refiner_.init(on_init()); }

  /*!
  Processes one front edge. Returns `false` when the mesh is complete
  (then the triangulation is valid again). Between two calls the
  triangulation data structure is partial: only the faces behind the front
  exist, so it must not be used through the triangulation's own functions
  (locate, insert, is_valid) before this function has returned `false`.
  */
  bool step_by_step_refine_mesh() { return refiner_.step_by_step(on_init()); }

  /// Returns `true` when the front is empty and the mesh complete.
  bool is_refinement_done() const { return refiner_.is_initialized() && refiner_.is_finished(); }

  /// @}

  /// \name Access
  /// @{

  const CDT& triangulation() const { return refiner_.triangulation(); }
  const Sizing_field& sizing_field() const { return refiner_.sizing_field(); }
  const Visitor& visitor() const { return refiner_.visitor(); }
  Visitor& visitor() { return refiner_.visitor(); }
  const Advancing_front_mesh_2::Statistics& statistics() const { return refiner_.statistics(); }
  /// number of front edges now
  std::size_t front_size() const { return refiner_.front_size(); }

  /*!
  Checks the front invariants (for tests and debugging, O(front size)):
  every front vertex has as many incoming as outgoing front edges, every
  front edge is recorded at both end points, and every front edge's face on
  the meshed side really has that edge; and the records of the active
  vertices (which are renumbered when memory is released) agree: every id
  not free names a vertex that maps back to it, with its coordinates and a
  place in the point index.
  */
  bool is_front_valid() const { return refiner_.is_front_valid(); }

  /// @}

private:
  // the visitor sees the mesher itself when the front is built
  auto on_init()
  {
    return [this] { refiner_.visitor().on_init(*this); };
  }

  Refiner refiner_;
};


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
  `Advancing_front_mesh_2::Size_criteria_sizing_field_2` for the mapping);
  a criteria object's shape bound `B` (the squared sine of the smallest
  angle; 0.125, 20.7 degrees, by default) is kept too: after the frontal
  pass, `Advancing_front_mesh_2::refine_to_minimum_angle_2()` raises the
  smallest angle to it (at most 30 degrees; none for `B == 0`), so a Mesh_2
  user who switches keeps Mesh_2's guarantee
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
  \cgalParamNBegin{protect_constraints}
    \cgalParamDescription{if `true`, the input constraints are not split: every
      one stays an edge of the mesh, as in the paper (Triangle's `-Y`); if
      `false`, constraints longer than the local size are split to the size
      first, as Mesh_2 splits them (see `split_constraints_to_size_2()`)}
    \cgalParamDefault{`false`}
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
  const bool split = !choose_parameter(get_parameter(np, internal_np::protect_constraints), false);
  mesher.set_constraint_splitting(split);
  const Advancing_front_mesh_2::Mesh_return_code code = mesher.refine_mesh();
  // a Mesh_2 criteria object's shape bound: Mesh_2's guarantee, kept
  const double angle = Maker::minimum_angle(size);
  if(code == Advancing_front_mesh_2::MESH_COMPLETE && angle > 0)
    Advancing_front_mesh_2::refine_to_minimum_angle_2(cdt, angle, split);
  return code;
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
