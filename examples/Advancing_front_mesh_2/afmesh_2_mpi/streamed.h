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
// What the sink has received (the counts, the scratch files' sizes, the
// used bits, the held triangles) is its state: written to a kept part file
// once the part is meshed, and to a side file at each of the mesher's
// checkpoints, from which a later run continues (--resume).
//
// The sink also finds the segments among the streamed triangles' edges and
// their region attributes (tags.h).
//
// Memory: the mesher's front and unfinished triangles, the held triangles
// (a few hundred bytes per interface point), about 4 bits per vertex, and
// 16 bytes per input vertex and 24 per segment. Disk: 28 bytes per
// triangle of scratch (36 when the input has regions) until the piece is
// written.
#ifndef AFMESH_2_MPI_STREAMED_H
#define AFMESH_2_MPI_STREAMED_H

#include "merged.h"
#include "tags.h"

#include <CGAL/Advancing_front_mesh_2/IO/internal/Streaming_files.h>
#include <CGAL/Advancing_front_mesh_2/Mesh_sink_2.h>

#include <algorithm>
#include <array>
#include <bitset>
#include <cstdint>
#include <cstdlib>
#include <cstdio>
#include <cstring>
#include <filesystem>
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

// A scratch file written through the library's streaming buffer (which
// can make it durable for a checkpoint); removed when destroyed unless kept.
class Scratch_file
{
public:
  explicit Scratch_file(const std::string& name) : file_(name) {}
  ~Scratch_file()
  {
    file_.abandon();
    if(exists_ && !kept_) std::remove(file_.path().c_str());
  }
  Scratch_file(const Scratch_file&) = delete;
  Scratch_file& operator=(const Scratch_file&) = delete;
  // left on disk at the end (a part kept for --resume, or checkpointed)
  void keep(bool on = true) { kept_ = on; }
  // the bytes written so far
  std::uint64_t size() const { return file_.size(); }
  const std::string& name() const { return file_.path(); }
  // Takes over the file a previous run left, cut back to `bytes`: it must
  // have exactly that many (a kept part) or at least (a checkpoint, after
  // which the interrupted run went on writing). False, and the file
  // untouched, when it has not.
  bool fits(std::uint64_t bytes, bool exact) const
  {
    std::error_code ec;
    const std::uintmax_t on_disk = std::filesystem::file_size(name(), ec);
    if(ec) return bytes == 0; // never written
    return on_disk >= bytes && (!exact || on_disk == bytes);
  }
  bool adopt(std::uint64_t bytes, bool exact)
  {
    if(!fits(bytes, exact)) return false;
    std::error_code ec;
    const std::uintmax_t on_disk = std::filesystem::file_size(name(), ec);
    if(ec) return true; // never written: created by the first put()
    if(on_disk != bytes) {
      std::filesystem::resize_file(name(), bytes, ec);
      if(ec) throw std::runtime_error("cannot cut " + name() + " back to the checkpoint");
    }
    file_.append(bytes);
    exists_ = true;
    return true;
  }
  template <class T>
  void put(const T* values, std::size_t n)
  {
    if(!exists_) {
      file_.create();
      exists_ = true;
    }
    file_.put(reinterpret_cast<const char*>(values), n * sizeof(T));
  }
  // everything put so far durable on disk (a checkpoint)
  void sync()
  {
    if(exists_ && file_.is_open()) guarded([&] { file_.sync(); });
  }
  // everything put so far durably on disk; throws std::runtime_error when
  // it is not
  void close()
  {
    guarded([&] { file_.close(true); });
  }
  // whether anything was put in the file (or adopted)
  bool written() const { return exists_; }
  // reads the file back, `n` values of type T at a time, into `f(values, n)`
  template <class T, class F>
  void read(std::size_t n, const F& f) const
  {
    if(!exists_) return;
    std::ifstream is(name().c_str(), std::ios::in | std::ios::binary);
    std::vector<T> values(n);
    while(is) {
      is.read(reinterpret_cast<char*>(values.data()), static_cast<std::streamsize>(n * sizeof(T)));
      const std::size_t got = std::size_t(is.gcount()) / sizeof(T);
      if(got > 0) f(values.data(), got);
    }
    if(is.bad()) throw std::runtime_error("cannot read " + name());
  }

private:
  template <class F>
  void guarded(const F& f)
  {
    try {
      f();
    } catch(const std::runtime_error& e) {
      throw std::runtime_error(std::string(e.what()) + " (is the disk full?)");
    }
  }
  AFM::IO::internal::Streaming_file file_;
  bool exists_ = false, kept_ = false;
};

