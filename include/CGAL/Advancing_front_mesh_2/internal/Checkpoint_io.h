// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_CHECKPOINT_IO_H
#define CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_CHECKPOINT_IO_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <CGAL/Advancing_front_mesh_2/Checkpoint_error.h>
#include <CGAL/Advancing_front_mesh_2/Checkpoint_info.h>
#include <CGAL/Advancing_front_mesh_2/internal/Binary_io.h>
#include <CGAL/Advancing_front_mesh_2/internal/Checkpoint_support.h>
#include <CGAL/Advancing_front_mesh_2/internal/Durable_files.h>
#include <CGAL/Advancing_front_mesh_2/internal/Front_2.h>
#include <CGAL/Advancing_front_mesh_2/internal/Front_triangles.h>
#include <CGAL/Advancing_front_mesh_2/internal/Front_visibility.h>
#include <CGAL/Advancing_front_mesh_2/internal/Streaming_state.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <queue>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <typeinfo>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Advancing_front_mesh_2 {
namespace internal {

// Section 4 of Mavriplis (1992), the restart facility: the whole state of
// the mesher written to a file and read back, so that a resumed run takes
// exactly the decisions of an uninterrupted one.
//
// The state is written as it is in memory, trees included (their query
// order decides ties). Handles become indices: vertices and faces are
// numbered in the file. Each section of the state has its save and its
// load, side by side; a load checks what it reads, so that a corrupt file
// throws instead of making a later step crash.
template <class Front, class Visibility, class Triangles>
class Checkpoint_io
{
public:
  typedef typename Front::Context Context;
  typedef typename Front::Vid Vid;
  typedef typename Front::Edge_key Edge_key;
  typedef typename Front::Front_edge Front_edge;
  typedef typename Front::Face_record Face_record;
  typedef typename Front::Queue_entry Queue_entry;
  typedef typename Front::Point Point;
  typedef typename Front::Vertex_handle Vertex_handle;
  typedef typename Front::Face_handle Face_handle;
  typedef typename Context::FT FT;
  typedef typename Context::Tds_vertex Tds_vertex;
  typedef typename Context::Tds_face Tds_face;
  typedef typename Visibility::Constraint Constraint;
  typedef Streaming_state<Context> Stream;

  static constexpr bool is_supported = Has_point_index_io<typename Front::Point_index>::value &&
                                       Has_circle_index_io<typename Front::Face_circle_index>::value &&
                                       Has_circle_index_io<typename Visibility::Constraint_circle_index>::value;

  Checkpoint_io(Context& ctx, Front& front, Stream& stream, Triangles& triangles, Visibility& visibility,
                bool& pocket_priority)
    : ctx_(ctx), front_(front), stream_(stream), triangles_(triangles), visibility_(visibility),
      pocket_priority_(pocket_priority) {}

  static std::string verified_content(const std::string& file_name);
  static Checkpoint_info read_header(Binary_reader& r, bool check_traits = true);
  void write(const std::string& file_name, const std::string& user_data, const std::string& sink_state);
  Checkpoint_info read(const std::string& content, const std::string& file_name);

private:
  static constexpr std::uint32_t version = 4; // 2: the coordinate origin; 3: constraint hubs; 4: the check of finished triangles' counters
  static constexpr std::uint32_t null_face = 0xffffffffu, ghost_face = 0xfffffffeu, no_index = 0xffffffffu;
  static std::string magic() { return "Advancing_front_mesh_2 checkpoint"; }
  static std::string traits_name() { return typeid(typename Context::Geom_traits).name(); }
  static double exact_double(const FT& v);

  // How handles are numbered in the file, when writing.
  struct Numbering
  {
    std::unordered_map<const Tds_vertex*, std::uint32_t> vindex;
    std::vector<Vertex_handle> vertices;
    std::unordered_map<const Tds_face*, std::uint32_t> findex;
    std::vector<Face_handle> faces;
    std::vector<bool> is_free; // of the vertex ids

    void number(Vertex_handle v)
    {
      if(vindex.emplace(&*v, std::uint32_t(vertices.size())).second) vertices.push_back(v);
    }
    std::uint32_t vertex_code(Vertex_handle v) const { return vindex.at(&*v); }
    std::uint32_t face_code(Face_handle f) const
    {
      if(f == Face_handle()) return null_face;
      const auto it = findex.find(&*f);
      // the ghost, or a face outside the domain: after a restart both are
      // the ghost, which the mesher treats alike
      return it == findex.end() ? ghost_face : it->second;
    }
  };

