// afmesh_2_mpi: each rank's share of the mesh, its vertices numbered
// across the ranks, and the files: one .vtu piece per rank with a .pvtu
// collection, or (--merge) one file written by rank 0.
//
// A rank's share is its part's triangles, less the band it sent to the rank
// below, plus the merged band of the cut above it. A vertex is owned by the
// lowest rank whose share holds it: a rank's vertices are its own but for
// those of the band it sent down, which the rank below holds too. Owned
// vertices are numbered across the ranks by an exclusive scan of their
// counts, in the order each rank met them; the rank below tells the rank
// above the numbers of the band's points.
#ifndef AFMESH_2_MPI_PIECES_H
#define AFMESH_2_MPI_PIECES_H

#include "bands.h"

#include <CGAL/Advancing_front_mesh_2/IO/internal/Vtu_layout.h>
#include <CGAL/Advancing_front_mesh_2/internal/Flat_hash_map.h>

#include <array>
#include <cstdint>
#include <fstream>
#include <functional>
#include <iomanip>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace afmesh_2_mpi {

// The tags of a share held in memory (tags.h): the points' markers, the
// triangles' region attributes (when the input has regions) and the
// segments, by the share's local indices.
struct Share_tagging
{
  bool regions = false;
  std::vector<int> markers;
  std::vector<double> regions_of_triangles;
  std::vector<std::array<std::uint64_t, 2> > segments;
  std::vector<int> segment_markers;
};

struct Rank_mesh
{
  Share_tagging tags;
  std::vector<std::array<double, 2> > points;
  std::vector<std::array<std::uint64_t, 3> > triangles; // by local point index
  std::vector<char> owned;
  std::vector<std::uint64_t> global_id;
  std::uint64_t owned_count = 0, first_id = 0;
};

// The local index of each vertex of a triangulation that a triangle of the
// share uses, given when first met (a hash table of the vertices'
// addresses: a tree of a million points took a tenth of the run).
class Vertex_numbering
{
public:
  explicit Vertex_numbering(Rank_mesh& m) : m_(m), index_(nullptr) {}
  void reserve(std::size_t n) { index_.reserve(n); }

  template <class Vertex_handle>
  std::uint64_t operator()(Vertex_handle v)
  {
    if(const std::uint64_t* i = index_.find(&*v)) return *i;
    m_.points.push_back({{CGAL::to_double(v->point().x()), CGAL::to_double(v->point().y())}});
    return index_.insert(&*v, m_.points.size() - 1);
  }
  template <class Vertex_handle>
  const std::uint64_t* find(Vertex_handle v) const
  {
    return index_.find(&*v);
  }
  // gives vertex v the index `i` (a vertex of another triangulation at the
  // same point)
  template <class Vertex_handle>
  void alias(Vertex_handle v, std::uint64_t i)
  {
    index_.insert(&*v, i);
  }

private:
  Rank_mesh& m_;
  AFM::internal::Flat_hash_map<const void*, std::uint64_t> index_;
};

// The vertex of `band`'s part at each point of its soup.
template <class K>
std::vector<typename CDT<K>::Vertex_handle> soup_vertices(const Band<K>& band)
{
  std::vector<typename CDT<K>::Vertex_handle> v(band.soup.points.size());
  for(std::size_t t = 0; t < band.faces.size(); ++t)
    for(int k = 0; k < 3; ++k) v[band.soup.triangles[t][std::size_t(k)]] = band.faces[t]->vertex(k);
  return v;
}

// A vertex's number not known yet.
constexpr std::uint64_t no_number = ~std::uint64_t(0);

// Numbers the owned vertices of `m` (`m.owned` set) across the ranks: an
// exclusive scan of their counts, in the order of the share's points; the
// other vertices get no_number (the rank that owns them sends theirs).
inline void number_owned(Rank_mesh& m, int rank)
{
  m.owned_count = 0;
  for(char o : m.owned) m.owned_count += o != 0;
  m.first_id = exclusive_scan(m.owned_count, rank);
  m.global_id.assign(m.points.size(), no_number);
  std::uint64_t next = m.first_id;
  for(std::size_t i = 0; i < m.points.size(); ++i)
    if(m.owned[i]) m.global_id[i] = next++;
}

