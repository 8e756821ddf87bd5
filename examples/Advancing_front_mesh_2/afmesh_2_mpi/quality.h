// afmesh_2_mpi: the quality figures of the whole mesh (--stats, --report,
// --histogram) added up over the ranks' shares; rank 0 gets the figures
// afmesh_2's AFM::mesh_quality() gives for a mesh held whole.
//
// The triangle figures are sums, minima and maxima reduced to rank 0. The
// percentiles are exact: a histogram of 65,536 bins reduced to rank 0 tells
// which bin holds each percentile, and the ranks send rank 0 their ratios
// in those bins alone (a few hundred thousand values for a billion
// triangles). Each edge is counted once: an edge two triangles of a share
// hold is counted by that share; one on the boundary of its share is on the
// domain's boundary, counted by the share, or on an interface, where both
// shares hold it and the lower rank counts it (each rank sends the rank
// above the edges on its share's boundary).
#ifndef AFMESH_2_MPI_QUALITY_H
#define AFMESH_2_MPI_QUALITY_H

#include "pieces.h"

#include <CGAL/Advancing_front_mesh_2/Mesh_quality.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <stdexcept>
#include <vector>

namespace afmesh_2_mpi {

// Fine bins of the radius ratio in [0, 1]: the bins of the percentiles.
constexpr std::size_t percentile_bins = std::size_t(1) << 16;

inline std::size_t percentile_bin(double ratio)
{
  return (std::min)(percentile_bins - 1, std::size_t((std::max)(0., ratio) * double(percentile_bins)));
}

// The percentiles p of Mesh_quality (1%, 5%, median) of the ratios of all
// ranks, `total` of them; rank 0 gets them.
inline std::array<double, 3> reduced_percentiles(const std::vector<double>& ratios, std::uint64_t total, int rank,
                                                 int ranks)
{
  const std::array<double, 3> p{{0.01, 0.05, 0.5}};
  std::array<double, 3> values{{0, 0, 0}};
  if(total == 0) return values;
  std::vector<std::uint64_t> mine(percentile_bins, 0), all(rank == 0 ? percentile_bins : 0);
  for(double r : ratios) ++mine[percentile_bin(r)];
  MPI_Reduce(mine.data(), all.data(), int(percentile_bins), MPI_UINT64_T, MPI_SUM, 0, MPI_COMM_WORLD);
  // the bin of each percentile, and its index among the ratios of the bin
  std::array<std::uint64_t, 3> bin{{0, 0, 0}}, within{{0, 0, 0}};
  if(rank == 0)
    for(std::size_t k = 0; k < 3; ++k) {
      std::uint64_t index = AFM::internal::percentile_index(p[k], std::size_t(total)), below = 0;
      std::size_t b = 0;
      while(below + all[b] <= index) below += all[b++];
      bin[k] = b;
      within[k] = index - below;
    }
  MPI_Bcast(bin.data(), 3, MPI_UINT64_T, 0, MPI_COMM_WORLD);
  for(std::size_t k = 0; k < 3; ++k) {
    std::vector<double> in_bin;
    for(double r : ratios)
      if(percentile_bin(r) == bin[k]) in_bin.push_back(r);
    if(rank != 0) {
      send_vector(in_bin, 0, QUALITY_RATIOS);
      continue;
    }
    for(int r = 1; r < ranks; ++r) {
      const std::vector<double> theirs = receive_vector<double>(r, QUALITY_RATIOS);
      in_bin.insert(in_bin.end(), theirs.begin(), theirs.end());
    }
    if(within[k] >= in_bin.size()) throw std::logic_error("a percentile's bin lost ratios");
    std::nth_element(in_bin.begin(), in_bin.begin() + std::ptrdiff_t(within[k]), in_bin.end());
    values[k] = in_bin[within[k]];
  }
  return values;
}

// The figures of the mesh whose share on this rank is `m`, with the edge
// length over the size `sizing` gives (its point type Point_2); whole on
// rank 0, which every rank must call it with. Memory: 8 bytes a triangle
// for its ratio and 24 for its edges (three 64-bit keys of two local
// vertex indices each).
template <class Point_2, class Sizing>
AFM::Mesh_quality mesh_quality_over_ranks(const Rank_mesh& m, const Sizing& sizing, int rank, int ranks)
{
  if(m.points.size() >> 32 != 0) throw std::length_error("a share of more than 2^32 vertices in memory");
  AFM::internal::Triangle_quality_sums t;
  std::vector<double> ratios;
  ratios.reserve(m.triangles.size());
  // each edge of each triangle, by its local vertex indices (low, high)
  std::vector<std::uint64_t> edges;
  edges.reserve(3 * m.triangles.size());
  for(const auto& tri : m.triangles) {
    double x[3], y[3];
    for(std::size_t k = 0; k < 3; ++k) {
      x[k] = m.points[tri[k]][0];
      y[k] = m.points[tri[k]][1];
      const std::uint64_t a = tri[(k + 1) % 3], b = tri[(k + 2) % 3];
      edges.push_back((std::min)(a, b) << 32 | (std::max)(a, b));
    }
    ratios.push_back(t.add(x, y));
  }
  // the edges held twice in the share, counted once; those held once, on
  // its boundary, sent to the rank above by their global numbers, which
  // leaves out those it holds once too
  std::sort(edges.begin(), edges.end());
  AFM::internal::Edge_size_sums e;
  auto add = [&](std::uint64_t edge) {
    const auto& a = m.points[edge >> 32];
    const auto& b = m.points[edge & 0xffffffffu];
    e.add(AFM::internal::edge_over_size<Point_2>(sizing, a[0], a[1], b[0], b[1]));
  };
  std::vector<std::uint64_t> once;
  for(std::size_t i = 0; i < edges.size();) {
    std::size_t j = i + 1;
    while(j < edges.size() && edges[j] == edges[i]) ++j;
    if(j - i > 2) throw std::logic_error("an edge of the rank's share is held by more than two triangles");
    if(j - i == 2) add(edges[i]);
    else once.push_back(edges[i]);
    i = j;
  }
  std::vector<std::uint64_t>().swap(edges);
  auto numbers = [&m](std::uint64_t edge) {
    const std::uint64_t a = m.global_id[edge >> 32], b = m.global_id[edge & 0xffffffffu];
    return std::array<std::uint64_t, 2>{{(std::min)(a, b), (std::max)(a, b)}};
  };
  std::vector<std::array<std::uint64_t, 2> > boundary;
  for(std::uint64_t edge : once) boundary.push_back(numbers(edge));
  std::sort(boundary.begin(), boundary.end());
  if(rank + 1 < ranks) send_vector(boundary, rank + 1, QUALITY_EDGES);
  const std::vector<std::array<std::uint64_t, 2> > below =
    rank > 0 ? receive_vector<std::array<std::uint64_t, 2> >(rank - 1, QUALITY_EDGES)
             : std::vector<std::array<std::uint64_t, 2> >();
  for(std::uint64_t edge : once)
    if(!std::binary_search(below.begin(), below.end(), numbers(edge))) add(edge);

  // the sums to rank 0
  std::vector<std::uint64_t> counts{t.triangles, t.above_0_9, t.sharp_angles, e.edges, e.within_sqrt2};
  counts.insert(counts.end(), t.ratio_histogram.begin(), t.ratio_histogram.end());
  counts.insert(counts.end(), t.angle_histogram.begin(), t.angle_histogram.end());
  std::vector<std::uint64_t> count_sums(counts.size());
  MPI_Reduce(counts.data(), count_sums.data(), int(counts.size()), MPI_UINT64_T, MPI_SUM, 0, MPI_COMM_WORLD);
  double sums[2] = {t.sum_of_ratios, e.sum}, minima[3] = {t.min_ratio, t.min_angle, e.min},
         maxima[2] = {t.max_angle, e.max};
  double all_sums[2], all_minima[3], all_maxima[2];
  MPI_Reduce(sums, all_sums, 2, MPI_DOUBLE, MPI_SUM, 0, MPI_COMM_WORLD);
  MPI_Reduce(minima, all_minima, 3, MPI_DOUBLE, MPI_MIN, 0, MPI_COMM_WORLD);
  MPI_Reduce(maxima, all_maxima, 2, MPI_DOUBLE, MPI_MAX, 0, MPI_COMM_WORLD);
  const std::uint64_t total = sum_over_ranks(t.triangles);
  const std::array<double, 3> percentiles = reduced_percentiles(ratios, total, rank, ranks);

  AFM::Mesh_quality q;
  if(rank != 0) return q;
  AFM::internal::Triangle_quality_sums all_t;
  all_t.triangles = count_sums[0];
  all_t.above_0_9 = count_sums[1];
  all_t.sharp_angles = count_sums[2];
  std::copy(count_sums.begin() + 5, count_sums.begin() + 25, all_t.ratio_histogram.begin());
  std::copy(count_sums.begin() + 25, count_sums.end(), all_t.angle_histogram.begin());
  all_t.sum_of_ratios = all_sums[0];
  all_t.min_ratio = all_minima[0];
  all_t.min_angle = all_minima[1];
  all_t.max_angle = all_maxima[0];
  all_t.finish(q);
  AFM::internal::Edge_size_sums all_e;
  all_e.edges = count_sums[3];
  all_e.within_sqrt2 = count_sums[4];
  all_e.sum = all_sums[1];
  all_e.min = all_minima[2];
  all_e.max = all_maxima[1];
  all_e.finish(q);
  q.radius_ratio_p1 = percentiles[0];
  q.radius_ratio_p5 = percentiles[1];
  q.radius_ratio_median = percentiles[2];
  return q;
}

} // namespace afmesh_2_mpi

#endif // AFMESH_2_MPI_QUALITY_H
