// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_POISSON_SIZING_FIELD_2_H
#define CGAL_ADVANCING_FRONT_MESH_2_POISSON_SIZING_FIELD_2_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <CGAL/Advancing_front_mesh_2/internal/Size_gradation_limiter.h>
#include <CGAL/Advancing_front_mesh_2/internal/Size_quadtree_2.h>
#include <CGAL/Advancing_front_mesh_2/internal/Size_quadtree_laplace_solver.h>

#include <CGAL/Bbox_2.h>
#include <CGAL/Fuzzy_iso_box.h>
#include <CGAL/Kd_tree.h>
#include <CGAL/Orthogonal_incremental_neighbor_search.h>
#include <CGAL/Search_traits_2.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/number_utils.h>
#include <CGAL/property_map.h>

#include <boost/tuple/tuple.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <utility>
#include <vector>

namespace CGAL {
namespace Advancing_front_mesh_2 {

/*!
\ingroup PkgAdvancingFrontMesh2Sizing

A point source of the background size field: the target edge length `size`
is prescribed at `point`.
*/
template <class GeomTraits>
struct Size_source_2
{
  typedef typename GeomTraits::FT FT;
  typedef typename GeomTraits::Point_2 Point_2;

  Point_2 point;
  FT size;

  Size_source_2() : point(), size(1) {}
  Size_source_2(const Point_2& p, const FT& h) : point(p), size(h) {}
};

/*!
\ingroup PkgAdvancingFrontMesh2Sizing

Options of `Poisson_sizing_field_2`.
*/
struct Poisson_sizing_field_options
{
  /// the default gradation limit (see `gradation`).
  static constexpr double default_gradation = 0.2;

  /// How the spacing of the boundary points enters the field.
  enum Boundary_spacing_mode
  {
    /// Held at the boundary points and grown away from each of them at the
    /// gradation rate, up to the field of the sources, or up to the extent
    /// of the points when there is no source: a fine boundary feature only
    /// refines its own neighbourhood. Needs the gradation limit.
    GROW_FROM_BOUNDARY,
    /// Held at the boundary points as Dirichlet values of the Laplace solve,
    /// together with the sources: the field of Mavriplis (1992), section 5.
    /// A fine feature then lowers the field logarithmically far away.
    DIFFUSE_WITH_SOURCES
  };

  /// how the boundary spacing enters the field (default: grown).
  Boundary_spacing_mode boundary_spacing = GROW_FROM_BOUNDARY;

  /// whether the gradation limit is applied (on by default).
  bool limit_gradation = true;

  /// the gradation limit `G`: after the solve, the field is lowered where
  /// needed so that it changes by at most `G` times the distance along each
  /// axis (so by at most `sqrt(2) G` times the distance in any direction).
  /// With `G = 0.2`, neighbouring triangles differ in size by about 20% at
  /// most. Must be positive.
  double gradation = default_gradation;

  /// an upper bound on the field, applied last (default: none).
  double max_size = std::numeric_limits<double>::infinity();

  /// a lower bound on the field, applied last (default: none).
  double min_size = 0;

  /// whether the Laplace equation is solved for `log h` rather than for `h`
  /// (the default). Sizes then blend geometrically: halfway between a source
  /// of size 0.01 and one of size 1 the field is about 0.1, not 0.5, which
  /// keeps the fine region about a small source from collapsing, as a
  /// harmonic `h` does in 2D. The field stays exact at sources and between
  /// the smallest and largest prescribed size either way.
  bool logarithmic = true;

