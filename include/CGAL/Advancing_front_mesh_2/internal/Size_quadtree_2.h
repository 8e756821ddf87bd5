// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_SIZE_QUADTREE_2_H
#define CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_SIZE_QUADTREE_2_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <CGAL/Bbox_2.h>
#include <CGAL/Quadtree.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/assertions.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Advancing_front_mesh_2 {
namespace internal {

// The background quadtree of section 5 of Mavriplis (1992), Fig. 10: a CGAL
// Quadtree refined about a set of points, 2:1 balanced, turned into a graph
// of cell corners on which a size is stored, and sampled by descending the
// tree and interpolating bilinearly between the corners of the leaf.
//
// Corners are addressed by integer coordinates at the finest level, so that
// two leaves share a corner exactly when they share its key. A corner lying
// in the middle of a side of a larger leaf is "hanging": its value is the
// mean of that side's end points, which keeps the sampled field continuous.
class Size_quadtree_2
{
public:
  typedef Simple_cartesian<double> K;
  typedef K::Point_2 Point;

  // Axis directions of the corner graph.
  enum Direction { LEFT = 0, RIGHT = 1, DOWN = 2, UP = 3 };

  struct Corner
  {
    Point point;                                   // rounded; for display and nearest-corner choices
    std::array<int, 4> neighbor{{-1, -1, -1, -1}}; // nearest corner along each axis direction
    // in cells of the finest level (at most 2^30), so that the Laplacian's
    // weights neither overflow nor underflow whatever the coordinates; see
    // finest_cell_width() for the length of one cell
    std::array<double, 4> distance{{0, 0, 0, 0}};
    int parent[2] = {-1, -1};                     // end points of the side a hanging corner splits
    bool is_hanging() const { return parent[0] >= 0; }
  };

  // Nodes deeper than this are not split: the tree's global coordinates are
  // 32-bit integers, and 2^-30 of the domain is far below any useful size.
  static constexpr std::size_t max_depth = 30;

  // `split` decides from a leaf's box and depth whether it must be split;
  // it is called by the refinement with `points_in_node` filled with the
  // indices (into `points`) of the points the cell contains.
  typedef std::function<bool(const Bbox_2&, std::size_t depth,
                             const std::vector<std::size_t>& points_in_node)> Split_rule;

  Size_quadtree_2(const std::vector<Point>& points, const Split_rule& split)
    : points_(points)
  {
    CGAL_precondition(!points_.empty());
    indices_.resize(points_.size());
    for(std::size_t i = 0; i < indices_.size(); ++i) indices_[i] = i;
    tree_.reset(new Tree(indices_, Point_map(&points_)));
    std::vector<std::size_t> in_node;
    tree_->refine([&](const Node& node) {
      if(node.depth() >= max_depth) return false;
      in_node.assign(node.begin(), node.end());
      return split(tree_->bbox(node), node.depth(), in_node);
    });
    // CGAL 5.5's grade() is a single pass: a neighbour it splits is not
    // looked at again, and may stay two levels coarser than a leaf next to
    // it. A pass that splits nothing has checked every pair.
    for(std::size_t leaves = count_leaves();;) {
      tree_->grade();
      const std::size_t after = count_leaves();
      if(after == leaves) break;
      leaves = after;
    }
    finest_ = tree_->depth();
    build_corner_graph();
  }

  Size_quadtree_2(const Size_quadtree_2&) = delete;
  Size_quadtree_2& operator=(const Size_quadtree_2&) = delete;

  const std::vector<Corner>& corners() const { return corners_; }
  std::size_t number_of_leaves() const { return leaves_.size(); }
  double finest_cell_width() const { return unit_; }
  Bbox_2 root_box() const { return tree_->bbox(tree_->root()); }

  // The corner indices of the leaf containing `p` (clamped to the root box),
  // ordered lower-left, lower-right, upper-left, upper-right, and the box.
  std::pair<const std::array<int, 4>*, Bbox_2> leaf_at(const Point& p) const
  {
    const Node leaf = tree_->locate(clamp(p));
    const auto it = leaves_.find(leaf_key(leaf));
    CGAL_assertion(it != leaves_.end());
    return std::make_pair(&it->second, tree_->bbox(leaf));
  }

