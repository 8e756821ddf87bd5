// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_VERSION_H
#define CGAL_ADVANCING_FRONT_MESH_2_VERSION_H

// The package's version; CMakeLists.txt reads it from here, so that the
// installed package configuration and the headers agree.
#define CGAL_ADVANCING_FRONT_MESH_2_VERSION_MAJOR 0
#define CGAL_ADVANCING_FRONT_MESH_2_VERSION_MINOR 1
#define CGAL_ADVANCING_FRONT_MESH_2_VERSION_PATCH 0
#define CGAL_ADVANCING_FRONT_MESH_2_VERSION_STR "0.1.0"

#endif // CGAL_ADVANCING_FRONT_MESH_2_VERSION_H
