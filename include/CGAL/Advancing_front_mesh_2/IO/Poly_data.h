// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_IO_POLY_DATA_H
#define CGAL_ADVANCING_FRONT_MESH_2_IO_POLY_DATA_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Advancing_front_mesh_2 {
namespace IO {

/*!
\ingroup PkgAdvancingFrontMesh2IO

A planar straight-line graph as stored in a Triangle `.poly` file:
points, segments joining them (0-based indices into `points`), hole seeds,
and what a solver tags: boundary markers of points and segments, and
regions (a seed point with an attribute and an optional area limit).
Coordinates are kept as `double` since this is what the file holds;
meshing code converts them to the kernel's points once.

The markers are integers as in Triangle; `point_markers` and
`segment_markers` are either empty (the file has none) or hold one marker
per point or segment. `Markers_and_regions_2` carries them and the regions
onto the mesh.
*/
struct Poly_data
{
  /*!
  A region of a `.poly` file: the part of the domain around `seed` bounded
  by segments gets `attribute` (Triangle's regional attribute), and its
  triangles' size is limited so that their area stays near or below
  `max_area` when it is positive (no limit when it is 0 or negative, as in
  Triangle).
  */
  struct Region
  {
    std::array<double, 2> seed = {{0, 0}};
    double attribute = 0;
    double max_area = -1;
  };

  std::vector<std::array<double, 2> > points;
  std::vector<std::array<std::size_t, 2> > segments;
  std::vector<std::array<double, 2> > holes;
  std::vector<int> point_markers;   ///< empty, or one boundary marker per point
  std::vector<int> segment_markers; ///< empty, or one boundary marker per segment
  std::vector<Region> regions;

  /*!
  Where the items were read, so that a problem found after reading (by
  `insert_poly()`) names the file, line and id as the file gives them.
  Filled by the readers (`read_poly()`, `read_WKT_polygons()`,
  `read_gmsh_boundary()`); left empty for data built in code, whose
  problems are then named by 0-based index without a line.
  */
  struct Origin
  {
    std::string file;        ///< the `.poly` file (segments and holes)
    std::string point_file;  ///< the file of the points (the `.poly` file, or its `.node` file)
    std::vector<std::size_t> point_lines, segment_lines, hole_lines, region_lines; ///< 1-based line of each item
    long long first_point_id = 0, first_segment_id = 0, first_hole_id = 0,
              first_region_id = 0; ///< 0 or 1, as in the file
    /// empty, or the id of each point and segment in the file when the ids
    /// are not consecutive (Gmsh's node and element tags); they then name
    /// the items instead of `first_point_id` and `first_segment_id`
    std::vector<long long> point_ids, segment_ids;
    /// elements of a Gmsh file that were skipped (surfaces and volumes:
    /// `read_gmsh_boundary()` reads lines and points only), 0 for other files
    std::size_t ignored_elements = 0;
  };
  Origin origin;
};

} // namespace IO
} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_IO_POLY_DATA_H
