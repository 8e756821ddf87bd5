// The boundary-graded size of the tests (afm_test::Boundary_graded_size:
// h(p) = min over boundary points i of s_i + g |p - x_i|, at most h_max),
// evaluated through a k-d tree instead of a loop over all boundary points.
// It returns exactly the same numbers: the same expression is evaluated for
// every boundary point that can attain the minimum, and a subtree is skipped
// only when a lower bound of its values (its smallest s_i plus g times the
// distance to its box, both computed with monotone operations) is not below
// the best value found. The MESH2D islands have 6,700 boundary points: the
// brute-force field would make the benchmark measure the field rather than
// the meshers (Gmsh's size callback calls it for every candidate point).
#ifndef AFM_BENCHMARK_BOUNDARY_GRADED_SIZE_TREE_H
#define AFM_BENCHMARK_BOUNDARY_GRADED_SIZE_TREE_H

#include "afm_test_mesh.h"

#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <vector>

namespace afm_bench {

template <class K>
class Boundary_graded_size_tree
{
  struct Node
  {
    double xmin, ymin, xmax, ymax, smin;
    std::size_t begin, end; // range of sources_; a leaf when child < 0
    int child = -1;         // the first child; the second is child + 1
  };
  struct Data
  {
    std::vector<std::array<double, 3> > sources; // x, y, spacing
    std::vector<Node> nodes;
    double grading = 0.2, h_max = 1e300;
  };

public:
  explicit Boundary_graded_size_tree(const afm_test::Boundary_graded_size<K>& brute_force)
    : d_(std::make_shared<Data>())
  {
    d_->sources = brute_force.sources;
    d_->grading = brute_force.grading;
    d_->h_max = brute_force.h_max;
    d_->nodes.reserve(2 * d_->sources.size() / leaf_size + 2);
    if(!d_->sources.empty()) {
      d_->nodes.emplace_back();
      build(0, 0, d_->sources.size());
    }
  }

  typename K::FT operator()(const typename K::Point_2& p) const
  {
    const double x = CGAL::to_double(p.x()), y = CGAL::to_double(p.y());
    const Data& d = *d_;
    double h = d.h_max;
    if(d.nodes.empty()) return typename K::FT(h);
    int stack[128];
    int top = 0;
    stack[top++] = 0;
    while(top > 0) {
      const Node& n = d.nodes[std::size_t(stack[--top])];
      const double dx = (std::max)(0., (std::max)(n.xmin - x, x - n.xmax));
      const double dy = (std::max)(0., (std::max)(n.ymin - y, y - n.ymax));
      if(n.smin + d.grading * std::hypot(dx, dy) >= h) continue;
      if(n.child < 0) {
        for(std::size_t i = n.begin; i < n.end; ++i) {
          const auto& s = d.sources[i];
          h = (std::min)(h, s[2] + d.grading * std::hypot(x - s[0], y - s[1]));
        }
        continue;
      }
      // the nearer child last, so that it is visited first
      const Node& a = d.nodes[std::size_t(n.child)];
      const Node& b = d.nodes[std::size_t(n.child + 1)];
      const bool a_nearer = box_distance2(a, x, y) <= box_distance2(b, x, y);
      stack[top++] = a_nearer ? n.child + 1 : n.child;
      stack[top++] = a_nearer ? n.child : n.child + 1;
    }
    return typename K::FT(h);
  }

private:
  static constexpr std::size_t leaf_size = 8;

  static double box_distance2(const Node& n, double x, double y)
  {
    const double dx = (std::max)(0., (std::max)(n.xmin - x, x - n.xmax));
    const double dy = (std::max)(0., (std::max)(n.ymin - y, y - n.ymax));
    return dx * dx + dy * dy;
  }

  // Fills node `id` with sources [begin, end): median split along the
  // longer side, down to leaves of at most leaf_size sources. The depth is
  // about log2(n / leaf_size), far below the query stack's 128 entries.
  void build(std::size_t id, std::size_t begin, std::size_t end)
  {
    auto& s = d_->sources;
    Node n;
    n.begin = begin;
    n.end = end;
    n.xmin = n.ymin = n.smin = 1e300;
    n.xmax = n.ymax = -1e300;
    for(std::size_t i = begin; i < end; ++i) {
      n.xmin = (std::min)(n.xmin, s[i][0]);
      n.xmax = (std::max)(n.xmax, s[i][0]);
      n.ymin = (std::min)(n.ymin, s[i][1]);
      n.ymax = (std::max)(n.ymax, s[i][1]);
      n.smin = (std::min)(n.smin, s[i][2]);
    }
    if(end - begin <= leaf_size) {
      d_->nodes[id] = n;
      return;
    }
    const int axis = (n.xmax - n.xmin >= n.ymax - n.ymin) ? 0 : 1;
    const std::size_t mid = begin + (end - begin) / 2;
    std::nth_element(s.begin() + std::ptrdiff_t(begin), s.begin() + std::ptrdiff_t(mid),
                     s.begin() + std::ptrdiff_t(end),
                     [axis](const std::array<double, 3>& a, const std::array<double, 3>& b) { return a[axis] < b[axis]; });
    // the two children side by side
    n.child = int(d_->nodes.size());
    d_->nodes.emplace_back();
    d_->nodes.emplace_back();
    d_->nodes[id] = n;
    build(std::size_t(n.child), begin, mid);
    build(std::size_t(n.child) + 1, mid, end);
  }

  std::shared_ptr<Data> d_; // shared: the meshers copy their sizing fields
};

} // namespace afm_bench

#endif // AFM_BENCHMARK_BOUNDARY_GRADED_SIZE_TREE_H
