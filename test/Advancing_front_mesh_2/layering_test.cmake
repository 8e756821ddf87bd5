# The layers of the package (doc: "Code map" in the user manual): a header
# may include the package's headers of its own layer and of lower layers,
# never of a higher one. The headers beside the mesher (IO, quality,
# smoothing, the Poisson field) may include layer 0 and each other, never the
# mesher's layers 1-6; layer 7 (parallel meshing) may include all of them. A
# header without a layer fails the test too, so a new
# one must be placed here.
#
#   cmake -DINCLUDE_DIR=<repository>/include -DWORK_DIR=<scratch> -P layering_test.cmake
#
# The test first checks itself on a scratch tree with one violation, which
# it must find.

set(AFM_LAYERS
  # L0: helpers and the public types the mesher uses
  "0 CGAL/license/Advancing_front_mesh_2.h"
  "0 CGAL/Advancing_front_mesh_2/Checkpoint_error.h"
  "0 CGAL/Advancing_front_mesh_2/Checkpoint_info.h"
  "0 CGAL/Advancing_front_mesh_2/Default_visitor.h"
  "0 CGAL/Advancing_front_mesh_2/Mesh_return_code.h"
  "0 CGAL/Advancing_front_mesh_2/Mesh_sink_2.h"
  "0 CGAL/Advancing_front_mesh_2/Sizing_fields.h"
  "0 CGAL/Advancing_front_mesh_2/Statistics.h"
  "0 CGAL/Advancing_front_mesh_2/version.h"
  "0 CGAL/Advancing_front_mesh_2/internal/Binary_io.h"
  "0 CGAL/Advancing_front_mesh_2/internal/Compact_id_list.h"
  "0 CGAL/Advancing_front_mesh_2/internal/Coordinate_scaling.h"
  "0 CGAL/Advancing_front_mesh_2/internal/Double_geometry.h"
  "0 CGAL/Advancing_front_mesh_2/internal/Durable_files.h"
  "0 CGAL/Advancing_front_mesh_2/internal/Finished_faces_check.h"
  "0 CGAL/Advancing_front_mesh_2/internal/Flat_hash_map.h"
  "0 CGAL/Advancing_front_mesh_2/internal/Front_predicates.h"
  "0 CGAL/Advancing_front_mesh_2/internal/Lawson_flips.h"
  "0 CGAL/Advancing_front_mesh_2/internal/Phase_timer.h"
  "0 CGAL/Advancing_front_mesh_2/internal/Tree_storage.h"
  "0 CGAL/Advancing_front_mesh_2/internal/Segment_size_division.h"
  "0 CGAL/Advancing_front_mesh_2/split_constraints_to_size_2.h"
  "0 CGAL/Advancing_front_mesh_2/refine_to_minimum_angle_2.h"
  "0 CGAL/Advancing_front_mesh_2/internal/Strip_decomposition_2.h"
  "0 CGAL/Advancing_front_mesh_2/internal/Part_splicing_2.h"
  # L1: the search structures (models of the two concepts)
  "1 CGAL/Advancing_front_mesh_2/internal/Dynamic_point_quadtree.h"
  "1 CGAL/Advancing_front_mesh_2/internal/Lifted_circle_octree.h"
  "1 CGAL/Advancing_front_mesh_2/Kd_tree_point_index.h"
  "1 CGAL/Advancing_front_mesh_2/internal/Checkpoint_support.h"
  "1 CGAL/Advancing_front_mesh_2/internal/Front_hubs.h"
  "1 CGAL/Advancing_front_mesh_2/internal/Constraint_hubs.h"
  # L2: the shared state, step 3
  "2 CGAL/Advancing_front_mesh_2/internal/Refinement_context.h"
  "2 CGAL/Advancing_front_mesh_2/internal/Front_2.h"
  "2 CGAL/Advancing_front_mesh_2/internal/Size_bound.h"
  "2 CGAL/Advancing_front_mesh_2/internal/Streaming_state.h"
  # L3: the steps of the paper
  "3 CGAL/Advancing_front_mesh_2/internal/Front_triangles.h"
  "3 CGAL/Advancing_front_mesh_2/internal/Neighbourhood.h"
  "3 CGAL/Advancing_front_mesh_2/internal/Front_visibility.h"
  "3 CGAL/Advancing_front_mesh_2/internal/Delaunay_apex.h"
  "3 CGAL/Advancing_front_mesh_2/internal/Point_placement.h"
  "3 CGAL/Advancing_front_mesh_2/internal/Cavity.h"
  "3 CGAL/Advancing_front_mesh_2/internal/Pockets.h"
  "3 CGAL/Advancing_front_mesh_2/internal/Initial_front.h"
  # L4: section 4 of the paper, streaming and restarts
  "4 CGAL/Advancing_front_mesh_2/internal/Streaming_output.h"
  "4 CGAL/Advancing_front_mesh_2/internal/Checkpoint_io.h"
  # L5: the driver
  "5 CGAL/Advancing_front_mesh_2/internal/Advancing_front_refiner.h"
  "5 CGAL/Advancing_front_mesh_2/internal/Sizing_field_maker.h"
  # L6: the documented interface
  "6 CGAL/Advancing_front_mesher_2.h"
  # L7: built on the mesher and the tools beside it (the parts of a
  # decomposed domain meshed at once, their seams smoothed)
  "7 CGAL/Advancing_front_mesh_2/mesh_in_parallel_2.h"
  # beside the mesher
  "B CGAL/Advancing_front_mesh_2/Mesh_quality.h"
  "B CGAL/Advancing_front_mesh_2/Markers_and_regions_2.h"
  "B CGAL/Advancing_front_mesh_2/Region_sizing_field_2.h"
  "B CGAL/Advancing_front_mesh_2/Sampled_sizing_field_2.h"
  "B CGAL/Advancing_front_mesh_2/laplacian_smooth_mesh_2.h"
  "B CGAL/Advancing_front_mesh_2/Smoothing_statistics.h"
  "B CGAL/Advancing_front_mesh_2/internal/Laplacian_smoother.h"
  "B CGAL/Advancing_front_mesh_2/internal/Star_smoother.h"
  "B CGAL/Advancing_front_mesh_2/internal/Quality_smoother.h"
  "B CGAL/Advancing_front_mesh_2/internal/Interface_band_2.h"
  "B CGAL/Advancing_front_mesh_2/quality_smooth_mesh_2.h"
  "B CGAL/Advancing_front_mesh_2/Poisson_sizing_field_2.h"
  "B CGAL/Advancing_front_mesh_2/Sizing_field_mesh_criteria_2.h"
  "B CGAL/Advancing_front_mesh_2/internal/Size_gradation_limiter.h"
  "B CGAL/Advancing_front_mesh_2/internal/Size_quadtree_2.h"
  "B CGAL/Advancing_front_mesh_2/internal/Size_quadtree_laplace_solver.h"
  "B CGAL/Advancing_front_mesh_2/IO/*")