// This rank's share, with every vertex's number; or, when
// `input_constraints` is given, its triangles alone, with the input
// constraints among their edges (bit k of a triangle: the edge opposite its
// vertex k, as Triangle_soup_2 has them), for the refinement of --min-angle
// (min_angle.h), which numbers the vertices afterwards.
template <class K>
Rank_mesh rank_mesh(const CDT<K>& part_cdt, const Interface_work<K>& w, int rank, bool has_part,
                    std::vector<unsigned char>* input_constraints = nullptr)
{
  typedef typename CDT<K>::Face_handle Face_handle;
  Rank_mesh m;
  Vertex_numbering part(m), merged(m);
  AFM::internal::Flat_hash_map<const void*, char> moved(nullptr);
  if(w.has_lower)
    for(Face_handle f : w.sent.faces) moved.insert(&*f, 1);
  if(w.has_upper)
    for(Face_handle f : w.kept_band.faces) moved.insert(&*f, 1);
  if(has_part && part_cdt.dimension() == 2) {
    part.reserve(part_cdt.number_of_vertices());
    for(auto f = part_cdt.finite_faces_begin(); f != part_cdt.finite_faces_end(); ++f)
      if(f->is_in_domain() && !moved.contains(&*f)) {
        m.triangles.push_back({{part(f->vertex(0)), part(f->vertex(1)), part(f->vertex(2))}});
        if(input_constraints != nullptr)
          input_constraints->push_back(
            (unsigned char)((f->is_constrained(0) ? 1 : 0) | (f->is_constrained(1) ? 2 : 0) | (f->is_constrained(2) ? 4 : 0)));
      }
  }
  if(w.has_upper) {
    // the merged band meets the part's triangles at the band's edge, where
    // its vertices have not moved: matched by point
    std::map<std::pair<double, double>, std::uint64_t> at_band_edge;
    for(const auto& v : soup_vertices<K>(w.kept_band))
      if(const std::uint64_t* i = part.find(v)) at_band_edge[key_of(v->point())] = *i;
    for(auto v = w.merged.finite_vertices_begin(); v != w.merged.finite_vertices_end(); ++v) {
      const auto it = at_band_edge.find(key_of(v->point()));
      if(it != at_band_edge.end()) merged.alias(v, it->second);
    }
    for(auto f = w.merged.finite_faces_begin(); f != w.merged.finite_faces_end(); ++f)
      if(f->is_in_domain()) {
        m.triangles.push_back({{merged(f->vertex(0)), merged(f->vertex(1)), merged(f->vertex(2))}});
        // the merged band holds its outer edges as constraints too: an input
        // constraint there has the band on both sides, or is one at the
        // band's edge that the part's triangle beside it says is one (an
        // edge on the domain's boundary is held either way)
        if(input_constraints != nullptr) {
          unsigned char bits = 0;
          for(int k = 0; k < 3; ++k) {
            const auto g = f->neighbor(k);
            if(f->is_constrained(k) && !w.merged.is_infinite(g) && g->is_in_domain()) bits |= (unsigned char)(1 << k);
          }
          input_constraints->push_back(bits);
        }
      }
  }
  if(input_constraints != nullptr) return m;
  m.owned.assign(m.points.size(), 1);
  std::vector<typename CDT<K>::Vertex_handle> sent;
  if(w.has_lower) {
    sent = soup_vertices<K>(w.sent);
    for(const auto& v : sent)
      if(const std::uint64_t* i = part.find(v)) m.owned[*i] = 0;
  }
  number_owned(m, rank);
  // the numbers of the band points: down from the rank that owns them
  if(w.has_upper) {
    std::vector<std::uint64_t> ids;
    for(const auto& v : w.upper_vertices) {
      const std::uint64_t* i = merged.find(v);
      if(i == nullptr) throw std::logic_error("a point of the band above is not in the merged band");
      ids.push_back(m.global_id[*i]);
    }
    send_vector(ids, rank + 1, BAND_IDS);
  }
  if(w.has_lower) {
    const std::vector<std::uint64_t> ids = receive_vector<std::uint64_t>(rank - 1, BAND_IDS);
    if(ids.size() != sent.size()) throw std::logic_error("the band's numbers do not match its points");
    for(std::size_t k = 0; k < ids.size(); ++k)
      if(const std::uint64_t* i = part.find(sent[k])) m.global_id[*i] = ids[k];
  }
  for(std::uint64_t id : m.global_id)
    if(id == no_number) throw std::logic_error("a vertex of the rank's share has no number");
  return m;
}