  // The handles read so far, when reading.
  struct Tables
  {
    Binary_reader& r;
    Face_handle ghost;
    std::vector<Vertex_handle> vertices;
    std::vector<Face_handle> faces;
    std::vector<bool> is_free; // of the vertex ids
    std::uint64_t nids = 0;

    void check(bool ok, const char* what) const
    {
      if(!ok) r.fail(std::string("corrupt checkpoint: ") + what);
    }
    Vertex_handle vertex_at(std::uint32_t i) const
    {
      check(i < vertices.size(), "vertex index");
      return vertices[i];
    }
    Face_handle face_at(std::uint32_t code) const
    {
      if(code == null_face) return Face_handle();
      if(code == ghost_face) return ghost;
      check(code < faces.size(), "face index");
      return faces[code];
    }
  };
  static constexpr std::uint64_t big = std::uint64_t(1) << 40;

  void write_state(Binary_writer& w, const std::string& user_data, const std::string& sink_state);
  void read_state(Binary_reader& r);
  void number_handles(Numbering& n);
  void save_scalars(Binary_writer& w) const;
  void load_scalars(Binary_reader& r);
  void save_vertices(Binary_writer& w, const Numbering& n) const;
  void load_vertices(Tables& t);
  void save_vertex_records(Binary_writer& w, const Numbering& n) const;
  void load_vertex_records(Tables& t);
  void check_free_ids(const Tables& t) const;
  void save_faces(Binary_writer& w, const Numbering& n) const;
  void load_faces(Tables& t);
  void link_loaded_faces(const Tables& t, const std::vector<std::array<std::uint32_t, 3> >& neighbours);
  void save_front_edges(Binary_writer& w, const Numbering& n) const;
  void load_front_edges(Tables& t);
  void save_queue(Binary_writer& w) const;
  void load_queue(Tables& t);
  void save_search_structures(Binary_writer& w, const Numbering& n) const;
  void load_search_structures(Tables& t);
  void save_ghosts(Binary_writer& w, const Numbering& n) const;
  void load_ghosts(Tables& t);
  void check_consistency(const Tables& t) const;