// A scratch file read back on demand, so that two files can be gone
// through in step (a triangle's vertices and its region attribute), which
// Scratch_file::read() cannot do.
template <class T>
class Scratch_reader
{
public:
  explicit Scratch_reader(const Scratch_file& f) : name_(f.name())
  {
    if(f.written()) is_.open(name_.c_str(), std::ios::in | std::ios::binary);
  }
  // up to `n` next values (fewer at the end of the file, none after it)
  const std::vector<T>& next(std::size_t n)
  {
    values_.resize(n);
    std::size_t got = 0;
    if(is_.is_open() && is_) {
      is_.read(reinterpret_cast<char*>(values_.data()), static_cast<std::streamsize>(n * sizeof(T)));
      got = std::size_t(is_.gcount()) / sizeof(T);
    }
    if(is_.bad()) throw std::runtime_error("cannot read " + name_);
    values_.resize(got);
    return values_;
  }

private:
  std::string name_;
  std::ifstream is_;
  std::vector<T> values_;
};

// `bytes` in `file`, durably: written to file.tmp, synced, then renamed,
// so that the file is either whole or as it was.
inline void write_durably(const std::string& file, const std::string& bytes)
{
  const std::string tmp = file + ".tmp";
  {
    AFM::IO::internal::Streaming_file f(tmp);
    try {
      f.create();
      f.put(bytes);
      f.close(true);
    } catch(const std::runtime_error&) {
      f.abandon();
      std::remove(tmp.c_str());
      throw std::runtime_error("cannot write " + file);
    }
  }
  if(std::rename(tmp.c_str(), file.c_str()) != 0) {
    std::remove(tmp.c_str());
    throw std::runtime_error("cannot write " + file);
  }
  AFM::IO::internal::streaming_sync_directories({file});
}

// The bytes of `file`; false when it cannot be read.
inline bool read_whole(const std::string& file, std::string& bytes)
{
  std::ifstream is(file.c_str(), std::ios::in | std::ios::binary);
  if(!is) return false;
  bytes.assign(std::istreambuf_iterator<char>(is), std::istreambuf_iterator<char>());
  return !is.bad();
}

