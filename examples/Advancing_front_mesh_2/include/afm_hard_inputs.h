// Legal inputs that once made the mesher quadratic, cubic or far too fine
// (issue 19), generated at any size: the test suite runs them small with a
// bound on the work per triangle, the benchmark at full size against the
// square with a hole.
#ifndef AFM_HARD_INPUTS_H
#define AFM_HARD_INPUTS_H

#include <CGAL/Advancing_front_mesh_2/IO/Poly_data.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace afm_hard_inputs {

typedef CGAL::Advancing_front_mesh_2::IO::Poly_data Poly_data;

namespace detail {

inline void close_loop(Poly_data& pd, std::size_t first)
{
  const std::size_t n = pd.points.size() - first;
  for(std::size_t i = 0; i < n; ++i) pd.segments.push_back({{first + i, first + (i + 1) % n}});
}

} // namespace detail

// Family 1: a length x width strip whose long sides hold n + 1 exactly
// collinear points each (n segments per side).
inline Poly_data collinear_strip(std::size_t n, double length = 1000, double width = 0.001)
{
  Poly_data pd;
  for(std::size_t i = 0; i <= n; ++i) pd.points.push_back({{length * double(i) / double(n), 0.}});
  for(std::size_t i = 0; i <= n; ++i) pd.points.push_back({{length * double(n - i) / double(n), width}});
  detail::close_loop(pd, 0);
  return pd;
}

// Family 2: a side x side box whose bottom holds n points at spacing 1,
// zigzagging between y = 0 and y = 1 (or on y = 0 when `collinear`), to be
// meshed at a size far coarser than 1.
inline Poly_data fine_bottom_box(std::size_t n, double side = 100000, bool collinear = false)
{
  Poly_data pd;
  for(std::size_t i = 0; i < n; ++i) pd.points.push_back({{double(i), collinear ? 0. : double(i % 2)}});
  pd.points.push_back({{side, 0.}});
  pd.points.push_back({{side, side}});
  pd.points.push_back({{0., side}});
  detail::close_loop(pd, 0);
  return pd;
}

// Family 2 with the box's other sides divided as a boundary discretization
// graded to the size would divide them: from the bottom's spacing, 1.2
// times longer per piece, up to `size` (what the mesher itself does not do
// yet), to measure how much of family 2's cost the coarse sides make.
inline Poly_data fine_bottom_box_graded_sides(std::size_t n, double side = 100000, double size = 2500)
{
  std::vector<double> up{0.};         // the sides' division from a bottom corner up
  for(double h = std::sqrt(2.); up.back() + 1.5 * h < side; h = (std::min)(1.2 * h, size))
    up.push_back(up.back() + h);
  Poly_data pd;
  for(std::size_t i = 0; i < n; ++i) pd.points.push_back({{double(i), double(i % 2)}});
  for(double y : up) pd.points.push_back({{side, y}});
  const std::size_t top = std::size_t(std::ceil(side / size));
  for(std::size_t i = 0; i < top; ++i) pd.points.push_back({{side - side * double(i) / double(top), side}});
  for(std::size_t i = up.size(); i-- > 1;) pd.points.push_back({{0., up[i]}});
  detail::close_loop(pd, 0);
  return pd;
}

// Family 3: n segments (spokes) of length 0.5 from the centre of the square
// [-1, 1]^2, all meeting at one interior vertex.
inline Poly_data constraint_star(std::size_t n)
{
  Poly_data pd;
  pd.points = {{{0., 0.}}, {{-1., -1.}}, {{1., -1.}}, {{1., 1.}}, {{-1., 1.}}};
  pd.segments = {{{1, 2}}, {{2, 3}}, {{3, 4}}, {{4, 1}}};
  const double pi = 3.14159265358979323846;
  for(std::size_t k = 0; k < n; ++k) {
    const double a = 2 * pi * double(k) / double(n);
    pd.points.push_back({{0.5 * std::cos(a), 0.5 * std::sin(a)}});
    pd.segments.push_back({{0, pd.points.size() - 1}});
  }
  return pd;
}

// Family 4: the unit square with a hole of radius 0.25, divided every
// `spacing`, moved by (offset, offset).
inline Poly_data offset_square_with_hole(double offset, double spacing)
{
  Poly_data pd;
  const std::size_t m = std::size_t(std::ceil(1 / spacing));
  for(int side = 0; side < 4; ++side)
    for(std::size_t i = 0; i < m; ++i) {
      const double t = double(i) / double(m);
      const double x = side == 0 ? t : side == 1 ? 1 : side == 2 ? 1 - t : 0;
      const double y = side == 0 ? 0 : side == 1 ? t : side == 2 ? 1 : 1 - t;
      pd.points.push_back({{offset + x, offset + y}});
    }
  detail::close_loop(pd, 0);
  const double pi = 3.14159265358979323846;
  const std::size_t k = std::size_t(std::ceil(2 * pi * 0.25 / spacing));
  const std::size_t first = pd.points.size();
  for(std::size_t j = 0; j < k; ++j) {
    const double a = 2 * pi * double(j) / double(k);
    pd.points.push_back({{offset + 0.5 + 0.25 * std::cos(a), offset + 0.5 + 0.25 * std::sin(a)}});
  }
  detail::close_loop(pd, first);
  pd.holes.push_back({{offset + 0.5, offset + 0.5}});
  return pd;
}

// Family 5: the unit square, divided every 0.01, with `count` square holes
// of side 1e-4 on a regular grid inside it.
inline Poly_data square_with_tiny_holes(std::size_t count)
{
  Poly_data pd;
  for(int side = 0; side < 4; ++side)
    for(int i = 0; i < 100; ++i) {
      const double t = i / 100.;
      pd.points.push_back({{side == 0 ? t : side == 1 ? 1 : side == 2 ? 1 - t : 0,
                            side == 0 ? 0 : side == 1 ? t : side == 2 ? 1 : 1 - t}});
    }
  detail::close_loop(pd, 0);
  std::size_t per_row = 1;
  while(per_row * per_row < count) ++per_row;
  const double s = 1e-4;
  for(std::size_t h = 0; h < count; ++h) {
    const double cx = (double(h % per_row) + 0.5) / double(per_row);
    const double cy = (double(h / per_row) + 0.5) / double(per_row);
    const std::size_t first = pd.points.size();
    pd.points.push_back({{cx - s / 2, cy - s / 2}});
    pd.points.push_back({{cx + s / 2, cy - s / 2}});
    pd.points.push_back({{cx + s / 2, cy + s / 2}});
    pd.points.push_back({{cx - s / 2, cy + s / 2}});
    detail::close_loop(pd, first);
    pd.holes.push_back({{cx, cy}});
  }
  return pd;
}

// Family 5, second input: a side x side box whose bottom holds n points at
// spacing 1 and whose other sides are divided every `coarse`.
inline Poly_data box_with_fine_bottom(std::size_t n, double coarse = 200)
{
  Poly_data pd;
  const double side = double(n);
  for(std::size_t i = 0; i < n; ++i) pd.points.push_back({{double(i), 0.}});
  const std::size_t m = std::size_t(std::ceil(side / coarse));
  for(std::size_t i = 0; i < m; ++i) pd.points.push_back({{side, side * double(i) / double(m)}});
  for(std::size_t i = 0; i < m; ++i) pd.points.push_back({{side - side * double(i) / double(m), side}});
  for(std::size_t i = 0; i < m; ++i) pd.points.push_back({{0., side - side * double(i) / double(m)}});
  detail::close_loop(pd, 0);
  return pd;
}

} // namespace afm_hard_inputs

#endif // AFM_HARD_INPUTS_H
