// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_SAMPLED_SIZING_FIELD_2_H
#define CGAL_ADVANCING_FRONT_MESH_2_SAMPLED_SIZING_FIELD_2_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Advancing_front_mesh_2 {

/*!
\ingroup PkgAdvancingFrontMesh2Sizing

A sizing field sampled from a function that evaluates many points at once:
a Python or NumPy function, a GPU kernel, a field read from a file. The
mesher asks for the size at one point at a time, millions of times; a
function with a high cost per call (a Python call is several microseconds)
would dominate the meshing time. This field calls it a few times, on arrays
of points, and answers the mesher from what it sampled.

The samples are the corners of a quadtree over the box given: a cell is
split (all new corners of one level are evaluated in one call) while it is
larger than `cell_ratio` times the smallest size at its corners and centre,
so that the cells near a point are at most twice the size there (by
default), and the field is the
bilinear interpolation of the four corners of the leaf containing the point.
Detail of the function finer than the cells is not seen. Outside the box the nearest point of the box is used.

The function receives `n` points as `2n` doubles `x0 y0 x1 y1 ...` and
writes `n` sizes; every size must be a positive finite number.

\cgalModels `AdvancingFrontSizingField_2`

\tparam GeomTraits the kernel of the mesh
*/
template <class GeomTraits>
class Sampled_sizing_field_2
{
public:
  typedef typename GeomTraits::FT FT;
  typedef typename GeomTraits::Point_2 Point_2;
  /// evaluates `n` points (`xy`, `2n` doubles) into `h` (`n` doubles)
  typedef std::function<void(const double* xy, std::size_t n, double* h)> Bulk_function;

  /*!
  samples `f` over the box `[xmin, xmax] x [ymin, ymax]` (made square about
  its centre).

  \param max_leaves the most leaves the quadtree may have: a function
  returning sizes far below the box's extent would otherwise ask for
  unbounded memory. Where the limit stops the refinement, cells stay larger
  than the size (the field is then coarser than asked there).

  \throws std::invalid_argument if the box is empty or not finite, or `f`
  returns a size that is not a positive finite number (the message gives the
  point)
  */
  Sampled_sizing_field_2(const Bulk_function& f, double xmin, double ymin, double xmax, double ymax,
                         double cell_ratio = 2.0, std::size_t max_leaves = 1u << 22)
  {
    if(!(xmax > xmin) || !(ymax > ymin) || !std::isfinite(xmax - xmin) || !std::isfinite(ymax - ymin))
      throw std::invalid_argument("Sampled_sizing_field_2: the box must be finite and not empty");
    if(!(cell_ratio > 0) || !std::isfinite(cell_ratio))
      throw std::invalid_argument("Sampled_sizing_field_2: cell_ratio must be positive and finite");
    const double side = (std::max)(xmax - xmin, ymax - ymin);
    x0_ = 0.5 * (xmin + xmax) - 0.5 * side;
    y0_ = 0.5 * (ymin + ymax) - 0.5 * side;
    side_ = side;
    build(f, cell_ratio, max_leaves);
  }

  /// the interpolated size at `p`
  FT operator()(const Point_2& p) const { return FT(at(CGAL::to_double(p.x()), CGAL::to_double(p.y()))); }

  /// the interpolated size at `(x, y)`
  double at(double x, double y) const
  {
    const double u = (std::min)((std::max)((x - x0_) / side_, 0.), 1.);
    const double v = (std::min)((std::max)((y - y0_) / side_, 0.), 1.);
    std::size_t node = 0;
    while(nodes_[node].child != none) {
      const Node& n = nodes_[node];
      const double half = 0.5 * n.size;
      const int qx = u >= n.u + half ? 1 : 0, qy = v >= n.v + half ? 1 : 0;
      node = n.child + std::size_t(qx + 2 * qy);
    }
    const Node& n = nodes_[node];
    const double s = (std::min)((std::max)((u - n.u) / n.size, 0.), 1.);
    const double t = (std::min)((std::max)((v - n.v) / n.size, 0.), 1.);
    const double* c = n.corner_value.data();
    return (1 - s) * (1 - t) * c[0] + s * (1 - t) * c[1] + (1 - s) * t * c[2] + s * t * c[3];
  }

  /// the number of leaves of the quadtree
  std::size_t number_of_leaves() const { return leaves_; }
  /// the number of points the function evaluated
  std::size_t number_of_samples() const { return samples_.size(); }
  /// the number of calls of the function
  std::size_t number_of_calls() const { return calls_; }

private:
  static constexpr std::size_t none = (std::numeric_limits<std::size_t>::max)();
  static constexpr int max_depth = 30;

