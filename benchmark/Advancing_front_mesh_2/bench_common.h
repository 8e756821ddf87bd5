// Common pieces of the mesher comparison: the figures of one run, the
// radius-ratio quality computed the same way for every mesher, and a meter
// for wall time and peak heap memory. Includes heap_meter.h, which defines
// the allocation functions: like it, include this header from one
// translation unit only (the benchmark is a single one).
#ifndef AFM_BENCHMARK_BENCH_COMMON_H
#define AFM_BENCHMARK_BENCH_COMMON_H

#include "afm_validity_checker.h"
#include "heap_meter.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>

namespace afm_bench {

/// Radius ratio 2r/R of the triangles of a mesh, from the triangle list alone
/// (so that Gmsh's output and CGAL's are measured by the same code).
struct Quality
{
  double mean = 0, min = 0, share_above_0_9 = 0;
};

/// 2r/R = 2 (2A)^2 / (s a b c), s the semi-perimeter and A the area; lengths
/// divided by the longest edge so that nothing under- or overflows.
inline double radius_ratio(const std::array<double, 2>& p, const std::array<double, 2>& q,
                           const std::array<double, 2>& r)
{
  const double ux = q[0] - p[0], uy = q[1] - p[1], vx = r[0] - p[0], vy = r[1] - p[1];
  const double a = std::hypot(r[0] - q[0], r[1] - q[1]), b = std::hypot(vx, vy), c = std::hypot(ux, uy);
  const double l = (std::max)(a, (std::max)(b, c));
  if(!(l > 0) || !std::isfinite(l)) return 0;
  const double area2 = (ux / l) * (vy / l) - (uy / l) * (vx / l);
  const double s = 0.5 * (a + b + c) / l;
  const double rr = 2 * area2 * area2 / (s * (a / l) * (b / l) * (c / l));
  return std::isfinite(rr) ? (std::min)(1., rr) : 0.;
}

inline Quality quality(const afm_check::Mesh& m)
{
  Quality q;
  if(m.triangles.empty()) return q;
  q.min = 1;
  double sum = 0;
  std::size_t good = 0;
  for(const auto& t : m.triangles) {
    const double rr = radius_ratio(m.vertices[t[0]], m.vertices[t[1]], m.vertices[t[2]]);
    sum += rr;
    q.min = (std::min)(q.min, rr);
    good += rr > 0.9;
  }
  q.mean = sum / double(m.triangles.size());
  q.share_above_0_9 = double(good) / double(m.triangles.size());
  return q;
}

/// The figures of one reported run.
struct Run
{
  std::string mesher;
  std::string parameter;          // the (tuned) size parameter, as text
  std::size_t triangles = 0, vertices = 0;
  double seconds = 0;
  std::size_t peak_bytes = 0;     // extra heap during the run
  int runs = 1;                   // the time is the fastest of this many runs
  Quality quality;
  std::string checker = "not checked";
  double off_target = 0;          // triangles / target - 1
  std::uint64_t allocations = 0;  // heap allocations during the run
  bool evaluated = false;

  double triangles_per_second() const { return seconds > 0 ? double(triangles) / seconds : 0; }
  double bytes_per_triangle() const { return triangles > 0 ? double(peak_bytes) / double(triangles) : 0; }
};

/// Wall time and extra peak heap of the code between start() and stop().
class Meter
{
public:
  void start()
  {
    heap_meter::reset_peak();
    baseline_ = heap_meter::current();
    t0_ = std::chrono::steady_clock::now();
  }
  void stop()
  {
    seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count();
    const std::size_t p = heap_meter::peak();
    peak_ = p > baseline_ ? p - baseline_ : 0;
  }
  double seconds() const { return seconds_; }
  std::size_t peak_bytes() const { return peak_; }

private:
  std::chrono::steady_clock::time_point t0_;
  std::size_t baseline_ = 0, peak_ = 0;
  double seconds_ = 0;
};

} // namespace afm_bench

#endif // AFM_BENCHMARK_BENCH_COMMON_H
