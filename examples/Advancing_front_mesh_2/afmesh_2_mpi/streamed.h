// afmesh_2_mpi --stream: a rank's part meshed in streaming mode, for parts
// larger than the rank's memory.
//
// The mesher hands each finished triangle to the rank's sink (Part_stream)
// and forgets it. The sink writes the vertices and the triangles to two
// scratch files beside the rank's piece, except the triangles near the
// part's cuts (a vertex within 32 interface sizes), which it holds in
// memory: the interface merge (bands.h) takes its bands from them and may
// change them. Once the interfaces are merged the rank's share is known:
// the streamed triangles, the held ones not in a band, and the merged band
// of the cut above. The piece is then written from the scratch files in one
// pass each, its vertices renumbered to leave out those only the band sent
// down used (bit sets with counts: a few bits per vertex in memory).
//
// Memory: the mesher's front and unfinished triangles, the held triangles
// (a few hundred bytes per interface point), and about 3 bits per vertex.
// Disk: 28 bytes per triangle of scratch until the piece is written.
#ifndef AFMESH_2_MPI_STREAMED_H
#define AFMESH_2_MPI_STREAMED_H

#include "pieces.h"

#include <CGAL/Advancing_front_mesh_2/Mesh_sink_2.h>

#include <array>
#include <bitset>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <iterator>
#include <fstream>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace afmesh_2_mpi {

// Bits, and the number of set bits before each once counted: the rank of a
// bit in constant time, for renumbering hundreds of millions of vertices
// with two bits each.
class Counted_bits
{
public:
  std::uint64_t size() const { return size_; }
  const std::vector<std::uint64_t>& words() const { return words_; }
  void assign(std::uint64_t n, std::vector<std::uint64_t> words)
  {
    words_ = std::move(words);
    size_ = n;
  }
  void resize(std::uint64_t n)
  {
    words_.resize(std::size_t((n + 63) / 64), 0);
    size_ = n;
  }
  void push_back_zero()
  {
    if(size_ % 64 == 0) words_.push_back(0);
    ++size_;
  }
  void set(std::uint64_t i) { words_[std::size_t(i >> 6)] |= bit(i); }
  void reset(std::uint64_t i) { words_[std::size_t(i >> 6)] &= ~bit(i); }
  bool test(std::uint64_t i) const { return (words_[std::size_t(i >> 6)] & bit(i)) != 0; }
  // after the last change: the counts rank() reads
  void count()
  {
    before_.resize(words_.size());
    std::uint64_t c = 0;
    for(std::size_t k = 0; k < words_.size(); ++k) {
      before_[k] = c;
      c += std::bitset<64>(words_[k]).count();
    }
    total_ = c;
  }
  std::uint64_t total() const { return total_; }
  // the set bits before bit i
  std::uint64_t rank(std::uint64_t i) const
  {
    const std::size_t k = std::size_t(i >> 6);
    return before_[k] + std::bitset<64>(words_[k] & (bit(i) - 1)).count();
  }

private:
  static std::uint64_t bit(std::uint64_t i) { return std::uint64_t(1) << (i & 63); }
  std::vector<std::uint64_t> words_, before_;
  std::uint64_t size_ = 0, total_ = 0;
};

