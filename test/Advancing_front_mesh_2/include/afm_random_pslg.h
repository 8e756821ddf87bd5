// Random domains and size fields for the randomised tests.
//
// A domain is a star-shaped outer polygon with star-shaped holes placed in
// disjoint disks inside it, dangling interior segments and free points,
// every side cut into a random number of pieces (so the boundary spacing
// varies along a loop), scaled and offset at random. Everything is built
// so that the graph is legal by construction (no test of the mesher's input
// checks is involved): holes lie in disjoint disks inside the disk that the
// outer polygon contains, and the interior segments and free points lie in
// the annulus-free part of that disk, away from every hole disk.
#ifndef AFM_TEST_RANDOM_PSLG_H
#define AFM_TEST_RANDOM_PSLG_H

#include <CGAL/Advancing_front_mesh_2/IO/Poly_data.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace afm_random {

typedef CGAL::Advancing_front_mesh_2::IO::Poly_data Poly_data;

struct Disk
{
  double x, y, r;
};

struct Domain
{
  Poly_data pslg;
  double scale = 1, offset_x = 0, offset_y = 0; // applied to the unit-size construction
  double inner_radius = 0;                      // (unscaled) disk the outer polygon contains
  std::vector<Disk> hole_disks;                 // (unscaled)
  std::vector<Disk> extra_disks;                // (unscaled) disks holding the free points and interior segments
  std::string description;
};

class Generator
{
public:
  explicit Generator(std::uint64_t seed) : rng_(seed) {}

  double uniform(double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng_); }
  int integer(int a, int b) { return std::uniform_int_distribution<int>(a, b)(rng_); }

  Domain domain()
  {
    Domain d;
    const double two_pi = 6.283185307179586;
    // outer polygon: 5..24 corners at sorted angles, no gap above 90 degrees
    const int corners = integer(5, 24);
    std::vector<double> angles;
    for(;;) {
      angles.clear();
      for(int i = 0; i < corners; ++i) angles.push_back(uniform(0, two_pi));
      std::sort(angles.begin(), angles.end());
      double gap = angles.front() + two_pi - angles.back();
      for(int i = 1; i < corners; ++i) gap = (std::max)(gap, angles[i] - angles[i - 1]);
      if(gap < 0.5 * 3.141592653589793) break;
    }
    const double rmin = 0.6;
    std::vector<std::array<double, 2> > outer;
    for(double a : angles) {
      const double r = uniform(rmin, 1.0);
      outer.push_back({{r * std::cos(a), r * std::sin(a)}});
    }
    // a star polygon with radii >= rmin and angular gaps < 90 degrees
    // contains the disk of radius rmin cos(45 deg)
    d.inner_radius = rmin * std::cos(0.25 * 3.141592653589793) * 0.98;
    add_loop(d.pslg, outer);

    // holes in disjoint disks inside the inner disk
    const int holes = integer(0, 6);
    for(int tries = 0; tries < 200 && int(d.hole_disks.size()) < holes; ++tries) {
      const double r = uniform(0.03, 0.15);
      const double rho = uniform(0, d.inner_radius - r), phi = uniform(0, two_pi);
      const Disk disk{rho * std::cos(phi), rho * std::sin(phi), r};
      bool free = true;
      for(const Disk& o : d.hole_disks)
        if(std::hypot(o.x - disk.x, o.y - disk.y) < o.r + disk.r + 0.02) free = false;
      if(!free) continue;
      d.hole_disks.push_back(disk);
      const int m = integer(3, 10);
      std::vector<double> ha;
      // angular gaps below 180 degrees: the disk centre (the seed) is inside
      for(int i = 0; i < m; ++i) ha.push_back(two_pi * (i + uniform(0.3, 0.7)) / m);
      std::vector<std::array<double, 2> > loop;
      for(double a : ha) {
        const double hr = disk.r * uniform(0.5, 1.0);
        loop.push_back({{disk.x + hr * std::cos(a), disk.y + hr * std::sin(a)}});
      }
      add_loop(d.pslg, loop);
      d.pslg.holes.push_back({{disk.x, disk.y}}); // the disk's centre is inside the star
    }

    // dangling interior segments and free points, away from the holes
    const int extras = integer(0, 3);
    for(int e = 0; e < extras; ++e) {
      std::array<double, 2> p;
      if(!free_point(d, 0.03, p)) continue;
      if(integer(0, 1) == 0) {
        add_point(d.pslg, p);
        d.extra_disks.push_back(Disk{p[0], p[1], 0.});
      } else {
        const double len = uniform(0.02, 0.1), a = uniform(0, two_pi);
        const std::array<double, 2> q = {{p[0] + len * std::cos(a), p[1] + len * std::sin(a)}};
        if(!is_free(d, q, 0.02 + len)) continue; // the whole segment clear of the others
        const std::size_t i = add_point(d.pslg, p), j = add_point(d.pslg, q);
        d.pslg.segments.push_back({{i, j}});
        d.extra_disks.push_back(Disk{q[0], q[1], len});
      }
    }

    // scale and offset: sizes from 1e-3 to 1e3, offsets up to 1e3 sizes
    d.scale = std::pow(10., uniform(-3, 3));
    d.offset_x = d.scale * uniform(-1000, 1000) * (integer(0, 2) == 0 ? 1 : 0);
    d.offset_y = d.scale * uniform(-1000, 1000) * (integer(0, 2) == 0 ? 1 : 0);
    auto map = [&d](std::array<double, 2>& p) {
      p[0] = p[0] * d.scale + d.offset_x;
      p[1] = p[1] * d.scale + d.offset_y;
    };
    for(auto& p : d.pslg.points) map(p);
    for(auto& p : d.pslg.holes) map(p);
    d.description = std::to_string(corners) + " corners, " + std::to_string(d.hole_disks.size()) + " holes, " +
                    std::to_string(d.pslg.points.size()) + " points, scale " + std::to_string(d.scale);
    return d;
  }