struct Stream_out
{
  std::ostream& os;
  void put(const char* s, std::size_t n) { os.write(s, static_cast<std::streamsize>(n)); }
};

namespace vtu = CGAL::Advancing_front_mesh_2::IO::internal;

// Connectivity and offsets are Int32 when every value fits (a piece of
// fewer than 715 million triangles), Int64 otherwise: a third less disk for
// the pieces of a large mesh.
inline bool wide_indices(std::uint64_t nv, std::uint64_t connectivity_length)
{
  const std::uint64_t int32_max = 2147483647u;
  return nv > int32_max || connectivity_length > int32_max;
}

// Appends index `v` to a binary array, or prints it.
inline void put_index(std::ostream& os, std::string& raw, bool binary, bool wide, std::uint64_t v, char end)
{
  if(!binary) os << v << end;
  else if(wide) vtu::vtu_append_raw(raw, std::int64_t(v));
  else vtu::vtu_append_raw(raw, std::int32_t(v));
}

// Writes what `raw` holds to `os` and empties it.
inline void write_out(std::ostream& os, std::string& raw)
{
  os.write(raw.data(), static_cast<std::streamsize>(raw.size()));
  raw.clear();
}

// Appends a value to a binary array, or prints it on a line.
template <class T>
void put_value(std::ostream& os, std::string& raw, bool binary, T v)
{
  if(binary) vtu::vtu_append_raw(raw, v);
  else os << v << '\n';
}

// What a .vtu holds besides its points and triangles, as afmesh_2 writes
// it: the segments as lines (type 3) after the triangles, point data
// `marker`, cell data `marker` (0 for the triangles) and, when the input
// has regions, cell data `region` (0 for the segments). The functions
// append the values (binary) or print them (ASCII), in order: `segments`
// two indices each (Int64 when `wide`, as the connectivity), the markers
// of the points, the attributes of the triangles, the markers of the
// segments.
struct Vtu_tags
{
  std::vector<std::uint64_t> segments_per_rank;
  bool regions = false;
  std::function<void(std::string&, bool)> segments;
  std::function<void(std::string&)> point_markers, triangle_regions, segment_markers;
};

