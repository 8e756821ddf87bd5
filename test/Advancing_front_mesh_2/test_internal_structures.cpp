// The mesher's own containers, each against a plain reference under random
// operations: the id lists of the front, the flat hash map, the point
// quadtree of the close-point search and the lifted circle octree (with
// their merging of empty nodes). The mesher's tests exercise them too, but
// a wrong answer there shows only as a bad mesh far from its cause.
#include "afm_test_harness.h"

#include <CGAL/Advancing_front_mesh_2/internal/Compact_id_list.h>
#include <CGAL/Advancing_front_mesh_2/internal/Dynamic_point_quadtree.h>
#include <CGAL/Advancing_front_mesh_2/internal/Flat_hash_map.h>
#include <CGAL/Advancing_front_mesh_2/internal/Lifted_circle_octree.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <cstdint>
#include <random>
#include <set>
#include <unordered_map>
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
  points.rebuild(new_id);
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
