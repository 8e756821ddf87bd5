// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_DURABLE_FILES_H
#define CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_DURABLE_FILES_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <cerrno>
#include <filesystem>
#include <string>

#if defined(__unix__) || defined(__APPLE__)
#  include <fcntl.h>
#  include <unistd.h>
#  define CGAL_ADVANCING_FRONT_MESH_2_DURABLE_FILES_POSIX
#endif

namespace CGAL {
namespace Advancing_front_mesh_2 {
namespace internal {

// A file written whole and then renamed into place (a checkpoint) must be
// on the disk before the rename is: else a power loss can leave the new
// name with content that was never written, which a kill -9 cannot. POSIX
// only; elsewhere these do nothing.

// Makes the content of the closed file `path` durable (fsync); false when
// it cannot be opened or synchronised. A special file that cannot be
// synchronised (EINVAL: /dev/null, a pipe) is not an error.
inline bool sync_file(const std::string& path)
{
#if defined(CGAL_ADVANCING_FRONT_MESH_2_DURABLE_FILES_POSIX)
  const int fd = ::open(path.c_str(), O_RDONLY);
  if(fd < 0) return false;
  const bool ok = ::fsync(fd) == 0 || errno == EINVAL;
  return (::close(fd) == 0) && ok;
#else
  return !path.empty();
#endif
}

// Makes the entries of the directory holding `path` durable (after a file
// was created or renamed there). Not every file system can synchronise a
// directory; the files' content is synchronised by sync_file().
inline void sync_directory_of(const std::string& path)
{
#if defined(CGAL_ADVANCING_FRONT_MESH_2_DURABLE_FILES_POSIX)
  std::string d = std::filesystem::path(path).parent_path().string();
  if(d.empty()) d = ".";
  const int fd = ::open(d.c_str(), O_RDONLY);
  if(fd < 0) return;
  static_cast<void>(::fsync(fd));
  ::close(fd);
#else
  static_cast<void>(path);
#endif
}

} // namespace internal
} // namespace Advancing_front_mesh_2
} // namespace CGAL

#undef CGAL_ADVANCING_FRONT_MESH_2_DURABLE_FILES_POSIX

#endif // CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_DURABLE_FILES_H