// The arrays of a .vtu of `nv` points and the triangles counted per rank in
// `triangles_per_rank`: `points(raw)` and `connectivity(raw, wide)` append
// the values (binary; Int64 indices when `wide`, else Int32) or print them
// (ASCII), and so does `global_ids(raw)` (when set); the partition of each
// cell is its rank, counted from `first_rank`; `tags` the rest.
template <class Points, class Connectivity>
void write_vtu(std::ostream& os, std::uint64_t nv, const std::vector<std::uint64_t>& triangles_per_rank,
               int first_rank, bool binary, const Points& points, const Connectivity& connectivity,
               const std::function<void(std::string&)>& global_ids, const Vtu_tags& tags)
{
  std::uint64_t nt = 0, ns = 0;
  for(std::uint64_t n : triangles_per_rank) nt += n;
  for(std::uint64_t n : tags.segments_per_rank) ns += n;
  const bool wide = wide_indices(nv, 3 * nt + 2 * ns);
  const std::uint64_t index_bytes = wide ? 8 : 4;
  const std::string index_type = wide ? "Int64" : "Int32";
  std::string raw;
  auto flush = [&] {
    os.write(raw.data(), static_cast<std::streamsize>(raw.size()));
    raw.clear();
  };
  auto flush_if_full = [&] {
    if(raw.size() > (1u << 20)) flush();
  };
  std::vector<vtu::Vtu_array> arrays;
  arrays.push_back({vtu::Vtu_section::POINTS, "type=\"Float64\" NumberOfComponents=\"3\"", 24 * nv, [&] {
    points(raw);
    flush();
  }});
  arrays.push_back({vtu::Vtu_section::CELLS, "type=\"" + index_type + "\" Name=\"connectivity\"",
                    index_bytes * (3 * nt + 2 * ns), [&] {
                      connectivity(raw, wide);
                      flush();
                      if(tags.segments) tags.segments(raw, wide);
                      flush();
                    }});
  arrays.push_back({vtu::Vtu_section::CELLS, "type=\"" + index_type + "\" Name=\"offsets\"",
                    index_bytes * (nt + ns), [&] {
                      for(std::uint64_t t = 1; t <= nt; ++t) {
                        put_index(os, raw, binary, wide, 3 * t, '\n');
                        flush_if_full();
                      }
                      for(std::uint64_t i = 1; i <= ns; ++i) put_index(os, raw, binary, wide, 3 * nt + 2 * i, '\n');
                      flush();
                    }});
  arrays.push_back({vtu::Vtu_section::CELLS, "type=\"UInt8\" Name=\"types\"", nt + ns, [&] {
    for(std::uint64_t t = 0; t < nt + ns; ++t) {
      const char type = t < nt ? 5 : 3;
      if(binary) raw.push_back(type);
      else os << int(type) << '\n';
      flush_if_full();
    }
    flush();
  }});
  if(global_ids)
    arrays.push_back({vtu::Vtu_section::POINT_DATA, "type=\"Int64\" Name=\"GlobalNodeId\"", 8 * nv, [&] {
      global_ids(raw);
      flush();
    }});
  if(tags.point_markers)
    arrays.push_back({vtu::Vtu_section::POINT_DATA, "type=\"Int32\" Name=\"marker\"", 4 * nv, [&] {
      tags.point_markers(raw);
      flush();
    }});
  arrays.push_back({vtu::Vtu_section::CELL_DATA, "type=\"Int32\" Name=\"partition\"", 4 * (nt + ns), [&] {
    for(const std::vector<std::uint64_t>* counts : {&triangles_per_rank, &tags.segments_per_rank})
      for(std::size_t r = 0; r < counts->size(); ++r)
        for(std::uint64_t t = 0; t < (*counts)[r]; ++t) {
          put_value(os, raw, binary, std::int32_t(first_rank + int(r)));
          flush_if_full();
        }
    flush();
  }});
  if(tags.point_markers) {
    arrays.push_back({vtu::Vtu_section::CELL_DATA, "type=\"Int32\" Name=\"marker\"", 4 * (nt + ns), [&] {
      for(std::uint64_t t = 0; t < nt; ++t) {
        put_value(os, raw, binary, std::int32_t(0));
        flush_if_full();
      }
      flush();
      if(tags.segment_markers) tags.segment_markers(raw);
      flush();
    }});
    if(tags.regions)
      arrays.push_back({vtu::Vtu_section::CELL_DATA, "type=\"Float64\" Name=\"region\"", 8 * (nt + ns), [&] {
        tags.triangle_regions(raw);
        flush();
        for(std::uint64_t i = 0; i < ns; ++i) put_value(os, raw, binary, 0.);
        flush();
      }});
  }
  Stream_out out{os};
  // ParaView takes the global numbers for what they are when told
  vtu::vtu_write(out, nv, nt + ns, arrays, binary,
                 {global_ids ? std::string(" GlobalIds=\"GlobalNodeId\"") : std::string(), std::string()});
}

// The tags of one piece in memory, written by local indices.
inline Vtu_tags vtu_tags(std::ostream& os, bool binary, const Share_tagging& t)
{
  Vtu_tags v;
  v.segments_per_rank = {t.segments.size()};
  v.regions = t.regions;
  v.segments = [&os, &t, binary](std::string& raw, bool wide) {
    for(const auto& s : t.segments) {
      put_index(os, raw, binary, wide, s[0], ' ');
      put_index(os, raw, binary, wide, s[1], '\n');
    }
  };
  v.point_markers = [&os, &t, binary](std::string& raw) {
    for(int k : t.markers) put_value(os, raw, binary, std::int32_t(k));
  };
  v.triangle_regions = [&os, &t, binary](std::string& raw) {
    for(double a : t.regions_of_triangles) put_value(os, raw, binary, a);
  };
  v.segment_markers = [&os, &t, binary](std::string& raw) {
    for(int k : t.segment_markers) put_value(os, raw, binary, std::int32_t(k));
  };
  return v;
}