  /// the background quadtree's leaves containing a boundary point are no
  /// wider than this fraction of the spacing there. Smaller values follow
  /// the boundary spacing more closely at the cost of a larger tree.
  double boundary_resolution = 0.5;
};

/*!
\ingroup PkgAdvancingFrontMesh2Sizing

The background size field of section 5 of Mavriplis (1992): point sources and
the spacing of the boundary discretization are diffused over the plane by a
Laplace (Poisson, with the sources as its right-hand side) equation solved on
a quadtree built about the boundary points, and the field is sampled by
descending the tree and interpolating bilinearly between the corners of the
leaf (the paper's Fig. 10; the approach follows Pirzadeh, AIAA 91-3233, where
the sources are heat sources held at a fixed temperature). By default the
boundary spacing is grown from the boundary rather than diffused (see
<b>The boundary spacing</b> below).

<b>Construction.</b> The quadtree (a `CGAL::Quadtree`) is refined until
every leaf containing a boundary point of spacing `s` is at most
`boundary_resolution * s` wide, and about each source until the source's leaf
is at most half its size wide and separated from every other source and
boundary point by a few leaves; it is then 2:1 balanced. The four corners of
a source's leaf are held at the source's size, so the field reproduces every
source exactly at the source. The corner nearest to a boundary point (among
those that do not lie in the middle of a larger leaf's side) is held at the
boundary spacing there, so the field agrees with the boundary
discretization; a source overrides a boundary point that would hold the same
corner. Corners lying in the middle of a larger leaf's side take the mean of
that side's ends, so the field is continuous. The other corners solve the
five-point Laplacian with zero flux through the sides of the root box; the
discretization satisfies the discrete maximum principle, so the solved field
lies between the smallest and the largest prescribed size. The linear system
is solved with Eigen's sparse LU.

<b>The boundary spacing</b> is, by default
(`Poisson_sizing_field_options::GROW_FROM_BOUNDARY`), not diffused: the
Laplace equation holds the sources only (or, with no source, the field
starts at the points' extent), the corners nearest the boundary points are
then set to the spacing, and the gradation limit below grows the field from
them, so that it is the smallest of the sources' field and
`s_i + G |p - b_i|` over the boundary points `b_i` of spacing `s_i` (up to
`sqrt(2) G` along the diagonals). A fine boundary feature then refines only
its neighbourhood. With `DIFFUSE_WITH_SOURCES` the corners nearest the
boundary points are Dirichlet values of the Laplace solve, as described
above, which is the paper's field; one fine feature then lowers the field
over the whole domain, logarithmically.

<b>Gradation.</b> A harmonic field falls off logarithmically about a small
source, faster than a mesh can follow. By default a gradation limit
(Lipschitz bound) `G = 0.2` is applied on top: corner values are lowered,
never raised, until the field changes by at most `G` per unit length along
each axis of every leaf. The field at a source may then be lower than the
source's size, when a smaller source nearby demands it. With the limit off,
the mesher still meshes any field, but its triangles lose quality where the
field changes faster than about one size per element (Mavriplis's Fig. 9).

<b>Sampling</b> costs one descent of the quadtree and one hash lookup. Points
outside the tree's box are clamped to it. The field is held through a shared
pointer: copies are cheap and share the tree. All computations are in double
precision, whatever the kernel.

Sources at the same position are merged (the smaller size wins). The tree is
at most 30 levels deep: sources placed more than about a million boundary
spacings away from the boundary enlarge the tree's box so much that the
boundary resolution above can no longer be reached, and the field then
follows the boundary spacing only approximately.

\cgalModels `AdvancingFrontSizingField_2`

\tparam GeomTraits a model of `Kernel`; only `FT`, `Point_2` and
`CGAL::to_double` of the coordinates are used.

\sa `Sizing_field_mesh_criteria_2`, to drive `CGAL::refine_Delaunay_mesh_2()`
with the same field, and `boundary_spacing_2()`.
*/
template <class GeomTraits>
class Poisson_sizing_field_2
{
public:
  typedef typename GeomTraits::FT FT;
  typedef typename GeomTraits::Point_2 Point_2;
  typedef Size_source_2<GeomTraits> Source;

  /// Figures about the construction of the field.
  struct Statistics
  {
    std::size_t number_of_sources = 0;         ///< after merging coincident ones
    std::size_t number_of_boundary_points = 0;
    std::size_t number_of_leaves = 0;
    std::size_t number_of_corners = 0;          ///< unknowns of the Laplace system
    std::size_t number_of_fixed_corners = 0;    ///< Dirichlet corners
    std::size_t corners_lowered_by_gradation = 0;
    double tree_seconds = 0, solve_seconds = 0, gradation_seconds = 0;
    double smallest_size = 0, largest_size = 0; ///< over the corners, after gradation
  };

