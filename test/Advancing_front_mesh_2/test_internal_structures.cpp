// The mesher's own containers, each against a plain reference under random
// operations: the id lists of the front, the flat hash map, the point
// quadtree of the close-point search and the lifted circle octree (with
// their merging of empty nodes). The mesher's tests exercise them too, but
// a wrong answer there shows only as a bad mesh far from its cause. The
// trees' checkpoints (save/load, exact to the order of the answers) and the
// binary streams under them are tested here too.
#include "afm_brute_force_indices.h"
#include "afm_test_harness.h"

#include <CGAL/Advancing_front_mesh_2/Kd_tree_point_index.h>

#include <CGAL/Advancing_front_mesh_2/internal/Binary_io.h>
#include <CGAL/Advancing_front_mesh_2/internal/Compact_id_list.h>
#include <CGAL/Advancing_front_mesh_2/internal/Dynamic_point_quadtree.h>
#include <CGAL/Advancing_front_mesh_2/internal/Double_geometry.h>
#include <CGAL/Advancing_front_mesh_2/internal/Finished_faces_check.h>
#include <CGAL/Advancing_front_mesh_2/internal/Flat_hash_map.h>
#include <CGAL/Advancing_front_mesh_2/internal/Front_predicates.h>
#include <CGAL/Advancing_front_mesh_2/internal/Lifted_circle_octree.h>
#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Exact_rational.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <cstdint>
#include <map>
#include <numeric>
#include <random>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <tuple>
#include <unordered_map>
#include <utility>
#include <vector>

namespace AFMI = CGAL::Advancing_front_mesh_2::internal;

AFM_TEST_CASE(test_internal_compact_id_list)
{
  std::mt19937 rng(7);
  std::vector<AFMI::Compact_id_list> lists(20);
  std::vector<std::multiset<std::uint32_t> > ref(20);
  for(int step = 0; step < 20000; ++step) {
    const std::size_t i = rng() % lists.size();
    if(ref[i].empty() || rng() % 2 == 0) {
      // grow past the inline capacity now and then
      if(ref[i].size() < 6) {
        const std::uint32_t id = rng() % 5;
        lists[i].push_back(id);
        ref[i].insert(id);
      }
    } else {
      auto it = ref[i].begin();
      std::advance(it, rng() % ref[i].size());
      lists[i].erase_value(*it);
      ref[i].erase(it);
    }
    if(step % 97 == 0) {
      // copies and moves keep the contents
      AFMI::Compact_id_list copy(lists[i]);
      AFMI::Compact_id_list moved(std::move(copy));
      lists[i] = moved;
    }
    AFM_CHECK_MSG(lists[i].size() == ref[i].size(), "step " << step);
    const std::multiset<std::uint32_t> got(lists[i].begin(), lists[i].end());
    AFM_CHECK_MSG(got == ref[i], "step " << step);
  }
  // a vector of lists survives reallocation
  for(int k = 0; k < 1000; ++k) {
    lists.emplace_back();
    lists.back().push_back(k);
    lists.back().push_back(k + 1);
    lists.back().push_back(k + 2);
  }
  for(int k = 0; k < 1000; ++k) {
    const AFMI::Compact_id_list& l = lists[20 + k];
    AFM_CHECK(l.size() == 3 && std::multiset<std::uint32_t>(l.begin(), l.end()) ==
                                 std::multiset<std::uint32_t>({std::uint32_t(k), std::uint32_t(k + 1), std::uint32_t(k + 2)}));
  }
}

AFM_TEST_CASE(test_internal_flat_hash_map)
{
  std::mt19937_64 rng(11);
  const std::uint64_t empty = ~std::uint64_t(0);
  AFMI::Flat_hash_map<std::uint64_t, int> map(empty);
  std::unordered_map<std::uint64_t, int> ref;
  for(int step = 0; step < 200000; ++step) {
    // keys like the mesher's: pairs of small vertex ids, in a range that
    // makes collisions and long probe runs common
    const std::uint64_t k = ((rng() % 300) << 32) | (rng() % 300);
    const int op = int(rng() % 3);
    if(op == 0) {
      if(ref.count(k) == 0) {
        map.insert(k, step);
        ref[k] = step;
      }
    } else if(op == 1) {
      AFM_CHECK(map.erase(k) == (ref.erase(k) == 1));
    } else {
      const int* v = map.find(k);
      auto it = ref.find(k);
      AFM_CHECK_MSG((v == nullptr) == (it == ref.end()), "step " << step);
      if(v != nullptr) AFM_CHECK(*v == it->second);
    }
    AFM_CHECK(map.size() == ref.size());
  }
  std::size_t seen = 0;
  map.for_each([&](std::uint64_t k, int v) {
    ++seen;
    AFM_CHECK(ref.count(k) == 1 && ref[k] == v);
  });
  AFM_CHECK(seen == ref.size());
}

AFM_TEST_CASE(test_internal_point_quadtree)
{
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> coord(0, 1);
  AFMI::Dynamic_point_quadtree tree;
  tree.reset(0, 0, 1, 1, 4);
  std::vector<std::array<double, 2> > pts(3000);
  std::vector<bool> in(pts.size(), false);
  for(auto& p : pts) p = {{coord(rng), coord(rng)}};
  // a few points outside the root box go to the overflow list
  pts[0] = {{-0.5, 0.5}};
  pts[1] = {{1.5, 2.0}};
  for(int round = 0; round < 6; ++round) {
    // sweep like a front: insert a band, remove the band before it
    for(std::size_t i = 0; i < pts.size(); ++i) {
      const double band = pts[i][0] * 6;
      if(band >= round && band < round + 1 && !in[i]) {
        tree.insert(i, pts[i][0], pts[i][1]);
        in[i] = true;
      }
      if(band < round && in[i] && rng() % 4 != 0) {
        tree.remove(i);
        in[i] = false;
      }
    }
    for(int q = 0; q < 200; ++q) {
      const double qx = coord(rng), qy = coord(rng), r = 0.2 * coord(rng);
      std::vector<std::size_t> got;
      tree.query(qx, qy, r, got);
      std::sort(got.begin(), got.end());
      AFM_CHECK_MSG(std::adjacent_find(got.begin(), got.end()) == got.end(), "duplicate report");
      for(std::size_t i = 0; i < pts.size(); ++i) {
        const double d = std::hypot(pts[i][0] - qx, pts[i][1] - qy);
        const bool reported = std::binary_search(got.begin(), got.end(), i);
        if(in[i] && d <= r) AFM_CHECK_MSG(reported, "round " << round << ": point " << i << " missed");
        if(reported) AFM_CHECK_MSG(in[i] && d <= r * (1 + 1e-6) + 1e-9, "point " << i << " reported wrongly");
      }
    }
    std::size_t count = 0;
    for(bool b : in) count += b;
    AFM_CHECK(tree.size() == count);
  }
  // empty quadrants merge back and their blocks are reused: the same
  // points inserted again make the same tree, without new nodes
  for(std::size_t i = 0; i < pts.size(); ++i)
    if(!in[i]) tree.insert(i, pts[i][0], pts[i][1]);
  const std::size_t nodes = tree.number_of_nodes();
  for(std::size_t i = 0; i < pts.size(); ++i) tree.remove(i);
  AFM_CHECK(tree.size() == 0);
  for(std::size_t i = 0; i < pts.size(); ++i) tree.insert(i, pts[i][0], pts[i][1]);
  AFM_CHECK_MSG(tree.number_of_nodes() == nodes, "merged node blocks were not reused: " << nodes << " -> "
                                                                                        << tree.number_of_nodes());
}

// The reach of a point (the mesher: its longest outgoing front edge) makes
// query_with_reach() report it for every disk within that reach, which is
// how the front edges near a disk are found; reaches go up and down, points
// come and go, and a few reaches are huge or NaN (reported everywhere).
AFM_TEST_CASE(test_internal_point_quadtree_reach)
{
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> coord(0, 1);
  AFMI::Dynamic_point_quadtree tree;
  tree.reset(0, 0, 1, 1, 4);
  const std::size_t n = 2000;
  std::vector<std::array<double, 2> > pts(n);
  std::vector<double> reach(n, 0.);
  std::vector<bool> in(n, false);
  for(auto& p : pts) p = {{coord(rng), coord(rng)}};
  pts[0] = {{1.5, -0.25}}; // outside the root box
  for(int round = 0; round < 8; ++round) {
    for(std::size_t i = 0; i < n; ++i) {
      if(!in[i] && rng() % 3 == 0) {
        tree.insert(i, pts[i][0], pts[i][1]);
        in[i] = true;
        reach[i] = 0;
      } else if(in[i] && rng() % 5 == 0) {
        tree.remove(i);
        in[i] = false;
      }
      if(in[i] && rng() % 2 == 0) {
        const unsigned kind = rng() % 100;
        reach[i] = kind == 0 ? std::numeric_limits<double>::quiet_NaN()
                 : kind == 1 ? 0.5
                             : 0.03 * coord(rng);
        tree.set_reach(i, reach[i]);
        const double stored = tree.reach(i);
        AFM_CHECK(std::isnan(reach[i]) ? stored == std::numeric_limits<double>::infinity() : stored == reach[i]);
      }
    }
    for(int q = 0; q < 150; ++q) {
      const double qx = coord(rng), qy = coord(rng), r = 0.1 * coord(rng);
      std::vector<std::size_t> got, got_in_disk;
      tree.query_with_reach(qx, qy, r, [&](std::size_t id, double px, double py, bool in_disk) {
        AFM_CHECK(px == pts[id][0] && py == pts[id][1]);
        got.push_back(id);
        if(in_disk) got_in_disk.push_back(id);
      });
      std::sort(got.begin(), got.end());
      std::sort(got_in_disk.begin(), got_in_disk.end());
      AFM_CHECK_MSG(std::adjacent_find(got.begin(), got.end()) == got.end(), "duplicate report");
      for(std::size_t i = 0; i < n; ++i) {
        const double d = std::hypot(pts[i][0] - qx, pts[i][1] - qy);
        const bool reported = std::binary_search(got.begin(), got.end(), i);
        const bool said_in_disk = std::binary_search(got_in_disk.begin(), got_in_disk.end(), i);
        const double within = std::isnan(reach[i]) ? std::numeric_limits<double>::infinity() : r + reach[i];
        if(in[i] && d <= within) AFM_CHECK_MSG(reported, "round " << round << ": point " << i << " missed");
        if(reported) AFM_CHECK_MSG(in[i] && d <= within * (1 + 1e-6) + 1e-9, "point " << i << " reported wrongly");
        if(in[i] && d <= r) AFM_CHECK_MSG(said_in_disk, "point " << i << " not marked in the disk");
        if(said_in_disk) AFM_CHECK_MSG(d <= r * (1 + 1e-6) + 1e-9, "point " << i << " marked in the disk wrongly");
      }
    }
  }
}