inline void append_points(std::ostream& os, std::string& raw, bool binary,
                          const std::vector<std::array<double, 2> >& points)
{
  for(std::size_t i = 0; i < points.size(); ++i) {
    if(binary) {
      vtu::vtu_append_raw(raw, points[i][0]);
      vtu::vtu_append_raw(raw, points[i][1]);
      vtu::vtu_append_raw(raw, 0.);
    } else {
      os << points[i][0] << ' ' << points[i][1] << " 0\n";
    }
  }
}

inline std::string piece_name(const std::string& pvtu, int rank)
{
  return pvtu.substr(0, pvtu.size() - 5) + "_" + std::to_string(rank) + ".vtu";
}

inline std::string base_name(const std::string& path)
{
  const std::size_t slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

// The collection file OUT.pvtu (rank 0): the pieces of the ranks that have
// triangles (meshio cannot read a piece without cells).
inline void write_collection(const std::string& pvtu, const std::vector<std::uint64_t>& triangles_per_rank, int ranks,
                             bool regions)
{
  std::ofstream os(pvtu);
  os << "<?xml version=\"1.0\"?>\n<VTKFile type=\"PUnstructuredGrid\" version=\"0.1\" byte_order=\""
     << (vtu::vtu_host_is_little_endian() ? "LittleEndian" : "BigEndian") << "\" header_type=\"UInt64\">\n"
     << "<PUnstructuredGrid GhostLevel=\"0\">\n"
     << "<PPointData GlobalIds=\"GlobalNodeId\"><PDataArray type=\"Int64\" Name=\"GlobalNodeId\"/>"
     << "<PDataArray type=\"Int32\" Name=\"marker\"/></PPointData>\n"
     << "<PCellData><PDataArray type=\"Int32\" Name=\"partition\"/><PDataArray type=\"Int32\" Name=\"marker\"/>"
     << (regions ? "<PDataArray type=\"Float64\" Name=\"region\"/>" : "") << "</PCellData>\n"
     << "<PPoints><PDataArray type=\"Float64\" NumberOfComponents=\"3\"/></PPoints>\n";
  for(int r = 0; r < ranks; ++r)
    if(triangles_per_rank[std::size_t(r)] > 0) os << "<Piece Source=\"" << base_name(piece_name(pvtu, r)) << "\"/>\n";
  os << "</PUnstructuredGrid>\n</VTKFile>\n";
  os.close();
  if(os.fail()) throw std::runtime_error("cannot write " + pvtu);
}

// This rank's piece of OUT.pvtu (OUT_<rank>.vtu), and the collection file
// (rank 0). A rank with no triangles writes no piece, and the collection
// names only the others (meshio cannot read a piece without cells). Throws
// std::runtime_error when a file cannot be written.
inline void write_piece(const std::string& pvtu, const Rank_mesh& m, int rank, int ranks, bool binary)
{
  const std::string name = piece_name(pvtu, rank);
  const std::vector<std::uint64_t> triangles_per_rank = gather_to_root<std::uint64_t>(m.triangles.size(), ranks);
  if(!m.triangles.empty()) {
    std::ofstream os(name, std::ios::binary);
    os << std::setprecision(17);
    write_vtu(os, m.points.size(), {m.triangles.size()}, rank, binary,
              [&](std::string& raw) { append_points(os, raw, binary, m.points); },
              [&](std::string& raw, bool wide) {
                for(const auto& t : m.triangles)
                  for(int k = 0; k < 3; ++k) put_index(os, raw, binary, wide, t[std::size_t(k)], k == 2 ? '\n' : ' ');
              },
              [&](std::string& raw) {
                for(std::uint64_t id : m.global_id) put_index(os, raw, binary, true, id, '\n');
              },
              vtu_tags(os, binary, m.tags));
    os.close();
    if(os.fail()) throw std::runtime_error("cannot write " + name);
  }
  if(rank == 0) write_collection(pvtu, triangles_per_rank, ranks, m.tags.regions);
}

} // namespace afmesh_2_mpi

#endif // AFMESH_2_MPI_PIECES_H