  // Bilinear interpolation of per-corner values; exact wherever the four
  // corner values are equal (the lerps then add zero).
  double interpolate(const std::vector<double>& value, const Point& p) const
  {
    const Point q = clamp(p);
    const auto leaf = leaf_at(q);
    const std::array<int, 4>& c = *leaf.first;
    const Bbox_2& b = leaf.second;
    const double tx = std::clamp((q.x() - b.xmin()) / (b.xmax() - b.xmin()), 0., 1.);
    const double ty = std::clamp((q.y() - b.ymin()) / (b.ymax() - b.ymin()), 0., 1.);
    const double v0 = value[c[0]] + tx * (value[c[1]] - value[c[0]]);
    const double v1 = value[c[2]] + tx * (value[c[3]] - value[c[2]]);
    return v0 + ty * (v1 - v0);
  }

  // The corners of the leaf containing `p`.
  const std::array<int, 4>& leaf_corners(const Point& p) const { return *leaf_at(p).first; }

  template <class OutputIterator>
  OutputIterator leaf_boxes(OutputIterator out) const
  {
    for(const Node& leaf : tree_->traverse(Orthtrees::Leaves_traversal()))
      *out++ = tree_->bbox(leaf);
    return out;
  }

  // Values of hanging corners set to the mean of their parents, larger sides
  // first, since a parent may itself hang on a side twice as long.
  void interpolate_hanging_corners(std::vector<double>& value) const
  {
    for(int i : hanging_by_decreasing_side_) {
      const Corner& c = corners_[i];
      value[i] = 0.5 * (value[c.parent[0]] + value[c.parent[1]]);
    }
  }

  const std::vector<int>& hanging_by_decreasing_side() const { return hanging_by_decreasing_side_; }

private:
  struct Point_map
  {
    typedef std::size_t key_type;
    typedef Point value_type;
    typedef const Point& reference;
    typedef boost::readable_property_map_tag category;
    const std::vector<Point>* points = nullptr;
    Point_map() = default;
    explicit Point_map(const std::vector<Point>* p) : points(p) {}
    friend reference get(const Point_map& m, std::size_t i) { return (*m.points)[i]; }
  };
  typedef Quadtree<K, std::vector<std::size_t>, Point_map> Tree;
  typedef typename Tree::Node Node;

  static std::uint64_t key(std::uint64_t ix, std::uint64_t iy) { return (ix << 32) | iy; }

  // A leaf is identified by its lower-left corner at the finest level: two
  // leaves cannot share it.
  std::uint64_t leaf_key(const Node& leaf) const
  {
    const std::size_t shift = finest_ - leaf.depth();
    return key(std::uint64_t(leaf.global_coordinates()[0]) << shift,
               std::uint64_t(leaf.global_coordinates()[1]) << shift);
  }

  Point clamp(const Point& p) const
  {
    const Bbox_2 b = root_box();
    double x = p.x(), y = p.y();
    if(!(x >= b.xmin())) x = b.xmin(); // also catches NaN
    if(!(y >= b.ymin())) y = b.ymin();
    if(x > b.xmax()) x = b.xmax();
    if(y > b.ymax()) y = b.ymax();
    return Point(x, y);
  }

  int corner_index(std::uint64_t ix, std::uint64_t iy, const Bbox_2& root, double unit)
  {
    auto inserted = corner_of_key_.emplace(key(ix, iy), int(corners_.size()));
    if(inserted.second) {
      Corner c;
      c.point = Point(root.xmin() + double(ix) * unit, root.ymin() + double(iy) * unit);
      corners_.push_back(c);
    }
    return inserted.first->second;
  }

  std::size_t count_leaves() const
  {
    std::size_t n = 0;
    for(const Node& leaf : tree_->traverse(Orthtrees::Leaves_traversal())) {
      (void)leaf;
      ++n;
    }
    return n;
  }

