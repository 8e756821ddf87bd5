// afmesh_2_mpi --merge in every format of afmesh_2's outputs.
//
// Three writers, each as afmesh_2 writes its formats:
// - .off and .vtu: merged.h's, one array of every rank after another;
// - .node/.ele (with .edge) and .msh: the library's Streaming_mesh_writer
//   (afmesh_2 --stream's), which takes a vertex with its marker and a
//   triangle with its region whole: rank 0 feeds it the ranks' points, then
//   their triangles, then their segments, a chunk at a time, so that it
//   holds one chunk, as for .off and .vtu (also with --stream);
// - .svg (the picture) and .poly (the boundary): they need the whole mesh,
//   as afmesh_2's do (refused with --stream, as there): rank 0 gathers it,
//   makes its triangulation (the mesh's triangles as faces, its segments as
//   constraints) and the markers and regions, and writes them with
//   afmesh_2's writer.
#ifndef AFMESH_2_MPI_MERGED_FORMATS_H
#define AFMESH_2_MPI_MERGED_FORMATS_H

#include "../afmesh_2/output.h"
#include "merged.h"
#include "min_angle.h"

#include <CGAL/Advancing_front_mesh_2/IO/Streaming_mesh_writer.h>
#include <CGAL/Advancing_front_mesh_2/Markers_and_regions_2.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