AFM_TEST_CASE(test_internal_lifted_circle_octree)
{
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> coord(0, 1);
  AFMI::Lifted_circle_octree<int> tree;
  tree.reset(-1, -1, 2, 2, 3, 4);
  struct C { double x, y, r; bool in; std::size_t item; };
  std::vector<C> circles(2500);
  for(auto& c : circles) {
    const double big = (rng() % 50 == 0) ? 1.0 : 0.03;
    c = C{coord(rng), coord(rng), big * coord(rng), false, 0};
  }
  circles[0].r = 10; // outside the root box: the overflow list
  for(int round = 0; round < 5; ++round) {
    for(std::size_t i = 0; i < circles.size(); ++i) {
      C& c = circles[i];
      const double band = c.x * 5;
      if(band >= round && band < round + 1 && !c.in) {
        c.item = tree.insert(c.x, c.y, c.r, int(i));
        c.in = true;
      }
      if(band < round && c.in && rng() % 3 != 0) {
        tree.remove(c.item);
        c.in = false;
      }
    }
    for(int q = 0; q < 200; ++q) {
      const double qx = coord(rng), qy = coord(rng), inflate = (q % 2) ? 0.05 * coord(rng) : 0.;
      std::vector<int> got;
      tree.query(qx, qy, inflate, [&got](int i) { got.push_back(i); });
      std::sort(got.begin(), got.end());
      for(std::size_t i = 0; i < circles.size(); ++i) {
        const C& c = circles[i];
        const bool reported = std::binary_search(got.begin(), got.end(), int(i));
        const double d = std::hypot(c.x - qx, c.y - qy);
        if(c.in && d < c.r + inflate) AFM_CHECK_MSG(reported, "round " << round << ": circle " << i << " missed");
        if(reported) AFM_CHECK_MSG(c.in && d <= (c.r + inflate) * (1 + 1e-6) + 1e-9, "circle " << i << " reported wrongly");
      }
    }
  }
  for(C& c : circles)
    if(!c.in) {
      c.item = tree.insert(c.x, c.y, c.r, 0);
      c.in = true;
    }
  const std::size_t nodes = tree.number_of_nodes();
  for(C& c : circles) tree.remove(c.item);
  AFM_CHECK(tree.size() == 0);
  for(std::size_t i = 0; i < circles.size(); ++i) tree.insert(circles[i].x, circles[i].y, circles[i].r, int(i));
  AFM_CHECK_MSG(tree.number_of_nodes() <= nodes, "merged node blocks were not reused: " << nodes << " -> "
                                                                                        << tree.number_of_nodes());

  // Radii are divided only where they differ by more than half a leaf's
  // width: not for circles of one size spread out, but for circles of
  // sizes 1e-6 .. 1 about nearly one centre, which queries must still find.
  auto brute_force_agrees = [](const AFMI::Lifted_circle_octree<int>& t, const std::vector<C>& cs,
                               double qx, double qy, double inflate) {
    std::vector<int> got;
    t.query(qx, qy, inflate, [&got](int i) { got.push_back(i); });
    std::sort(got.begin(), got.end());
    for(std::size_t i = 0; i < cs.size(); ++i) {
      const double d = std::hypot(cs[i].x - qx, cs[i].y - qy);
      const bool reported = std::binary_search(got.begin(), got.end(), int(i));
      if(d < cs[i].r + inflate && !reported) return false;
      if(reported && d > (cs[i].r + inflate) * (1 + 1e-6) + 1e-9) return false;
    }
    return true;
  };
  AFMI::Lifted_circle_octree<int> uniform, nested;
  uniform.reset(-1, -1, 2, 2, 3, 4);
  nested.reset(-1, -1, 2, 2, 3, 4);
  std::vector<C> same(2000), sizes(400);
  for(std::size_t i = 0; i < same.size(); ++i) {
    same[i] = C{coord(rng), coord(rng), 0.01, true, 0};
    uniform.insert(same[i].x, same[i].y, same[i].r, int(i));
  }
  for(std::size_t i = 0; i < sizes.size(); ++i) {
    sizes[i] = C{0.5 + 1e-7 * coord(rng), 0.5 + 1e-7 * coord(rng), std::pow(10., -6 * coord(rng)), true, 0};
    nested.insert(sizes[i].x, sizes[i].y, sizes[i].r, int(i));
  }
  AFM_CHECK_MSG(uniform.number_of_radius_divisions() == 0, uniform.number_of_radius_divisions());
  AFM_CHECK(nested.number_of_radius_divisions() > 0);
  for(int q = 0; q < 300; ++q) {
    const double qx = coord(rng), qy = coord(rng), inflate = (q % 2) ? 0.02 * coord(rng) : 0.;
    AFM_CHECK_MSG(brute_force_agrees(uniform, same, qx, qy, inflate), "uniform, query " << q);
    // queries near the nested circles' centre, at distances of all scales
    const double dist = std::pow(10., -7 * coord(rng)), angle = 6.283 * coord(rng);
    AFM_CHECK_MSG(brute_force_agrees(nested, sizes, 0.5 + dist * std::cos(angle), 0.5 + dist * std::sin(angle), 0.),
                  "nested, query " << q);
  }
}

// Memory release: once the front has shrunk, the hash map shrinks and the
// trees are rebuilt at their current size (the trees renaming their items),
// and they answer as before.
AFM_TEST_CASE(test_internal_memory_release)
{
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> coord(0, 1);

  // hash map: grown to 8192 slots, shrunk to a quarter-full table
  const std::uint64_t empty = ~std::uint64_t(0);
  AFMI::Flat_hash_map<std::uint64_t, int> map(empty);
  for(int i = 0; i < 5000; ++i) map.insert(std::uint64_t(i) * 7919, i);
  const std::size_t full = map.memory();
  AFM_CHECK(!map.shrink_if_sparse());
  for(int i = 100; i < 5000; ++i) AFM_CHECK(map.erase(std::uint64_t(i) * 7919));
  AFM_CHECK(map.shrink_if_sparse());
  AFM_CHECK_MSG(8 * map.memory() <= full, map.memory() << " bytes of " << full);
  AFM_CHECK(!map.shrink_if_sparse());
  for(int i = 0; i < 5000; ++i) {
    const int* v = map.find(std::uint64_t(i) * 7919);
    AFM_CHECK_MSG((v != nullptr) == (i < 100), "key " << i);
    if(v != nullptr) AFM_CHECK(*v == i);
  }
  map.reserve(3000);
  const std::size_t reserved = map.memory();
  for(int i = 100; i < 3000; ++i) map.insert(std::uint64_t(i) * 7919, i);
  AFM_CHECK(map.memory() == reserved && map.size() == 3000);

  // point quadtree: a swept band of points left, renamed in reverse order
  AFMI::Dynamic_point_quadtree points;
  points.reset(0, 0, 1, 1, 4);
  const std::size_t n = 3000;
  std::vector<std::array<double, 2> > xy(n);
  std::vector<double> reach(n, 0.);
  std::vector<bool> live(n, false);
  for(std::size_t i = 0; i < n; ++i) {
    xy[i] = {{coord(rng), coord(rng)}};
    if(i == 0) xy[i] = {{1.5, 0.5}}; // the overflow list
    points.insert(i, xy[i][0], xy[i][1]);
    if(i % 3 == 0) reach[i] = 0.05 * coord(rng);
    if(i == 3) reach[i] = std::numeric_limits<double>::infinity();
    if(reach[i] != 0) points.set_reach(i, reach[i]);
    live[i] = true;
  }
  for(std::size_t i = 0; i < n; ++i)
    if(xy[i][0] < 0.9 && i != 3 && i != 0) {
      points.remove(i);
      live[i] = false;
    }
  std::vector<std::size_t> new_id(n, std::size_t(-1)), old_id;
  for(std::size_t i = n; i-- > 0;)
    if(live[i]) {
      new_id[i] = old_id.size();
      old_id.push_back(i);
    }
  const std::size_t nodes_before = points.number_of_nodes();
  points.renumber(new_id);
  AFM_CHECK(points.size() == old_id.size());
  AFM_CHECK_MSG(points.number_of_nodes() < nodes_before, points.number_of_nodes() << " nodes, " << nodes_before << " before");
  for(std::size_t w = 0; w < old_id.size(); ++w) {
    AFM_CHECK(points.contains(w));
    AFM_CHECK_MSG(points.reach(w) == reach[old_id[w]], "point " << old_id[w]);
  }
  for(int q = 0; q < 200; ++q) {
    const double qx = coord(rng), qy = coord(rng), r = 0.1 * coord(rng);
    std::vector<std::pair<std::size_t, bool> > got;
    points.query_with_reach(qx, qy, r, [&got](std::size_t id, double, double, bool in) { got.push_back({id, in}); });
    std::sort(got.begin(), got.end());
    for(std::size_t w = 0; w < old_id.size(); ++w) {
      const std::size_t i = old_id[w];
      const double d = std::hypot(xy[i][0] - qx, xy[i][1] - qy);
      auto it = std::lower_bound(got.begin(), got.end(), std::make_pair(w, false));
      const bool reported = it != got.end() && it->first == w;
      if(d <= r + reach[i]) AFM_CHECK_MSG(reported, "query " << q << ": point " << i << " missed");
      if(d <= r) AFM_CHECK_MSG(reported && it->second, "query " << q << ": point " << i << " not in the disk");
    }
    for(const auto& g : got) AFM_CHECK_MSG(g.first < old_id.size(), "unknown id " << g.first);
  }

  // circle octree: the live circles get new items, named to the caller
  AFMI::Lifted_circle_octree<int> circles;
  circles.reset(-1, -1, 2, 2, 3, 4);
  struct C { double x, y, r; std::size_t item; bool in; };
  std::vector<C> cs(2500);
  for(std::size_t i = 0; i < cs.size(); ++i) {
    cs[i] = C{coord(rng), coord(rng), 0.03 * coord(rng), 0, true};
    if(i == 0) cs[i].r = 10; // the overflow list
    cs[i].item = circles.insert(cs[i].x, cs[i].y, cs[i].r, int(i));
  }
  AFM_CHECK(!circles.is_sparse());
  for(std::size_t i = 1; i < cs.size(); ++i)
    if(cs[i].x < 0.85) {
      circles.remove(cs[i].item);
      cs[i].in = false;
    }
  AFM_CHECK(circles.is_sparse());
  const std::size_t octree_nodes_before = circles.number_of_nodes();
  std::vector<int> renamed(cs.size(), 0);
  std::set<std::size_t> items;
  circles.rebuild([&](int payload, std::size_t item) {
    ++renamed[payload];
    cs[payload].item = item;
    items.insert(item);
  });
  std::size_t live_circles = 0;
  for(std::size_t i = 0; i < cs.size(); ++i) {
    live_circles += cs[i].in;
    AFM_CHECK_MSG(renamed[i] == (cs[i].in ? 1 : 0), "circle " << i << " renamed " << renamed[i] << " times");
    if(cs[i].in) AFM_CHECK(circles.payload(cs[i].item) == int(i));
  }
  AFM_CHECK(items.size() == live_circles && circles.size() == live_circles && !circles.is_sparse());
  AFM_CHECK_MSG(circles.number_of_nodes() < octree_nodes_before,
                circles.number_of_nodes() << " nodes, " << octree_nodes_before << " before");
  for(int q = 0; q < 200; ++q) {
    const double qx = coord(rng), qy = coord(rng), inflate = (q % 2) ? 0.05 * coord(rng) : 0.;
    std::vector<int> got;
    circles.query(qx, qy, inflate, [&got](int i) { got.push_back(i); });
    std::sort(got.begin(), got.end());
    for(std::size_t i = 0; i < cs.size(); ++i) {
      const bool reported = std::binary_search(got.begin(), got.end(), int(i));
      const double d = std::hypot(cs[i].x - qx, cs[i].y - qy);
      if(cs[i].in && d < cs[i].r + inflate) AFM_CHECK_MSG(reported, "query " << q << ": circle " << i << " missed");
      if(reported) AFM_CHECK_MSG(cs[i].in, "query " << q << ": removed circle " << i << " reported");
    }
  }
  for(const C& c : cs)
    if(c.in) circles.remove(c.item);
  AFM_CHECK(circles.size() == 0);
}