  /*!
  builds the field from boundary points with their spacing and from point
  sources.

  \tparam BoundaryRange a range of `std::pair<Point_2, FT>` (a point and the
  boundary spacing there), for example the output of `boundary_spacing_2()`.
  \tparam SourceRange a range of `Size_source_2<GeomTraits>` or of
  `std::pair<Point_2, FT>`.

  \pre at least one boundary point or source.
  \throws std::invalid_argument naming the offending entry if a size is not
  a positive finite number, a coordinate is not finite, both ranges are empty,
  the points span more than the largest double, or an option is out of range
  (gradation not positive, `max_size` below `min_size`, `GROW_FROM_BOUNDARY`
  without the gradation limit).
  \throws std::runtime_error if Eigen cannot factorise the Laplace system
  (not observed; the matrix is a nonsingular M-matrix).
  */
  template <class BoundaryRange, class SourceRange>
  Poisson_sizing_field_2(const BoundaryRange& boundary, const SourceRange& sources,
                         const Poisson_sizing_field_options& options = Poisson_sizing_field_options())
    : data_(std::make_shared<Data>())
  {
    Data& d = *data_;
    check_options(options);
    std::vector<Point> bpts;
    std::vector<double> bsize;
    std::size_t k = 0;
    for(const auto& b : boundary) {
      add_checked(bpts, bsize, point_of(b), size_of(b), "boundary point", k++);
    }
    std::vector<Point> spts;
    std::vector<double> ssize;
    k = 0;
    for(const auto& s : sources) {
      add_checked(spts, ssize, point_of(s), size_of(s), "source", k++);
    }
    if(bpts.empty() && spts.empty())
      throw std::invalid_argument("background size field: no boundary point and no source");
    merge_coincident_sources(spts, ssize);
    d.stats.number_of_sources = spts.size();
    d.stats.number_of_boundary_points = bpts.size();
    d.gradation = options.limit_gradation ? options.gradation : 0.;
    d.min_size = options.min_size;
    d.max_size = options.max_size;
    build(d, bpts, bsize, spts, ssize, options);
  }

  /// returns the size at `p`.
  FT operator()(const Point_2& p) const
  {
    const Data& d = *data_;
    const double x = CGAL::to_double(p.x()), y = CGAL::to_double(p.y());
    if(!d.tree) return FT(d.constant);
    return FT(d.tree->interpolate(d.value, typename Tree::Point((x - d.origin_x) / d.span, (y - d.origin_y) / d.span)));
  }

  /// the gradation limit applied, or 0 when the limit is off.
  double gradation() const { return data_->gradation; }

  /// figures about the construction.
  const Statistics& statistics() const { return data_->stats; }

  /// writes the boxes (`CGAL::Bbox_2`) of the quadtree's leaves to `out`
  /// (nothing when all the input points coincide and the field is constant).
  template <class OutputIterator>
  OutputIterator leaf_boxes(OutputIterator out) const
  {
    if(!data_->tree) return out;
    std::vector<Bbox_2> boxes;
    data_->tree->leaf_boxes(std::back_inserter(boxes));
    const Data& d = *data_;
    for(const Bbox_2& b : boxes)
      *out++ = Bbox_2(d.origin_x + b.xmin() * d.span, d.origin_y + b.ymin() * d.span,
                      d.origin_x + b.xmax() * d.span, d.origin_y + b.ymax() * d.span);
    return out;
  }

private:
  typedef internal::Size_quadtree_2 Tree;
  typedef Tree::Point Point;

  struct Data
  {
    std::unique_ptr<Tree> tree;
    std::vector<double> value;
    double constant = 0;
    double gradation = 0, min_size = 0, max_size = 0;
    // The tree is built on coordinates mapped to [0, 1]^2, so that no
    // squared distance under- or overflows and the field is the same at
    // every scale; sizes stay in the user's units.
    double origin_x = 0, origin_y = 0, span = 1;
    Statistics stats;
  };