  struct Node
  {
    double u, v, size; // lower-left corner and side, in units of the root box
    int depth;
    std::size_t child = none; // the first of four children, ordered (0,0) (1,0) (0,1) (1,1)
    std::array<double, 4> corner_value{{0, 0, 0, 0}};
    double centre_value = 0;
  };

  // Integer lattice keys of the finest level: exact, whatever the depth.
  static std::uint64_t key(const Node& n, int cx, int cy)
  {
    const double scale = double(std::uint64_t(1) << max_depth);
    const std::uint64_t ix = std::uint64_t((n.u + cx * 0.5 * n.size) * scale + 0.5);
    const std::uint64_t iy = std::uint64_t((n.v + cy * 0.5 * n.size) * scale + 0.5);
    return (ix << 32) | iy;
  }

  // Evaluates the lattice points `keys` not sampled yet, in one call.
  void sample(const Bulk_function& f, const std::vector<std::uint64_t>& keys)
  {
    std::vector<std::uint64_t> fresh;
    std::vector<double> xy;
    for(std::uint64_t k : keys) {
      if(samples_.count(k)) continue;
      samples_.emplace(k, 0.);
      fresh.push_back(k);
      const double scale = double(std::uint64_t(1) << max_depth);
      xy.push_back(x0_ + side_ * double(k >> 32) / scale);
      xy.push_back(y0_ + side_ * double(k & 0xffffffffu) / scale);
    }
    if(fresh.empty()) return;
    std::vector<double> h(fresh.size(), std::numeric_limits<double>::quiet_NaN());
    ++calls_;
    f(xy.data(), fresh.size(), h.data());
    for(std::size_t i = 0; i < fresh.size(); ++i) {
      if(!(h[i] > 0) || !std::isfinite(h[i])) {
        std::ostringstream os;
        os.precision(17);
        os << "Sampled_sizing_field_2: the size function returned " << h[i] << " at (" << xy[2 * i] << ", "
           << xy[2 * i + 1] << "); sizes must be positive finite numbers";
        throw std::invalid_argument(os.str());
      }
      samples_[fresh[i]] = h[i];
    }
  }

  void fill(Node& n) const
  {
    for(int c = 0; c < 4; ++c) n.corner_value[std::size_t(c)] = samples_.at(key(n, 2 * (c % 2), 2 * (c / 2)));
    n.centre_value = samples_.at(key(n, 1, 1));
  }

  // the corners and the centre of a cell
  static std::array<std::uint64_t, 5> keys_of(const Node& n)
  {
    return {{key(n, 0, 0), key(n, 2, 0), key(n, 0, 2), key(n, 2, 2), key(n, 1, 1)}};
  }

  // Level by level: the leaves of one level that are larger than the size
  // are split, and the corners and centres of all their children sampled in
  // one call.
  void build(const Bulk_function& f, double cell_ratio, std::size_t max_leaves)
  {
    nodes_.push_back(Node{0., 0., 1., 0});
    const std::array<std::uint64_t, 5> root_keys = keys_of(nodes_[0]);
    sample(f, std::vector<std::uint64_t>(root_keys.begin(), root_keys.end()));
    fill(nodes_[0]);
    leaves_ = 1;
    std::vector<std::size_t> level(1, 0);
    while(!level.empty()) {
      std::vector<std::size_t> split;
      for(std::size_t i : level) {
        const Node& n = nodes_[i];
        const double smallest = (std::min)(n.centre_value, *std::min_element(n.corner_value.begin(), n.corner_value.end()));
        // the centre of a cell of depth max_depth - 1 is the finest lattice point
        if(n.depth < max_depth - 1 && n.size * side_ > cell_ratio * smallest && leaves_ + 3 * (split.size() + 1) <= max_leaves)
          split.push_back(i);
      }
      std::vector<std::uint64_t> keys;
      std::vector<std::size_t> next;
      for(std::size_t i : split) {
        nodes_[i].child = nodes_.size();
        const Node parent = nodes_[i];
        for(int c = 0; c < 4; ++c) {
          Node child{parent.u + 0.5 * parent.size * (c % 2), parent.v + 0.5 * parent.size * (c / 2), 0.5 * parent.size,
                     parent.depth + 1};
          const std::array<std::uint64_t, 5> k = keys_of(child);
          keys.insert(keys.end(), k.begin(), k.end());
          next.push_back(nodes_.size());
          nodes_.push_back(child);
        }
        leaves_ += 3;
      }
      sample(f, keys);
      for(std::size_t i : next) fill(nodes_[i]);
      level.swap(next);
    }
  }

  double x0_ = 0, y0_ = 0, side_ = 1;
  std::vector<Node> nodes_;
  std::unordered_map<std::uint64_t, double> samples_;
  std::size_t leaves_ = 0, calls_ = 0;
};

} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_SAMPLED_SIZING_FIELD_2_H
