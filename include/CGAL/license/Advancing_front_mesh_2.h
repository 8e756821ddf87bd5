// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_LICENSE_ADVANCING_FRONT_MESH_2_H
#define CGAL_LICENSE_ADVANCING_FRONT_MESH_2_H

#include <CGAL/config.h>
#include <CGAL/license.h>

// The package is distributed under the GPL-3.0-or-later only (no commercial
// licence exists yet), so this header only documents that fact and keeps the
// include structure of CGAL's own packages.

#endif // CGAL_LICENSE_ADVANCING_FRONT_MESH_2_H