private:
  static std::size_t add_point(Poly_data& d, const std::array<double, 2>& p)
  {
    d.points.push_back(p);
    return d.points.size() - 1;
  }

  // a closed loop, each side cut into 1..k pieces at random parameters
  void add_loop(Poly_data& d, const std::vector<std::array<double, 2> >& corners)
  {
    const std::size_t first = d.points.size();
    const int max_pieces = integer(1, 12);
    for(std::size_t c = 0; c < corners.size(); ++c) {
      const auto& a = corners[c];
      const auto& b = corners[(c + 1) % corners.size()];
      const int pieces = integer(1, max_pieces);
      std::vector<double> ts;
      for(int k = 1; k < pieces; ++k) ts.push_back(uniform(0.05, 0.95));
      std::sort(ts.begin(), ts.end());
      add_point(d, a);
      double last = 0;
      for(double t : ts) {
        if(t - last < 0.01) continue; // no near-duplicate points once scaled and rounded
        add_point(d, {{a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])}});
        last = t;
      }
    }
    const std::size_t n = d.points.size() - first;
    for(std::size_t i = 0; i < n; ++i) d.segments.push_back({{first + i, first + (i + 1) % n}});
  }

  bool is_free(const Domain& d, const std::array<double, 2>& p, double clearance) const
  {
    if(std::hypot(p[0], p[1]) > d.inner_radius - clearance) return false;
    for(const Disk& h : d.hole_disks)
      if(std::hypot(p[0] - h.x, p[1] - h.y) < h.r + clearance) return false;
    for(const Disk& e : d.extra_disks)
      if(std::hypot(p[0] - e.x, p[1] - e.y) < e.r + clearance) return false;
    return true;
  }

  bool free_point(const Domain& d, double clearance, std::array<double, 2>& p)
  {
    for(int tries = 0; tries < 100; ++tries) {
      p = {{uniform(-d.inner_radius, d.inner_radius), uniform(-d.inner_radius, d.inner_radius)}};
      if(is_free(d, p, clearance)) return true;
    }
    return false;
  }

  std::mt19937_64 rng_;
};

} // namespace afm_random

#endif // AFM_TEST_RANDOM_PSLG_H