  template <class P, class S>
  static const P& point_of(const std::pair<P, S>& e) { return e.first; }
  template <class P, class S>
  static const S& size_of(const std::pair<P, S>& e) { return e.second; }
  static const Point_2& point_of(const Source& s) { return s.point; }
  static const FT& size_of(const Source& s) { return s.size; }

  static void check_options(const Poisson_sizing_field_options& o)
  {
    if(o.limit_gradation && !(o.gradation > 0 && std::isfinite(o.gradation)))
      throw std::invalid_argument("background size field: the gradation limit must be a positive number");
    if(!o.limit_gradation && o.boundary_spacing == Poisson_sizing_field_options::GROW_FROM_BOUNDARY)
      throw std::invalid_argument("background size field: growing the boundary spacing needs the gradation limit "
                                  "(or boundary_spacing = DIFFUSE_WITH_SOURCES)");
    if(!(o.min_size >= 0) || std::isnan(o.max_size) || !(o.max_size >= o.min_size) || !(o.max_size > 0))
      throw std::invalid_argument("background size field: need 0 <= min_size <= max_size and max_size > 0");
    if(!(o.boundary_resolution > 0 && std::isfinite(o.boundary_resolution)))
      throw std::invalid_argument("background size field: boundary_resolution must be a positive number");
  }

  template <class P, class S>
  static void add_checked(std::vector<Point>& pts, std::vector<double>& sizes, const P& p, const S& s,
                          const char* what, std::size_t index)
  {
    const double x = CGAL::to_double(p.x()), y = CGAL::to_double(p.y()), h = CGAL::to_double(s);
    if(!std::isfinite(x) || !std::isfinite(y) || !(h > 0) || !std::isfinite(h)) {
      std::ostringstream os;
      os << "background size field: " << what << " " << index << " at (" << x << ", " << y << ") has ";
      if(!std::isfinite(x) || !std::isfinite(y)) os << "a non-finite coordinate";
      else os << "size " << h << ", which is not a positive finite number";
      throw std::invalid_argument(os.str());
    }
    pts.emplace_back(x, y);
    sizes.push_back(h);
  }

  static void merge_coincident_sources(std::vector<Point>& pts, std::vector<double>& sizes)
  {
    std::map<std::pair<double, double>, double> merged;
    for(std::size_t i = 0; i < pts.size(); ++i) {
      auto it = merged.emplace(std::make_pair(pts[i].x(), pts[i].y()), sizes[i]).first;
      it->second = (std::min)(it->second, sizes[i]);
    }
    pts.clear();
    sizes.clear();
    for(const auto& m : merged) {
      pts.emplace_back(m.first.first, m.first.second);
      sizes.push_back(m.second);
    }
  }

  // The width to which the tree is refined about each source: half its size,
  // and small enough that the source's leaf and its neighbours hold no other
  // prescribed point (boundary points closer than half the source's size are
  // the source's to override).
  static std::vector<double> source_resolutions(const std::vector<Point>& bpts, const std::vector<Point>& spts,
                                                const std::vector<double>& ssize, double finest_width)
  {
    typedef boost::tuple<Point, std::size_t> Point_and_id;
    typedef Search_traits_2<Tree::K> Base_traits;
    typedef Search_traits_adapter<Point_and_id, Nth_of_tuple_property_map<0, Point_and_id>, Base_traits> Traits;
    typedef Orthogonal_incremental_neighbor_search<Traits> Search;
    typedef typename Search::Tree Kd;
    std::vector<Point_and_id> all;
    for(std::size_t i = 0; i < bpts.size(); ++i) all.emplace_back(bpts[i], i);
    for(std::size_t i = 0; i < spts.size(); ++i) all.emplace_back(spts[i], bpts.size() + i);
    Kd kd(all.begin(), all.end());
    std::vector<double> w(spts.size());
    for(std::size_t i = 0; i < spts.size(); ++i) {
      double separation = std::numeric_limits<double>::infinity();
      Search search(kd, spts[i]);
      for(auto it = search.begin(); it != search.end(); ++it) {
        const std::size_t j = boost::get<1>(it->first);
        const double dist = std::sqrt(it->second);
        if(dist >= 4 * ssize[i]) break; // separation / 8 would exceed the size / 2 anyway
        if(j >= bpts.size()) {
          if(j - bpts.size() == i || ssize[j - bpts.size()] == ssize[i]) continue;
        } else if(dist < 0.5 * ssize[i]) {
          continue;
        }
        separation = dist;
        break;
      }
      w[i] = (std::max)((std::min)(0.5 * ssize[i], separation / 8), finest_width);
    }
    return w;
  }