# The layer of a header (relative to the include directory), or "" if none.
function(afm_layer_of header out)
  set(found "")
  foreach(entry ${AFM_LAYERS})
    string(REGEX MATCH "^([0-9B]) (.*)$" m "${entry}")
    set(layer ${CMAKE_MATCH_1})
    set(pattern ${CMAKE_MATCH_2})
    if(pattern MATCHES "\\*$")
      string(REGEX REPLACE "\\*$" "" prefix "${pattern}")
      string(FIND "${header}" "${prefix}" at)
      if(at EQUAL 0)
        set(found ${layer})
      endif()
    elseif(header STREQUAL pattern)
      set(found ${layer})
    endif()
  endforeach()
  set(${out} "${found}" PARENT_SCOPE)
endfunction()

# May a header of layer `from` include one of layer `to`?
function(afm_may_include from to out)
  if(from STREQUAL "B")
    if(to STREQUAL "B" OR to STREQUAL "0")
      set(${out} TRUE PARENT_SCOPE)
    else()
      set(${out} FALSE PARENT_SCOPE)
    endif()
  elseif(from STREQUAL "7")
    set(${out} TRUE PARENT_SCOPE)
  elseif(to STREQUAL "B")
    set(${out} FALSE PARENT_SCOPE)
  elseif(to GREATER from)
    set(${out} FALSE PARENT_SCOPE)
  else()
    set(${out} TRUE PARENT_SCOPE)
  endif()
endfunction()

# The violations in the headers under `root`, one message each.
function(afm_check_layers root out)
  set(problems "")
  file(GLOB_RECURSE headers RELATIVE "${root}" "${root}/*.h")
  foreach(header ${headers})
    afm_layer_of("${header}" layer)
    if(layer STREQUAL "")
      list(APPEND problems "${header}: no layer (add it to test/Advancing_front_mesh_2/layering_test.cmake)")
      continue()
    endif()
    file(STRINGS "${root}/${header}" includes REGEX "^[ \t]*#[ \t]*include[ \t]*[<\"]CGAL/(Advancing_front|license/Advancing_front)")
    foreach(line ${includes})
      string(REGEX REPLACE "^[ \t]*#[ \t]*include[ \t]*[<\"]([^>\"]+)[>\"].*$" "\\1" included "${line}")
      afm_layer_of("${included}" to)
      if(to STREQUAL "")
        list(APPEND problems "${header} (layer ${layer}) includes ${included}, which has no layer")
        continue()
      endif()
      afm_may_include(${layer} ${to} ok)
      if(NOT ok)
        list(APPEND problems "${header} (layer ${layer}) includes ${included} (layer ${to})")
      endif()
    endforeach()
  endforeach()
  set(${out} "${problems}" PARENT_SCOPE)
endfunction()

# the check must find a violation where there is one
set(fixture "${WORK_DIR}/layering_fixture")
file(REMOVE_RECURSE "${fixture}")
file(WRITE "${fixture}/CGAL/Advancing_front_mesh_2/internal/Front_2.h"
     "#include <CGAL/Advancing_front_mesh_2/internal/Cavity.h>\n#include <CGAL/Advancing_front_mesh_2/internal/Flat_hash_map.h>\n")
file(WRITE "${fixture}/CGAL/Advancing_front_mesh_2/internal/Cavity.h" "#include <CGAL/Advancing_front_mesh_2/internal/Front_2.h>\n")
file(WRITE "${fixture}/CGAL/Advancing_front_mesh_2/internal/Flat_hash_map.h" "\n")
afm_check_layers("${fixture}" fixture_problems)
list(LENGTH fixture_problems n)
if(NOT n EQUAL 1)
  message(FATAL_ERROR "the layering check found ${n} violations in its fixture, not 1: ${fixture_problems}")
endif()
file(REMOVE_RECURSE "${fixture}")

afm_check_layers("${INCLUDE_DIR}" problems)
if(problems)
  list(JOIN problems "\n  " text)
  message(FATAL_ERROR "layering violations:\n  ${text}")
endif()
file(GLOB_RECURSE all RELATIVE "${INCLUDE_DIR}" "${INCLUDE_DIR}/*.h")
list(LENGTH all count)
message(STATUS "layering: ${count} headers, every include goes to its own or a lower layer")