// A scratch file written through a buffer; removed when destroyed.
class Scratch_file
{
public:
  explicit Scratch_file(const std::string& name) : name_(name) {}
  ~Scratch_file()
  {
    if(os_.is_open()) os_.close();
    if(opened_ && !kept_) std::remove(name_.c_str());
  }
  // left on disk at the end (a part kept for --resume)
  void keep(bool on = true) { kept_ = on; }
  // the bytes written so far
  std::uint64_t size() const { return written_; }
  // takes over the file a previous run left, which must have `bytes`
  bool adopt(std::uint64_t bytes)
  {
    std::ifstream is(name_.c_str(), std::ios::in | std::ios::binary | std::ios::ate);
    if(!is || std::uint64_t(is.tellg()) != bytes) return false;
    opened_ = true;
    written_ = bytes;
    return true;
  }
  Scratch_file(const Scratch_file&) = delete;
  Scratch_file& operator=(const Scratch_file&) = delete;
  const std::string& name() const { return name_; }
  template <class T>
  void put(const T* values, std::size_t n)
  {
    if(!opened_) {
      os_.open(name_.c_str(), std::ios::out | std::ios::binary | std::ios::trunc);
      opened_ = true;
    }
    buffer_.append(reinterpret_cast<const char*>(values), n * sizeof(T));
    written_ += n * sizeof(T);
    if(buffer_.size() >= (std::size_t(1) << 22)) flush();
  }
  // everything put so far on disk; throws std::runtime_error when it is not
  void close()
  {
    if(!opened_) return;
    flush();
    os_.close();
    if(os_.fail()) throw std::runtime_error("cannot write " + name_ + " (is the disk full?)");
  }
  // reads the file back, `n` values of type T at a time, into `f(values, n)`
  template <class T, class F>
  void read(std::size_t n, const F& f) const
  {
    if(!opened_) return;
    std::ifstream is(name_.c_str(), std::ios::in | std::ios::binary);
    std::vector<T> values(n);
    while(is) {
      is.read(reinterpret_cast<char*>(values.data()), static_cast<std::streamsize>(n * sizeof(T)));
      const std::size_t got = std::size_t(is.gcount()) / sizeof(T);
      if(got > 0) f(values.data(), got);
    }
    if(is.bad()) throw std::runtime_error("cannot read " + name_);
  }

private:
  void flush()
  {
    os_.write(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
    buffer_.clear();
    if(os_.fail()) throw std::runtime_error("cannot write " + name_ + " (is the disk full?)");
  }
  std::string name_, buffer_;
  std::ofstream os_;
  bool opened_ = false, kept_ = false;
  std::uint64_t written_ = 0;
};

// The first bytes of a kept part's file.
constexpr const char* part_file_magic = "afmesh_2_mpi kept part 1\n";

// The triangles held back near the cuts start at this many interface sizes
// from the cut: the largest band the merge may try (bands.h).
constexpr double held_band_sizes = initial_band_sizes * (1u << most_streamed_widenings);

// The mesher's sink on a rank of a streamed run.
template <class K>
class Part_stream : public AFM::Mesh_sink_2<typename K::Point_2>
{
public:
  typedef typename K::Point_2 Point;
  // a triangle held back: its vertices (the mesher's numbers) and points,
  // and bit k set when its edge opposite vertex k is a constraint of the
  // part (an input segment or a cut)
  struct Held
  {
    std::array<std::uint64_t, 3> v;
    std::array<Point, 3> p;
    unsigned char constraint_edges;
  };

  // The sink of part `part` of `d` (none: `part` >= d.parts), whose input
  // (before meshing) is `part_cdt`; the scratch files start with `stem`.
  Part_stream(const Decomposition<K>& d, std::size_t part, const CDT<K>& part_cdt, const std::string& stem)
      : d_(d), points_(stem + ".points.tmp"), triangles_(stem + ".triangles.tmp")
  {
    if(part >= d.parts) return;
    if(part >= 1) cuts_.push_back(part - 1);
    if(part + 1 < d.parts) cuts_.push_back(part);
    // the mesher puts no vertex on a constrained edge: the part's
    // constraints are the constrained edges of its mesh
    if(part_cdt.dimension() == 2)
      for(auto e = part_cdt.finite_edges_begin(); e != part_cdt.finite_edges_end(); ++e)
        if(part_cdt.is_constrained(*e))
          constraints_.insert(undirected_key(e->first->vertex(CDT<K>::ccw(e->second))->point(),
                                       e->first->vertex(CDT<K>::cw(e->second))->point()));
  }

  void add_vertex(std::size_t i, const Point& p) override
  {
    if(i != used_.size()) throw std::logic_error("afmesh_2_mpi: the mesher's vertices came out of order");
    if(i > 0xffffffffu) throw std::runtime_error("a part has more than 2^32 vertices: start more ranks");
    const double xy[2] = {CGAL::to_double(p.x()), CGAL::to_double(p.y())};
    points_.put(xy, 2);
    used_.push_back_zero();
  }