// Checkpoints: a saved and reloaded tree must behave exactly as the tree
// saved, reporting the same points (circles) in the same order under any
// later operations, since that order breaks the mesher's ties.
namespace {

void write_int(AFMI::Binary_writer& w, const int& p) { w.write(p); }
int read_int(AFMI::Binary_reader& r) { return r.read<int>(); }

std::string saved_bytes(const AFMI::Dynamic_point_quadtree& t)
{
  std::ostringstream os;
  AFMI::Binary_writer w(os);
  t.save(w);
  return os.str();
}

std::string saved_bytes(const AFMI::Lifted_circle_octree<int>& t)
{
  std::ostringstream os;
  AFMI::Binary_writer w(os);
  t.save(w, write_int);
  return os.str();
}

void load_bytes(AFMI::Dynamic_point_quadtree& t, const std::string& bytes)
{
  std::istringstream is(bytes);
  AFMI::Binary_reader r(is, "quadtree.bin");
  t.load(r);
}

void load_bytes(AFMI::Lifted_circle_octree<int>& t, const std::string& bytes)
{
  std::istringstream is(bytes);
  AFMI::Binary_reader r(is, "octree.bin");
  t.load(r, read_int);
}

// The saved forms of the trees, read and written here field by field as
// save() writes them: to see what a saved tree holds, and to make corrupt
// ones by hand.
struct Saved_point_quadtree
{
  struct Place { std::int32_t node; std::uint32_t position; };
  struct Entry { double x, y, reach; std::size_t id; };
  struct Node
  {
    std::array<double, 4> box;
    double max_reach;
    std::int32_t first_child, parent, depth;
    std::vector<Entry> entries;
  };
  std::uint32_t tag, version;
  std::size_t bucket_size;
  int max_depth;
  double abs_pad;
  std::size_t size, number_of_queries;
  std::vector<Place> places;
  std::vector<Node> nodes;
  std::vector<Entry> overflow;
  std::vector<std::int32_t> free_blocks;

  static void read_entries(AFMI::Binary_reader& r, std::vector<Entry>& v)
  {
    v.resize(r.read<std::uint64_t>());
    for(Entry& e : v) e = Entry{r.read<double>(), r.read<double>(), r.read<double>(), r.read<std::size_t>()};
  }
  static void write_entries(AFMI::Binary_writer& w, const std::vector<Entry>& v)
  {
    w.write<std::uint64_t>(v.size());
    for(const Entry& e : v) {
      w.write(e.x);
      w.write(e.y);
      w.write(e.reach);
      w.write(e.id);
    }
  }
  explicit Saved_point_quadtree(const std::string& bytes)
  {
    std::istringstream is(bytes);
    AFMI::Binary_reader r(is, "quadtree.bin");
    tag = r.read<std::uint32_t>();
    version = r.read<std::uint32_t>();
    bucket_size = r.read<std::size_t>();
    max_depth = r.read<int>();
    abs_pad = r.read<double>();
    size = r.read<std::size_t>();
    number_of_queries = r.read<std::size_t>();
    places.resize(r.read<std::uint64_t>());
    for(Place& p : places) p = Place{r.read<std::int32_t>(), r.read<std::uint32_t>()};
    nodes.resize(r.read<std::uint64_t>());
    for(Node& n : nodes) {
      n.box = r.read<std::array<double, 4> >();
      n.max_reach = r.read<double>();
      n.first_child = r.read<std::int32_t>();
      n.parent = r.read<std::int32_t>();
      n.depth = r.read<std::int32_t>();
      read_entries(r, n.entries);
    }
    read_entries(r, overflow);
    r.read_vector(free_blocks, nodes.size());
    AFM_CHECK(is.peek() == std::char_traits<char>::eof());
  }
  std::string bytes() const
  {
    std::ostringstream os;
    AFMI::Binary_writer w(os);
    w.write(tag);
    w.write(version);
    w.write(bucket_size);
    w.write(max_depth);
    w.write(abs_pad);
    w.write(size);
    w.write(number_of_queries);
    w.write<std::uint64_t>(places.size());
    for(const Place& p : places) {
      w.write(p.node);
      w.write(p.position);
    }
    w.write<std::uint64_t>(nodes.size());
    for(const Node& n : nodes) {
      w.write(n.box);
      w.write(n.max_reach);
      w.write(n.first_child);
      w.write(n.parent);
      w.write(n.depth);
      write_entries(w, n.entries);
    }
    write_entries(w, overflow);
    w.write_vector(free_blocks);
    return os.str();
  }
};

struct Saved_circle_octree
{
  struct Item { std::uint8_t alive; int node; std::size_t position; int payload; };
  struct Entry { double x, y, r; std::size_t id; };
  struct Node
  {
    std::array<double, 6> box;
    double max_r, r_split;
    int first_child, parent, depth, children;
    std::vector<Entry> entries;
  };
  std::uint32_t tag, version;
  std::size_t bucket_size;
  int max_depth;
  double abs_pad;
  std::size_t size;
  std::vector<Item> items;
  std::vector<Node> nodes;
  std::vector<Entry> overflow;
  std::array<std::vector<int>, 2> free_blocks;
  std::vector<std::size_t> free_items;

