// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_IO_INTERNAL_VTU_LAYOUT_H
#define CGAL_ADVANCING_FRONT_MESH_2_IO_INTERNAL_VTU_LAYOUT_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

namespace CGAL {
namespace Advancing_front_mesh_2 {
namespace IO {
namespace internal {

// The layout of every VTU file we write, in memory (write_mesh_VTU.h) and
// streamed (Streaming_mesh_writer.h), so that the two give the same bytes
// for the same mesh in the same numbering.
//
// Binary files put every array in one raw appended block, each preceded by
// its size in bytes as a UInt64 (header_type), in the byte order of the
// machine that wrote them (the file says which): no base64 expansion, no
// second pass over the data, and the arrays can be copied from the
// streaming writer's part files as they are.

enum class Vtu_section { POINTS, CELLS, POINT_DATA, CELL_DATA };

// One DataArray: where it goes, its XML attributes other than the format
// (`type="Float64" Name="..."`), and its content, written by `write` to the
// output (text lines in ASCII, `bytes` raw bytes in binary).
struct Vtu_array
{
  Vtu_section section;
  std::string attributes;
  std::uint64_t bytes;
  std::function<void()> write;
};

inline bool vtu_host_is_little_endian()
{
  const std::uint16_t one = 1;
  unsigned char first = 0;
  std::memcpy(&first, &one, 1);
  return first == 1;
}

// Writes the file to `out`, which has put(const char*, std::size_t). The
// PointData and CellData elements get the attributes `data_attributes`
// (by default the markers are their scalars).
template <class Out>
void vtu_write(Out& out, std::uint64_t n_points, std::uint64_t n_cells, const std::vector<Vtu_array>& arrays,
               bool binary,
               const std::vector<std::string>& data_attributes = {" Scalars=\"marker\"", " Scalars=\"marker\""})
{
  auto put = [&out](const std::string& s) { out.put(s.data(), s.size()); };
  put(std::string("<?xml version=\"1.0\"?>\n"
                  "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"") +
      (vtu_host_is_little_endian() ? "LittleEndian" : "BigEndian") +
      "\" header_type=\"UInt64\">\n<UnstructuredGrid>\n<Piece NumberOfPoints=\"" + std::to_string(n_points) +
      "\" NumberOfCells=\"" + std::to_string(n_cells) + "\">\n");
  static const char* const names[] = {"Points", "Cells", "PointData", "CellData"};
  // the appended block holds the arrays in the order given
  std::vector<std::uint64_t> offsets;
  std::uint64_t offset = 0;
  for(const Vtu_array& a : arrays) {
    offsets.push_back(offset);
    offset += sizeof(std::uint64_t) + a.bytes;
  }
  for(int s = 0; s < 4; ++s) {
    bool opened = false;
    for(std::size_t i = 0; i < arrays.size(); ++i) {
      const Vtu_array& a = arrays[i];
      if(static_cast<int>(a.section) != s) continue;
      if(!opened) {
        put(std::string("<") + names[s] + (s >= 2 ? data_attributes.at(std::size_t(s - 2)) : std::string()) + ">\n");
        opened = true;
      }
      if(binary) {
        put("<DataArray " + a.attributes + " format=\"appended\" offset=\"" + std::to_string(offsets[i]) + "\"/>\n");
      } else {
        put("<DataArray " + a.attributes + " format=\"ascii\">\n");
        a.write();
        put("</DataArray>\n");
      }
    }
    if(opened) put(std::string("</") + names[s] + ">\n");
  }
  put("</Piece>\n</UnstructuredGrid>\n");
  if(binary) {
    put("<AppendedData encoding=\"raw\">\n_");
    for(const Vtu_array& a : arrays) {
      const std::uint64_t n = a.bytes;
      char size[sizeof n];
      std::memcpy(size, &n, sizeof n);
      out.put(size, sizeof n);
      a.write();
    }
    put("\n</AppendedData>\n");
  }
  put("</VTKFile>\n");
}

// Raw values appended to a byte buffer, in the machine's byte order.
template <class T>
void vtu_append_raw(std::string& buffer, T value)
{
  char b[sizeof(T)];
  std::memcpy(b, &value, sizeof(T));
  buffer.append(b, sizeof(T));
}

} // namespace internal
} // namespace IO
} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_IO_INTERNAL_VTU_LAYOUT_H
