// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_IO_READ_GMSH_BOUNDARY_H
#define CGAL_ADVANCING_FRONT_MESH_2_IO_READ_GMSH_BOUNDARY_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <CGAL/Advancing_front_mesh_2/IO/Poly_data.h>
#include <CGAL/Advancing_front_mesh_2/IO/Poly_read_error.h>
#include <CGAL/Advancing_front_mesh_2/IO/internal/Msh_line_reader.h>
#include <CGAL/Advancing_front_mesh_2/IO/internal/Poly_line_reader.h>
#include <CGAL/Advancing_front_mesh_2/IO/polygons_to_poly.h>

#include <array>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <fstream>
#include <istream>
#include <limits>
#include <map>
#include <streambuf>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Advancing_front_mesh_2 {
namespace IO {

namespace internal {

// The number of nodes of the element types read: lines of order 1 to 5
// (their end nodes come first) and points. 0 for the types skipped.
inline std::size_t msh_boundary_element_nodes(long long type)
{
  switch(type) {
  case 1: return 2;  // 2-node line
  case 8: return 3;  // 3-node line
  case 26: return 4; // 4-node line
  case 27: return 5; // 5-node line
  case 28: return 6; // 6-node line
  case 15: return 1; // point
  default: return 0;
  }
}

struct Msh_node
{
  long long tag;
  double x, y, z;
  std::size_t line; // of the coordinates
};

// A line element (two end nodes) or a point element (one node), with where
// its marker comes from: the physical tag of its curve entity (MSH 4.1) or
// its own first tag (MSH 2).
struct Msh_element
{
  long long tag;
  bool is_point;
  std::array<long long, 2> nodes;
  std::size_t other_nodes_begin, other_nodes_end; // its other nodes, in Msh_contents::other_nodes
  std::size_t line;
  bool from_entity;
  long long entity;        // MSH 4.1: the curve entity of its block
  std::size_t block_line;  // MSH 4.1: the line of its block's header
  int physical;            // MSH 2: its physical tag (0 when it has none)
};

struct Msh_curve
{
  int physical; // the first physical tag, 0 without one
  std::size_t line;
};

// Everything read from the file that the boundary needs.
struct Msh_contents
{
  bool version_4 = false;
  std::vector<Msh_node> nodes;
  std::unordered_map<long long, std::size_t> node_index; // tag -> index into nodes
  std::vector<Msh_element> elements;
  std::vector<long long> other_nodes; // the nodes of lines other than their ends
  bool has_entities = false;
  std::map<long long, Msh_curve> curves;
  std::map<int, std::string> curve_group_names; // physical tag of dimension 1 -> name
  std::size_t ignored_elements = 0;
};

// The shortest decimal that reads back to `v`.
inline std::string msh_shortest(double v)
{
  char b[32];
  return std::string(b, std::to_chars(b, b + sizeof(b), v).ptr);
}

inline std::string msh_block_phrase(std::size_t n, const char* singular, const char* plural)
{
  return std::to_string(n) + " " + (n == 1 ? singular : plural);
}

// Returns the line of $MeshFormat.
inline std::size_t msh_read_format(Msh_line_reader& r, Msh_contents& c)
{
  if(!r.next()) r.fail("file holds no data, expected $MeshFormat: not a Gmsh .msh file");
  if(r.token(0) != "$MeshFormat")
    r.fail("expected $MeshFormat, found " + poly_quote(r.token(0)) + ": not a Gmsh .msh file");
  if(r.size() != 1) r.fail("$MeshFormat must be alone on its line");
  const std::size_t format_line = r.line();
  if(!r.next()) r.fail("file ends in section $MeshFormat, expected 'version file-type data-size'");
  r.expect_size(3, "the format line 'version file-type data-size'");
  const std::string version = r.token(0);
  if(version == "4.1") {
    c.version_4 = true;
  } else if(version == "2.2" || version == "2.1" || version == "2.0" || version == "2") {
    c.version_4 = false;
  } else {
    r.fail("MSH version " + poly_quote(version) + " is not supported (versions 4.1 and 2.2 are): save the mesh "
           "again in Gmsh's default format 4.1, or in 2.2 (option Mesh.MshFileVersion)");
  }
  const long long file_type = r.integer(1, "file type");
  if(file_type == 1)
    r.fail("binary .msh is not supported: save it as ASCII (Gmsh's default: option Mesh.Binary = 0, "
           "or no -bin on the command line)");
  if(file_type != 0) r.fail("file type " + std::to_string(file_type) + " must be 0 (ASCII) or 1 (binary)");
  r.integer(2, "data size");
  r.end_of_section("$MeshFormat", "the format line");
  return format_line;
}

inline void msh_read_physical_names(Msh_line_reader& r, Msh_contents& c)
{
  r.data_line("$PhysicalNames", "the number of names");
  r.expect_size(1, "the number of physical names");
  const std::size_t n = r.count(0, "physical name count");
  std::map<std::pair<long long, int>, std::size_t> seen;
  for(std::size_t i = 0; i < n; ++i) {
    r.data_line("$PhysicalNames", "physical name " + std::to_string(i + 1) + " of " + std::to_string(n));
    if(r.size() < 3) r.fail("a physical name needs 'dimension tag \"name\"'");
    const long long dim = r.integer_in(0, "dimension", 0, 3);
    const int tag = r.physical(1);
    const std::string name = r.rest_after(1);
    if(name.size() < 2 || name.front() != '"' || name.back() != '"')
      r.fail("the name of physical group " + std::to_string(tag) + " must be in double quotes");
    const auto key = std::make_pair(dim, tag);
    const auto it = seen.find(key);
    if(it != seen.end())
      r.fail("physical group " + std::to_string(tag) + " of dimension " + std::to_string(dim) +
             " is named twice (first on line " + std::to_string(it->second) + ")");
    seen.emplace(key, r.line());
    if(dim == 1) c.curve_group_names[tag] = name.substr(1, name.size() - 2);
  }
  r.end_of_section("$PhysicalNames", msh_block_phrase(n, "name", "names"));
}

// MSH 4.1: points `tag x y z numPhysicalTags tags...`; curves, surfaces
// and volumes `tag minX minY minZ maxX maxY maxZ numPhysicalTags tags...
// numBoundingEntities tags...`.
inline void msh_read_entities(Msh_line_reader& r, Msh_contents& c)
{
  c.has_entities = true;
  r.data_line("$Entities", "'numPoints numCurves numSurfaces numVolumes'");
  r.expect_size(4, "the entity counts 'numPoints numCurves numSurfaces numVolumes'");
  static const char* const kinds[4] = {"point", "curve", "surface", "volume"};
  std::size_t counts[4];
  for(std::size_t d = 0; d < 4; ++d) counts[d] = r.count(d, "entity count");
  for(std::size_t d = 0; d < 4; ++d) {
    for(std::size_t i = 0; i < counts[d]; ++i) {
      r.data_line("$Entities", std::string(kinds[d]) + " entity " + std::to_string(i + 1) + " of " +
                                 std::to_string(counts[d]));
      const std::size_t first_physical = d == 0 ? 5 : 8;
      if(r.size() < first_physical)
        r.fail(std::string("a ") + kinds[d] + " entity has " + std::to_string(r.size()) + " values, expected at least " +
               std::to_string(first_physical));
      const long long tag = r.integer(0, "entity tag");
      for(std::size_t k = 1; k + 1 < first_physical; ++k) r.real(k, "coordinate");
      const std::size_t physicals = r.count(first_physical - 1, "physical tag count");
      if(physicals > r.size() - first_physical)
        r.fail(std::string("a ") + kinds[d] + " entity with " + std::to_string(physicals) + " physical tags has " +
               std::to_string(r.size()) + " values");
      for(std::size_t k = 0; k < physicals; ++k) r.physical(first_physical + k);
      std::size_t expected = first_physical + physicals;
      if(d > 0) {
        if(r.size() == expected)
          r.fail(std::string("a ") + kinds[d] + " entity needs its number of bounding entities after its physical tags");
        expected += 1 + r.count(expected, "bounding entity count");
      }
      if(r.size() != expected)
        r.fail(std::string("a ") + kinds[d] + " entity has " + std::to_string(r.size()) + " values, expected " +
               std::to_string(expected));
      for(std::size_t k = first_physical + physicals + 1; k < expected; ++k) r.integer(k, "bounding entity tag");
      if(d == 1) {
        const auto it = c.curves.find(tag);
        if(it != c.curves.end())
          r.fail("curve entity " + std::to_string(tag) + " is listed twice (first on line " +
                 std::to_string(it->second.line) + ")");
        c.curves.emplace(tag, Msh_curve{physicals > 0 ? r.physical(first_physical) : 0, r.line()});
      }
    }
  }
  r.end_of_section("$Entities", "the entities announced (" + msh_block_phrase(counts[0], "point", "points") + ", " +
                                  msh_block_phrase(counts[1], "curve", "curves") + ", " +
                                  msh_block_phrase(counts[2], "surface", "surfaces") + ", " +
                                  msh_block_phrase(counts[3], "volume", "volumes") + ")");
}

inline void msh_add_node(Msh_line_reader& r, Msh_contents& c, long long tag, std::size_t x)
{
  const std::size_t index = c.nodes.size();
  const auto inserted = c.node_index.emplace(tag, index);
  if(!inserted.second)
    r.fail("node " + std::to_string(tag) + " is defined twice (first on line " +
           std::to_string(c.nodes[inserted.first->second].line) + ")");
  c.nodes.push_back(Msh_node{tag, r.real(x, "x coordinate"), r.real(x + 1, "y coordinate"),
                             r.real(x + 2, "z coordinate"), r.line()});
}

// MSH 4.1: `numEntityBlocks numNodes minNodeTag maxNodeTag`, then per
// block `entityDim entityTag parametric numNodesInBlock`, the block's node
// tags one per line, then their coordinates one node per line (`x y z`,
// and `u`, `u v` or `u v w` on curves, surfaces and volumes when parametric).
inline void msh_read_nodes_4(Msh_line_reader& r, Msh_contents& c)
{
  r.data_line("$Nodes", "'numEntityBlocks numNodes minNodeTag maxNodeTag'");
  r.expect_size(4, "the node header 'numEntityBlocks numNodes minNodeTag maxNodeTag'");
  const std::size_t blocks = r.count(0, "node block count");
  const std::size_t total = r.count(1, "node count");
  r.integer(2, "smallest node tag");
  r.integer(3, "largest node tag");
  const std::size_t header_line = r.line();
  const std::size_t before = c.nodes.size();
  std::vector<long long> tags;
  for(std::size_t b = 0; b < blocks; ++b) {
    r.data_line("$Nodes", "node block " + std::to_string(b + 1) + " of " + std::to_string(blocks));
    r.expect_size(4, "a node block header 'entityDim entityTag parametric numNodesInBlock'");
    const long long dim = r.integer_in(0, "entity dimension", 0, 3);
    r.integer(1, "entity tag");
    const long long parametric = r.integer_in(2, "parametric flag", 0, 1);
    const std::size_t n = r.count(3, "node count");
    const std::size_t block_line = r.line();
    const std::string where = " of the block on line " + std::to_string(block_line);
    tags.clear();
    for(std::size_t i = 0; i < n; ++i) {
      r.data_line("$Nodes", "node tag " + std::to_string(i + 1) + " of " + std::to_string(n) + where);
      r.expect_size(1, "a node tag line");
      tags.push_back(r.tag(0, "node tag"));
    }
    const std::size_t values = 3 + (parametric == 1 ? static_cast<std::size_t>(dim) : 0);
    for(std::size_t i = 0; i < n; ++i) {
      r.data_line("$Nodes", "the coordinates of node " + std::to_string(tags[i]) + " (" +
                              std::to_string(i + 1) + " of " + std::to_string(n) + where + ")");
      r.expect_size(values, values == 3 ? std::string("a node's coordinates 'x y z'")
                                        : "a parametric node's coordinates on an entity of dimension " +
                                            std::to_string(dim));
      for(std::size_t k = 3; k < values; ++k) r.real(k, "parametric coordinate");
      msh_add_node(r, c, tags[i], 0);
    }
  }
  if(c.nodes.size() - before != total)
    throw Poly_read_error(r.file(), header_line,
                          "the node header announces " + msh_block_phrase(total, "node", "nodes") +
                            ", its blocks hold " + std::to_string(c.nodes.size() - before));
  r.end_of_section("$Nodes", "the " + msh_block_phrase(blocks, "node block", "node blocks") + " announced");
}

// MSH 2: `numNodes`, then `tag x y z` per line.
inline void msh_read_nodes_2(Msh_line_reader& r, Msh_contents& c)
{
  r.data_line("$Nodes", "the number of nodes");
  r.expect_size(1, "the number of nodes");
  const std::size_t n = r.count(0, "node count");
  for(std::size_t i = 0; i < n; ++i) {
    r.data_line("$Nodes", "node " + std::to_string(i + 1) + " of " + std::to_string(n));
    r.expect_size(4, "a node line 'tag x y z'");
    msh_add_node(r, c, r.tag(0, "node tag"), 1);
  }
  r.end_of_section("$Nodes", "the " + msh_block_phrase(n, "node", "nodes") + " announced");
}

inline void msh_check_block_dimension(Msh_line_reader& r, long long type, long long dim)
{
  const long long expected = type == 15 ? 0 : 1;
  if(dim != expected)
    r.fail("a block of " + std::string(type == 15 ? "point elements (type 15) must be on a point entity (dimension 0)"
                                                  : "line elements (type " + std::to_string(type) +
                                                      ") must be on a curve entity (dimension 1)") +
           ", not on one of dimension " + std::to_string(dim));
}

// MSH 4.1: `numEntityBlocks numElements minElementTag maxElementTag`, then
// per block `entityDim entityTag elementType numElementsInBlock` and its
// elements `tag node...`, one per line.
inline void msh_read_elements_4(Msh_line_reader& r, Msh_contents& c)
{
  r.data_line("$Elements", "'numEntityBlocks numElements minElementTag maxElementTag'");
  r.expect_size(4, "the element header 'numEntityBlocks numElements minElementTag maxElementTag'");
  const std::size_t blocks = r.count(0, "element block count");
  const std::size_t total = r.count(1, "element count");
  r.integer(2, "smallest element tag");
  r.integer(3, "largest element tag");
  const std::size_t header_line = r.line();
  std::size_t read = 0;
  for(std::size_t b = 0; b < blocks; ++b) {
    r.data_line("$Elements", "element block " + std::to_string(b + 1) + " of " + std::to_string(blocks));
    r.expect_size(4, "an element block header 'entityDim entityTag elementType numElementsInBlock'");
    const long long dim = r.integer_in(0, "entity dimension", 0, 3);
    const long long entity = r.integer(1, "entity tag");
    const long long type = r.integer_in(2, "element type", 1, (std::numeric_limits<int>::max)());
    const std::size_t n = r.count(3, "element count");
    const std::size_t block_line = r.line();
    const std::size_t nodes = msh_boundary_element_nodes(type);
    if(nodes > 0) msh_check_block_dimension(r, type, dim);
    const std::string where = " of the block on line " + std::to_string(block_line);
    for(std::size_t i = 0; i < n; ++i) {
      r.data_line("$Elements", "element " + std::to_string(i + 1) + " of " + std::to_string(n) + where);
      if(nodes == 0) {
        if(r.size() < 2) r.fail("an element needs its tag and its nodes");
        r.tag(0, "element tag");
        ++c.ignored_elements;
        continue;
      }
      r.expect_size(1 + nodes, "an element of type " + std::to_string(type) + " 'tag' and " +
                                 msh_block_phrase(nodes, "node", "nodes"));
      Msh_element e;
      e.tag = r.tag(0, "element tag");
      e.is_point = type == 15;
      e.nodes[0] = r.tag(1, "node tag");
      e.nodes[1] = e.is_point ? e.nodes[0] : r.tag(2, "node tag");
      e.other_nodes_begin = c.other_nodes.size();
      for(std::size_t k = 3; k <= nodes; ++k) c.other_nodes.push_back(r.tag(k, "node tag"));
      e.other_nodes_end = c.other_nodes.size();
      e.line = r.line();
      e.from_entity = true;
      e.entity = entity;
      e.block_line = block_line;
      e.physical = 0;
      c.elements.push_back(e);
    }
    read += n;
  }
  if(read != total)
    throw Poly_read_error(r.file(), header_line,
                          "the element header announces " + msh_block_phrase(total, "element", "elements") +
                            ", its blocks hold " + std::to_string(read));
  r.end_of_section("$Elements", "the " + msh_block_phrase(blocks, "element block", "element blocks") + " announced");
}

// MSH 2: `numElements`, then `tag type numTags tags... nodes...` per line;
// the first tag is the physical one.
inline void msh_read_elements_2(Msh_line_reader& r, Msh_contents& c)
{
  r.data_line("$Elements", "the number of elements");
  r.expect_size(1, "the number of elements");
  const std::size_t n = r.count(0, "element count");
  for(std::size_t i = 0; i < n; ++i) {
    r.data_line("$Elements", "element " + std::to_string(i + 1) + " of " + std::to_string(n));
    if(r.size() < 4) r.fail("an element line needs 'tag type numTags tags... nodes...'");
    const long long tag = r.tag(0, "element tag");
    const long long type = r.integer_in(1, "element type", 1, (std::numeric_limits<int>::max)());
    const std::size_t ntags = r.count(2, "tag count");
    if(ntags > r.size() - 3)
      r.fail("an element with " + std::to_string(ntags) + " tags has " + std::to_string(r.size()) + " values");
    for(std::size_t k = 0; k < ntags; ++k) r.integer(3 + k, "tag");
    const std::size_t nodes = msh_boundary_element_nodes(type);
    if(nodes == 0) {
      if(r.size() == 3 + ntags) r.fail("an element needs its nodes after its tags");
      ++c.ignored_elements;
      continue;
    }
    r.expect_size(3 + ntags + nodes, "an element of type " + std::to_string(type) + " with " +
                                       msh_block_phrase(ntags, "tag", "tags") + " 'tag type numTags tags...' and " +
                                       msh_block_phrase(nodes, "node", "nodes"));
    Msh_element e;
    e.tag = tag;
    e.is_point = type == 15;
    const std::size_t first = 3 + ntags;
    e.nodes[0] = r.tag(first, "node tag");
    e.nodes[1] = e.is_point ? e.nodes[0] : r.tag(first + 1, "node tag");
    e.other_nodes_begin = c.other_nodes.size();
    for(std::size_t k = first + 2; k < first + nodes; ++k) c.other_nodes.push_back(r.tag(k, "node tag"));
    e.other_nodes_end = c.other_nodes.size();
    e.line = r.line();
    e.from_entity = false;
    e.entity = 0;
    e.block_line = 0;
    e.physical = ntags > 0 ? r.physical(3) : 0;
    c.elements.push_back(e);
  }
  r.end_of_section("$Elements", "the " + msh_block_phrase(n, "element", "elements") + " announced");
}

// Skips a section this reader does not use ($NodeData, $Periodic, ...).
inline void msh_skip_section(Msh_line_reader& r, const std::string& section)
{
  const std::size_t start = r.line();
  const std::string end = "$End" + section.substr(1);
  while(r.next())
    if(r.size() == 1 && r.token(0) == end) return;
  r.fail("section " + section + " of line " + std::to_string(start) + " is not closed: the file ends before " + end);
}

// The marker of a segment whose physical tag is `physical`: the tag, or M
// when the curve's physical group is named `marker_M` with M an int (as
// write_gmsh_msh() names the groups of markers that are no positive tag).
inline int msh_marker(const Msh_contents& c, int physical)
{
  const auto it = c.curve_group_names.find(physical);
  if(it == c.curve_group_names.end() || it->second.compare(0, 7, "marker_") != 0) return physical;
  long long m = 0;
  if(poly_parse_integer(it->second.substr(7), m) != POLY_INTEGER_OK || m < (std::numeric_limits<int>::min)() ||
     m > (std::numeric_limits<int>::max)())
    return physical;
  return static_cast<int>(m);
}

// The boundary of what was read: the nodes of line and point elements
// (renumbered in the order of $Nodes), the line elements as segments, and
// the hole seeds by nesting.
inline Poly_data msh_boundary(const Msh_contents& c, const std::string& file)
{
  Poly_data d;
  d.origin.file = d.origin.point_file = file;
  d.origin.first_point_id = d.origin.first_segment_id = 1;
  d.origin.ignored_elements = c.ignored_elements;

  std::vector<std::size_t> point_of_node(c.nodes.size(), (std::numeric_limits<std::size_t>::max)());
  std::vector<std::array<std::size_t, 2> > element_nodes(c.elements.size());
  bool has_lines = false;
  for(std::size_t i = 0; i < c.elements.size(); ++i) {
    const Msh_element& e = c.elements[i];
    auto undefined = [&](long long node) {
      return Poly_read_error(file, e.line, "element " + std::to_string(e.tag) + " refers to node " +
                                             std::to_string(node) + ", which $Nodes does not define");
    };
    for(std::size_t k = 0; k < 2; ++k) {
      const auto it = c.node_index.find(e.nodes[k]);
      if(it == c.node_index.end()) throw undefined(e.nodes[k]);
      element_nodes[i][k] = it->second;
      point_of_node[it->second] = 0; // used
    }
    for(std::size_t k = e.other_nodes_begin; k < e.other_nodes_end; ++k)
      if(c.node_index.find(c.other_nodes[k]) == c.node_index.end()) throw undefined(c.other_nodes[k]);
    if(e.is_point) continue;
    has_lines = true;
    if(e.nodes[0] == e.nodes[1])
      throw Poly_read_error(file, e.line, "element " + std::to_string(e.tag) + " joins node " +
                                            std::to_string(e.nodes[0]) + " to itself");
    if(e.from_entity && c.has_entities && c.curves.find(e.entity) == c.curves.end())
      throw Poly_read_error(file, e.block_line, "the element block is on curve " + std::to_string(e.entity) +
                                                  ", which $Entities does not list");
  }
  if(!has_lines)
    throw Poly_read_error(file, 0,
                          "no line elements (type 1 or 8, or lines of higher order 26 to 28): give the boundary as a "
                          "1D mesh (gmsh -1, or gmsh.model.mesh.generate(1))" +
                            (c.ignored_elements == 0   ? std::string()
                             : c.ignored_elements == 1 ? std::string("; its 1 element of another type is not read")
                                                       : "; its " + std::to_string(c.ignored_elements) +
                                                           " elements of other types are not read"));

  const Msh_node* first = nullptr;
  for(std::size_t n = 0; n < c.nodes.size(); ++n) {
    if(point_of_node[n] != 0) continue;
    const Msh_node& node = c.nodes[n];
    if(first == nullptr) {
      first = &node;
    } else if(node.z != first->z) {
      throw Poly_read_error(file, node.line,
                            "node " + std::to_string(node.tag) + " lies at z = " + msh_shortest(node.z) +
                              ", node " + std::to_string(first->tag) + " (line " + std::to_string(first->line) +
                              ") at z = " + msh_shortest(first->z) + ": the boundary must lie in a plane z = constant");
    }
    point_of_node[n] = d.points.size();
    d.points.push_back({{node.x, node.y}});
    d.origin.point_lines.push_back(node.line);
    d.origin.point_ids.push_back(node.tag);
  }

  bool markers = false;
  for(std::size_t i = 0; i < c.elements.size(); ++i) {
    const Msh_element& e = c.elements[i];
    if(e.is_point) continue;
    int physical = e.physical;
    if(e.from_entity && c.has_entities) physical = c.curves.find(e.entity)->second.physical;
    const int marker = physical == 0 ? 0 : msh_marker(c, physical);
    markers = markers || marker != 0;
    d.segments.push_back({{point_of_node[element_nodes[i][0]], point_of_node[element_nodes[i][1]]}});
    d.segment_markers.push_back(marker);
    d.origin.segment_lines.push_back(e.line);
    d.origin.segment_ids.push_back(e.tag);
  }
  if(!markers) d.segment_markers.clear();
  d.holes = polygon_hole_seeds(d);
  return d;
}

} // namespace internal

/*!
\ingroup PkgAdvancingFrontMesh2IO

Reads the boundary of a domain from a Gmsh `.msh` file holding a 1D mesh
(`gmsh -1`, or `gmsh.model.mesh.generate(1)` in the API) from `in`, so
that a geometry drawn and meshed along its curves in Gmsh can be meshed
here. Both ASCII formats Gmsh writes are read: MSH 4.1 (its default) and
MSH 2.2 (`Mesh.MshFileVersion = 2.2`; 2.0 and 2.1 have the same layout).

What is read:
- the nodes of the line and point elements become the points (the other
  nodes are dropped), in the order of `$Nodes`; node tags may be sparse
  and in any order, parametric coordinates are checked and dropped. The
  points must lie in a plane z = constant (z = 0, or any other constant);
- line elements become the segments, in file order: 2-node lines (type 1),
  and lines of higher order (3-node lines, type 8, and types 26 to 28),
  straight between their two end nodes, their other nodes dropped;
- point elements (type 15) make their node a point even when no line uses
  it: an isolated point, which the mesh will contain;
- the segment marker is the physical tag of the element's curve: in MSH
  4.1 the first physical tag of its curve entity in `$Entities`, in MSH 2
  the element's first tag; 0 without one. When the physical group has the
  name `marker_M` in `$PhysicalNames`, M an integer, the marker is M: so a
  file written by `write_gmsh_msh()` with markers gives them back, also
  the markers 0 or negative, which cannot be Gmsh tags.
  `Poly_data::segment_markers` stays empty when every marker is 0 (no
  physical groups on curves); the points have no markers;
- elements of every other type (triangles, quadrangles, volumes) are
  skipped: the boundary is taken from the lines alone, and
  `Poly_data::Origin::ignored_elements` counts them, so that a caller can
  say so;
- sections other than `$MeshFormat`, `$PhysicalNames`, `$Entities`, `$Nodes`
  and `$Elements` (`$NodeData`, `$Periodic`, `$Comments`, ...) are skipped
  up to their end line. A partitioned mesh (`$PartitionedEntities`) is
  refused.

A 1D mesh says nothing about which regions its curves bound, so hole seeds
are placed as for polygons (`poly_data_from_polygons()`): a region that an
even number of closed curves (two or more) separate from the outside is a
hole; an inclusion meant to be meshed (a closed curve inside the domain
around another surface) is therefore taken for a hole. Duplicate segments
(MSH 2 repeats an element for each physical group it is in) are left to
`insert_poly()`, which drops them. Where the items were read is kept in
`Poly_data::Origin`: the line of each point's coordinates and of each
segment's element, with the node and element tags as their ids, so that
`insert_poly()` names them as the file does.

The reader is strict, as `read_poly()`: each entity, block header, node
tag, node and element on a line of its own, as Gmsh writes them; every line
must hold the number of values it calls for, every value be a complete
number (integers for tags and counts), every coordinate finite, and the
counts of the section headers must match what follows. A binary file is
refused with the option that saves it as ASCII.

\param in the stream to read; it is read through its stream buffer
\param file_name the name used in error messages

\returns the points, the segments as 0-based indices into the points, the
hole seeds, and the segment markers

\throws Poly_read_error on any problem, as `FILE:LINE: problem` (for
instance a missing `$MeshFormat`, an unsupported version, a section cut
short, a malformed number, an element referring to an undefined node, a node
off the plane of the others), or `FILE: no line elements ...` when the file
holds no line element.
*/
inline Poly_data read_gmsh_boundary(std::istream& in, const std::string& file_name)
{
  internal::Msh_line_reader r(in, file_name);
  internal::Msh_contents c;
  std::map<std::string, std::size_t> seen; // section -> its line
  seen["$MeshFormat"] = internal::msh_read_format(r, c);
  while(r.next()) {
    const std::string section = r.token(0);
    if(!r.at_section()) r.fail("expected a section ($Nodes, $Elements, ...), found " + internal::poly_quote(section));
    if(r.size() != 1) r.fail("section line " + internal::poly_quote(section) + " must be alone on its line");
    if(section.compare(0, 4, "$End") == 0) r.fail(internal::poly_quote(section) + " closes no open section");
    if(section == "$MeshFormat" || section == "$PhysicalNames" || section == "$Entities" || section == "$Nodes" ||
       section == "$Elements") {
      const auto it = seen.find(section);
      if(it != seen.end())
        r.fail("a second " + section + " section (the first on line " + std::to_string(it->second) + ")");
      seen.emplace(section, r.line());
    }
    if(section == "$PhysicalNames") {
      internal::msh_read_physical_names(r, c);
    } else if(section == "$Entities" && c.version_4) {
      internal::msh_read_entities(r, c);
    } else if(section == "$PartitionedEntities") {
      r.fail("partitioned meshes are not supported: save the mesh without partitions");
    } else if(section == "$Nodes") {
      if(c.version_4)
        internal::msh_read_nodes_4(r, c);
      else
        internal::msh_read_nodes_2(r, c);
    } else if(section == "$Elements") {
      if(c.version_4)
        internal::msh_read_elements_4(r, c);
      else
        internal::msh_read_elements_2(r, c);
    } else {
      internal::msh_skip_section(r, section);
    }
  }
  if(seen.find("$Nodes") == seen.end()) throw Poly_read_error(file_name, 0, "no $Nodes section");
  if(seen.find("$Elements") == seen.end()) throw Poly_read_error(file_name, 0, "no $Elements section");
  return internal::msh_boundary(c, file_name);
}

/*!
\ingroup PkgAdvancingFrontMesh2IO

Reads the boundary in the Gmsh `.msh` file `file_name`; see
`read_gmsh_boundary(std::istream&, const std::string&)`.

\throws Poly_read_error "cannot open file", or on any problem with its content
*/
inline Poly_data read_gmsh_boundary(const std::string& file_name)
{
  // binary mode: the reader handles line ends, and the lines are those an editor shows
  std::ifstream in(file_name.c_str(), std::ios::in | std::ios::binary);
  if(!in) throw Poly_read_error(file_name, 0, "cannot open file");
  return read_gmsh_boundary(in, file_name);
}

} // namespace IO
} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_IO_READ_GMSH_BOUNDARY_H