  void add_finished_triangle(std::size_t i, std::size_t j, std::size_t k, const Point& a, const Point& b,
                             const Point& c) override
  {
    for(std::size_t cut : cuts_)
      if(near(cut, held_band_sizes * d_.interface_size[cut], a, b, c)) {
        unsigned char flags = 0;
        if(constraints_.count(undirected_key(b, c)) > 0) flags |= 1;
        if(constraints_.count(undirected_key(c, a)) > 0) flags |= 2;
        if(constraints_.count(undirected_key(a, b)) > 0) flags |= 4;
        held_.push_back(Held{{{i, j, k}}, {{a, b, c}}, flags});
        return;
      }
    const std::uint32_t v[3] = {std::uint32_t(i), std::uint32_t(j), std::uint32_t(k)};
    triangles_.put(v, 3);
    used_.set(i);
    used_.set(j);
    used_.set(k);
    ++streamed_;
  }

  // the scratch files complete on disk (after meshing)
  void close()
  {
    points_.close();
    triangles_.close();
  }

  // The band near cut `c` of width `width`: the held triangles with a
  // vertex within it; a cut edge is a constraint unless both its ends are
  // points of that cut's interface.
  Band<K, std::size_t> band(std::size_t c, double width) const
  {
    if(width > held_band_sizes * d_.interface_size[c] * (1 + 1e-12))
      throw std::logic_error("afmesh_2_mpi: a band wider than the triangles held back");
    Band<K, std::size_t> b;
    AFM::internal::Flat_hash_map<std::uint64_t, std::size_t> index(~std::uint64_t(0));
    for(std::size_t t = 0; t < held_.size(); ++t) {
      const Held& h = held_[t];
      if(!near(c, width, h.p[0], h.p[1], h.p[2])) continue;
      std::array<std::size_t, 3> tri;
      for(int k = 0; k < 3; ++k) {
        if(const std::size_t* s = index.find(h.v[std::size_t(k)])) {
          tri[std::size_t(k)] = *s;
        } else {
          tri[std::size_t(k)] = index.insert(h.v[std::size_t(k)], b.soup.points.size());
          b.soup.points.push_back(h.p[std::size_t(k)]);
        }
      }
      unsigned char flags = 0;
      for(int k = 0; k < 3; ++k)
        if(((h.constraint_edges >> k) & 1) != 0 &&
           !(on_interface(c, h.p[std::size_t((k + 1) % 3)]) && on_interface(c, h.p[std::size_t((k + 2) % 3)])))
          flags |= static_cast<unsigned char>(1u << k);
      b.soup.triangles.push_back(tri);
      b.soup.constrained.push_back(flags);
      b.faces.push_back(t);
    }
    AFM::internal::sort_soup(b.soup, &b.faces);
    return b;
  }

  // the mesher's number of each point of a band's soup
  std::vector<std::uint64_t> soup_ids(const Band<K, std::size_t>& b) const
  {
    std::vector<std::uint64_t> ids(b.soup.points.size());
    for(std::size_t t = 0; t < b.faces.size(); ++t)
      for(std::size_t k = 0; k < 3; ++k) ids[b.soup.triangles[t][k]] = held_[b.faces[t]].v[k];
    return ids;
  }

  // The part kept for a later run (--stop-after-meshing, or a run that
  // fails after this rank meshed): the scratch files stay, and `file` gets
  // the rest (written whole, then renamed, so that it is either complete or
  // absent), with the digest `run` of the run's decomposition and options.
  void keep(const std::string& file, std::uint64_t run)
  {
    points_.keep();
    triangles_.keep();
    std::string b = part_file_magic;
    auto put = [&b](const void* data, std::size_t n) { b.append(static_cast<const char*>(data), n); };
    const std::uint64_t head[6] = {run, used_.size(), streamed_, points_.size(), triangles_.size(), held_.size()};
    put(head, sizeof head);
    put(used_.words().data(), used_.words().size() * 8);
    for(const Held& h : held_) {
      put(h.v.data(), 24);
      for(const Point& p : h.p) {
        const double xy[2] = {CGAL::to_double(p.x()), CGAL::to_double(p.y())};
        put(xy, 16);
      }
      put(&h.constraint_edges, 1);
    }
    const std::uint64_t sum = checksum(b);
    put(&sum, 8);
    const std::string tmp = file + ".tmp";
    std::ofstream os(tmp.c_str(), std::ios::out | std::ios::binary | std::ios::trunc);
    os.write(b.data(), static_cast<std::streamsize>(b.size()));
    os.close();
    if(os.fail() || std::rename(tmp.c_str(), file.c_str()) != 0) throw std::runtime_error("cannot write " + file);
  }