  static void read_entries(AFMI::Binary_reader& r, std::vector<Entry>& v)
  {
    v.resize(r.read<std::uint64_t>());
    for(Entry& e : v) e = Entry{r.read<double>(), r.read<double>(), r.read<double>(), r.read<std::size_t>()};
  }
  static void write_entries(AFMI::Binary_writer& w, const std::vector<Entry>& v)
  {
    w.write<std::uint64_t>(v.size());
    for(const Entry& e : v) {
      w.write(e.x);
      w.write(e.y);
      w.write(e.r);
      w.write(e.id);
    }
  }
  explicit Saved_circle_octree(const std::string& bytes)
  {
    std::istringstream is(bytes);
    AFMI::Binary_reader r(is, "octree.bin");
    tag = r.read<std::uint32_t>();
    version = r.read<std::uint32_t>();
    bucket_size = r.read<std::size_t>();
    max_depth = r.read<int>();
    abs_pad = r.read<double>();
    size = r.read<std::size_t>();
    items.resize(r.read<std::uint64_t>());
    for(Item& it : items) {
      it.alive = r.read<std::uint8_t>();
      it.node = r.read<int>();
      it.position = r.read<std::size_t>();
      it.payload = it.alive ? r.read<int>() : 0;
    }
    nodes.resize(r.read<std::uint64_t>());
    for(Node& n : nodes) {
      n.box = r.read<std::array<double, 6> >();
      n.max_r = r.read<double>();
      n.r_split = r.read<double>();
      n.first_child = r.read<int>();
      n.parent = r.read<int>();
      n.depth = r.read<int>();
      n.children = r.read<int>();
      read_entries(r, n.entries);
    }
    read_entries(r, overflow);
    r.read_vector(free_blocks[0], nodes.size());
    r.read_vector(free_blocks[1], nodes.size());
    r.read_vector(free_items, items.size());
    AFM_CHECK(is.peek() == std::char_traits<char>::eof());
  }
  std::string bytes() const
  {
    std::ostringstream os;
    AFMI::Binary_writer w(os);
    w.write(tag);
    w.write(version);
    w.write(bucket_size);
    w.write(max_depth);
    w.write(abs_pad);
    w.write(size);
    w.write<std::uint64_t>(items.size());
    for(const Item& it : items) {
      w.write(it.alive);
      w.write(it.node);
      w.write(it.position);
      if(it.alive) w.write(it.payload);
    }
    w.write<std::uint64_t>(nodes.size());
    for(const Node& n : nodes) {
      w.write(n.box);
      w.write(n.max_r);
      w.write(n.r_split);
      w.write(n.first_child);
      w.write(n.parent);
      w.write(n.depth);
      w.write(n.children);
      write_entries(w, n.entries);
    }
    write_entries(w, overflow);
    w.write_vector(free_blocks[0]);
    w.write_vector(free_blocks[1]);
    w.write_vector(free_items);
    return os.str();
  }
};

// One random operation, the same on both trees, whose answers (in order)
// must agree.
void point_quadtree_step(std::mt19937& rng, const std::vector<std::array<double, 2> >& xy,
                         AFMI::Dynamic_point_quadtree& a, AFMI::Dynamic_point_quadtree& b)
{
  std::uniform_real_distribution<double> coord(0, 1);
  const std::size_t id = rng() % xy.size();
  AFM_CHECK(a.contains(id) == b.contains(id));
  const unsigned op = rng() % 10;
  if(op < 4) {
    a.insert(id, xy[id][0], xy[id][1]);
    b.insert(id, xy[id][0], xy[id][1]);
  } else if(op < 6) {
    a.remove(id);
    b.remove(id);
  } else if(op == 6) {
    if(a.contains(id)) {
      const unsigned kind = rng() % 50;
      const double reach = kind == 0 ? std::numeric_limits<double>::quiet_NaN() : kind == 1 ? 0.4 : 0.03 * coord(rng);
      a.set_reach(id, reach);
      b.set_reach(id, reach);
    }
  } else {
    const double qx = 1.2 * coord(rng) - 0.1, qy = 1.2 * coord(rng) - 0.1, r = 0.1 * coord(rng);
    if(op < 9) {
      typedef std::tuple<std::size_t, double, double, bool> Report;
      std::vector<Report> ra, rb;
      a.query_with_reach(qx, qy, r, [&ra](std::size_t i, double x, double y, bool in) {
        ra.emplace_back(i, x, y, in);
      });
      b.query_with_reach(qx, qy, r, [&rb](std::size_t i, double x, double y, bool in) {
        rb.emplace_back(i, x, y, in);
      });
      AFM_CHECK(ra == rb);
    } else {
      std::vector<std::size_t> ra, rb;
      a.query(qx, qy, r, ra);
      b.query(qx, qy, r, rb);
      AFM_CHECK(ra == rb);
    }
  }
  AFM_CHECK(a.size() == b.size() && a.contains(id) == b.contains(id));
  if(a.contains(id)) AFM_CHECK(a.reach(id) == b.reach(id));
  AFM_CHECK(a.number_of_nodes() == b.number_of_nodes() && a.number_of_queries() == b.number_of_queries());
}

struct Circle { double x, y, r; };

Circle random_circle(std::mt19937& rng)
{
  std::uniform_real_distribution<double> coord(0, 1);
  const unsigned kind = rng() % 100;
  const double x = coord(rng), y = coord(rng), t = coord(rng);
  if(kind < 2) return Circle{x, y, 10.}; // outside the root box: the overflow list
  if(kind < 4) return Circle{x, y, t};   // big
  if(kind < 14) // radii of all scales about one centre: octants that divide the radii
    return Circle{0.25 + 1e-7 * x, 0.25 + 1e-7 * y, std::pow(10., -6 * t)};
  return Circle{x, y, 0.03 * t};
}

// alive: (payload, item) of the circles in both trees
void circle_octree_step(std::mt19937& rng, AFMI::Lifted_circle_octree<int>& a, AFMI::Lifted_circle_octree<int>& b,
                        std::vector<std::pair<int, std::size_t> >& alive, int& next_payload)
{
  std::uniform_real_distribution<double> coord(0, 1);
  const unsigned op = rng() % 100;
  if(op < 35) {
    const Circle c = random_circle(rng);
    const std::size_t ia = a.insert(c.x, c.y, c.r, next_payload);
    const std::size_t ib = b.insert(c.x, c.y, c.r, next_payload);
    AFM_CHECK(ia == ib);
    alive.emplace_back(next_payload++, ia);
  } else if(op < 70) {
    if(!alive.empty()) {
      const std::size_t k = rng() % alive.size();
      AFM_CHECK(a.payload(alive[k].second) == alive[k].first && b.payload(alive[k].second) == alive[k].first);
      a.remove(alive[k].second);
      b.remove(alive[k].second);
      alive[k] = alive.back();
      alive.pop_back();
    }
  } else {
    const double qx = coord(rng), qy = coord(rng), inflate = (op % 2) ? 0.05 * coord(rng) : 0.;
    std::vector<int> ra, rb;
    a.query(qx, qy, inflate, [&ra](int p) { ra.push_back(p); });
    b.query(qx, qy, inflate, [&rb](int p) { rb.push_back(p); });
    AFM_CHECK(ra == rb);
  }
  AFM_CHECK(a.size() == alive.size() && b.size() == alive.size());
  AFM_CHECK(a.number_of_nodes() == b.number_of_nodes() && a.overflow_size() == b.overflow_size());
  AFM_CHECK(a.number_of_radius_divisions() == b.number_of_radius_divisions() && a.is_sparse() == b.is_sparse());
}

void rebuild_both(AFMI::Lifted_circle_octree<int>& a, AFMI::Lifted_circle_octree<int>& b,
                  std::vector<std::pair<int, std::size_t> >& alive)
{
  std::vector<std::pair<int, std::size_t> > ra, rb;
  a.rebuild([&ra](int p, std::size_t item) { ra.emplace_back(p, item); });
  b.rebuild([&rb](int p, std::size_t item) { rb.emplace_back(p, item); });
  AFM_CHECK(ra == rb && ra.size() == alive.size());
  alive = ra;
}

} // namespace

AFM_TEST_CASE(test_internal_point_quadtree_save_load)
{
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> coord(0, 1);
  const std::size_t n = 3000;
  std::vector<std::array<double, 2> > xy(n);
  for(std::size_t i = 0; i < n; ++i) {
    const double x = coord(rng), y = coord(rng);
    xy[i] = (i % 40 == 0) ? std::array<double, 2>{{1 + x, -y}} : std::array<double, 2>{{x, y}}; // 1/40 outside
  }
  AFMI::Dynamic_point_quadtree a;
  a.reset(0, 0, 1, 1, 4);
  // a front sweeping from left to right: the quadrants it leaves merge, and
  // their blocks of nodes go to the free list
  for(int round = 0; round < 4; ++round)
    for(std::size_t i = 0; i < n; ++i) {
      const double band = xy[i][0] * 5;
      if(band >= round && band < round + 1) {
        a.insert(i, xy[i][0], xy[i][1]);
        if(rng() % 3 == 0) a.set_reach(i, 0.05 * coord(rng));
      }
      if(band < round && a.contains(i) && rng() % 8 != 0) a.remove(i);
      if(i % 100 == 0) {
        std::vector<std::size_t> out;
        a.query(coord(rng), coord(rng), 0.05, out);
      }
    }
  for(std::size_t i = 0; i < n; i += 40) a.insert(i, xy[i][0], xy[i][1]);
  a.remove(40);
  {
    const Saved_point_quadtree saved(saved_bytes(a));
    AFM_CHECK_MSG(!saved.free_blocks.empty() && saved.overflow.size() > 10,
                  saved.free_blocks.size() << " free blocks, " << saved.overflow.size() << " overflow");
    AFM_CHECK(saved.bytes() == saved_bytes(a));
  }

  std::stringstream checkpoint;
  AFMI::Binary_writer w(checkpoint);
  a.save(w);
  w.write_checksum();
  AFMI::Dynamic_point_quadtree b;
  b.reset(-3, -3, 3, 3, 2, 5); // overwritten by load()
  b.insert(7, 0.5, 0.5);
  AFMI::Binary_reader r(checkpoint, "checkpoint");
  b.load(r);
  r.check_checksum();
  AFM_CHECK(saved_bytes(b) == saved_bytes(a));
  for(std::size_t i = 0; i < n; ++i) {
    AFM_CHECK(a.contains(i) == b.contains(i));
    if(a.contains(i)) AFM_CHECK(a.reach(i) == b.reach(i));
  }

  std::vector<std::size_t> new_id(n);
  for(int s = 0; s < 30000; ++s) {
    if(s == 10000 || s == 20000) {
      // renamed in random order
      std::iota(new_id.begin(), new_id.end(), std::size_t(0));
      std::shuffle(new_id.begin(), new_id.end(), rng);
      a.renumber(new_id);
      b.renumber(new_id);
    }
    if(s == 15000) load_bytes(b, saved_bytes(a)); // a second checkpoint, into a tree in use
    point_quadtree_step(rng, xy, a, b);
  }
  AFM_CHECK(saved_bytes(b) == saved_bytes(a));
}

AFM_TEST_CASE(test_internal_lifted_circle_octree_save_load)
{
  std::mt19937 rng(19);
  AFMI::Lifted_circle_octree<int> a;
  a.reset(-1, -1, 2, 2, 3, 4);
  std::vector<Circle> circles;
  std::vector<std::pair<int, std::size_t> > alive;
  int next_payload = 0;
  for(int i = 0; i < 3000; ++i) {
    circles.push_back(random_circle(rng));
    alive.emplace_back(i, a.insert(circles.back().x, circles.back().y, circles.back().r, i));
  }
  next_payload = 3000;
  AFM_CHECK(a.number_of_radius_divisions() > 0 && a.overflow_size() > 0);
  // the left half emptied: its octants (radii divided) and quadrants merge
  for(std::size_t k = alive.size(); k-- > 0;)
    if(circles[alive[k].first].x < 0.5 && (circles[alive[k].first].r < 3 || rng() % 2 == 0)) {
      a.remove(alive[k].second);
      alive.erase(alive.begin() + k);
    }
  for(int i = 0; i < 300; ++i) {
    const Circle c = random_circle(rng);
    const int p = next_payload++;
    alive.emplace_back(p, a.insert(c.x, c.y, c.r, p));
  }
  {
    const Saved_circle_octree saved(saved_bytes(a));
    std::size_t dead = 0;
    for(const auto& it : saved.items) dead += (it.alive == 0);
    AFM_CHECK_MSG(!saved.free_blocks[0].empty() && !saved.free_blocks[1].empty() && !saved.overflow.empty() && dead > 0,
                  saved.free_blocks[0].size() << " and " << saved.free_blocks[1].size() << " free blocks, "
                                              << saved.overflow.size() << " overflow, " << dead << " dead");
    AFM_CHECK(saved.bytes() == saved_bytes(a));
  }
  for(const auto& pi : alive) AFM_CHECK(a.payload(pi.second) == pi.first);

  std::stringstream checkpoint;
  AFMI::Binary_writer w(checkpoint);
  a.save(w, write_int);
  w.write_checksum();
  AFMI::Lifted_circle_octree<int> b;
  b.reset(-5, -5, 5, 5, 1, 2, 3); // overwritten by load()
  b.insert(0.5, 0.5, 0.1, 1);
  AFMI::Binary_reader r(checkpoint, "checkpoint");
  b.load(r, read_int);
  r.check_checksum();
  AFM_CHECK(saved_bytes(b) == saved_bytes(a));
  for(const auto& pi : alive) AFM_CHECK(b.payload(pi.second) == pi.first);

  for(int s = 0; s < 30000; ++s) {
    if(s == 10000 || s == 20000) rebuild_both(a, b, alive);
    if(s == 15000) load_bytes(b, saved_bytes(a)); // a second checkpoint, into a tree in use
    circle_octree_step(rng, a, b, alive, next_payload);
  }
  AFM_CHECK(saved_bytes(b) == saved_bytes(a));
}