  void connect(int a, int b, Direction a_to_b, std::uint64_t cells)
  {
    static const Direction opposite[4] = {RIGHT, LEFT, UP, DOWN};
    const double d = double(cells);
    auto keep_nearest = [&](int from, int to, Direction dir) {
      Corner& c = corners_[from];
      if(c.neighbor[dir] < 0 || d < c.distance[dir]) {
        c.neighbor[dir] = to;
        c.distance[dir] = d;
      }
    };
    keep_nearest(a, b, a_to_b);
    keep_nearest(b, a, opposite[a_to_b]);
  }

  void build_corner_graph()
  {
    const Bbox_2 root = root_box();
    const double unit = (root.xmax() - root.xmin()) / double(std::uint64_t(1) << finest_);
    unit_ = unit;
    struct Leaf_extent { std::uint64_t x0, y0, w; };
    std::vector<Leaf_extent> extents;
    for(const Node& leaf : tree_->traverse(Orthtrees::Leaves_traversal())) {
      const std::size_t shift = finest_ - leaf.depth();
      const Leaf_extent e{std::uint64_t(leaf.global_coordinates()[0]) << shift,
                          std::uint64_t(leaf.global_coordinates()[1]) << shift,
                          std::uint64_t(1) << shift};
      std::array<int, 4> c{{corner_index(e.x0, e.y0, root, unit), corner_index(e.x0 + e.w, e.y0, root, unit),
                            corner_index(e.x0, e.y0 + e.w, root, unit),
                            corner_index(e.x0 + e.w, e.y0 + e.w, root, unit)}};
      leaves_.emplace(key(e.x0, e.y0), c);
      extents.push_back(e);
    }
    // Sides: split at a midpoint corner when the neighbour across is finer
    // (the 2:1 balance allows no more than one such corner per side).
    std::vector<std::pair<std::uint64_t, int> > hanging_side; // (side length, corner)
    for(const Leaf_extent& e : extents) {
      const std::array<int, 4>& c = leaves_.at(key(e.x0, e.y0));
      const std::uint64_t h = e.w / 2;
      struct Side { int a, b; std::uint64_t mx, my; Direction dir; };
      const Side sides[4] = {{c[0], c[1], e.x0 + h, e.y0, RIGHT},
                             {c[2], c[3], e.x0 + h, e.y0 + e.w, RIGHT},
                             {c[0], c[2], e.x0, e.y0 + h, UP},
                             {c[1], c[3], e.x0 + e.w, e.y0 + h, UP}};
      for(const Side& s : sides) {
        const auto m = (h > 0) ? corner_of_key_.find(key(s.mx, s.my)) : corner_of_key_.end();
        // 2:1 balance: no corner at a quarter of the side
        CGAL_assertion(h < 2 || (s.dir == RIGHT ? corner_of_key_.count(key(s.mx - h / 2, s.my)) +
                                                  corner_of_key_.count(key(s.mx + h / 2, s.my))
                                                : corner_of_key_.count(key(s.mx, s.my - h / 2)) +
                                                  corner_of_key_.count(key(s.mx, s.my + h / 2))) == 0);
        if(m == corner_of_key_.end()) {
          connect(s.a, s.b, s.dir, e.w);
        } else {
          Corner& mc = corners_[m->second];
          if(!mc.is_hanging()) hanging_side.emplace_back(e.w, m->second);
          mc.parent[0] = s.a;
          mc.parent[1] = s.b;
          connect(s.a, m->second, s.dir, h);
          connect(m->second, s.b, s.dir, h);
        }
      }
    }
    std::sort(hanging_side.begin(), hanging_side.end(),
              [](const std::pair<std::uint64_t, int>& a, const std::pair<std::uint64_t, int>& b) {
                return a.first > b.first;
              });
    for(const auto& hs : hanging_side) hanging_by_decreasing_side_.push_back(hs.second);
  }

  std::vector<Point> points_;
  std::vector<std::size_t> indices_;
  std::unique_ptr<Tree> tree_; // the tree refers to indices_ and points_: never copied
  std::size_t finest_ = 0;
  double unit_ = 0;
  std::unordered_map<std::uint64_t, int> corner_of_key_;
  std::unordered_map<std::uint64_t, std::array<int, 4> > leaves_;
  std::vector<Corner> corners_;
  std::vector<int> hanging_by_decreasing_side_;
};

} // namespace internal
} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_SIZE_QUADTREE_2_H