  // Takes the part a previous run kept in `file` (and its scratch files)
  // when that run had the digest `run`; false when there is none, or it is
  // not whole, or it is another run's.
  bool resume(const std::string& file, std::uint64_t run)
  {
    std::ifstream is(file.c_str(), std::ios::in | std::ios::binary);
    if(!is) return false;
    const std::string b((std::istreambuf_iterator<char>(is)), std::istreambuf_iterator<char>());
    const std::size_t magic = std::strlen(part_file_magic);
    if(b.size() < magic + 56 || b.compare(0, magic, part_file_magic) != 0) return false;
    std::uint64_t sum = 0;
    std::memcpy(&sum, b.data() + b.size() - 8, 8);
    if(sum != checksum(b.substr(0, b.size() - 8))) return false;
    std::size_t at = magic;
    auto get = [&](void* data, std::size_t n) {
      if(at + n > b.size() - 8) throw std::runtime_error(file + ": damaged");
      std::memcpy(data, b.data() + at, n);
      at += n;
    };
    std::uint64_t head[6];
    get(head, sizeof head);
    if(head[0] != run || !points_.adopt(head[3]) || !triangles_.adopt(head[4])) return false;
    std::vector<std::uint64_t> words(std::size_t((head[1] + 63) / 64));
    get(words.data(), words.size() * 8);
    used_.assign(head[1], std::move(words));
    streamed_ = head[2];
    held_.clear();
    for(std::uint64_t t = 0; t < head[5]; ++t) {
      Held h;
      get(h.v.data(), 24);
      for(Point& p : h.p) {
        double xy[2];
        get(xy, 16);
        p = Point(xy[0], xy[1]);
      }
      get(&h.constraint_edges, 1);
      held_.push_back(h);
    }
    return at == b.size() - 8;
  }

  // the kept part removed, and the scratch files with the sink
  void discard(const std::string& file)
  {
    std::remove(file.c_str());
    points_.keep(false);
    triangles_.keep(false);
  }

  const std::vector<Held>& held() const { return held_; }
  Counted_bits& used() { return used_; }
  std::uint64_t vertices() const { return used_.size(); }
  std::uint64_t streamed_triangles() const { return streamed_; }
  const Scratch_file& points_file() const { return points_; }
  const Scratch_file& triangles_file() const { return triangles_; }

private:
  bool near(std::size_t c, double width, const Point& a, const Point& b, const Point& p) const
  {
    const double position = d_.plan.cuts[c].position;
    for(const Point* q : {&a, &b, &p}) {
      const double x = AFM::internal::coordinate(CGAL::to_double(q->x()), CGAL::to_double(q->y()), d_.plan.axis);
      if(std::abs(x - position) <= width) return true;
    }
    return false;
  }
  bool on_interface(std::size_t c, const Point& p) const { return d_.interface_points[c].count(key_of(p)) > 0; }
  // an undirected edge as parts.h's key: its ends in order
  static Edge_key undirected_key(const Point& p, const Point& q)
  {
    return key_of(q) < key_of(p) ? edge_key(q, p) : edge_key(p, q);
  }

  static std::uint64_t checksum(const std::string& b)
  {
    return digest_bytes(b.data(), b.size());
  }