AFM_TEST_CASE(test_internal_binary_io)
{
  // round trip, with the checksum
  std::vector<std::int32_t> big(20000);
  std::iota(big.begin(), big.end(), -10000); // read in two chunks
  const std::vector<double> small{1.5, -2., 1e300, -0.};
  std::ostringstream os;
  AFMI::Binary_writer w(os);
  w.write<std::int32_t>(-7);
  w.write(3.25);
  w.write(true);
  w.write(std::uint64_t(0xfedcba9876543210ull));
  w.write_vector(small);
  w.write_vector(std::vector<std::int32_t>());
  w.write_vector(big);
  w.write_string("checkpoint");
  w.write_string("");
  const std::uint64_t sum = w.checksum();
  w.write_checksum();
  AFM_CHECK(w.checksum() == sum);
  const std::string bytes = os.str();
  auto read_back = [&](const std::string& data, bool check) {
    std::istringstream is(data);
    AFMI::Binary_reader r(is, "test.bin");
    const std::int32_t i = r.read<std::int32_t>();
    const double d = r.read<double>();
    const bool b = r.read<bool>();
    const std::uint64_t u = r.read<std::uint64_t>();
    std::vector<double> v1;
    std::vector<std::int32_t> v2{1, 2}, v3;
    r.read_vector(v1, 4);
    r.read_vector(v2, 4);
    r.read_vector(v3, big.size());
    const std::string s1 = r.read_string(10), s2 = r.read_string(10);
    r.check_checksum();
    if(check) {
      AFM_CHECK(i == -7 && d == 3.25 && b && u == 0xfedcba9876543210ull);
      AFM_CHECK(v1 == small && std::signbit(v1[3]) && v2.empty() && v3 == big && s1 == "checkpoint" && s2.empty());
      AFM_CHECK(is.peek() == std::char_traits<char>::eof());
    }
  };
  read_back(bytes, true);
  auto message = [&](const std::string& data) -> std::string {
    try {
      read_back(data, false);
    } catch(const afm_test::Failure&) {
      throw;
    } catch(const std::runtime_error& e) {
      return e.what();
    }
    return "";
  };
  // every byte matters, including the checksum's (tested at every byte
  // but those inside the big vector, of which a few are tested)
  for(std::size_t pos = 0; pos < bytes.size(); ++pos) {
    if(pos >= 200 && pos + 200 < bytes.size() && pos % 4099 != 0) continue;
    std::string flipped = bytes;
    flipped[pos] = char(flipped[pos] ^ (1 << (pos % 8)));
    const std::string m = message(flipped);
    AFM_CHECK_MSG(m.compare(0, 10, "test.bin: ") == 0, "byte " << pos << ": " << m);
    if(pos == 5) AFM_CHECK_MSG(m == "test.bin: corrupt: checksum mismatch", m); // inside the double
    if(pos == 12) AFM_CHECK_MSG(m == "test.bin: corrupt: a boolean is neither 0 nor 1", m);
  }
  for(std::size_t length = 0; length < bytes.size(); ++length) {
    if(length >= 200 && length + 200 < bytes.size() && length % 4099 != 0) continue;
    const std::string m = message(bytes.substr(0, length));
    AFM_CHECK_MSG(m == "test.bin: truncated", "length " << length << ": " << m);
  }
  {
    // a length beyond the bound, or beyond the file, allocates nothing of it
    std::ostringstream os2;
    AFMI::Binary_writer w2(os2);
    w2.write(std::uint64_t(1) << 62);
    w2.write(std::uint64_t(100000000));
    w2.write(1.0);
    w2.write(std::uint64_t(1) << 40);
    std::istringstream is(os2.str());
    AFMI::Binary_reader r(is, "big.bin");
    std::vector<double> v;
    bool thrown = false;
    try {
      r.read_vector(v, std::uint64_t(1) << 50);
    } catch(const std::runtime_error& e) {
      thrown = std::string(e.what()).compare(0, 18, "big.bin: corrupt: ") == 0;
    }
    AFM_CHECK(thrown && v.capacity() == 0);
    thrown = false;
    try {
      r.read_vector(v, std::uint64_t(1) << 50);
    } catch(const std::runtime_error& e) {
      thrown = std::string(e.what()) == "big.bin: truncated";
    }
    AFM_CHECK_MSG(thrown && v.capacity() < (1u << 20), v.capacity());
    std::istringstream is2(os2.str().substr(24));
    AFMI::Binary_reader r2(is2, "big.bin");
    thrown = false;
    try {
      r2.read_string(std::uint64_t(1) << 50);
    } catch(const std::runtime_error& e) {
      thrown = std::string(e.what()) == "big.bin: truncated";
    }
    AFM_CHECK(thrown);
  }
  {
    // a stream that fails
    std::ostringstream bad;
    bad.setstate(std::ios::badbit);
    AFMI::Binary_writer w3(bad);
    bool thrown = false;
    try {
      w3.write(1);
    } catch(const std::runtime_error&) {
      thrown = true;
    }
    AFM_CHECK(thrown);
  }

  // small trees, with every kind of part: overflow, free blocks, dead items
  std::mt19937 rng(23);
  std::uniform_real_distribution<double> coord(0, 1);
  AFMI::Dynamic_point_quadtree points;
  points.reset(0, 0, 1, 1, 2);
  for(std::size_t i = 0; i < 60; ++i) {
    const double x = coord(rng), y = coord(rng);
    points.insert(i, i % 20 == 0 ? 2. : (i % 2 == 0 ? 0.5 * x : 0.5 + 0.5 * x), y);
    if(i % 3 == 0) points.set_reach(i, 0.1 * coord(rng));
  }
  for(std::size_t i = 2; i < 60; i += 2) points.remove(i); // the left half, two of the overflow points
  AFMI::Lifted_circle_octree<int> circles;
  circles.reset(-1, -1, 2, 2, 3, 4);
  std::vector<std::size_t> items, to_remove;
  for(int i = 0; i < 60; ++i) {
    const double x = coord(rng), y = coord(rng), t = coord(rng);
    const Circle c = (i % 3 == 0) ? Circle{0.25 + 0.01 * x, 0.25 + 0.01 * y, 0.1 * std::pow(10., -2 * t)}
                   : (i % 20 == 1) ? Circle{x, y, 10.} : Circle{x, y, 0.03 * t};
    items.push_back(circles.insert(c.x, c.y, c.r, i));
    if((i % 20 != 1 && c.x < 0.5) || i == 21) to_remove.push_back(items.back()); // the left half, an overflow circle
  }
  for(std::size_t item : to_remove) circles.remove(item);
  const std::string good_points = saved_bytes(points), good_circles = saved_bytes(circles);
  {
    const Saved_point_quadtree sp(good_points);
    const Saved_circle_octree sc(good_circles);
    AFM_CHECK(!sp.free_blocks.empty() && !sp.overflow.empty());
    AFM_CHECK_MSG(!sc.free_blocks[0].empty() && !sc.free_blocks[1].empty() && !sc.overflow.empty() &&
                    !sc.free_items.empty(),
                  sc.free_blocks[0].size() << " " << sc.free_blocks[1].size() << " " << sc.overflow.size());
  }

  // load() throws (and leaves the tree as it was) on corrupt data
  auto point_load_error = [&](const std::string& data, bool check_unchanged) -> std::string {
    AFMI::Dynamic_point_quadtree t;
    if(check_unchanged) load_bytes(t, good_points);
    try {
      load_bytes(t, data);
    } catch(const std::runtime_error& e) {
      if(check_unchanged) AFM_CHECK(saved_bytes(t) == good_points);
      return e.what();
    }
    return "";
  };
  auto circle_load_error = [&](const std::string& data, bool check_unchanged) -> std::string {
    AFMI::Lifted_circle_octree<int> t;
    if(check_unchanged) load_bytes(t, good_circles);
    try {
      load_bytes(t, data);
    } catch(const std::runtime_error& e) {
      if(check_unchanged) AFM_CHECK(saved_bytes(t) == good_circles);
      return e.what();
    }
    return "";
  };
  const std::string bad_points = "quadtree.bin: corrupt point quadtree: ";
  const std::string bad_circles = "octree.bin: corrupt lifted circle octree: ";
  auto corrupt_points = [&](const char* what, auto change) {
    Saved_point_quadtree s(good_points);
    change(s);
    AFM_CHECK_MSG(s.bytes() != good_points, what << ": nothing changed");
    const std::string m = point_load_error(s.bytes(), true);
    AFM_CHECK_MSG(m.compare(0, bad_points.size(), bad_points) == 0, what << ": " << m);
  };
  auto corrupt_circles = [&](const char* what, auto change) {
    Saved_circle_octree s(good_circles);
    change(s);
    AFM_CHECK_MSG(s.bytes() != good_circles, what << ": nothing changed");
    const std::string m = circle_load_error(s.bytes(), true);
    AFM_CHECK_MSG(m.compare(0, bad_circles.size(), bad_circles) == 0, what << ": " << m);
  };
  typedef Saved_point_quadtree SP;
  typedef Saved_circle_octree SC;
  corrupt_points("tag", [](SP& s) { ++s.tag; });
  corrupt_points("child out of range", [](SP& s) { s.nodes[0].first_child = int(s.nodes.size()) - 3; });
  corrupt_points("negative child", [](SP& s) { s.nodes[0].first_child = -5; });
  corrupt_points("cycle", [](SP& s) {
    for(auto& n : s.nodes)
      if(!n.entries.empty()) {
        n.entries.clear();
        n.first_child = s.nodes[0].first_child;
        break;
      }
  });
  corrupt_points("parent", [](SP& s) { s.nodes.back().parent = 100000; });
  corrupt_points("depth", [](SP& s) { s.nodes[1].depth = 2; });
  corrupt_points("free block in use", [](SP& s) { s.free_blocks.push_back(s.nodes[0].first_child); });
  corrupt_points("free block twice", [](SP& s) { s.free_blocks.push_back(s.free_blocks[0]); });
  corrupt_points("lost block", [](SP& s) { s.free_blocks.pop_back(); });
  corrupt_points("entry id", [](SP& s) { s.overflow[0].id = s.places.size(); });
  corrupt_points("place", [](SP& s) { ++s.places[s.overflow[0].id].position; });
  corrupt_points("place node", [](SP& s) { s.places[s.overflow[0].id].node = int(s.nodes.size()); });
  corrupt_points("absent id", [](SP& s) { s.places[s.overflow[0].id].node = -1; });
  corrupt_points("size", [](SP& s) { ++s.size; });
  corrupt_points("no nodes", [](SP& s) { s.nodes.clear(); s.free_blocks.clear(); });
  corrupt_circles("version", [](SC& s) { ++s.version; });
  corrupt_circles("child out of range", [](SC& s) { s.nodes[0].first_child = int(s.nodes.size()) - 2; });
  corrupt_circles("children", [](SC& s) { s.nodes[0].children = 5; });
  corrupt_circles("children 4 for 8 or 8 for 4", [](SC& s) {
    for(auto& n : s.nodes)
      if(n.first_child != -1 && n.parent != -1) {
        n.children = 12 - n.children;
        break;
      }
  });
  corrupt_circles("cycle", [](SC& s) {
    for(auto& n : s.nodes)
      if(!n.entries.empty()) {
        n.entries.clear();
        n.first_child = s.nodes[0].first_child;
        n.children = 4;
        break;
      }
  });
  corrupt_circles("free block of 8 as 4", [](SC& s) {
    s.free_blocks[0].push_back(s.free_blocks[1].back());
    s.free_blocks[1].pop_back();
  });
  corrupt_circles("free block out of range", [](SC& s) { s.free_blocks[1].back() = int(s.nodes.size()) - 4; });
  corrupt_circles("entry of a dead item", [](SC& s) { s.overflow[0].id = s.free_items[0]; });
  corrupt_circles("item position", [](SC& s) { ++s.items[s.overflow[0].id].position; });
  corrupt_circles("item node", [](SC& s) { s.items[s.free_items[0]].node = -7; });
  corrupt_circles("alive flag", [](SC& s) { s.items[s.free_items[0]].alive = 2; });
  corrupt_circles("free item alive", [](SC& s) { s.free_items[0] = s.overflow[0].id; });
  corrupt_circles("free item twice", [](SC& s) { s.free_items[1] = s.free_items[0]; });
  corrupt_circles("free item out of range", [](SC& s) { s.free_items[0] = s.items.size(); });
  corrupt_circles("size", [](SC& s) { --s.size; });
  {
    // the alive flag of an item that does not go back to its entry
    const std::string m = circle_load_error([&] {
      Saved_circle_octree s(good_circles);
      s.items[s.free_items[0]].alive = 1; // a payload follows now
      s.free_items.erase(s.free_items.begin());
      ++s.size;
      return s.bytes();
    }(), true);
    AFM_CHECK_MSG(m.compare(0, bad_circles.size(), bad_circles) == 0, m);
  }
  // a cut anywhere: truncated
  for(std::size_t length = 0; length < good_points.size(); ++length) {
    const std::string m = point_load_error(good_points.substr(0, length), false);
    AFM_CHECK_MSG(m == "quadtree.bin: truncated", "length " << length << ": " << m);
  }
  for(std::size_t length = 0; length < good_circles.size(); ++length) {
    const std::string m = circle_load_error(good_circles.substr(0, length), false);
    AFM_CHECK_MSG(m == "octree.bin: truncated", "length " << length << ": " << m);
  }
  // Any changed byte: load() throws std::runtime_error, or accepts a tree
  // that the operations can use (ASan and UBSan watch them).
  auto changed = [](const std::string& good, std::size_t pos) {
    std::string data = good;
    data[pos] = (pos % 3 == 0) ? char(0xff) : char(data[pos] ^ (1 << (pos % 8)));
    return data;
  };
  std::size_t accepted = 0, refused = 0;
  for(std::size_t pos = 0; pos < good_points.size(); ++pos) {
    AFMI::Dynamic_point_quadtree t;
    try {
      load_bytes(t, changed(good_points, pos));
    } catch(const std::runtime_error&) {
      ++refused;
      continue;
    }
    ++accepted;
    for(std::size_t i = 0; i < 80; ++i) {
      t.insert(i, coord(rng), coord(rng));
      if(i % 2 == 0) t.set_reach(i, 0.1 * coord(rng));
      if(i % 8 == 0) {
        std::vector<std::size_t> out;
        t.query(coord(rng), coord(rng), 0.2, out);
        t.query_with_reach(coord(rng), coord(rng), 0.1, [](std::size_t, double, double, bool) {});
      }
    }
    struct Swap_pairs { std::size_t operator[](std::size_t i) const { return i ^ 1; } };
    t.renumber(Swap_pairs());
    for(std::size_t i = 0; i < 80; ++i) t.remove(i);
    AFM_CHECK(t.size() == 0);
  }
  AFM_CHECK(accepted > 0 && refused > 0);
  accepted = refused = 0;
  for(std::size_t pos = 0; pos < good_circles.size(); ++pos) {
    AFMI::Lifted_circle_octree<int> t;
    try {
      load_bytes(t, changed(good_circles, pos));
    } catch(const std::runtime_error&) {
      ++refused;
      continue;
    }
    ++accepted;
    std::vector<std::size_t> mine;
    for(int i = 0; i < 20; ++i) {
      const Circle c = random_circle(rng);
      mine.push_back(t.insert(c.x, c.y, c.r, -1));
      if(i % 4 == 0) t.query(coord(rng), coord(rng), 0.05, [](int) {});
    }
    for(std::size_t k = 0; k < mine.size(); k += 2) t.remove(mine[k]);
    std::vector<std::size_t> all;
    t.rebuild([&all](int, std::size_t item) { all.push_back(item); });
    for(std::size_t item : all) t.remove(item);
    AFM_CHECK(t.size() == 0);
  }
  AFM_CHECK(accepted > 0 && refused > 0);
}