// The first bytes of a kept part's file.
constexpr const char* part_file_magic = "afmesh_2_mpi kept part 2\n";
// The sink's state stored in the mesher's checkpoint.
constexpr const char* checkpoint_state_magic = "afmesh_2_mpi part checkpoint 1\n";

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
  // `run` is the digest of the run's decomposition and options: a later
  // run takes what this one kept only if it has the same.
  // `tags` finds the markers and regions (and outlives the sink).
  Part_stream(const Decomposition<K>& d, std::size_t part, const CDT<K>& part_cdt, const std::string& stem,
              std::uint64_t run, Share_tags<K>& tags)
      : d_(d), stem_(stem), run_(run), tags_(tags), points_(stem + ".points.tmp"),
        triangles_(stem + ".triangles.tmp"), regions_(stem + ".regions.tmp")
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
    // the input vertices, for the segments
    input_bits_.push_back_zero();
    const std::size_t ordinal = tags_.input_vertex(xy[0], xy[1]);
    if(ordinal != Share_tags<K>::none) {
      input_bits_.set(i);
      input_vertices_.push_back({{std::uint64_t(i), std::uint64_t(ordinal)}});
    }
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
    if(tags_.has_regions()) {
      const double attribute = tags_.region_attribute(a, b, c);
      regions_.put(&attribute, 1);
    }
    // a segment is an edge between two input vertices
    if(int(input_bits_.test(i)) + int(input_bits_.test(j)) + int(input_bits_.test(k)) >= 2)
      for(int e = 0; e < 3; ++e) {
        const std::uint64_t from = e == 0 ? i : e == 1 ? j : k, to = e == 0 ? j : e == 1 ? k : i;
        int marker = 0;
        if(tags_.segment(input_ordinal(from), input_ordinal(to), marker))
          segments_.push_back({{from, to, std::uint64_t(std::int64_t(marker))}});
      }
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
    regions_.close();
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

  // The files a rank's part leaves beside its piece `stem` (OUT_<rank>.vtu)
  // for a later run: the part once meshed, the mesher's checkpoint and the
  // sink's state at the last two checkpoints (whichever the checkpoint
  // names).
  static std::string kept_part_file(const std::string& stem) { return stem + ".part"; }
  static std::string checkpoint_file(const std::string& stem) { return stem + ".checkpoint"; }
  static std::string checkpoint_sink_file(const std::string& stem, int generation)
  {
    return stem + ".checkpoint.sink" + std::to_string(generation);
  }

  // The part kept for a later run (--stop-after-meshing, or a run that
  // fails after this rank meshed): the scratch files stay, and the kept
  // part file gets the rest, durably (either whole or absent).
  void keep()
  {
    keep_scratch();
    write_durably(kept_part_file(stem_), state());
  }

  // The scratch files left on disk whatever happens (a checkpointed run
  // resumes from them).
  void keep_scratch()
  {
    points_.keep();
    triangles_.keep();
    regions_.keep();
  }

  // Takes the part a previous run of the same command kept (and its scratch
  // files); false when there is none, or it is not whole, or it is another
  // run's.
  bool resume()
  {
    std::string b;
    return read_whole(kept_part_file(stem_), b) && load(b, true);
  }

  // Called by the mesher at a checkpoint: the scratch files made durable,
  // and the rest of the sink's state (the held triangles, the used bits:
  // too large for the checkpoint itself) written to the side file of this
  // generation, so that the previous checkpoint's stays whole until the
  // mesher has renamed the new checkpoint into place. The checkpoint keeps
  // the generation and the side file's checksum.
  std::string checkpoint_state() override
  {
    points_.sync();
    triangles_.sync();
    regions_.sync();
    // (the mesher renames the checkpoint into place after this call; if
    // that failed and the mesher went on, the next call would overwrite the
    // side file the checkpoint on disk names: the tool stops at a
    // Checkpoint_error instead)
    const int generation = 1 - generation_;
    const std::string b = state();
    write_durably(checkpoint_sink_file(stem_, generation), b);
    generation_ = generation;
    return std::string(checkpoint_state_magic) + std::to_string(generation) + " " + std::to_string(checksum(b));
  }

  // Continues from the checkpoint whose sink state the mesher stored
  // (Checkpoint_info::sink_state): the held triangles and the counts as
  // they were then, the scratch files cut back to it. Throws
  // std::runtime_error, the files untouched, when the side file is missing
  // or not the one the checkpoint names.
  void resume_checkpoint(const std::string& sink_state)
  {
    const std::size_t magic = std::strlen(checkpoint_state_magic);
    int generation = -1;
    unsigned long long sum = 0;
    if(sink_state.compare(0, magic, checkpoint_state_magic) != 0 ||
       std::sscanf(sink_state.c_str() + magic, "%d %llu", &generation, &sum) != 2 ||
       (generation != 0 && generation != 1))
      throw std::runtime_error(checkpoint_file(stem_) + ": not a checkpoint of afmesh_2_mpi");
    const std::string side = checkpoint_sink_file(stem_, generation);
    std::string b;
    if(!read_whole(side, b) || checksum(b) != sum)
      throw std::runtime_error(side + ": missing, or not the state the checkpoint " + checkpoint_file(stem_) +
                               " was written with");
    if(!load(b, false))
      throw std::runtime_error(checkpoint_file(stem_) + ": the scratch files beside it (" + points_.name() + ", " +
                               triangles_.name() + ", " + regions_.name() + ") are missing or shorter than at the "
                               "checkpoint");
    generation_ = generation;
    keep_scratch();
  }

  // Everything this part left for a later run removed: the kept part, the
  // checkpoints, and the scratch files with the sink.
  void discard()
  {
    std::remove(kept_part_file(stem_).c_str());
    std::remove((kept_part_file(stem_) + ".tmp").c_str());
    discard_checkpoints();
    points_.keep(false);
    triangles_.keep(false);
    regions_.keep(false);
  }

  // This run meshes the part from its start: what a previous run left of
  // it is removed (a scratch file of regions from a run with other input
  // files too, which no put() of this run would empty).
  void start_anew()
  {
    std::remove(kept_part_file(stem_).c_str());
    discard_checkpoints();
    if(!tags_.has_regions()) std::remove(regions_.name().c_str());
  }

  // A previous run's checkpoint of this part removed.
  void discard_checkpoints()
  {
    for(const std::string& f :
        {checkpoint_file(stem_), checkpoint_sink_file(stem_, 0), checkpoint_sink_file(stem_, 1)}) {
      std::remove(f.c_str());
      std::remove((f + ".tmp").c_str()); // a run killed while writing it
    }
  }

  const std::vector<Held>& held() const { return held_; }
  // the segments found in the streamed triangles: their ends (the mesher's
  // numbers) and marker
  const std::vector<std::array<std::uint64_t, 3> >& segments() const { return segments_; }
  const Scratch_file& regions_file() const { return regions_; }
  Share_tags<K>& tags() const { return tags_; }
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

  // What the sink has received, as bytes: the run's digest, the counts,
  // the scratch files' sizes, the used bits and the held triangles, then a
  // checksum of all that.
  std::string state() const
  {
    std::string b = part_file_magic;
    auto put = [&b](const void* data, std::size_t n) { b.append(static_cast<const char*>(data), n); };
    const std::uint64_t head[9] = {run_,           used_.size(),           streamed_,
                                   points_.size(), triangles_.size(),      held_.size(),
                                   regions_.size(), input_vertices_.size(), segments_.size()};
    put(head, sizeof head);
    put(input_vertices_.data(), input_vertices_.size() * 16);
    put(segments_.data(), segments_.size() * 24);
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
    return b;
  }

  // Takes the state `b` written by state() in a run with the same digest,
  // the scratch files of that moment (`exact`: of exactly that size, a
  // part kept once meshed; else cut back to it, a checkpoint). False, and
  // nothing changed, when `b` is damaged or another run's, or the scratch
  // files are not there.
  bool load(const std::string& b, bool exact)
  {
    const std::size_t magic = std::strlen(part_file_magic);
    if(b.size() < magic + 80 || b.compare(0, magic, part_file_magic) != 0) return false;
    std::uint64_t sum = 0;
    std::memcpy(&sum, b.data() + b.size() - 8, 8);
    if(sum != checksum(b.substr(0, b.size() - 8))) return false;
    std::size_t at = magic;
    auto get = [&](void* data, std::size_t n) {
      if(at + n > b.size() - 8) return false;
      std::memcpy(data, b.data() + at, n);
      at += n;
      return true;
    };
    std::uint64_t head[9];
    get(head, sizeof head);
    // the counts bounded by the bytes there are (a damaged file whose
    // checksum happens to match must not make huge vectors)
    if(head[0] != run_ || head[1] / 64 > b.size() || head[7] > b.size() / 16 || head[8] > b.size() / 24 ||
       head[5] > b.size() / 73)
      return false;
    std::vector<std::array<std::uint64_t, 2> > input_vertices(static_cast<std::size_t>(head[7]));
    std::vector<std::array<std::uint64_t, 3> > segments(static_cast<std::size_t>(head[8]));
    if(!get(input_vertices.data(), input_vertices.size() * 16) || !get(segments.data(), segments.size() * 24))
      return false;
    std::vector<std::uint64_t> words(std::size_t((head[1] + 63) / 64));
    if(!get(words.data(), words.size() * 8)) return false;
    std::vector<Held> held;
    for(std::uint64_t t = 0; t < head[5]; ++t) {
      Held h;
      double xy[3][2];
      if(!get(h.v.data(), 24) || !get(xy, 48) || !get(&h.constraint_edges, 1)) return false;
      for(int k = 0; k < 3; ++k) h.p[std::size_t(k)] = Point(xy[k][0], xy[k][1]);
      held.push_back(h);
    }
    if(at != b.size() - 8) return false;
    for(std::size_t k = 0; k < input_vertices.size(); ++k)
      if(input_vertices[k][0] >= head[1] || (k > 0 && input_vertices[k][0] <= input_vertices[k - 1][0])) return false;
    for(const auto& seg : segments)
      if(seg[0] >= head[1] || seg[1] >= head[1]) return false;
    for(const Held& h : held)
      for(std::uint64_t v : h.v)
        if(v >= head[1]) return false;
    // the scratch files last: nothing is cut back unless the rest is good
    if(!points_.fits(head[3], exact) || !triangles_.fits(head[4], exact) || !regions_.fits(head[6], exact))
      return false;
    if(!points_.adopt(head[3], exact) || !triangles_.adopt(head[4], exact) || !regions_.adopt(head[6], exact))
      throw std::runtime_error("the scratch files beside " + stem_ + " changed while they were taken");
    used_.assign(head[1], std::move(words));
    input_vertices_ = std::move(input_vertices);
    segments_ = std::move(segments);
    input_bits_.assign(0, {});
    input_bits_.resize(head[1]);
    for(const auto& v : input_vertices_) input_bits_.set(v[0]);
    streamed_ = head[2];
    held_ = std::move(held);
    return true;
  }

  // the input ordinal of the mesher's vertex `v`, or none
  std::size_t input_ordinal(std::uint64_t v) const
  {
    if(!input_bits_.test(v)) return Share_tags<K>::none;
    const auto it = std::lower_bound(input_vertices_.begin(), input_vertices_.end(),
                                     std::array<std::uint64_t, 2>{{v, 0}});
    return std::size_t((*it)[1]);
  }

  static std::uint64_t checksum(const std::string& b)
  {
    return digest_bytes(b.data(), b.size());
  }

  const Decomposition<K>& d_;
  std::string stem_;
  std::uint64_t run_;
  int generation_ = 1; // of the last checkpoint's side file
  std::vector<std::size_t> cuts_;
  std::set<Edge_key> constraints_;
  Share_tags<K>& tags_;
  Scratch_file points_, triangles_, regions_; // regions: the attribute of each streamed triangle
  std::vector<Held> held_;
  // the input vertices among the mesher's (bits, and the mesher's numbers
  // with the input's ordinals, in order), and the segments found in the
  // streamed triangles (the mesher's numbers, the marker)
  Counted_bits input_bits_;
  std::vector<std::array<std::uint64_t, 2> > input_vertices_;
  std::vector<std::array<std::uint64_t, 3> > segments_;
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
  // their tags: region attributes, and the segments among their edges
  // (by vertex number, with the marker)
  std::vector<double> regions;
  std::vector<std::array<std::uint64_t, 3> > segments;
  std::vector<std::array<double, 2> > new_points;
  AFM::internal::Flat_hash_map<std::uint64_t, std::array<double, 2> > moved{~std::uint64_t(0)};
  // the vertices the share uses, those it owns, and the numbers of the
  // others (the band sent down) from the rank below
  Counted_bits used, owned;
  AFM::internal::Flat_hash_map<std::uint64_t, std::uint64_t> id_from_below{~std::uint64_t(0)};
  std::uint64_t vertices = 0, streamed_triangles = 0, first_id = 0;
  std::uint64_t triangle_count() const { return streamed_triangles + triangles.size(); }
  // the global number of used vertex i: its own, or the rank below's
  std::uint64_t number(std::uint64_t i) const
  {
    if(owned.test(i)) return first_id + owned.rank(i);
    const std::uint64_t* below = id_from_below.find(i);
    if(below == nullptr) throw std::logic_error("a vertex of the rank's share has no number");
    return *below;
  }
};