  const Decomposition<K>& d_;
  std::vector<std::size_t> cuts_;
  std::set<Edge_key> constraints_;
  Scratch_file points_, triangles_;
  std::vector<Held> held_;
  Counted_bits used_;
  std::uint64_t streamed_ = 0;
};

// A streamed rank's share once its interfaces are merged: what is not in
// the scratch files, and the vertices' numbers.
struct Streamed_share
{
  // the held triangles the rank keeps and the merged band's, by vertex
  // number: the mesher's (below `vertices`), then the band's new points
  std::vector<std::array<std::uint64_t, 3> > triangles;
  std::vector<std::array<double, 2> > new_points;
  AFM::internal::Flat_hash_map<std::uint64_t, std::array<double, 2> > moved{~std::uint64_t(0)};
  // the vertices the share uses, those it owns, and the numbers of the
  // others (the band sent down) from the rank below
  Counted_bits used, owned;
  AFM::internal::Flat_hash_map<std::uint64_t, std::uint64_t> id_from_below{~std::uint64_t(0)};
  std::uint64_t vertices = 0, streamed_triangles = 0, first_id = 0;
  std::uint64_t triangle_count() const { return streamed_triangles + triangles.size(); }
};

// The share of a streamed rank, its vertices numbered across the ranks (as
// rank_mesh() does for a part in memory).
template <class K>
Streamed_share streamed_share(Part_stream<K>& s, const Interface_work<K, Band<K, std::size_t> >& w, int rank)
{
  typedef typename CDT<K>::Vertex_handle Vertex_handle;
  Streamed_share m;
  m.vertices = s.vertices();
  m.streamed_triangles = s.streamed_triangles();
  std::vector<char> left(s.held().size(), 0);
  if(w.has_lower)
    for(std::size_t t : w.sent.faces) left[t] = 1;
  if(w.has_upper)
    for(std::size_t t : w.kept_band.faces) left[t] = 1;
  for(std::size_t t = 0; t < s.held().size(); ++t)
    if(!left[t]) m.triangles.push_back(s.held()[t].v);
  // the merged band: the points of this rank's band keep their numbers (and
  // take the place the seam smoothing gave them), rank r + 1's are new
  AFM::internal::Flat_hash_map<const void*, std::uint64_t> number(nullptr);
  if(w.has_upper) {
    const std::vector<std::uint64_t> own = s.soup_ids(w.kept_band);
    for(std::size_t k = 0; k < own.size(); ++k) {
      const Vertex_handle v = w.own_vertices[k];
      number.insert(&*v, own[k]);
      if(v->point() != w.kept_band.soup.points[k])
        m.moved.insert(own[k], {{CGAL::to_double(v->point().x()), CGAL::to_double(v->point().y())}});
    }
    auto number_of = [&](Vertex_handle v) {
      if(const std::uint64_t* i = number.find(&*v)) return *i;
      m.new_points.push_back({{CGAL::to_double(v->point().x()), CGAL::to_double(v->point().y())}});
      return number.insert(&*v, m.vertices + m.new_points.size() - 1);
    };
    for(auto f = w.merged.finite_faces_begin(); f != w.merged.finite_faces_end(); ++f)
      if(f->is_in_domain())
        m.triangles.push_back({{number_of(f->vertex(0)), number_of(f->vertex(1)), number_of(f->vertex(2))}});
  }
  m.used = std::move(s.used());
  m.used.resize(m.vertices + m.new_points.size());
  for(const auto& t : m.triangles)
    for(std::uint64_t v : t) m.used.set(v);
  m.used.count();
  // owned: used, and not a point of the band sent down
  m.owned = m.used;
  std::vector<std::uint64_t> sent;
  if(w.has_lower) {
    sent = s.soup_ids(w.sent);
    for(std::uint64_t v : sent) m.owned.reset(v);
  }
  m.owned.count();
  m.first_id = exclusive_scan(m.owned.total(), rank);
  if(w.has_upper) {
    std::vector<std::uint64_t> ids;
    for(const Vertex_handle& v : w.upper_vertices) {
      const std::uint64_t* i = number.find(&*v);
      if(i == nullptr || !m.owned.test(*i))
        throw std::logic_error("a point of the band above is not one of the rank's own");
      ids.push_back(m.first_id + m.owned.rank(*i));
    }
    send_vector(ids, rank + 1, BAND_IDS);
  }
  if(w.has_lower) {
    const std::vector<std::uint64_t> ids = receive_vector<std::uint64_t>(rank - 1, BAND_IDS);
    if(ids.size() != sent.size()) throw std::logic_error("the band's numbers do not match its points");
    for(std::size_t k = 0; k < ids.size(); ++k)
      if(m.used.test(sent[k]) && !m.id_from_below.contains(sent[k])) m.id_from_below.insert(sent[k], ids[k]);
  }
  if(m.id_from_below.size() != m.used.total() - m.owned.total())
    throw std::logic_error("a vertex of the rank's share has no number");
  return m;
}

// This rank's piece of OUT.pvtu from its scratch files and its share.
template <class K>
void write_streamed_piece(const std::string& pvtu, const Part_stream<K>& s, const Streamed_share& m, int rank,
                          int ranks, bool binary)
{
  const std::string name = piece_name(pvtu, rank);
  const std::vector<std::uint64_t> triangles_per_rank = gather_to_root<std::uint64_t>(m.triangle_count(), ranks);
  if(m.triangle_count() > 0) {
    std::ofstream os(name, std::ios::binary);
    os << std::setprecision(17);
    const std::size_t chunk = std::size_t(1) << 20;
    auto put_point = [&](std::string& raw, double x, double y) {
      if(binary) {
        vtu::vtu_append_raw(raw, x);
        vtu::vtu_append_raw(raw, y);
        vtu::vtu_append_raw(raw, 0.);
      } else {
        os << x << ' ' << y << " 0\n";
      }
    };
    auto flush = [&](std::string& raw) {
      os.write(raw.data(), static_cast<std::streamsize>(raw.size()));
      raw.clear();
    };
    write_vtu(
      os, m.used.total(), {m.triangle_count()}, rank, binary,
      [&](std::string& raw) {
        std::uint64_t i = 0;
        s.points_file().template read<double>(2 * chunk, [&](const double* xy, std::size_t n) {
          for(std::size_t k = 0; k + 1 < n; k += 2, ++i) {
            if(!m.used.test(i)) continue;
            if(const std::array<double, 2>* p = m.moved.find(i)) put_point(raw, (*p)[0], (*p)[1]);
            else put_point(raw, xy[k], xy[k + 1]);
          }
          flush(raw);
        });
        if(i != m.vertices) throw std::runtime_error("the scratch file " + s.points_file().name() + " is short");
        for(const auto& p : m.new_points) {
          if(m.used.test(i++)) put_point(raw, p[0], p[1]);
        }
        flush(raw);
      },
      [&](std::string& raw, bool wide) {
        std::uint64_t read = 0;
        s.triangles_file().template read<std::uint32_t>(3 * chunk, [&](const std::uint32_t* v, std::size_t n) {
          for(std::size_t k = 0; k < n; ++k)
            put_index(os, raw, binary, wide, m.used.rank(v[k]), k % 3 == 2 ? '\n' : ' ');
          read += n;
          flush(raw);
        });
        if(read != 3 * m.streamed_triangles)
          throw std::runtime_error("the scratch file " + s.triangles_file().name() + " is short");
        for(const auto& t : m.triangles)
          for(std::size_t k = 0; k < 3; ++k) put_index(os, raw, binary, wide, m.used.rank(t[k]), k == 2 ? '\n' : ' ');
        flush(raw);
      },
      [&](std::string& raw) {
        for(std::uint64_t i = 0; i < m.used.size(); ++i) {
          if(!m.used.test(i)) continue;
          const std::uint64_t* below = m.id_from_below.find(i);
          put_index(os, raw, binary, true, below != nullptr ? *below : m.first_id + m.owned.rank(i), '\n');
          if(raw.size() > chunk) flush(raw);
        }
        flush(raw);
      });
    os.close();
    if(os.fail()) throw std::runtime_error("cannot write " + name);
  }
  if(rank == 0) write_collection(pvtu, triangles_per_rank, ranks);
}

} // namespace afmesh_2_mpi

#endif // AFMESH_2_MPI_STREAMED_H