namespace {

// The answers of a point index against the truth: every point within the
// radius reported in the disk, every point within its reach reported, and
// nothing reported that is far from both (the padding is tiny).
template <class Index>
void check_point_index_answers(const Index& index, const std::vector<std::array<double, 3> >& pts,
                               const std::vector<bool>& in, double qx, double qy, double r, const std::string& label)
{
  std::vector<int> seen(pts.size(), 0); // 1: reported outside, 2: in the disk
  index.query_with_reach(qx, qy, r, [&](std::size_t id, double px, double py, bool in_disk) {
    AFM_CHECK_MSG(id < pts.size() && in[id] && seen[id] == 0, label << ": point " << id << " reported wrongly");
    const auto same = [](double a, double b) { return a == b || (std::isnan(a) && std::isnan(b)); };
    AFM_CHECK_MSG(same(px, pts[id][0]) && same(py, pts[id][1]), label << ": point " << id << " with other coordinates");
    seen[id] = in_disk ? 2 : 1;
  });
  for(std::size_t i = 0; i < pts.size(); ++i) {
    const double d = std::hypot(pts[i][0] - qx, pts[i][1] - qy);
    if(!in[i]) continue;
    if(!std::isfinite(d)) {
      AFM_CHECK_MSG(seen[i] == 2, label << ": point " << i << " (not finite) missed");
      continue;
    }
    if(d <= r) AFM_CHECK_MSG(seen[i] == 2, label << ": point " << i << " in the disk missed");
    else if(d <= r + pts[i][2]) AFM_CHECK_MSG(seen[i] != 0, label << ": point " << i << " within reach missed");
    if(seen[i] == 2) AFM_CHECK_MSG(d <= r * (1 + 1e-6) + 1e-9, label << ": point " << i << " not in the disk");
    if(seen[i] == 1) AFM_CHECK_MSG(d <= (r + pts[i][2]) * (1 + 1e-6) + 1e-9, label << ": point " << i << " too far");
  }
}

} // namespace

// The three models of AdvancingFrontPointIndex_2 (the quadtree, CGAL's
// Kd_tree, the brute-force oracle of the tests) under the same random
// sequence of insertions, removals, reaches, renumberings and queries, each
// against the truth: a wrong answer here would only show as a bad mesh.
AFM_TEST_CASE(test_internal_point_index_models_agree)
{
  std::mt19937 rng(29);
  std::uniform_real_distribution<double> coord(0, 1);
  AFMI::Dynamic_point_quadtree quadtree;
  CGAL::Advancing_front_mesh_2::Kd_tree_point_index kd_tree;
  afm_test::Brute_force_point_index brute_force;
  quadtree.reset(0, 0, 1, 1, 16);
  kd_tree.reset(0, 0, 1, 1, 16);
  brute_force.reset(0, 0, 1, 1, 16);
  std::vector<std::array<double, 3> > pts(2000); // x, y, reach
  std::vector<bool> in(pts.size(), false);
  for(int step = 0; step < 40000; ++step) {
    const std::size_t i = rng() % pts.size();
    const int op = int(rng() % 10);
    if(op < 4 && !in[i]) {
      pts[i] = {{coord(rng), coord(rng), 0.}};
      // a few points with non-finite coordinates, which every query reports
      if(rng() % 200 == 0) pts[i][rng() % 2] = (rng() % 2) ? std::numeric_limits<double>::infinity()
                                                             : std::numeric_limits<double>::quiet_NaN();
      quadtree.insert(i, pts[i][0], pts[i][1]);
      kd_tree.insert(i, pts[i][0], pts[i][1]);
      brute_force.insert(i, pts[i][0], pts[i][1]);
      in[i] = true;
    } else if(op < 7 && in[i]) {
      quadtree.remove(i);
      kd_tree.remove(i);
      brute_force.remove(i);
      in[i] = false;
    } else if(op < 9 && in[i]) {
      pts[i][2] = 0.05 * coord(rng);
      quadtree.set_reach(i, pts[i][2]);
      kd_tree.set_reach(i, pts[i][2]);
      brute_force.set_reach(i, pts[i][2]);
      AFM_CHECK(kd_tree.reach(i) == pts[i][2] && brute_force.reach(i) == pts[i][2]);
    } else if(op == 9 && step % 50 == 0) {
      // renumbering reverses the ids
      std::vector<std::size_t> new_id(pts.size());
      for(std::size_t k = 0; k < pts.size(); ++k) new_id[k] = pts.size() - 1 - k;
      quadtree.renumber(new_id);
      kd_tree.renumber(new_id);
      brute_force.renumber(new_id);
      std::reverse(pts.begin(), pts.end());
      std::vector<bool> reversed(in.rbegin(), in.rend());
      in.swap(reversed);
    }
    if(step % 40 == 0) {
      const double qx = coord(rng), qy = coord(rng), r = 0.1 * coord(rng);
      check_point_index_answers(quadtree, pts, in, qx, qy, r, "quadtree");
      check_point_index_answers(kd_tree, pts, in, qx, qy, r, "Kd_tree");
      check_point_index_answers(brute_force, pts, in, qx, qy, r, "brute force");
      const std::size_t count = std::size_t(std::count(in.begin(), in.end(), true));
      AFM_CHECK(quadtree.size() == count && kd_tree.size() == count && brute_force.size() == count);
      for(std::size_t k = 0; k < pts.size(); k += 97)
        AFM_CHECK(quadtree.contains(k) == in[k] && kd_tree.contains(k) == in[k] && brute_force.contains(k) == in[k]);
    }
  }
  AFM_CHECK_MSG(kd_tree.number_of_rebuilds() > 10, "the Kd_tree was rebuilt " << kd_tree.number_of_rebuilds()
                                                                              << " times only");
  // emptied and used again, with a point that is not finite among the first
  kd_tree.reset(0, 0, 1, 1, 16);
  AFM_CHECK(kd_tree.size() == 0);
  kd_tree.insert(0, std::numeric_limits<double>::infinity(), 0.5);
  for(std::size_t k = 1; k < 300; ++k) kd_tree.insert(k, coord(rng), coord(rng));
  std::size_t reported = 0;
  bool infinite_reported = false;
  kd_tree.query_with_reach(0.5, 0.5, 0.01, [&](std::size_t id, double, double, bool in_disk) {
    ++reported;
    infinite_reported = infinite_reported || (id == 0 && in_disk);
  });
  AFM_CHECK(infinite_reported && reported < 300 && kd_tree.size() == 300);
}

