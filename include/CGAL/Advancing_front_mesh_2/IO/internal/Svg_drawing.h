// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_IO_INTERNAL_SVG_DRAWING_H
#define CGAL_ADVANCING_FRONT_MESH_2_IO_INTERNAL_SVG_DRAWING_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <CGAL/Advancing_front_mesh_2/IO/internal/Svg_clipping.h>
#include <CGAL/Advancing_front_mesh_2/IO/internal/Svg_path_writer.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Advancing_front_mesh_2 {
namespace IO {

namespace internal {

// The first part of svg_draw_edges(): skips the edges wholly on one side
// outside `view`, draws those reaching outside `clip` clipped, each on its
// own (a clipped end is no vertex to chain at), and returns the others, the
// indices into `edges` of those left to chain.
inline std::vector<std::size_t>
svg_draw_unchainable_edges(const std::vector<std::array<double, 2> >& pts,
                           const std::vector<std::array<std::size_t, 2> >& edges,
                           const Svg_box& view, const Svg_box& clip,
                           Svg_path_writer& out)
{
  std::vector<std::size_t> chained;
  chained.reserve(edges.size());
  for(std::size_t e = 0; e < edges.size(); ++e) {
    const std::array<double, 2>& a = pts[edges[e][0]];
    const std::array<double, 2>& b = pts[edges[e][1]];
    if((svg_outcode(a, view) & svg_outcode(b, view)) != 0)
      continue;
    if(svg_outcode(a, clip) == 0 && svg_outcode(b, clip) == 0) {
      chained.push_back(e);
    } else {
      std::array<double, 2> p = a, q = b;
      if(svg_clip_segment(p, q, clip)) {
        out.move_to(p);
        out.line_to(q);
      }
    }
  }
  return chained;
}

// Draws undirected edges as few polylines as a greedy walk finds: a polyline
// costs one point per edge instead of two, which roughly halves the file for
// a large mesh. Edges wholly on one side outside `view` are skipped; edges
// reaching outside `clip` are clipped and drawn on their own.
inline void svg_draw_edges(const std::vector<std::array<double, 2> >& pts,
                           const std::vector<std::array<std::size_t, 2> >& edges,
                           const Svg_box& view, const Svg_box& clip,
                           Svg_path_writer& out)
{
  const std::size_t nv = pts.size();
  const std::vector<std::size_t> chained = svg_draw_unchainable_edges(pts, edges, view, clip, out);

  // Adjacency in compressed rows: vertex v's edges are adj[first[v]..first[v+1]).
  std::vector<std::size_t> first(nv + 1, 0);
  for(std::size_t k = 0; k < chained.size(); ++k) {
    ++first[edges[chained[k]][0] + 1];
    ++first[edges[chained[k]][1] + 1];
  }
  for(std::size_t v = 0; v < nv; ++v)
    first[v + 1] += first[v];
  std::vector<std::size_t> adj(first[nv]);
  std::vector<std::size_t> next(first.begin(), first.end() - 1);
  for(std::size_t k = 0; k < chained.size(); ++k) {
    adj[next[edges[chained[k]][0]]++] = k;
    adj[next[edges[chained[k]][1]]++] = k;
  }
  std::copy(first.begin(), first.end() - 1, next.begin());
  std::vector<char> used(chained.size(), 0);

  auto unused_edge_at = [&](std::size_t v, std::size_t& k) {
    while(next[v] < first[v + 1] && used[adj[next[v]]])
      ++next[v];
    if(next[v] == first[v + 1])
      return false;
    k = adj[next[v]];
    return true;
  };
  auto walk_from = [&](std::size_t v) {
    std::size_t k;
    while(unused_edge_at(v, k)) {
      out.move_to(pts[v]);
      std::size_t cur = v;
      while(unused_edge_at(cur, k)) {
        used[k] = 1;
        const std::array<std::size_t, 2>& e = edges[chained[k]];
        cur = (e[0] == cur) ? e[1] : e[0];
        out.line_to(pts[cur]);
      }
    }
  };
  // A walk can only end at an odd vertex, so starting from those first leaves
  // fewer, longer polylines.
  for(std::size_t v = 0; v < nv; ++v)
    if((first[v + 1] - first[v]) % 2 == 1)
      walk_from(v);
  for(std::size_t v = 0; v < nv; ++v)
    walk_from(v);
}

// Fills the domain through its boundary loops rather than triangle by
// triangle: the boundary is tiny compared to the mesh, and with every loop
// oriented with the domain on its left the nonzero rule fills exactly the
// domain, holes and islands included.
inline void svg_fill_domain(const std::vector<std::array<double, 2> >& pts,
                            const std::vector<std::array<std::size_t, 2> >& directed,
                            const Svg_box& view, const Svg_box& clip,
                            Svg_path_writer& out)
{
  const std::size_t nv = pts.size();
  std::vector<std::size_t> first(nv + 1, 0);
  for(const std::array<std::size_t, 2>& e : directed)
    ++first[e[0] + 1];
  for(std::size_t v = 0; v < nv; ++v)
    first[v + 1] += first[v];
  std::vector<std::size_t> adj(first[nv]);
  std::vector<std::size_t> next(first.begin(), first.end() - 1);
  for(std::size_t k = 0; k < directed.size(); ++k)
    adj[next[directed[k][0]]++] = k;
  std::copy(first.begin(), first.end() - 1, next.begin());
  std::vector<char> used(directed.size(), 0);

  std::vector<std::array<double, 2> > loop;
  for(std::size_t k0 = 0; k0 < directed.size(); ++k0) {
    if(used[k0])
      continue;
    used[k0] = 1;
    loop.clear();
    loop.push_back(pts[directed[k0][0]]);
    std::size_t cur = directed[k0][1];
    int code_and = svg_outcode(pts[directed[k0][0]], view);
    bool inside_clip = svg_outcode(pts[directed[k0][0]], clip) == 0;
    for(;;) {
      // As many boundary edges enter a vertex as leave it, so the walk ends
      // where it started.
      while(next[cur] < first[cur + 1] && used[adj[next[cur]]])
        ++next[cur];
      if(next[cur] == first[cur + 1])
        break;
      loop.push_back(pts[cur]);
      code_and &= svg_outcode(pts[cur], view);
      inside_clip = inside_clip && svg_outcode(pts[cur], clip) == 0;
      const std::size_t k = adj[next[cur]];
      used[k] = 1;
      cur = directed[k][1];
    }
    if(code_and != 0)
      continue; // wholly on one side outside the window
    if(!inside_clip)
      svg_clip_polygon(loop, clip);
    if(loop.size() < 3)
      continue;
    out.move_to(loop[0]);
    for(std::size_t i = 1; i < loop.size(); ++i)
      out.line_to(loop[i]);
    out.close();
  }
}

} // namespace internal

} // namespace IO
} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_IO_INTERNAL_SVG_DRAWING_H
