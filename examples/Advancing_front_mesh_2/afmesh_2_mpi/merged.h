// afmesh_2_mpi --merge: the whole mesh in one file, written by rank 0 as
// the other ranks send their shares, one array and one rank after another,
// in chunks (rank 0 holds one chunk at a time): first the owned points of
// each rank in the order of their numbers, then each rank's triangles by
// those numbers, then the segments, markers and regions. A share comes from
// memory (Rank_mesh) or, with --stream, from the rank's scratch files
// (streamed.h makes a Merged_share of them).
#ifndef AFMESH_2_MPI_MERGED_H
#define AFMESH_2_MPI_MERGED_H

#include "pieces.h"

#include <cstring>
#include <fstream>
#include <functional>
#include <iomanip>
#include <stdexcept>
#include <string>
#include <vector>

namespace afmesh_2_mpi {

inline std::vector<double> owned_points(const Rank_mesh& m)
{
  std::vector<double> xy;
  xy.reserve(2 * m.owned_count);
  for(std::size_t i = 0; i < m.points.size(); ++i)
    if(m.owned[i]) {
      xy.push_back(m.points[i][0]);
      xy.push_back(m.points[i][1]);
    }
  return xy;
}

inline std::vector<std::uint64_t> numbered_triangles(const Rank_mesh& m)
{
  std::vector<std::uint64_t> t;
  t.reserve(3 * m.triangles.size());
  for(const auto& tri : m.triangles)
    for(std::uint64_t v : tri) t.push_back(m.global_id[v]);
  return t;
}

inline std::vector<std::uint64_t> numbered_segments(const Rank_mesh& m)
{
  std::vector<std::uint64_t> s;
  s.reserve(2 * m.tags.segments.size());
  for(const auto& seg : m.tags.segments)
    for(std::uint64_t v : seg) s.push_back(m.global_id[v]);
  return s;
}

inline std::vector<std::int32_t> owned_markers(const Rank_mesh& m)
{
  std::vector<std::int32_t> k;
  k.reserve(m.owned_count);
  for(std::size_t i = 0; i < m.points.size(); ++i)
    if(m.owned[i]) k.push_back(std::int32_t(m.tags.markers[i]));
  return k;
}

// A region attribute sent among a triangle's vertex numbers: its bits.
inline std::uint64_t attribute_bits(double attribute)
{
  std::uint64_t bits = 0;
  std::memcpy(&bits, &attribute, sizeof bits);
  return bits;
}
inline double attribute_of_bits(std::uint64_t bits)
{
  double attribute = 0;
  std::memcpy(&attribute, &bits, sizeof attribute);
  return attribute;
}

// One rank's share as the merged file takes it: its counts, and for each
// array a function that hands the values to `put` in chunks, in the order
// of the file.
struct Merged_share
{
  template <class T>
  using Values = std::function<void(const std::function<void(const T*, std::size_t)>& put)>;
  std::uint64_t owned_vertices = 0, triangles = 0, segments = 0;
  bool regions = false;
  Values<double> points;                 // x and y of the owned points, by number
  Values<std::uint64_t> triangle_numbers; // the numbers of each triangle's vertices
  Values<std::uint64_t> segment_numbers;  // the numbers of each segment's ends
  Values<std::int32_t> point_markers;     // of the owned points
  Values<std::int32_t> segment_markers;
  Values<double> triangle_regions;        // when the input has regions
  // the same zipped, for the writers that take a vertex or a triangle
  // whole (merged_formats.h): x, y and marker of each owned point; each
  // triangle's vertex numbers and the bits of its region attribute (of 0
  // without regions)
  Values<double> marked_points;
  Values<std::uint64_t> regioned_triangles;
};

// A share held in memory, each array in one chunk.
inline Merged_share merged_share(const Rank_mesh& m)
{
  Merged_share s;
  s.owned_vertices = m.owned_count;
  s.triangles = m.triangles.size();
  s.segments = m.tags.segments.size();
  s.regions = m.tags.regions;
  auto whole = [](auto make) {
    return [make](const auto& put) {
      const auto v = make();
      put(v.data(), v.size());
    };
  };
  s.points = whole([&m] { return owned_points(m); });
  s.triangle_numbers = whole([&m] { return numbered_triangles(m); });
  s.segment_numbers = whole([&m] { return numbered_segments(m); });
  s.point_markers = whole([&m] { return owned_markers(m); });
  s.segment_markers = whole([&m] {
    return std::vector<std::int32_t>(m.tags.segment_markers.begin(), m.tags.segment_markers.end());
  });
  s.triangle_regions = [&m](const std::function<void(const double*, std::size_t)>& put) {
    put(m.tags.regions_of_triangles.data(), m.tags.regions_of_triangles.size());
  };
  s.marked_points = whole([&m] {
    std::vector<double> xyk;
    xyk.reserve(3 * m.owned_count);
    for(std::size_t i = 0; i < m.points.size(); ++i)
      if(m.owned[i]) xyk.insert(xyk.end(), {m.points[i][0], m.points[i][1], double(m.tags.markers[i])});
    return xyk;
  });
  s.regioned_triangles = whole([&m] {
    std::vector<std::uint64_t> t;
    t.reserve(4 * m.triangles.size());
    for(std::size_t k = 0; k < m.triangles.size(); ++k)
      t.insert(t.end(), {m.global_id[m.triangles[k][0]], m.global_id[m.triangles[k][1]],
                         m.global_id[m.triangles[k][2]],
                         attribute_bits(m.tags.regions ? m.tags.regions_of_triangles[k] : 0.)});
    return t;
  });
  return s;
}

// Rank 0: hands rank r's values of one array to `take`, in chunks, its own
// from `mine`. Another rank: sends its values to rank 0.
template <class T, class Take>
void each_rank_values(int rank, int ranks, const Merged_share::Values<T>& mine, Tag tag, const Take& take)
{
  if(rank != 0) {
    mine([tag](const T* v, std::size_t n) { send_chunk(v, n, 0, tag); });
    end_chunks<T>(0, tag);
    return;
  }
  for(int r = 0; r < ranks; ++r) {
    if(r == 0) mine([&take](const T* v, std::size_t n) { take(v, n); });
    else receive_chunks<T>(r, tag, take);
  }
}

// Rank 0 writes every rank's values of one array of the .vtu (binary or
// ASCII); another rank sends its own.
template <class T>
void write_values(std::ostream& os, std::string& raw, bool binary, int rank, int ranks,
                  const Merged_share::Values<T>& values, Tag tag)
{
  each_rank_values<T>(rank, ranks, values, tag, [&](const T* v, std::size_t n) {
    for(std::size_t i = 0; i < n; ++i) put_value(os, raw, binary, v[i]);
    write_out(os, raw);
  });
}

// Rank 0 writes `out` (.off or .vtu: with the segments, markers and
// regions as afmesh_2 writes them); the others send it their shares, in
// the order rank 0 writes the arrays (a large message waits until rank 0
// takes it). Throws std::runtime_error (rank 0) when the file cannot be
// written.
inline void write_merged(const std::string& out, const Merged_share& share, int rank, int ranks, bool binary)
{
  const std::vector<std::uint64_t> triangles_per_rank = gather_to_root<std::uint64_t>(share.triangles, ranks);
  const std::vector<std::uint64_t> segments_per_rank = gather_to_root<std::uint64_t>(share.segments, ranks);
  const std::uint64_t nv = sum_over_ranks(share.owned_vertices);
  const bool vtu = !afmesh_2::ends_with(out, ".off");
  std::ofstream os;
  if(rank == 0) {
    os.open(out, std::ios::binary);
    os << std::setprecision(17);
  }
  // the arrays, each with what rank 0 does with a chunk of it
  std::string raw;
  const std::size_t full = std::size_t(1) << 20;
  auto points = [&] {
    each_rank_values<double>(rank, ranks, share.points, MERGED_POINTS, [&](const double* xy, std::size_t n) {
      for(std::size_t i = 0; i + 1 < n; i += 2) {
        if(binary && vtu) {
          vtu::vtu_append_raw(raw, xy[i]);
          vtu::vtu_append_raw(raw, xy[i + 1]);
          vtu::vtu_append_raw(raw, 0.);
          if(raw.size() > full) write_out(os, raw);
        } else {
          os << xy[i] << ' ' << xy[i + 1] << " 0\n";
        }
      }
      write_out(os, raw);
    });
  };
  auto indices = [&](const Merged_share::Values<std::uint64_t>& values, Tag tag, std::size_t per_cell, bool wide) {
    std::uint64_t k = 0;
    each_rank_values<std::uint64_t>(rank, ranks, values, tag, [&](const std::uint64_t* v, std::size_t n) {
      for(std::size_t i = 0; i < n; ++i, ++k) {
        const bool last = k % per_cell == per_cell - 1;
        if(vtu) put_index(os, raw, binary, wide, v[i], last ? '\n' : ' ');
        else os << (k % per_cell == 0 ? "3 " : "") << v[i] << (last ? '\n' : ' ');
        if(raw.size() > full) write_out(os, raw);
      }
      write_out(os, raw);
    });
  };
  if(!vtu) {
    if(rank == 0) {
      std::uint64_t nt = 0;
      for(std::uint64_t n : triangles_per_rank) nt += n;
      os << "OFF\n" << nv << ' ' << nt << " 0\n";
    }
    points();
    indices(share.triangle_numbers, MERGED_TRIANGLES, 3, false);
  } else if(rank != 0) {
    // the order of write_vtu()'s arrays
    points();
    indices(share.triangle_numbers, MERGED_TRIANGLES, 3, false);
    indices(share.segment_numbers, MERGED_SEGMENTS, 2, false);
    write_values<std::int32_t>(os, raw, binary, rank, ranks, share.point_markers, MERGED_MARKERS);
    write_values<std::int32_t>(os, raw, binary, rank, ranks, share.segment_markers, MERGED_SEGMENT_MARKERS);
    if(share.regions) write_values<double>(os, raw, binary, rank, ranks, share.triangle_regions, MERGED_REGIONS);
  } else {
    Vtu_tags tags;
    tags.segments_per_rank = segments_per_rank;
    tags.regions = share.regions;
    tags.segments = [&](std::string&, bool wide) { indices(share.segment_numbers, MERGED_SEGMENTS, 2, wide); };
    tags.point_markers = [&](std::string&) {
      write_values<std::int32_t>(os, raw, binary, rank, ranks, share.point_markers, MERGED_MARKERS);
    };
    tags.segment_markers = [&](std::string&) {
      write_values<std::int32_t>(os, raw, binary, rank, ranks, share.segment_markers, MERGED_SEGMENT_MARKERS);
    };
    tags.triangle_regions = [&](std::string&) {
      write_values<double>(os, raw, binary, rank, ranks, share.triangle_regions, MERGED_REGIONS);
    };
    write_vtu(os, nv, triangles_per_rank, 0, binary, [&](std::string&) { points(); },
              [&](std::string&, bool wide) { indices(share.triangle_numbers, MERGED_TRIANGLES, 3, wide); }, {},
              tags);
  }
  if(rank != 0) return;
  os.close();
  if(os.fail()) throw std::runtime_error("cannot write " + out);
}

} // namespace afmesh_2_mpi

#endif // AFMESH_2_MPI_MERGED_H
