// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_BINARY_IO_H
#define CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_BINARY_IO_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <istream>
#include <ostream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Advancing_front_mesh_2 {
namespace internal {

// Binary streams for the mesher's checkpoints (its whole state, dumped so
// that a later run resumes it and makes the same decisions).
//
// Values are written as their bytes in memory: native byte order and type
// sizes, no conversion. A checkpoint is therefore read by the build that
// wrote it, on the same kind of machine; it is not an exchange format.
// Both sides keep a running 64-bit FNV-1a hash of the bytes that went
// through them, so that a checksum written at the end detects a damaged
// file. The reader checks every length it reads against a bound given by
// the caller and never allocates more than what the file really holds, so
// a corrupt file ends in an exception, not in a crash or an exhausted
// memory.

inline constexpr std::uint64_t fnv1a_offset_basis = 14695981039346656037ull;
inline constexpr std::uint64_t fnv1a_prime = 1099511628211ull;

inline std::uint64_t fnv1a_update(std::uint64_t h, const void* data, std::size_t n)
{
  const unsigned char* p = static_cast<const unsigned char*>(data);
  for(std::size_t i = 0; i < n; ++i) {
    h ^= p[i];
    h *= fnv1a_prime;
  }
  return h;
}

class Binary_writer
{
public:
  explicit Binary_writer(std::ostream& os) : os_(os) {}

  /// Writes the bytes of `v` (a type without padding bytes, whose content
  /// would be indeterminate, and without pointers).
  template <class T>
  void write(const T& v)
  {
    static_assert(std::is_trivially_copyable<T>::value, "Binary_writer::write() needs a trivially copyable type");
    write_bytes(&v, sizeof(T));
  }

  /// Writes the size of `v` as a 64-bit integer, then its elements' bytes.
  template <class T>
  void write_vector(const std::vector<T>& v)
  {
    static_assert(std::is_trivially_copyable<T>::value && !std::is_same<T, bool>::value,
                  "Binary_writer::write_vector() needs a trivially copyable type other than bool");
    write<std::uint64_t>(v.size());
    if(!v.empty()) write_bytes(v.data(), v.size() * sizeof(T));
  }

  void write_string(const std::string& s)
  {
    write<std::uint64_t>(s.size());
    write_bytes(s.data(), s.size());
  }

  void write_bytes(const void* data, std::size_t n)
  {
    if(n == 0) return;
    os_.write(static_cast<const char*>(data), static_cast<std::streamsize>(n));
    if(!os_) throw std::runtime_error("Binary_writer: write error");
    checksum_ = fnv1a_update(checksum_, data, n);
  }

  /// The FNV-1a hash of all the bytes written so far (the checksums
  /// appended by `write_checksum()` excepted).
  std::uint64_t checksum() const { return checksum_; }

  /// Appends `checksum()`, which `Binary_reader::check_checksum()` compares
  /// with the hash of the bytes it has read.
  void write_checksum()
  {
    const std::uint64_t h = checksum_;
    os_.write(reinterpret_cast<const char*>(&h), sizeof(h));
    if(!os_) throw std::runtime_error("Binary_writer: write error");
  }

private:
  std::ostream& os_;
  std::uint64_t checksum_ = fnv1a_offset_basis;
};

class Binary_reader
{
public:
  /// `name` (the file's) prefixes the messages of the exceptions thrown.
  Binary_reader(std::istream& is, std::string name) : is_(is), name_(std::move(name)) {}

  const std::string& name() const { return name_; }

  /// Reads a value written by `Binary_writer::write()`; a `bool` must be
  /// 0 or 1 (another byte would make it undefined).
  template <class T>
  T read()
  {
    static_assert(std::is_trivially_copyable<T>::value && std::is_default_constructible<T>::value,
                  "Binary_reader::read() needs a trivially copyable, default constructible type");
    if constexpr(std::is_same<T, bool>::value) {
      const std::uint8_t b = read<std::uint8_t>();
      if(b > 1) fail("corrupt: a boolean is neither 0 nor 1");
      return b == 1;
    } else {
      T v;
      read_bytes(&v, sizeof(T));
      return v;
    }
  }

  /// Reads a vector written by `Binary_writer::write_vector()`, of at most
  /// `max_size` elements. The vector grows as its elements are read, so a
  /// length beyond the end of the file costs no more memory than the file.
  template <class T>
  void read_vector(std::vector<T>& v, std::uint64_t max_size)
  {
    static_assert(std::is_trivially_copyable<T>::value && !std::is_same<T, bool>::value,
                  "Binary_reader::read_vector() needs a trivially copyable type other than bool");
    const std::uint64_t n = read_size((std::min)(max_size, std::uint64_t(v.max_size())), "vector");
    v.clear();
    const std::uint64_t chunk = (std::max)(std::size_t(1), std::size_t(chunk_bytes / sizeof(T)));
    while(v.size() < n) {
      const std::size_t old = v.size();
      const std::size_t k = std::size_t((std::min)(chunk, n - old));
      v.resize(old + k);
      read_bytes(v.data() + old, k * sizeof(T));
    }
  }

  std::string read_string(std::uint64_t max_size)
  {
    std::string s;
    const std::uint64_t n = read_size((std::min)(max_size, std::uint64_t(s.max_size())), "string");
    while(s.size() < n) {
      const std::size_t old = s.size();
      const std::size_t k = std::size_t((std::min)(chunk_bytes, n - old));
      s.resize(old + k);
      read_bytes(&s[old], k);
    }
    return s;
  }

  void read_bytes(void* data, std::size_t n)
  {
    if(n == 0) return;
    is_.read(static_cast<char*>(data), static_cast<std::streamsize>(n));
    if(static_cast<std::size_t>(is_.gcount()) != n) fail(is_.eof() ? "truncated" : "read error");
    checksum_ = fnv1a_update(checksum_, data, n);
  }

  /// Reads a checksum appended by `Binary_writer::write_checksum()` and
  /// fails unless it is the hash of the bytes read since the start.
  void check_checksum()
  {
    const std::uint64_t expected = checksum_;
    std::uint64_t stored;
    is_.read(reinterpret_cast<char*>(&stored), sizeof(stored));
    if(is_.gcount() != sizeof(stored)) fail(is_.eof() ? "truncated" : "read error");
    if(stored != expected) fail("corrupt: checksum mismatch");
  }

  [[noreturn]] void fail(const std::string& what) const { throw std::runtime_error(name_ + ": " + what); }

private:
  static constexpr std::uint64_t chunk_bytes = std::uint64_t(1) << 16;

  std::uint64_t read_size(std::uint64_t max_size, const char* what)
  {
    const std::uint64_t n = read<std::uint64_t>();
    if(n > max_size)
      fail("corrupt: " + std::string(what) + " of " + std::to_string(n) + " elements (at most " +
           std::to_string(max_size) + " expected)");
    return n;
  }

  std::istream& is_;
  std::string name_;
  std::uint64_t checksum_ = fnv1a_offset_basis;
};

} // namespace internal
} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_BINARY_IO_H