  static double seconds_since(std::chrono::steady_clock::time_point t)
  {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
  }

  // The points and sizes in the unit frame of their extent (the field's
  // internal frame), with the sizes as given (in the user's units).
  struct Frame_input
  {
    std::vector<Point> bpts, spts;       // boundary points and sources, normalised
    std::vector<double> bsize, ssize;    // their sizes, normalised
    std::vector<double> raw_bsize, raw_ssize;
  };

  static void build(Data& d, const std::vector<Point>& raw_bpts, const std::vector<double>& raw_bsize,
                    const std::vector<Point>& raw_spts, const std::vector<double>& ssize_in_units,
                    const Poisson_sizing_field_options& options)
  {
    const auto t0 = std::chrono::steady_clock::now();
    Frame_input in;
    if(!normalise(d, raw_bpts, raw_bsize, raw_spts, ssize_in_units, in)) return;
    build_tree(d, in, options);
    d.stats.tree_seconds = seconds_since(t0);
    const auto t1 = std::chrono::steady_clock::now();
    std::vector<char> fixed, by_source;
    hold_prescribed_corners(d, in, fixed, by_source);
    if(options.boundary_spacing == Poisson_sizing_field_options::GROW_FROM_BOUNDARY)
      fill_from_sources(d, fixed, by_source, options);
    else
      solve(d, fixed, options);
    d.stats.solve_seconds = seconds_since(t1);
    const auto t2 = std::chrono::steady_clock::now();
    if(d.gradation > 0)
      d.stats.corners_lowered_by_gradation = internal::limit_size_gradation(*d.tree, d.gradation, d.value, d.span);
    for(double& v : d.value) v = (std::min)(d.max_size, (std::max)(d.min_size, v));
    d.stats.gradation_seconds = seconds_since(t2);
    d.stats.smallest_size = *std::min_element(d.value.begin(), d.value.end());
    d.stats.largest_size = *std::max_element(d.value.begin(), d.value.end());
  }

  // The frame of the points' extent; false when they are one point, and
  // the field is then the constant smallest size.
  static bool normalise(Data& d, const std::vector<Point>& raw_bpts, const std::vector<double>& raw_bsize,
                        const std::vector<Point>& raw_spts, const std::vector<double>& ssize_in_units,
                        Frame_input& in)
  {
    Bbox_2 extent;
    for(const Point& p : raw_bpts) extent += p.bbox();
    for(const Point& p : raw_spts) extent += p.bbox();
    const double span = (std::max)(extent.xmax() - extent.xmin(), extent.ymax() - extent.ymin());
    if(!std::isfinite(1.2 * span))
      throw std::invalid_argument("background size field: the points span more than the largest double");
    if(!(span > 0)) { // one point: nothing to diffuse
      double h = std::numeric_limits<double>::infinity();
      for(double s : raw_bsize) h = (std::min)(h, s);
      for(double s : ssize_in_units) h = (std::min)(h, s);
      d.constant = (std::min)(d.max_size, (std::max)(d.min_size, h));
      d.stats.smallest_size = d.stats.largest_size = d.constant;
      return false;
    }
    d.origin_x = extent.xmin();
    d.origin_y = extent.ymin();
    d.span = span;
    auto to_frame = [&](const std::vector<Point>& pts, const std::vector<double>& sizes, std::vector<Point>& out,
                        std::vector<double>& out_sizes) {
      for(std::size_t i = 0; i < pts.size(); ++i) {
        out.emplace_back((pts[i].x() - d.origin_x) / span, (pts[i].y() - d.origin_y) / span);
        out_sizes.push_back(sizes[i] / span);
      }
    };
    to_frame(raw_bpts, raw_bsize, in.bpts, in.bsize);
    to_frame(raw_spts, ssize_in_units, in.spts, in.ssize);
    in.raw_bsize = raw_bsize;
    in.raw_ssize = ssize_in_units;
    return true;
  }