// The share of a streamed rank, its vertices numbered across the ranks (as
// rank_mesh() does for a part in memory).
template <class K>
Streamed_share streamed_share(Part_stream<K>& s, const Interface_work<K, Band<K, std::size_t> >& w, int rank)
{
  typedef typename CDT<K>::Vertex_handle Vertex_handle;
  typedef typename K::Point_2 Point;
  Streamed_share m;
  m.vertices = s.vertices();
  m.streamed_triangles = s.streamed_triangles();
  // the tags of the triangles in memory, from their points
  Share_tags<K>& tags = s.tags();
  auto tag = [&](const std::array<std::uint64_t, 3>& v, const std::array<Point, 3>& p) {
    if(tags.has_regions()) m.regions.push_back(tags.region_attribute(p[0], p[1], p[2]));
    std::array<std::size_t, 3> ordinal;
    for(std::size_t k = 0; k < 3; ++k)
      ordinal[k] = tags.input_vertex(CGAL::to_double(p[k].x()), CGAL::to_double(p[k].y()));
    for(std::size_t k = 0; k < 3; ++k) {
      int marker = 0;
      if(tags.segment(ordinal[k], ordinal[(k + 1) % 3], marker))
        m.segments.push_back({{v[k], v[(k + 1) % 3], std::uint64_t(std::int64_t(marker))}});
    }
  };
  std::vector<char> left(s.held().size(), 0);
  if(w.has_lower)
    for(std::size_t t : w.sent.faces) left[t] = 1;
  if(w.has_upper)
    for(std::size_t t : w.kept_band.faces) left[t] = 1;
  for(std::size_t t = 0; t < s.held().size(); ++t)
    if(!left[t]) {
      m.triangles.push_back(s.held()[t].v);
      tag(s.held()[t].v, s.held()[t].p);
    }
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
      if(f->is_in_domain()) {
        m.triangles.push_back({{number_of(f->vertex(0)), number_of(f->vertex(1)), number_of(f->vertex(2))}});
        tag(m.triangles.back(), {{f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point()}});
      }
  }
  check_segments_found<K>(tags, s.segments().size() + m.segments.size());
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

