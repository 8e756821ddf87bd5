/*!
\ingroup PkgAdvancingFrontMesh2Concepts
\cgalConcept

The concept `AdvancingFrontMeshTraits_2` describes the geometric traits of the
constrained Delaunay triangulation that `CGAL::Advancing_front_mesher_2` and
`CGAL::advancing_front_mesh_2()` work on.

It refines `DelaunayMeshTraits_2`, the concept \ref PkgMesh2 "Mesh_2" requires,
because the mesher shares Mesh_2's domain marking and leaves the triangulation
in the state Mesh_2's tools expect. The types and functors listed below are
those the advancing front itself calls. Some are already required by the
refined concepts; they are listed again because every combinatorial decision
of the mesher (which side of a front edge a point is on, whether a point
breaks a circle, whether a segment leaves a front vertex into the unmeshed
region or crosses a front edge) rests on them, so their exactness is what makes
the mesher robust.

What is not required: the mesher uses none of the traits' constructions. New
points, circumcentres and distances are computed in double precision from
`CGAL::to_double()` of the coordinates, and new points are created from two
doubles; see the user manual (section "Kernels and Exactness") for why. This
is also why kernels without square roots, such as
`CGAL::Simple_cartesian<CGAL::Exact_rational>`, are models.

\cgalRefines{DelaunayMeshTraits_2}

\cgalHasModelsBegin
\cgalHasModels{CGAL::Exact_predicates_inexact_constructions_kernel}
\cgalHasModels{CGAL::Exact_predicates_exact_constructions_kernel}
\cgalHasModels{CGAL::Simple_cartesian<CGAL::Exact_rational>}
\cgalHasModelsEnd

More generally every \cgal 2D kernel is a model. The guarantees of the package
hold for kernels with exact predicates (the three above are tested); with
`CGAL::Simple_cartesian<double>` the mesher compiles and runs, but its decisions
may contradict each other near degeneracies.

\sa `DelaunayMeshTraits_2`
\sa `AdvancingFrontSizingField_2`
*/
class AdvancingFrontMeshTraits_2 {
public:

/// \name Types
/// @{

/*!
The number type. It must be constructible from `double` (a uniform size
given as a number is converted to it), and `CGAL::to_double()` must apply to
it (it is a model of `RealEmbeddable`): sizes and coordinates are read in
double precision for placement and for the search structures.
*/
typedef unspecified_type FT;

/*!
The point type. It must be constructible from two `double`s,
`Point_2(double x, double y)`: new points are created from their rounded
double coordinates, and the sizing field is evaluated at points created that
way. Its coordinates are accessed with `x()` and `y()`.
*/
typedef unspecified_type Point_2;

/*!
A predicate object with
`CGAL::Orientation operator()(const Point_2& p, const Point_2& q, const Point_2& r)`,
returning `CGAL::LEFT_TURN`, `CGAL::RIGHT_TURN` or `CGAL::COLLINEAR` as `r`
lies to the left of, to the right of, or on the line through `p` and `q`.

Used to keep candidate and new points strictly on the unmeshed side of a
front edge, to order directions about a front vertex (free sectors), to test
whether two segments cross, and to locate a new point with respect to the
front triangles whose circles it breaks.
*/
typedef unspecified_type Orientation_2;

/*!
A predicate object with
`CGAL::Oriented_side operator()(const Point_2& p, const Point_2& q, const Point_2& r, const Point_2& t)`,
returning `CGAL::ON_POSITIVE_SIDE` when `t` lies strictly inside the circle
through the counter-clockwise points `p`, `q` and `r`.

Used by Merriam's iteration (steps 5 and 11), by the search for broken
triangles (steps 7 and 8) and by the final Lawson check.
*/
typedef unspecified_type Side_of_oriented_circle_2;

/*!
A predicate object with
`CGAL::Angle operator()(const Point_2& p, const Point_2& q, const Point_2& r)`,
returning `CGAL::OBTUSE`, `CGAL::RIGHT` or `CGAL::ACUTE` as the angle at `q`
between `qp` and `qr` is.

Used, for collinear directions, to tell a direction from its opposite when
ordering directions about a front vertex and when deciding whether two
segments from a common end point overlap.
*/
typedef unspecified_type Angle_2;

/*!
A predicate object with
`bool operator()(const Point_2& p, const Point_2& q, const Point_2& r)`,
returning `true` when `q` lies on the closed segment `[p, r]`, for collinear
`p`, `q` and `r`.

Used to decide whether collinear segments overlap (visibility).
*/
typedef unspecified_type Collinear_are_ordered_along_line_2;

/*!
A predicate object with
`bool operator()(const Point_2& p, const Point_2& q, const Point_2& r)`,
returning `true` when `q` lies strictly between `p` and `r`, for collinear
`p`, `q` and `r`.

Used to reject a segment that passes through a vertex (visibility).
*/
typedef unspecified_type Collinear_are_strictly_ordered_along_line_2;

/// @}

/// \name Access to Predicate Objects
/// @{

/*!
returns the orientation predicate.
*/
Orientation_2 orientation_2_object() const;

/*!
returns the in-circle predicate.
*/
Side_of_oriented_circle_2 side_of_oriented_circle_2_object() const;

/*!
returns the angle predicate.
*/
Angle_2 angle_2_object() const;

/*!
returns the predicate for the order of collinear points.
*/
Collinear_are_ordered_along_line_2 collinear_are_ordered_along_line_2_object() const;

/*!
returns the predicate for the strict order of collinear points.
*/
Collinear_are_strictly_ordered_along_line_2 collinear_are_strictly_ordered_along_line_2_object() const;

/// @}

}; /* end AdvancingFrontMeshTraits_2 */