  // The quadtree, refined about the boundary points to their spacing over
  // `boundary_resolution`, and about each source to its resolution.
  static void build_tree(Data& d, const Frame_input& in, const Poisson_sizing_field_options& options)
  {
    std::vector<Point> all(in.bpts);
    all.insert(all.end(), in.spts.begin(), in.spts.end());
    const double root_width = 1.2; // Orthtree's default enlargement of the unit span
    const double finest_width = root_width / double(std::uint64_t(1) << Tree::max_depth);
    const std::vector<double> wsrc = source_resolutions(in.bpts, in.spts, in.ssize, finest_width);

    // Sources are looked up by box in a Kd-tree, so that many sources cost
    // little during refinement.
    typedef boost::tuple<Point, std::size_t> Point_and_id;
    typedef Search_traits_2<Tree::K> Base_traits;
    typedef Search_traits_adapter<Point_and_id, Nth_of_tuple_property_map<0, Point_and_id>, Base_traits> Traits;
    std::vector<Point_and_id> sp;
    for(std::size_t i = 0; i < in.spts.size(); ++i) sp.emplace_back(in.spts[i], i);
    Kd_tree<Traits> source_tree(sp.begin(), sp.end());
    std::vector<Point_and_id> found;

    const std::size_t nb = in.bpts.size();
    const double resolution = options.boundary_resolution;
    auto split = [&](const Bbox_2& box, std::size_t depth, const std::vector<std::size_t>& inside) {
      if(depth < 3) return true; // a minimal resolution everywhere
      const double width = box.xmax() - box.xmin();
      for(std::size_t i : inside)
        if(i < nb && width > resolution * in.bsize[i]) return true;
      if(in.spts.empty()) return false;
      found.clear();
      const Point lo(box.xmin() - 3 * width, box.ymin() - 3 * width);
      const Point hi(box.xmax() + 3 * width, box.ymax() + 3 * width);
      source_tree.search(std::back_inserter(found), Fuzzy_iso_box<Traits>(Point_and_id(lo, 0), Point_and_id(hi, 0)));
      for(const Point_and_id& f : found) {
        const std::size_t s = boost::get<1>(f);
        if(width <= wsrc[s]) continue;
        const Point& c = in.spts[s];
        const double dx = (std::max)({box.xmin() - c.x(), 0., c.x() - box.xmax()});
        const double dy = (std::max)({box.ymin() - c.y(), 0., c.y() - box.ymax()});
        if((std::max)(dx, dy) <= 3 * wsrc[s]) return true;
      }
      return false;
    };
    d.tree.reset(new Tree(all, split));
    d.stats.number_of_leaves = d.tree->number_of_leaves();
    d.stats.number_of_corners = d.tree->corners().size();
  }

  // The Dirichlet corners: sources first, they override boundary points.
  static void hold_prescribed_corners(Data& d, const Frame_input& in, std::vector<char>& fixed,
                                      std::vector<char>& by_source)
  {
    const Tree& tree = *d.tree;
    const std::vector<Tree::Corner>& corners = tree.corners();
    fixed.assign(corners.size(), 0);
    by_source.assign(corners.size(), 0);
    d.value.assign(corners.size(), 0.);
    std::function<void(int, double)> hold = [&](int c, double h) {
      if(by_source[c]) d.value[c] = (std::min)(d.value[c], h);
      else d.value[c] = h;
      fixed[c] = by_source[c] = 1;
      // A held corner in the middle of a larger side would break continuity
      // unless the side's ends are held too.
      if(corners[c].is_hanging()) {
        hold(corners[c].parent[0], h);
        hold(corners[c].parent[1], h);
      }
    };
    for(std::size_t s = 0; s < in.spts.size(); ++s)
      for(int c : tree.leaf_corners(in.spts[s])) hold(c, in.raw_ssize[s]);
    for(std::size_t i = 0; i < in.bpts.size(); ++i) {
      int best = -1;
      double best_d = std::numeric_limits<double>::infinity();
      for(int c : tree.leaf_corners(in.bpts[i])) {
        if(corners[c].is_hanging()) continue;
        const double dd = squared_distance(corners[c].point, in.bpts[i]);
        if(dd < best_d) { best_d = dd; best = c; }
      }
      if(best < 0 || by_source[best]) continue;
      d.value[best] = fixed[best] ? (std::min)(d.value[best], in.raw_bsize[i]) : in.raw_bsize[i];
      fixed[best] = 1;
    }
    d.stats.number_of_fixed_corners = std::size_t(std::count(fixed.begin(), fixed.end(), 1));
  }