// The tags of a streamed piece: the segments and region attributes the
// sink found in the streamed triangles (the attributes in a scratch file),
// then the share's; the markers of the points from their coordinates.
template <class K>
Vtu_tags streamed_tags(std::ostream& os, bool binary, const Part_stream<K>& s, const Streamed_share& m)
{
  Vtu_tags v;
  v.segments_per_rank = {s.segments().size() + m.segments.size()};
  v.regions = s.tags().has_regions();
  const std::size_t chunk = std::size_t(1) << 20;
  auto flush = [&os](std::string& raw) { write_out(os, raw); };
  auto each_segment = [&s, &m](const std::function<void(const std::array<std::uint64_t, 3>&)>& f) {
    for(const auto& seg : s.segments()) f(seg);
    for(const auto& seg : m.segments) f(seg);
  };
  v.segments = [&os, &m, binary, each_segment](std::string& raw, bool wide) {
    each_segment([&](const std::array<std::uint64_t, 3>& seg) {
      put_index(os, raw, binary, wide, m.used.rank(seg[0]), ' ');
      put_index(os, raw, binary, wide, m.used.rank(seg[1]), '\n');
    });
  };
  v.segment_markers = [&os, binary, each_segment](std::string& raw) {
    each_segment([&](const std::array<std::uint64_t, 3>& seg) {
      put_value(os, raw, binary, std::int32_t(std::int64_t(seg[2])));
    });
  };
  v.point_markers = [&os, &s, &m, binary, chunk, flush](std::string& raw) {
    std::uint64_t i = 0;
    s.points_file().template read<double>(2 * chunk, [&](const double* xy, std::size_t n) {
      for(std::size_t k = 0; k + 1 < n; k += 2, ++i)
        if(m.used.test(i)) put_value(os, raw, binary, std::int32_t(s.tags().marker_at(xy[k], xy[k + 1])));
      flush(raw);
    });
    if(i != m.vertices) throw std::runtime_error("the scratch file " + s.points_file().name() + " is short");
    for(const auto& p : m.new_points)
      if(m.used.test(i++)) put_value(os, raw, binary, std::int32_t(s.tags().marker_at(p[0], p[1])));
  };
  v.triangle_regions = [&os, &s, &m, binary, chunk, flush](std::string& raw) {
    std::uint64_t read = 0;
    s.regions_file().template read<double>(chunk, [&](const double* a, std::size_t n) {
      for(std::size_t k = 0; k < n; ++k) put_value(os, raw, binary, a[k]);
      read += n;
      flush(raw);
    });
    if(read != m.streamed_triangles)
      throw std::runtime_error("the scratch file " + s.regions_file().name() + " is short");
    for(double a : m.regions) put_value(os, raw, binary, a);
  };
  return v;
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
          put_index(os, raw, binary, true, m.number(i), '\n');
          if(raw.size() > chunk) flush(raw);
        }
        flush(raw);
      },
      streamed_tags(os, binary, s, m));
    os.close();
    if(os.fail()) throw std::runtime_error("cannot write " + name);
  }
  if(rank == 0) write_collection(pvtu, triangles_per_rank, ranks, s.tags().has_regions());
}