// The two models of AdvancingFrontCircleIndex_2 (the lifted circle octree,
// the brute-force oracle) report the same circles for points and disks.
AFM_TEST_CASE(test_internal_circle_index_models_agree)
{
  std::mt19937 rng(31);
  std::uniform_real_distribution<double> coord(0, 1);
  AFMI::Lifted_circle_octree<int> octree;
  afm_test::Brute_force_circle_index<int> brute_force;
  octree.reset(-1, -1, 2, 2, 3, 32);
  brute_force.reset(-1, -1, 2, 2, 3, 32);
  std::map<int, std::pair<std::size_t, std::size_t> > items; // payload -> (octree item, brute-force item)
  int next = 0;
  for(int step = 0; step < 20000; ++step) {
    if(items.empty() || rng() % 3 != 0) {
      const double x = coord(rng), y = coord(rng), r = 0.05 * coord(rng) * (rng() % 50 == 0 ? 20 : 1);
      items[next] = std::make_pair(octree.insert(x, y, r, next), brute_force.insert(x, y, r, next));
      ++next;
    } else {
      auto it = items.begin();
      std::advance(it, rng() % items.size());
      octree.remove(it->second.first);
      brute_force.remove(it->second.second);
      items.erase(it);
    }
    if(step % 25 == 0) {
      const double qx = coord(rng), qy = coord(rng), inflate = (step % 50 == 0) ? 0. : 0.02 * coord(rng);
      std::set<int> a, b;
      octree.query(qx, qy, inflate, [&a](int p) { AFM_CHECK(a.insert(p).second); });
      brute_force.query(qx, qy, inflate, [&b](int p) { AFM_CHECK(b.insert(p).second); });
      AFM_CHECK_MSG(a == b, "step " << step << ": the octree reports " << a.size() << " circles, the brute force "
                                    << b.size());
      AFM_CHECK(octree.size() == items.size() && brute_force.size() == items.size());
    }
  }
}

// Front_predicates with Simple_cartesian<Exact_rational> answers
// orientation, angle and in-circle with Epick's predicates on the doubles
// when told that every coordinate is a double: the same answers as the
// rational ones, on exactly collinear and cocircular points and on points
// a few units in the last place from them, where a double computation
// without a filter errs.
AFM_TEST_CASE(test_internal_front_predicates_on_doubles)
{
  typedef CGAL::Simple_cartesian<CGAL::Exact_rational> RK;
  typedef RK::Point_2 P;
  typedef CGAL::Advancing_front_mesh_2::internal::Front_predicates<RK> Predicates;
  Predicates exact, on_doubles;
  on_doubles.set_coordinates_are_doubles(true);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(-1, 1);
  std::uniform_int_distribution<int> ulps(-3, 3);
  auto nudge = [&](double v) {
    for(int k = ulps(rng); k != 0; k += k > 0 ? -1 : 1) v = std::nextafter(v, k > 0 ? 2. : -2.);
    return v;
  };
  std::size_t degenerate = 0;
  for(int i = 0; i < 20000; ++i) {
    // a and b on a grid and t a multiple of 1/8, so that c, on the line ab
    // before its nudge, is exactly there
    auto grid = [&]() { return std::round(unit(rng) * 1024) / 1024; };
    const P a(grid(), grid()), b(grid(), grid());
    const double t = std::round(unit(rng) * 8) / 8;
    const double lx = CGAL::to_double(a.x()) + t * CGAL::to_double(b.x() - a.x());
    const double ly = CGAL::to_double(a.y()) + t * CGAL::to_double(b.y() - a.y());
    const P c(nudge(lx), nudge(ly));
    const P d = i % 2 ? P(nudge(CGAL::to_double(b.x())), nudge(CGAL::to_double(a.y()))) : P(unit(rng), unit(rng));
    const P e(CGAL::to_double(a.x()) + CGAL::to_double(b.x()) - CGAL::to_double(d.x()),
              CGAL::to_double(a.y()) + CGAL::to_double(b.y()) - CGAL::to_double(d.y()));
    // (a, d, b, e is a parallelogram; a rectangle, so cocircular, when d is not nudged)
    AFM_CHECK(exact.orientation(a, b, c) == on_doubles.orientation(a, b, c));
    AFM_CHECK(exact.turns_before(a, b, c, d) == on_doubles.turns_before(a, b, c, d));
    AFM_CHECK(exact.overlap_from_shared_end(a, b, c) == on_doubles.overlap_from_shared_end(a, b, c));
    for(const P& q : {c, d, e})
      AFM_CHECK(exact.strictly_inside_circle(a, b, d, q) == on_doubles.strictly_inside_circle(a, b, d, q));
    if(exact.orientation(a, b, c) == CGAL::COLLINEAR) ++degenerate;
  }
  std::cout << "  " << degenerate << " exactly collinear triples of 20,000\n";
  AFM_CHECK(degenerate > 100);
}

