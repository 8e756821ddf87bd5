// afmesh_2_mpi --merge: the whole mesh in one file, written by rank 0 as
// the other ranks send their shares, one rank after another (rank 0 holds
// one share at a time): first the owned points of each rank in the order of
// their numbers, then each rank's triangles by those numbers.
#ifndef AFMESH_2_MPI_MERGED_H
#define AFMESH_2_MPI_MERGED_H

#include "pieces.h"

#include <fstream>
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

// The tags of the merged .vtu (rank 0): its own share's, then each other
// rank's as it sends them, one array at a time (the ranks send in the
// order of the arrays).
inline Vtu_tags merged_tags(std::ostream& os, bool binary, const Rank_mesh& m, int ranks,
                            const std::vector<std::uint64_t>& segments_per_rank)
{
  Vtu_tags v;
  v.segments_per_rank = segments_per_rank;
  v.regions = m.tags.regions;
  auto flush = [&os](std::string& raw) { write_out(os, raw); };
  v.segments = [&os, &m, binary, ranks, flush](std::string& raw, bool wide) {
    for(int r = 0; r < ranks; ++r) {
      const std::vector<std::uint64_t> s =
        r == 0 ? numbered_segments(m) : receive_vector<std::uint64_t>(r, MERGED_SEGMENTS);
      for(std::size_t i = 0; i < s.size(); ++i) put_index(os, raw, binary, wide, s[i], i % 2 == 1 ? '\n' : ' ');
      flush(raw);
    }
  };
  v.point_markers = [&os, &m, binary, ranks, flush](std::string& raw) {
    for(int r = 0; r < ranks; ++r) {
      for(std::int32_t k : r == 0 ? owned_markers(m) : receive_vector<std::int32_t>(r, MERGED_MARKERS))
        put_value(os, raw, binary, k);
      flush(raw);
    }
  };
  v.triangle_regions = [&os, &m, binary, ranks, flush](std::string& raw) {
    for(int r = 0; r < ranks; ++r) {
      for(double a : r == 0 ? m.tags.regions_of_triangles : receive_vector<double>(r, MERGED_REGIONS))
        put_value(os, raw, binary, a);
      flush(raw);
    }
  };
  v.segment_markers = [&os, &m, binary, ranks, flush](std::string& raw) {
    for(int r = 0; r < ranks; ++r) {
      const std::vector<std::int32_t> k =
        r == 0 ? std::vector<std::int32_t>(m.tags.segment_markers.begin(), m.tags.segment_markers.end())
               : receive_vector<std::int32_t>(r, MERGED_SEGMENT_MARKERS);
      for(std::int32_t marker : k) put_value(os, raw, binary, marker);
      flush(raw);
    }
  };
  return v;
}

// Rank 0 writes `out` (.off or .vtu: with the segments, markers and
// regions as afmesh_2 writes them); the others send it their shares.
// Throws std::runtime_error (rank 0) when the file cannot be written.
inline void write_merged(const std::string& out, const Rank_mesh& m, int rank, int ranks, bool binary)
{
  const std::vector<std::uint64_t> triangles_per_rank = gather_to_root<std::uint64_t>(m.triangles.size(), ranks);
  const std::vector<std::uint64_t> segments_per_rank = gather_to_root<std::uint64_t>(m.tags.segments.size(), ranks);
  const std::uint64_t nv = sum_over_ranks(m.owned_count);
  const bool vtu = !afmesh_2::ends_with(out, ".off");
  if(rank != 0) {
    send_vector(owned_points(m), 0, MERGED_POINTS);
    send_vector(numbered_triangles(m), 0, MERGED_TRIANGLES);
    if(vtu) {
      send_vector(numbered_segments(m), 0, MERGED_SEGMENTS);
      // in the order rank 0 writes the arrays (write_vtu()): a large
      // message waits until rank 0 takes it
      send_vector(owned_markers(m), 0, MERGED_MARKERS);
      std::vector<std::int32_t> segment_markers(m.tags.segment_markers.begin(), m.tags.segment_markers.end());
      send_vector(segment_markers, 0, MERGED_SEGMENT_MARKERS);
      if(m.tags.regions) send_vector(m.tags.regions_of_triangles, 0, MERGED_REGIONS);
    }
    return;
  }
  auto points_of = [&](int r) { return r == 0 ? owned_points(m) : receive_vector<double>(r, MERGED_POINTS); };
  auto triangles_of = [&](int r) {
    return r == 0 ? numbered_triangles(m) : receive_vector<std::uint64_t>(r, MERGED_TRIANGLES);
  };
  std::ofstream os(out, std::ios::binary);
  os << std::setprecision(17);
  if(!vtu) {
    std::uint64_t nt = 0;
    for(std::uint64_t n : triangles_per_rank) nt += n;
    os << "OFF\n" << nv << ' ' << nt << " 0\n";
    for(int r = 0; r < ranks; ++r) {
      const std::vector<double> xy = points_of(r);
      for(std::size_t i = 0; i + 1 < xy.size(); i += 2) os << xy[i] << ' ' << xy[i + 1] << " 0\n";
    }
    for(int r = 0; r < ranks; ++r) {
      const std::vector<std::uint64_t> t = triangles_of(r);
      for(std::size_t i = 0; i + 2 < t.size(); i += 3) os << "3 " << t[i] << ' ' << t[i + 1] << ' ' << t[i + 2] << '\n';
    }
  } else {
    write_vtu(os, nv, triangles_per_rank, 0, binary,
              [&](std::string& raw) {
                for(int r = 0; r < ranks; ++r) {
                  const std::vector<double> xy = points_of(r);
                  for(std::size_t i = 0; i + 1 < xy.size(); i += 2) {
                    if(binary) {
                      vtu::vtu_append_raw(raw, xy[i]);
                      vtu::vtu_append_raw(raw, xy[i + 1]);
                      vtu::vtu_append_raw(raw, 0.);
                    } else {
                      os << xy[i] << ' ' << xy[i + 1] << " 0\n";
                    }
                  }
                  os.write(raw.data(), static_cast<std::streamsize>(raw.size()));
                  raw.clear();
                }
              },
              [&](std::string& raw, bool wide) {
                for(int r = 0; r < ranks; ++r) {
                  const std::vector<std::uint64_t> t = triangles_of(r);
                  for(std::size_t i = 0; i < t.size(); ++i)
                    put_index(os, raw, binary, wide, t[i], i % 3 == 2 ? '\n' : ' ');
                  os.write(raw.data(), static_cast<std::streamsize>(raw.size()));
                  raw.clear();
                }
              },
              {}, merged_tags(os, binary, m, ranks, segments_per_rank));
  }
  os.close();
  if(os.fail()) throw std::runtime_error("cannot write " + out);
}

} // namespace afmesh_2_mpi

#endif // AFMESH_2_MPI_MERGED_H