// The points or triangles of a streamed share sent to rank 0 in one chunk
// for --merge: 2^18, or the count in the environment variable
// AFMESH_2_MPI_MERGE_CHUNK (at least 1), with which the tests make small
// meshes cross many chunk boundaries.
inline std::size_t merged_share_chunk()
{
  const char* given = std::getenv("AFMESH_2_MPI_MERGE_CHUNK");
  if(given == nullptr) return std::size_t(1) << 18;
  const long long n = std::atoll(given);
  return n >= 1 ? std::size_t(n) : std::size_t(1) << 18;
}

// This rank's share of the merged file (--merge with --stream), read from
// its scratch files a chunk at a time as rank 0 takes each array: the
// owned points in the order of their numbers, the triangles and segments by
// number, the markers (as a piece's, from the points' coordinates in the
// scratch file) and the region attributes.
template <class K>
Merged_share merged_share(const Part_stream<K>& s, const Streamed_share& m)
{
  typedef std::function<void(const double*, std::size_t)> Put_doubles;
  typedef std::function<void(const std::uint64_t*, std::size_t)> Put_numbers;
  typedef std::function<void(const std::int32_t*, std::size_t)> Put_markers;
  // a quarter of a piece's chunks: each is copied once more (its numbers
  // widened to 64 bits) before it is sent
  const std::size_t chunk = merged_share_chunk();
  Merged_share share;
  share.owned_vertices = m.owned.total();
  share.triangles = m.triangle_count();
  share.segments = s.segments().size() + m.segments.size();
  share.regions = s.tags().has_regions();
  auto number = [&m](std::uint64_t i) { return m.number(i); };
  // each owned point, where it is (`moved`: by the seam smoothing) and
  // where the scratch file has it
  auto each_owned_point = [&s, &m, chunk](const std::function<void(double, double, double, double)>& f,
                                          const std::function<void()>& chunk_done) {
    std::uint64_t i = 0;
    s.points_file().template read<double>(2 * chunk, [&](const double* xy, std::size_t n) {
      for(std::size_t k = 0; k + 1 < n; k += 2, ++i) {
        if(!m.owned.test(i)) continue;
        const std::array<double, 2>* p = m.moved.find(i);
        f(p != nullptr ? (*p)[0] : xy[k], p != nullptr ? (*p)[1] : xy[k + 1], xy[k], xy[k + 1]);
      }
      chunk_done();
    });
    if(i != m.vertices) throw std::runtime_error("the scratch file " + s.points_file().name() + " is short");
    for(const auto& p : m.new_points)
      if(m.owned.test(i++)) f(p[0], p[1], p[0], p[1]);
    chunk_done();
  };
  share.points = [each_owned_point](const Put_doubles& put) {
    std::vector<double> xy;
    each_owned_point([&xy](double x, double y, double, double) { xy.insert(xy.end(), {x, y}); },
                     [&] { put(xy.data(), xy.size()); xy.clear(); });
  };
  share.point_markers = [each_owned_point, &s](const Put_markers& put) {
    std::vector<std::int32_t> k;
    each_owned_point([&](double, double, double x, double y) { k.push_back(std::int32_t(s.tags().marker_at(x, y))); },
                     [&] { put(k.data(), k.size()); k.clear(); });
  };
  share.triangle_numbers = [&s, &m, chunk, number](const Put_numbers& put) {
    std::vector<std::uint64_t> t;
    std::uint64_t read = 0;
    s.triangles_file().template read<std::uint32_t>(3 * chunk, [&](const std::uint32_t* v, std::size_t n) {
      for(std::size_t k = 0; k < n; ++k) t.push_back(number(v[k]));
      read += n;
      put(t.data(), t.size());
      t.clear();
    });
    if(read != 3 * m.streamed_triangles)
      throw std::runtime_error("the scratch file " + s.triangles_file().name() + " is short");
    for(const auto& tri : m.triangles)
      for(std::uint64_t v : tri) t.push_back(number(v));
    put(t.data(), t.size());
  };
  auto each_segment = [&s, &m](const std::function<void(const std::array<std::uint64_t, 3>&)>& f) {
    for(const auto& seg : s.segments()) f(seg);
    for(const auto& seg : m.segments) f(seg);
  };
  share.segment_numbers = [each_segment, number](const Put_numbers& put) {
    std::vector<std::uint64_t> ends;
    each_segment([&](const std::array<std::uint64_t, 3>& seg) { ends.insert(ends.end(), {number(seg[0]), number(seg[1])}); });
    put(ends.data(), ends.size());
  };
  share.segment_markers = [each_segment](const Put_markers& put) {
    std::vector<std::int32_t> k;
    each_segment([&](const std::array<std::uint64_t, 3>& seg) { k.push_back(std::int32_t(std::int64_t(seg[2]))); });
    put(k.data(), k.size());
  };
  // the points with their markers, and the triangles with the bits of
  // their region attributes (the region file read in step with the
  // triangles'), for the writers that take a vertex or a triangle whole
  share.marked_points = [each_owned_point, &s](const Put_doubles& put) {
    std::vector<double> xyk;
    each_owned_point(
      [&](double x, double y, double xs, double ys) { xyk.insert(xyk.end(), {x, y, double(s.tags().marker_at(xs, ys))}); },
      [&] { put(xyk.data(), xyk.size()); xyk.clear(); });
  };
  share.regioned_triangles = [&s, &m, chunk, number](const Put_numbers& put) {
    const bool regions = s.tags().has_regions();
    Scratch_reader<std::uint32_t> vertices(s.triangles_file());
    Scratch_reader<double> attributes(s.regions_file());
    std::vector<std::uint64_t> t;
    std::uint64_t read = 0;
    for(;;) {
      const std::vector<std::uint32_t>& v = vertices.next(3 * chunk);
      if(v.empty()) break;
      const std::size_t n = v.size() / 3;
      const std::vector<double>* a = regions ? &attributes.next(n) : nullptr;
      if(a != nullptr && a->size() != n)
        throw std::runtime_error("the scratch file " + s.regions_file().name() + " is short");
      for(std::size_t k = 0; k < n; ++k)
        t.insert(t.end(), {number(v[3 * k]), number(v[3 * k + 1]), number(v[3 * k + 2]),
                           attribute_bits(a != nullptr ? (*a)[k] : 0.)});
      read += n;
      put(t.data(), t.size());
      t.clear();
    }
    if(read != m.streamed_triangles)
      throw std::runtime_error("the scratch file " + s.triangles_file().name() + " is short");
    for(std::size_t k = 0; k < m.triangles.size(); ++k)
      t.insert(t.end(), {number(m.triangles[k][0]), number(m.triangles[k][1]), number(m.triangles[k][2]),
                         attribute_bits(regions ? m.regions[k] : 0.)});
    put(t.data(), t.size());
  };
  share.triangle_regions = [&s, &m, chunk](const Put_doubles& put) {
    std::uint64_t read = 0;
    s.regions_file().template read<double>(chunk, [&](const double* a, std::size_t n) {
      put(a, n);
      read += n;
    });
    if(read != m.streamed_triangles)
      throw std::runtime_error("the scratch file " + s.regions_file().name() + " is short");
    put(m.regions.data(), m.regions.size());
  };
  return share;
}

} // namespace afmesh_2_mpi

#endif // AFMESH_2_MPI_STREAMED_H