  // GROW_FROM_BOUNDARY: the sources' field alone (Laplace between the
  // sources' corners, or the points' extent everywhere when there is no
  // source), with the boundary spacing held on top. The gradation limit
  // that follows then lowers every corner to at most the smallest held
  // value plus G times the distance: the field grows from each boundary
  // point until it meets the sources' field, whatever the other boundary
  // points are.
  static void fill_from_sources(Data& d, const std::vector<char>& fixed, const std::vector<char>& by_source,
                                const Poisson_sizing_field_options& options)
  {
    const std::vector<double> held = d.value;
    if(std::find(by_source.begin(), by_source.end(), char(1)) != by_source.end())
      solve(d, by_source, options);
    else
      std::fill(d.value.begin(), d.value.end(), d.span); // the extent, in the user's units
    for(std::size_t i = 0; i < d.value.size(); ++i)
      if(fixed[i] && !by_source[i]) d.value[i] = held[i];
  }

  // Laplace's equation between the held corners, on the sizes or on their
  // logarithms.
  static void solve(Data& d, const std::vector<char>& fixed, const Poisson_sizing_field_options& options)
  {
    const Tree& tree = *d.tree;
    if(!options.logarithmic) {
      internal::solve_laplace_on_quadtree(tree, fixed, d.value);
      return;
    }
    const std::vector<double> prescribed = d.value;
    for(std::size_t i = 0; i < d.value.size(); ++i)
      if(fixed[i]) d.value[i] = std::log(d.value[i]);
    internal::solve_laplace_on_quadtree(tree, fixed, d.value);
    // exp(log(h)) need not give h back to the last bit: prescribed corners
    // take their size as given.
    for(std::size_t i = 0; i < d.value.size(); ++i) d.value[i] = fixed[i] ? prescribed[i] : std::exp(d.value[i]);
    tree.interpolate_hanging_corners(d.value);
  }

  std::shared_ptr<Data> data_;
};

/*!
\ingroup PkgAdvancingFrontMesh2Sizing

writes to `out`, for every vertex of `cdt` incident to a constrained edge,
the pair (point, mean length of its constrained edges): the spacing of the
boundary discretization, from which `Poisson_sizing_field_2` makes a field
that agrees with the boundary.

\tparam CDT a `CGAL::Constrained_Delaunay_triangulation_2` or
`CGAL::Constrained_triangulation_plus_2`.
\tparam OutputIterator accepts `std::pair<CDT::Point, CDT::Geom_traits::FT>`.
*/
template <class CDT, class OutputIterator>
OutputIterator boundary_spacing_2(const CDT& cdt, OutputIterator out)
{
  typedef typename CDT::Vertex_handle Vertex_handle;
  typedef typename CDT::Geom_traits::FT FT;
  std::map<Vertex_handle, std::pair<double, int> > sum;
  for(const auto& e : cdt.constrained_edges()) {
    const Vertex_handle a = e.first->vertex(CDT::cw(e.second));
    const Vertex_handle b = e.first->vertex(CDT::ccw(e.second));
    const double l = std::sqrt(CGAL::to_double(CGAL::squared_distance(a->point(), b->point())));
    for(Vertex_handle v : {a, b}) {
      auto& s = sum[v];
      s.first += l;
      ++s.second;
    }
  }
  for(const auto& s : sum)
    *out++ = std::make_pair(s.first->point(), FT(s.second.first / s.second.second));
  return out;
}

} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_POISSON_SIZING_FIELD_2_H