// The check of the finished triangles in streaming mode
// (Finished_faces_check.h) on two triangles made not Delaunay by hand: a
// pair in the batch is flipped; a pair with a triangle that stays in memory
// holds the finished one back; a triangle already written beyond an edge
// (the ghost, with its apex) is counted, not repaired. A Delaunay pair
// passes untouched.
AFM_TEST_CASE(test_internal_finished_faces_check)
{
  typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
  typedef CGAL::Triangulation_data_structure_2<CGAL::Triangulation_vertex_base_2<K>, CGAL::Delaunay_mesh_face_base_2<K> >
    Tds;
  typedef CGAL::Constrained_Delaunay_triangulation_2<K, Tds> CDT;
  typedef CDT::Face_handle Face_handle;
  typedef CDT::Vertex_handle Vertex_handle;
  typedef CGAL::Advancing_front_mesh_2::internal::Front_predicates<K> Predicates;
  namespace AI = CGAL::Advancing_front_mesh_2::internal;
  const Predicates pred;
  // a square split by the diagonal (0,0)-(1,1), then (1,0) pulled towards
  // the middle: the diagonal is no longer Delaunay
  auto make = [](CDT& cdt, std::vector<Face_handle>& faces, Vertex_handle& moved) {
    cdt.insert(K::Point_2(0, 0));
    moved = cdt.insert(K::Point_2(1, 0));
    cdt.insert(K::Point_2(1, 1));
    cdt.insert(K::Point_2(0, 1));
    for(auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f) f->set_in_domain(!cdt.is_infinite(f));
    for(auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) faces.push_back(f);
    AFM_CHECK(faces.size() == 2);
  };
  auto delaunay = [&](const CDT& cdt) {
    for(auto e = cdt.finite_edges_begin(); e != cdt.finite_edges_end(); ++e) {
      const Face_handle f = e->first, g = f->neighbor(e->second);
      if(cdt.is_infinite(f) || cdt.is_infinite(g)) continue;
      if(pred.strictly_inside_circle(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point(),
                                     g->vertex(g->index(f))->point()))
        return false;
    }
    return true;
  };
  const auto no_apex = [](Vertex_handle, Vertex_handle) -> const K::Point_2* { return nullptr; };
  std::size_t gained = 0, lost = 0;
  const auto count = [&](Vertex_handle, Vertex_handle, Vertex_handle, Vertex_handle) { lost += 2; gained += 2; };
  {
    CDT cdt;
    std::vector<Face_handle> faces;
    Vertex_handle moved;
    make(cdt, faces, moved);
    const AI::Finished_faces_check untouched = AI::check_finished_faces(cdt, pred, faces, Face_handle(), no_apex, count);
    AFM_CHECK(untouched.flips == 0 && untouched.held == 0 && untouched.unrepaired == 0 && faces.size() == 2);
    // one of the corners off the diagonal, pulled towards the middle
    Vertex_handle off;
    for(auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
      if(cdt.degree(v) == 3) off = v; // (degree counts the infinite vertex) an end of no diagonal
    AFM_CHECK(off != Vertex_handle());
    const K::Point_2 p = off->point();
    off->set_point(K::Point_2(0.5 + 0.6 * (p.x() - 0.5), 0.5 + 0.6 * (p.y() - 0.5)));
    AFM_CHECK(!delaunay(cdt));
    const AI::Finished_faces_check flipped = AI::check_finished_faces(cdt, pred, faces, Face_handle(), no_apex, count);
    AFM_CHECK(flipped.flips == 1 && flipped.held == 0 && flipped.unrepaired == 0 && faces.size() == 2);
    AFM_CHECK(cdt.is_valid() && delaunay(cdt) && lost == 2 && gained == 2);
  }
  {
    // one of the two stays in memory: the finished one is held back
    CDT cdt;
    std::vector<Face_handle> faces;
    Vertex_handle moved;
    make(cdt, faces, moved);
    Vertex_handle off;
    for(auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
      if(cdt.degree(v) == 3) off = v;
    const K::Point_2 p = off->point();
    off->set_point(K::Point_2(0.5 + 0.6 * (p.x() - 0.5), 0.5 + 0.6 * (p.y() - 0.5)));
    std::vector<Face_handle> one{faces[0]};
    const AI::Finished_faces_check held = AI::check_finished_faces(cdt, pred, one, Face_handle(), no_apex, count);
    AFM_CHECK(held.flips == 0 && held.held == 1 && held.unrepaired == 0 && one.empty());
    // the other one already written: its apex stands beyond the ghost
    Face_handle ghost = cdt.tds().create_face();
    ghost->set_in_domain(false);
    Face_handle f = faces[0], g = faces[1];
    const int i = f->index(g);
    const K::Point_2 apex = g->vertex(g->index(f))->point();
    f->set_neighbor(i, ghost);
    const Vertex_handle s = f->vertex(CDT::ccw(i)), t = f->vertex(CDT::cw(i));
    const auto apex_beyond = [&](Vertex_handle a, Vertex_handle b) -> const K::Point_2* {
      return (a == s && b == t) ? &apex : nullptr;
    };
    std::vector<Face_handle> written{f};
    const AI::Finished_faces_check unrepaired = AI::check_finished_faces(cdt, pred, written, ghost, apex_beyond, count);
    AFM_CHECK(unrepaired.flips == 0 && unrepaired.held == 0 && unrepaired.unrepaired == 1 && written.size() == 1);
    f->set_neighbor(i, g); // the triangulation as it was, for its destructor
    cdt.tds().delete_face(ghost);
  }
}

// A triangle for the tests of circle_of()'s error bound: at a scale from
// 2^-600 to 2^600, every third one 10^6 of its sizes from the origin, its
// third point c near the line ab when flat (flatness down to
// 10^-max_decades).
struct Circle_test_triangle
{
  double ax, ay, bx, by, cx, cy, scale, flatness;
};

Circle_test_triangle random_circle_test_triangle(std::mt19937_64& rng, int i, double max_decades)
{
  std::uniform_real_distribution<double> unit(-1, 1);
  Circle_test_triangle t;
  t.scale = std::ldexp(1., int(unit(rng) * 600));
  const double offset = i % 3 == 0 ? 1e6 * t.scale : 0;
  t.flatness = std::pow(10., -max_decades * (0.5 + 0.5 * unit(rng)));
  t.ax = offset + t.scale * unit(rng), t.ay = offset + t.scale * unit(rng);
  t.bx = offset + t.scale * unit(rng), t.by = offset + t.scale * unit(rng);
  const double along = unit(rng);
  t.cx = t.ax + along * (t.bx - t.ax) - t.flatness * (t.by - t.ay);
  t.cy = t.ay + along * (t.by - t.ay) + t.flatness * (t.bx - t.ax);
  return t;
}

// twice the signed area of the triangle ABC, exactly
CGAL::Exact_rational circle_test_determinant(const CGAL::Exact_rational (&A)[2], const CGAL::Exact_rational (&B)[2],
                                             const CGAL::Exact_rational (&C)[2])
{
  return 2 * (A[0] * (B[1] - C[1]) + B[0] * (C[1] - A[1]) + C[0] * (A[1] - B[1]));
}

// The computed circle c lies within `error` of the true circumcircle of
// the points A, B, C (rationals): its centre on each axis, its radius.
// False for a degenerate triangle.
bool circle_within_bound(const CGAL::Exact_rational (&A)[2], const CGAL::Exact_rational (&B)[2],
                         const CGAL::Exact_rational (&C)[2], const CGAL::Advancing_front_mesh_2::internal::Circle& c,
                         double error)
{
  typedef CGAL::Exact_rational Q;
  const Q d = circle_test_determinant(A, B, C);
  if(d == 0) return false;
  const Q a2 = A[0] * A[0] + A[1] * A[1], b2 = B[0] * B[0] + B[1] * B[1], c2 = C[0] * C[0] + C[1] * C[1];
  const Q ux = (a2 * (B[1] - C[1]) + b2 * (C[1] - A[1]) + c2 * (A[1] - B[1])) / d;
  const Q uy = (a2 * (C[0] - B[0]) + b2 * (A[0] - C[0]) + c2 * (B[0] - A[0])) / d;
  // |centre - true centre| <= error, without square roots: each axis
  if(!(CGAL::abs(ux - Q(c.cx)) <= Q(error) && CGAL::abs(uy - Q(c.cy)) <= Q(error))) return false;
  // |r - true r| <= error: (r - e)^2 <= r*^2 <= (r + e)^2
  const Q r2 = (ux - A[0]) * (ux - A[0]) + (uy - A[1]) * (uy - A[1]);
  const Q lo = c.r > error ? (Q(c.r) - Q(error)) * (Q(c.r) - Q(error)) : Q(0);
  return lo <= r2 && r2 <= (Q(c.r) + Q(error)) * (Q(c.r) + Q(error));
}

// circle_of()'s error bound: the circle computed in doubles lies within the
// bound of the true circumcircle (computed in rationals), for well-shaped,
// thin and nearly flat triangles at scales from 1e-200 to 1e200 and far from
// the origin; flat enough, the bound says nothing (infinity), and it is
// small against the radius for reasonable triangles.
AFM_TEST_CASE(test_internal_circle_error_bound)
{
  typedef CGAL::Exact_rational Q;
  std::mt19937_64 rng(11);
  std::size_t checked = 0, unbounded = 0;
  double worst_share = 0;
  for(int i = 0; i < 20000; ++i) {
    const Circle_test_triangle t = random_circle_test_triangle(rng, i, 18);
    double error = 0;
    const CGAL::Advancing_front_mesh_2::internal::Circle c =
      CGAL::Advancing_front_mesh_2::internal::circle_of(t.ax, t.ay, t.bx, t.by, t.cx, t.cy, &error);
    const Q A[2] = {Q(t.ax), Q(t.ay)}, B[2] = {Q(t.bx), Q(t.by)}, C[2] = {Q(t.cx), Q(t.cy)};
    if(circle_test_determinant(A, B, C) == 0) continue;
    if(!std::isfinite(error)) {
      ++unbounded;
      continue;
    }
    AFM_CHECK_MSG(circle_within_bound(A, B, C, c, error), "circle off by more than " << error);
    ++checked;
    if(t.flatness > 1e-3) worst_share = (std::max)(worst_share, error / c.r);
  }
  std::cout << "  " << checked << " circles within their bound, " << unbounded
            << " too flat to bound; largest bound over radius for reasonable triangles " << worst_share << "\n";
  AFM_CHECK(checked > 15000 && unbounded > 0);
  AFM_CHECK(worst_share < 1e-7); // 1.0e-8 measured (a thin triangle 1e6 of its sizes from the origin)
}

// circle_of()'s error bound for coordinates that are themselves off by up
// to coordinate_error (to_double() of a number that is not a double): the
// circle computed from the doubles lies within the bound of the true
// circumcircle of points moved by up to that much on each axis (computed in
// rationals), for errors from 1e-16 to 1e-4 of the triangle's size; and for
// an error of a few units in the last place of the coordinates the bound
// stays small against the radius, as the mesher needs (it builds no
// triangle about a new point unless the triangle's circle, grown by its
// bound, lies inside the star's disk).
AFM_TEST_CASE(test_internal_circle_error_bound_inexact_coordinates)
{
  typedef CGAL::Exact_rational Q;
  std::mt19937_64 rng(12);
  std::uniform_real_distribution<double> unit(-1, 1);
  std::size_t checked = 0, unbounded = 0;
  double worst_share = 0, worst_share_fat = 0;
  for(int i = 0; i < 20000; ++i) {
    const Circle_test_triangle t = random_circle_test_triangle(rng, i, 12);
    const double magnitude =
      (std::max)({std::abs(t.ax), std::abs(t.ay), std::abs(t.bx), std::abs(t.by), std::abs(t.cx), std::abs(t.cy)});
    // an error of 4 units in the last place of the magnitude, or up to
    // 1e-4 of the triangle's size
    const bool ulps = i % 2 == 0;
    const double coordinate_error =
      ulps ? 4 * std::ldexp(magnitude, -52) : t.scale * std::pow(10., -16 + 6 * (1 + unit(rng)));
    double error = 0;
    const CGAL::Advancing_front_mesh_2::internal::Circle c = CGAL::Advancing_front_mesh_2::internal::circle_of(
      t.ax, t.ay, t.bx, t.by, t.cx, t.cy, &error, coordinate_error);
    if(!std::isfinite(error)) {
      ++unbounded;
      continue;
    }
    // the true points: each coordinate moved by up to the error, the
    // extremes more often than not (the lambda returns a Q, not the gmpxx
    // expression of temporaries that `auto` would deduce: those die with
    // the return statement)
    auto moved = [&](double v) -> Q {
      const double f = unit(rng);
      return Q(v) + Q(coordinate_error) * Q(std::abs(f) > 0.5 ? (f > 0 ? 1. : -1.) : f);
    };
    const Q A[2] = {moved(t.ax), moved(t.ay)}, B[2] = {moved(t.bx), moved(t.by)}, C[2] = {moved(t.cx), moved(t.cy)};
    AFM_CHECK_MSG(circle_within_bound(A, B, C, c, error),
                  "circle off by more than " << error << " (coordinate error " << coordinate_error << ")");
    ++checked;
    if(ulps && t.flatness > 1e-3) worst_share = (std::max)(worst_share, error / c.r);
    if(ulps && t.flatness > 0.1) worst_share_fat = (std::max)(worst_share_fat, error / c.r);
  }
  std::cout << "  " << checked << " circles within their bound, " << unbounded
            << " too flat to bound; with coordinates off by 4 ulps, the largest bound over the radius "
            << worst_share << " (flatness above 1e-3), " << worst_share_fat << " (above 0.1)\n";
  AFM_CHECK(checked > 15000 && unbounded > 0);
  // measured: 5.1e-4 and 8.5e-6, both for triangles 1e6 of their sizes from
  // the origin, where to_double()'s promised relative 1e-5 would be 10 sizes
  AFM_CHECK(worst_share < 1e-3);
  AFM_CHECK(worst_share_fat < 1e-4);
}