  Context& ctx_;
  Front& front_;
  Stream& stream_;
  Triangles& triangles_;
  Visibility& visibility_;
  bool& pocket_priority_;
};

// The file's content, once its checksum is verified: nothing is built from
// a damaged checkpoint, which is refused as a whole.
template <class F, class V, class T>
std::string Checkpoint_io<F, V, T>::verified_content(const std::string& file_name)
{
  std::ifstream file(file_name.c_str(), std::ios::in | std::ios::binary);
  if(!file) throw std::runtime_error(file_name + ": cannot read the checkpoint");
  std::string content((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  std::istringstream is(content);
  Binary_reader r(is, file_name);
  if(content.size() < sizeof(std::uint64_t)) r.fail("truncated");
  std::vector<char> buffer(std::size_t(1) << 16);
  for(std::size_t left = content.size() - sizeof(std::uint64_t); left > 0;) {
    const std::size_t n = (std::min)(left, buffer.size());
    r.read_bytes(buffer.data(), n);
    left -= n;
  }
  r.check_checksum();
  return content;
}

template <class F, class V, class T>
Checkpoint_info Checkpoint_io<F, V, T>::read_header(Binary_reader& r, bool check_traits)
{
  if(r.read_string(64) != magic()) r.fail("not a checkpoint of Advancing_front_mesher_2");
  if(r.read<std::uint32_t>() != version) r.fail("a checkpoint of another version of the mesher");
  if(r.read_string(4096) != traits_name() && check_traits) r.fail("a checkpoint written with another kernel");
  Checkpoint_info info;
  info.user_data = r.read_string(std::uint64_t(1) << 24);
  info.sink_state = r.read_string(std::uint64_t(1) << 24);
  info.vertices_written = std::size_t(r.read<std::uint64_t>());
  info.triangles_written = std::size_t(r.read<std::uint64_t>());
  return info;
}

template <class F, class V, class T>
double Checkpoint_io<F, V, T>::exact_double(const FT& v)
{
  const double d = CGAL::to_double(v);
  if(!(FT(d) == v))
    throw std::logic_error("Advancing_front_mesher_2: a checkpoint needs coordinates that are doubles");
  return d;
}

// Written to `file_name.tmp`, made durable and renamed, so that a run
// killed while writing, or a power loss, leaves the previous checkpoint; a
// partial file is removed.
template <class F, class V, class T>
void Checkpoint_io<F, V, T>::write(const std::string& file_name, const std::string& user_data,
                                   const std::string& sink_state)
{
  const std::string tmp = file_name + ".tmp";
  try {
    std::ofstream os(tmp.c_str(), std::ios::out | std::ios::binary | std::ios::trunc);
    if(!os) throw Checkpoint_error(tmp + ": cannot write the checkpoint");
    Binary_writer w(os);
    write_state(w, user_data, sink_state);
    w.write_checksum();
    os.flush();
    if(!os) throw Checkpoint_error(tmp + ": cannot write the checkpoint");
    os.close();
    if(!os) throw Checkpoint_error(tmp + ": cannot write the checkpoint");
    if(!sync_file(tmp)) throw Checkpoint_error(tmp + ": cannot make the checkpoint durable (fsync)");
    if(std::rename(tmp.c_str(), file_name.c_str()) != 0)
      throw Checkpoint_error(tmp + ": cannot rename it to " + file_name);
    sync_directory_of(file_name);
  } catch(...) {
    std::remove(tmp.c_str()); // a partial file would only mislead
    throw;
  }
}

// Loads the state of the file `file_name`, whose verified `content` is
// given, into the (cleared) mesher.
template <class F, class V, class T>
Checkpoint_info Checkpoint_io<F, V, T>::read(const std::string& content, const std::string& file_name)
{
  std::istringstream is(content);
  Binary_reader r(is, file_name);
  const Checkpoint_info info = read_header(r);
  stream_.vertices_output = info.vertices_written;
  stream_.triangles_output = info.triangles_written;
  read_state(r);
  r.check_checksum();
  return info;
}

template <class F, class V, class T>
void Checkpoint_io<F, V, T>::write_state(Binary_writer& w, const std::string& user_data,
                                         const std::string& sink_state)
{
  w.write_string(magic());
  w.write(version);
  w.write_string(traits_name());
  w.write_string(user_data);
  w.write_string(sink_state);
  w.write(std::uint64_t(stream_.vertices_output));
  w.write(std::uint64_t(stream_.triangles_output));
  Numbering n;
  number_handles(n);
  save_scalars(w);
  save_vertices(w, n);
  save_vertex_records(w, n);
  save_faces(w, n);
  save_front_edges(w, n);
  save_queue(w);
  save_search_structures(w, n);
  save_ghosts(w, n);
}

template <class F, class V, class T>
void Checkpoint_io<F, V, T>::read_state(Binary_reader& r)
{
  Tables t{r, Face_handle(), {}, {}, {}, 0};
  load_scalars(r);
  load_vertices(t);
  load_vertex_records(t);
  stream_.ghost = ctx_.tds().create_face();
  stream_.ghost->set_in_domain(false);
  t.ghost = stream_.ghost;
  load_faces(t);
  load_front_edges(t);
  load_queue(t);
  load_search_structures(t);
  load_ghosts(t);
  check_consistency(t);
  front_.rebuild_hubs();
  t.check(front_.reach_covers_edges(), "point quadtree");
}

// The vertices anything refers to (the active ones, those of the faces in
// memory, the constraints' end points) and the faces in memory.
template <class F, class V, class T>
void Checkpoint_io<F, V, T>::number_handles(Numbering& n)
{
  n.is_free.assign(front_.vertex.size(), false);
  for(Vid v : front_.free_ids) n.is_free[v] = true;
  for(Vid v : front_.released_ids) n.is_free[v] = true;
  for(Vid v = 0; v < front_.vertex.size(); ++v)
    if(!n.is_free[v]) n.number(front_.vertex[v]);
  for(auto f = ctx_.tds().faces().begin(); f != ctx_.tds().faces().end(); ++f) {
    Face_handle fh = f;
    if(fh == stream_.ghost || !fh->is_in_domain()) continue;
    n.findex.emplace(&*fh, std::uint32_t(n.faces.size()));
    n.faces.push_back(fh);
    for(int i = 0; i < 3; ++i) n.number(fh->vertex(i));
  }
  visibility_.constraint_circles.for_each_payload([&](const Constraint& c) {
    n.number(c.first);
    n.number(c.second);
  });
  // the hubs' other end points, in the order of the hubs' codes (the hubs
  // were numbered with their circles above), not in the map's order of
  // addresses: the same run writes the same bytes
  std::vector<std::pair<std::uint32_t, const std::vector<Vertex_handle>*> > hubs;
  visibility_.constraint_hubs.for_each([&](const Vertex_handle& hub, const std::vector<Vertex_handle>& others) {
    hubs.emplace_back(n.vertex_code(hub), &others);
  });
  std::sort(hubs.begin(), hubs.end());
  for(const auto& h : hubs)
    for(const Vertex_handle& w : *h.second) n.number(w);
}

template <class F, class V, class T>
void Checkpoint_io<F, V, T>::save_scalars(Binary_writer& w) const
{
  w.write(ctx_.scaling.exponent());
  w.write(ctx_.scaling.origin_x());
  w.write(ctx_.scaling.origin_y());
  w.write(triangles_.domain_area);
  w.write(triangles_.meshed_area);
  w.write(front_.version_counter);
  w.write(std::uint64_t(front_.queue_compactions));
  w.write(static_cast<std::uint8_t>(pocket_priority_));
  // the counters without the times, which are this session's: a checkpoint
  // depends on the input and the options only, and two runs write the same
  // bytes
  Advancing_front_mesh_2::Statistics counters = ctx_.stats;
  counters.init_time = counters.meshing_time = 0;
  counters.phase_times = Advancing_front_mesh_2::Phase_times();
  w.write(counters);
  for(std::size_t n : {stream_.triangles_in_memory, stream_.created_since_sweep, stream_.sweep_after,
                       stream_.minimum_sweep})
    w.write(std::uint64_t(n));
}

template <class F, class V, class T>
void Checkpoint_io<F, V, T>::load_scalars(Binary_reader& r)
{
  {
    const int exponent = r.read<int>();
    const double origin_x = r.read<double>();
    const double origin_y = r.read<double>();
    if(!std::isfinite(origin_x) || !std::isfinite(origin_y)) r.fail("an origin that is not finite");
    Coordinate_scaling<Point> scaling;
    scaling.set(exponent, origin_x, origin_y);
    scaling.set_exact(true); // a checkpoint stores every vertex's coordinates as doubles
    ctx_.set_scaling(scaling);
  }
  triangles_.domain_area = r.read<double>();
  triangles_.meshed_area = r.read<double>();
  front_.version_counter = r.read<std::uint32_t>();
  front_.queue_compactions = std::size_t(r.read<std::uint64_t>());
  pocket_priority_ = r.read<std::uint8_t>() != 0;
  ctx_.stats = r.read<Advancing_front_mesh_2::Statistics>();
  stream_.triangles_in_memory = std::size_t(r.read<std::uint64_t>());
  stream_.created_since_sweep = std::size_t(r.read<std::uint64_t>());
  stream_.sweep_after = std::size_t(r.read<std::uint64_t>());
  stream_.minimum_sweep = std::size_t(r.read<std::uint64_t>());
}

template <class F, class V, class T>
void Checkpoint_io<F, V, T>::save_vertices(Binary_writer& w, const Numbering& n) const
{
  w.write(std::uint64_t(n.vertices.size()));
  for(Vertex_handle v : n.vertices) {
    w.write(exact_double(v->point().x()));
    w.write(exact_double(v->point().y()));
    const std::uint64_t* out = stream_.output_id.find(&*v);
    w.write(out != nullptr ? *out : ~std::uint64_t(0));
    w.write(static_cast<std::uint8_t>(stream_.live_faces.find(&*v) != nullptr));
  }
}

template <class F, class V, class T>
void Checkpoint_io<F, V, T>::load_vertices(Tables& t)
{
  const std::uint64_t nv = t.r.template read<std::uint64_t>();
  t.check(nv < big, "vertex count");
  t.vertices.reserve(std::size_t((std::min)(nv, std::uint64_t(1) << 20)));
  for(std::uint64_t i = 0; i < nv; ++i) {
    const double px = t.r.template read<double>(), py = t.r.template read<double>();
    t.check(std::isfinite(px) && std::isfinite(py), "vertex coordinates");
    const std::uint64_t out = t.r.template read<std::uint64_t>();
    const bool created = t.r.template read<std::uint8_t>() != 0;
    Vertex_handle v = ctx_.tds().create_vertex();
    v->set_point(Point(px, py));
    t.vertices.push_back(v);
    if(out != ~std::uint64_t(0)) stream_.output_id.insert(&*v, out);
    if(created) stream_.live_faces.insert(&*v, 0);
  }
}

template <class F, class V, class T>
void Checkpoint_io<F, V, T>::save_vertex_records(Binary_writer& w, const Numbering& n) const
{
  w.write(std::uint64_t(front_.vertex.size()));
  for(Vid v = 0; v < front_.vertex.size(); ++v) {
    w.write(n.is_free[v] ? no_index : n.vertex_code(front_.vertex[v]));
    w.write(front_.xy[v]);
    w.write_vector(std::vector<Vid>(front_.out[v].begin(), front_.out[v].end()));
    w.write_vector(std::vector<Vid>(front_.in[v].begin(), front_.in[v].end()));
  }
  w.write_vector(front_.free_ids);
  w.write_vector(front_.released_ids);
}

template <class F, class V, class T>
void Checkpoint_io<F, V, T>::load_vertex_records(Tables& t)
{
  t.nids = t.r.template read<std::uint64_t>();
  t.check(t.nids < F::no_vertex, "number of vertex ids");
  // grown per record: nids is not trusted yet
  for(std::uint64_t v = 0; v < t.nids; ++v) {
    t.is_free.push_back(true);
    const std::uint32_t code = t.r.template read<std::uint32_t>();
    front_.vertex.push_back(code == no_index ? Vertex_handle() : t.vertex_at(code));
    front_.xy.push_back(t.r.template read<std::array<double, 2> >());
    std::vector<Vid> ids;
    front_.out.emplace_back();
    front_.in.emplace_back();
    t.r.read_vector(ids, t.nids);
    for(Vid w : ids) { t.check(w < t.nids, "front edge"); front_.out.back().push_back(w); }
    t.r.read_vector(ids, t.nids);
    for(Vid w : ids) { t.check(w < t.nids, "front edge"); front_.in.back().push_back(w); }
    if(code != no_index) {
      t.check(front_.ids.find(&*front_.vertex.back()) == nullptr, "vertex ids");
      t.is_free[std::size_t(v)] = false;
      front_.ids.insert(&*front_.vertex.back(), Vid(v));
    }
  }
  t.r.read_vector(front_.free_ids, t.nids);
  t.r.read_vector(front_.released_ids, t.nids);
  check_free_ids(t);
}

// every id without a vertex is free or released, once
template <class F, class V, class T>
void Checkpoint_io<F, V, T>::check_free_ids(const Tables& t) const
{
  std::vector<bool> listed(t.is_free.size(), false);
  for(Vid v : front_.free_ids) {
    t.check(v < t.nids && t.is_free[v] && !listed[v], "free vertex id");
    listed[v] = true;
  }
  for(Vid v : front_.released_ids) {
    t.check(v < t.nids && t.is_free[v] && !listed[v], "released vertex id");
    listed[v] = true;
  }
  t.check(std::count(t.is_free.begin(), t.is_free.end(), true) ==
            std::ptrdiff_t(front_.free_ids.size() + front_.released_ids.size()),
          "free vertex ids");
}

template <class F, class V, class T>
void Checkpoint_io<F, V, T>::save_faces(Binary_writer& w, const Numbering& n) const
{
  w.write(std::uint64_t(n.faces.size()));
  for(Face_handle f : n.faces) {
    for(int i = 0; i < 3; ++i) w.write(n.vertex_code(f->vertex(i)));
    for(int i = 0; i < 3; ++i) w.write(n.face_code(f->neighbor(i)));
    for(int i = 0; i < 3; ++i) w.write(static_cast<std::uint8_t>(f->is_constrained(i)));
    const Face_record* rec = front_.face_records.find(&*f);
    w.write(static_cast<std::uint8_t>(rec != nullptr));
    if(rec != nullptr) {
      w.write(std::uint64_t(rec->circle_item));
      w.write(rec->front_edges);
    }
  }
}

template <class F, class V, class T>
void Checkpoint_io<F, V, T>::load_faces(Tables& t)
{
  const std::uint64_t nf = t.r.template read<std::uint64_t>();
  t.check(nf < big, "face count");
  std::vector<std::array<std::uint32_t, 3> > neighbours;
  for(std::uint64_t i = 0; i < nf; ++i) {
    std::array<std::uint32_t, 3> vs;
    for(int k = 0; k < 3; ++k) vs[k] = t.r.template read<std::uint32_t>();
    t.check(vs[0] != vs[1] && vs[1] != vs[2] && vs[2] != vs[0], "face vertices");
    Face_handle f = ctx_.tds().create_face(t.vertex_at(vs[0]), t.vertex_at(vs[1]), t.vertex_at(vs[2]));
    f->set_in_domain(true);
    t.faces.push_back(f);
    std::array<std::uint32_t, 3> ns;
    for(int k = 0; k < 3; ++k) ns[k] = t.r.template read<std::uint32_t>();
    neighbours.push_back(ns);
    for(int k = 0; k < 3; ++k) f->set_constraint(k, t.r.template read<std::uint8_t>() != 0);
    for(int k = 0; k < 3; ++k) {
      t.vertex_at(vs[k])->set_face(f);
      if(std::uint32_t* n = stream_.live_faces.find(&*t.vertex_at(vs[k]))) ++*n;
    }
    if(t.r.template read<std::uint8_t>() != 0) {
      Face_record rec;
      rec.circle_item = std::size_t(t.r.template read<std::uint64_t>());
      rec.front_edges = t.r.template read<int>();
      t.check(rec.front_edges > 0 && rec.front_edges <= 3, "face record");
      front_.face_records.insert(&*f, rec);
    }
  }
  link_loaded_faces(t, neighbours);
}

// Sets the neighbours read; two faces in memory must see each other across
// the same edge.
template <class F, class V, class T>
void Checkpoint_io<F, V, T>::link_loaded_faces(const Tables& t,
                                               const std::vector<std::array<std::uint32_t, 3> >& neighbours)
{
  for(std::size_t i = 0; i < t.faces.size(); ++i)
    for(int k = 0; k < 3; ++k) t.faces[i]->set_neighbor(k, t.face_at(neighbours[i][k]));
  for(Face_handle f : t.faces)
    for(int k = 0; k < 3; ++k) {
      Face_handle g = f->neighbor(k);
      if(g == Face_handle() || g == t.ghost) continue;
      int j = 0;
      while(j < 3 && g->neighbor(j) != f) ++j;
      t.check(j < 3 && g->vertex(Context::cw(j)) == f->vertex(Context::ccw(k)) &&
                g->vertex(Context::ccw(j)) == f->vertex(Context::cw(k)) &&
                g->is_constrained(j) == f->is_constrained(k),
              "face neighbours");
    }
}

template <class F, class V, class T>
void Checkpoint_io<F, V, T>::save_front_edges(Binary_writer& w, const Numbering& n) const
{
  w.write(std::uint64_t(front_.edges.size()));
  front_.edges.for_each([&](Edge_key k, const Front_edge& fe) {
    w.write(k);
    w.write(n.face_code(fe.behind));
    w.write(fe.behind_index);
    w.write(static_cast<std::uint8_t>(fe.constrained));
    w.write(fe.level);
    w.write(fe.version);
  });
}

template <class F, class V, class T>
void Checkpoint_io<F, V, T>::load_front_edges(Tables& t)
{
  const std::uint64_t ne = t.r.template read<std::uint64_t>();
  t.check(ne < big, "front size");
  for(std::uint64_t i = 0; i < ne; ++i) {
    const Edge_key k = t.r.template read<Edge_key>();
    t.check(F::source(k) < t.nids && F::target(k) < t.nids && F::source(k) != F::target(k), "front edge key");
    Front_edge fe;
    fe.behind = t.face_at(t.r.template read<std::uint32_t>());
    fe.behind_index = t.r.template read<int>();
    t.check(fe.behind_index >= -1 && fe.behind_index < 3, "front edge");
    if(fe.behind == t.ghost) fe.behind_index = -1;
    t.check(fe.behind == Face_handle() || fe.behind == t.ghost || fe.behind_index >= 0, "front edge");
    t.check(front_.edges.find(k) == nullptr, "front edge twice");
    fe.constrained = t.r.template read<std::uint8_t>() != 0;
    fe.level = t.r.template read<std::uint16_t>();
    fe.version = t.r.template read<std::uint32_t>();
    front_.edges.insert(k, fe);
  }
}

template <class F, class V, class T>
void Checkpoint_io<F, V, T>::save_queue(Binary_writer& w) const
{
  std::priority_queue<Queue_entry> q = front_.queue;
  w.write(std::uint64_t(q.size()));
  for(; !q.empty(); q.pop()) {
    const Queue_entry& e = q.top();
    w.write(e.length);
    w.write(e.key);
    w.write(e.version);
    w.write(e.level);
  }
}

template <class F, class V, class T>
void Checkpoint_io<F, V, T>::load_queue(Tables& t)
{
  const std::uint64_t nq = t.r.template read<std::uint64_t>();
  t.check(nq < big, "queue size");
  std::vector<Queue_entry> entries;
  for(std::uint64_t i = 0; i < nq; ++i) {
    const double length = t.r.template read<double>();
    const Edge_key k = t.r.template read<Edge_key>();
    const std::uint32_t version = t.r.template read<std::uint32_t>();
    const std::uint16_t level = t.r.template read<std::uint16_t>();
    t.check(F::source(k) < t.nids && F::target(k) < t.nids, "queue entry");
    entries.push_back(Queue_entry{length, k, version, level});
  }
  front_.queue = std::priority_queue<Queue_entry>(std::less<Queue_entry>(), std::move(entries));
}

template <class F, class V, class T>
void Checkpoint_io<F, V, T>::save_search_structures(Binary_writer& w, const Numbering& n) const
{
  if constexpr(is_supported) {
    front_.active_points.save(w);
    front_.front_triangle_circles.save(w, [&](Binary_writer& bw, const Face_handle& f) { bw.write(n.face_code(f)); });
    visibility_.constraint_circles.save(w, [&](Binary_writer& bw, const Constraint& c) {
      bw.write(n.vertex_code(c.first));
      bw.write(n.vertex_code(c.second));
    });
    // the hubs' constraints, in the order of the hubs' codes
    std::vector<std::pair<std::uint32_t, std::vector<std::uint32_t> > > hubs;
    visibility_.constraint_hubs.for_each([&](const Vertex_handle& hub, const std::vector<Vertex_handle>& others) {
      hubs.emplace_back(n.vertex_code(hub), std::vector<std::uint32_t>());
      for(const Vertex_handle& o : others) hubs.back().second.push_back(n.vertex_code(o));
    });
    std::sort(hubs.begin(), hubs.end());
    w.write(std::uint64_t(hubs.size()));
    for(const auto& h : hubs) {
      w.write(h.first);
      w.write_vector(h.second);
    }
  }
}

template <class F, class V, class T>
void Checkpoint_io<F, V, T>::load_search_structures(Tables& t)
{
  if constexpr(is_supported) {
    front_.active_points.load(t.r);
    front_.front_triangle_circles.load(t.r, [&](Binary_reader& br) { return t.face_at(br.read<std::uint32_t>()); });
    std::vector<std::uint32_t> hub_codes; // a hub's circle names it twice
    visibility_.constraint_circles.load(t.r, [&](Binary_reader& br) {
      const std::uint32_t a = br.read<std::uint32_t>();
      const std::uint32_t b = br.read<std::uint32_t>();
      if(a == b) hub_codes.push_back(a);
      return std::make_pair(t.vertex_at(a), t.vertex_at(b));
    });
    // every hub's circle has its constraints, once
    const std::uint64_t nhubs = t.r.template read<std::uint64_t>();
    std::sort(hub_codes.begin(), hub_codes.end());
    t.check(nhubs == hub_codes.size() && std::adjacent_find(hub_codes.begin(), hub_codes.end()) == hub_codes.end(),
            "constraint hubs");
    visibility_.constraint_hubs.clear();
    std::vector<std::uint32_t> codes;
    for(std::uint64_t i = 0; i < nhubs; ++i) {
      const std::uint32_t hub = t.r.template read<std::uint32_t>();
      t.check(hub == hub_codes[std::size_t(i)], "constraint hub");
      t.r.read_vector(codes, big);
      std::vector<Vertex_handle> others;
      const Vertex_handle hv = t.vertex_at(hub);
      for(std::uint32_t c : codes) {
        // a constraint of no length would have no direction to sort by
        t.check(c != hub && t.vertex_at(c)->point() != hv->point(), "constraint hub");
        others.push_back(t.vertex_at(c));
      }
      visibility_.constraint_hubs.add(hv, std::move(others), ctx_.pred);
    }
  }
}

template <class F, class V, class T>
void Checkpoint_io<F, V, T>::save_ghosts(Binary_writer& w, const Numbering& n) const
{
  // in the order of the vertices' numbers, not the hash table's, which
  // depends on addresses
  std::vector<std::pair<std::array<std::uint32_t, 2>, Point> > ghosts;
  ghosts.reserve(stream_.ghost_apex.size());
  for(const auto& g : stream_.ghost_apex)
    ghosts.emplace_back(std::array<std::uint32_t, 2>{{n.vindex.at(g.first.first), n.vindex.at(g.first.second)}},
                        g.second);
  std::sort(ghosts.begin(), ghosts.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  w.write(std::uint64_t(ghosts.size()));
  for(const auto& g : ghosts) {
    w.write(g.first[0]);
    w.write(g.first[1]);
    w.write(exact_double(g.second.x()));
    w.write(exact_double(g.second.y()));
  }
}

template <class F, class V, class T>
void Checkpoint_io<F, V, T>::load_ghosts(Tables& t)
{
  const std::uint64_t ng = t.r.template read<std::uint64_t>();
  t.check(ng < big, "ghost count");
  for(std::uint64_t i = 0; i < ng; ++i) {
    const Vertex_handle a = t.vertex_at(t.r.template read<std::uint32_t>());
    const Vertex_handle b = t.vertex_at(t.r.template read<std::uint32_t>());
    const double px = t.r.template read<double>(), py = t.r.template read<double>();
    stream_.ghost_apex[std::make_pair(&*a, &*b)] = Point(px, py);
  }
}

// What the mesher cross-checks in every step must hold.
template <class F, class V, class T>
void Checkpoint_io<F, V, T>::check_consistency(const Tables& t) const
{
  for(Vid v = 0; v < t.nids; ++v)
    if(!t.is_free[v]) t.check(front_.active_points.contains(v), "point quadtree");
  front_.edges.for_each([&](Edge_key k, const Front_edge&) {
    t.check(!t.is_free[F::source(k)] && !t.is_free[F::target(k)], "front edge");
    // of positive length: the edges at a hub are sorted by direction
    t.check(front_.point(F::source(k)) != front_.point(F::target(k)), "front edge");
  });
  t.check(front_.active_points.size() == front_.ids.size(), "point quadtree");
  // the circle index holds exactly the circles of the face records, and a
  // record counts the front edges its face is behind
  std::size_t circles = 0;
  bool circles_ok = true;
  front_.front_triangle_circles.for_each_payload([&](const Face_handle& f) {
    ++circles;
    if(f == Face_handle() || f == t.ghost || front_.face_records.find(&*f) == nullptr) circles_ok = false;
  });
  t.check(circles_ok && circles == front_.face_records.size(), "circle octree");
  std::unordered_map<const Tds_face*, int> edges_behind;
  front_.edges.for_each([&](Edge_key, const Front_edge& fe) {
    if(fe.behind != Face_handle() && fe.behind != t.ghost) ++edges_behind[&*fe.behind];
  });
  t.check(edges_behind.size() == front_.face_records.size(), "face records");
  front_.face_records.for_each([&](const Tds_face* f, const Face_record& rec) {
    t.check(front_.front_triangle_circles.is_alive(rec.circle_item) &&
              &*front_.front_triangle_circles.payload(rec.circle_item) == f,
            "circle octree");
    const auto it = edges_behind.find(f);
    t.check(it != edges_behind.end() && it->second == rec.front_edges, "face records");
  });
  t.check(front_.is_valid(t.ghost), "front");
}

} // namespace internal
} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_CHECKPOINT_IO_H