namespace afmesh_2_mpi {

// The writer of a --merge output, by its extension.
enum class Merged_writer { ARRAYS, STREAMING, WHOLE };

inline Merged_writer merged_writer_of(const std::string& out)
{
  using afmesh_2::ends_with;
  if(ends_with(out, ".off") || ends_with(out, ".vtu")) return Merged_writer::ARRAYS;
  if(ends_with(out, ".svg") || ends_with(out, ".poly")) return Merged_writer::WHOLE;
  return Merged_writer::STREAMING; // .node, .ele, .msh
}

// Rank 0 hands every rank's segments (the ends' numbers and the marker) to
// `take`, one rank after another; the others send theirs. Segments lie on
// the boundary and the input's constraints, so each rank's are few.
template <class Take>
void each_segment_of_ranks(int rank, int ranks, const Merged_share& share, const Take& take)
{
  std::vector<std::uint64_t> ends;
  std::vector<std::int32_t> markers;
  share.segment_numbers([&ends](const std::uint64_t* v, std::size_t n) { ends.insert(ends.end(), v, v + n); });
  share.segment_markers([&markers](const std::int32_t* v, std::size_t n) { markers.insert(markers.end(), v, v + n); });
  if(ends.size() != 2 * markers.size()) throw std::logic_error("a share's segments and their markers differ in count");
  if(rank != 0) {
    send_vector(ends, 0, MERGED_SEGMENTS);
    send_vector(markers, 0, MERGED_SEGMENT_MARKERS);
    return;
  }
  for(int r = 0; r < ranks; ++r) {
    if(r != 0) {
      ends = receive_vector<std::uint64_t>(r, MERGED_SEGMENTS);
      markers = receive_vector<std::int32_t>(r, MERGED_SEGMENT_MARKERS);
    }
    for(std::size_t i = 0; i < markers.size(); ++i) take(ends[2 * i], ends[2 * i + 1], int(markers[i]));
  }
}

// Rank 0 writes the outputs `outs` (.node/.ele, .msh) with one
// Streaming_mesh_writer, as afmesh_2 --stream does, from the ranks' shares;
// the others send their shares. `attributes` are the input's region
// attributes (0 included), empty without regions. Throws std::runtime_error
// (rank 0, after every share was taken) when a file cannot be written.
template <class Point>
void write_merged_streaming(const std::vector<std::string>& outs, const Merged_share& share,
                            const std::vector<double>& attributes, int rank, int ranks, bool binary)
{
  typedef CGAL::Advancing_front_mesh_2::IO::Streaming_mesh_writer<Point> Writer;
  std::unique_ptr<Writer> writer;
  std::string failure;
  // a failure stops the writing, not the protocol: the shares are taken
  // all the same, so that no rank waits for rank 0 forever
  auto guarded = [&](const auto& f) {
    if(rank != 0 || !failure.empty()) return;
    try {
      f();
    } catch(const std::exception& e) {
      failure = e.what();
    }
  };
  guarded([&] {
    CGAL::Advancing_front_mesh_2::IO::Streaming_mesh_writer_options o;
    o.use_binary_mode = binary;
    o.markers = true;
    o.region_attributes = attributes;
    writer.reset(new Writer(outs, o));
  });
  std::size_t vertex = 0;
  each_rank_values<double>(rank, ranks, share.marked_points, MERGED_POINTS, [&](const double* v, std::size_t n) {
    guarded([&] {
      for(std::size_t i = 0; i + 2 < n; i += 3) writer->add_vertex(vertex++, Point(v[i], v[i + 1]), int(v[i + 2]));
    });
  });
  each_rank_values<std::uint64_t>(rank, ranks, share.regioned_triangles, MERGED_TRIANGLES,
                                  [&](const std::uint64_t* v, std::size_t n) {
                                    guarded([&] {
                                      for(std::size_t i = 0; i + 3 < n; i += 4)
                                        writer->add_triangle(std::size_t(v[i]), std::size_t(v[i + 1]),
                                                             std::size_t(v[i + 2]), attribute_of_bits(v[i + 3]));
                                    });
                                  });
  each_segment_of_ranks(rank, ranks, share, [&](std::uint64_t a, std::uint64_t b, int marker) {
    guarded([&] { writer->add_segment(std::size_t(a), std::size_t(b), marker); });
  });
  guarded([&] { writer->close(); });
  if(!failure.empty()) throw std::runtime_error(failure);
}

// The whole mesh on rank 0 (the others send their shares and get an empty
// mesh): its points by number, its triangles, and the markers of both.
struct Whole_mesh
{
  Rank_mesh mesh; // points and triangles by global number
  std::vector<int> point_markers;
  std::vector<std::array<std::uint64_t, 3> > segments; // ends, marker
};

inline Whole_mesh gather_whole_mesh(const Merged_share& share, int rank, int ranks)
{
  Whole_mesh w;
  each_rank_values<double>(rank, ranks, share.marked_points, MERGED_POINTS, [&](const double* v, std::size_t n) {
    for(std::size_t i = 0; i + 2 < n; i += 3) {
      w.mesh.points.push_back({{v[i], v[i + 1]}});
      w.point_markers.push_back(int(v[i + 2]));
    }
  });
  each_rank_values<std::uint64_t>(rank, ranks, share.regioned_triangles, MERGED_TRIANGLES,
                                  [&](const std::uint64_t* v, std::size_t n) {
                                    for(std::size_t i = 0; i + 3 < n; i += 4)
                                      w.mesh.triangles.push_back({{v[i], v[i + 1], v[i + 2]}});
                                  });
  each_segment_of_ranks(rank, ranks, share, [&](std::uint64_t a, std::uint64_t b, int marker) {
    w.segments.push_back({{a, b, std::uint64_t(std::int64_t(marker))}});
  });
  return w;
}

// Rank 0 writes the outputs `outs` (.svg, .poly) of the whole mesh with
// afmesh_2's writer: the mesh in a triangulation of its own (each triangle a
// face, the segments its constraints), the markers as the shares have them
// and the regions of the input (`tags`), found again on its faces as
// afmesh_2 finds them. The others send their shares. Throws
// std::runtime_error (rank 0) when a file cannot be written.
template <class K>
void write_merged_whole(const afmesh_2::Options& opt, const std::vector<std::string>& outs,
                        const Merged_share& share, const AFM::Markers_and_regions_2<CDT<K> >& input_tags, int rank,
                        int ranks)
{
  typedef CDT<K> Cdt;
  typedef typename Cdt::Vertex_handle Vertex_handle;
  Whole_mesh w = gather_whole_mesh(share, rank, ranks);
  if(rank != 0) return;
  // the segments of each triangle, as Triangle_soup_2 has its input
  // constraints: bit k for the edge opposite vertex k
  std::unordered_map<std::uint64_t, char> segment;
  auto key = [](std::uint64_t a, std::uint64_t b) { return ((std::min)(a, b) << 32) | (std::max)(a, b); };
  if(w.mesh.points.size() >= (std::uint64_t(1) << 32))
    throw std::runtime_error("more than 2^32 vertices: too many for a picture or a boundary of the whole mesh");
  for(const auto& s : w.segments) segment.emplace(key(s[0], s[1]), 1);
  std::vector<unsigned char> input_constraints(w.mesh.triangles.size(), 0);
  for(std::size_t t = 0; t < w.mesh.triangles.size(); ++t)
    for(int k = 0; k < 3; ++k)
      if(segment.count(key(w.mesh.triangles[t][(k + 1) % 3], w.mesh.triangles[t][(k + 2) % 3])))
        input_constraints[t] |= (unsigned char)(1 << k);
  Cdt cdt;
  std::vector<Vertex_handle> vertex;
  share_triangulation<K>(w.mesh, input_constraints, cdt, &vertex);
  AFM::Markers_and_regions_2<Cdt> tags;
  for(std::size_t i = 0; i < vertex.size(); ++i)
    if(w.point_markers[i] != 0) tags.set_vertex_marker(vertex[i], w.point_markers[i]);
  for(const auto& s : w.segments)
    if(s[2] != 0) tags.set_constraint_marker(vertex[s[0]], vertex[s[1]], int(std::int64_t(s[2])));
  for(const auto& r : input_tags.regions()) tags.add_region(r.seed, r.attribute, r.max_area);
  if(tags.has_regions()) tags.mark_regions(cdt);
  for(const std::string& out : outs) {
    try {
      afmesh_2::write_output(opt, out, cdt, tags);
    } catch(const std::exception& e) {
      throw std::runtime_error(out + ": " + e.what());
    }
  }
}

// Rank 0 writes every output of --merge (`outs`), each through its writer;
// the others send their share once for each writer. `make_share` makes this
// rank's Merged_share (from memory, or from the scratch files of --stream).
template <class K, class Make_share>
void write_merged_outputs(const afmesh_2::Options& opt, const std::vector<std::string>& outs,
                          const Make_share& make_share, const AFM::Markers_and_regions_2<CDT<K> >& input_tags,
                          const std::vector<double>& attributes, int rank, int ranks)
{
  std::vector<std::string> streaming, whole;
  // -o a.node -o a.ele name the same files (a.node, a.ele, a.edge): once
  std::vector<std::string> written;
  for(const std::string& out : outs) {
    const bool triangle_files = afmesh_2::ends_with(out, ".node") || afmesh_2::ends_with(out, ".ele");
    const std::string files = triangle_files ? out.substr(0, out.find_last_of('.')) + ".node" : out;
    if(std::find(written.begin(), written.end(), files) != written.end()) continue;
    written.push_back(files);
    switch(merged_writer_of(out)) {
    case Merged_writer::ARRAYS: write_merged(out, make_share(), rank, ranks, !opt.vtu_ascii); break;
    case Merged_writer::STREAMING: streaming.push_back(out); break;
    case Merged_writer::WHOLE: whole.push_back(out); break;
    }
  }
  if(!streaming.empty())
    write_merged_streaming<typename K::Point_2>(streaming, make_share(), attributes, rank, ranks, !opt.vtu_ascii);
  if(!whole.empty()) write_merged_whole<K>(opt, whole, make_share(), input_tags, rank, ranks);
}

} // namespace afmesh_2_mpi

#endif // AFMESH_2_MPI_MERGED_FORMATS_H
