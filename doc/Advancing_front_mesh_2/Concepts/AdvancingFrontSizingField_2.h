/*!
\ingroup PkgAdvancingFrontMesh2Concepts
\cgalConcept

A sizing field gives the <em>target edge length</em> `h` at a point of the
domain. `CGAL::Advancing_front_mesher_2` evaluates it once for every front edge
it processes, at the edge's midpoint (step 3 of Mavriplis's algorithm), and
bounds the circumradius of the triangles it builds there by
`rho = h / sqrt(3)`, the circumradius of the equilateral triangle of side `h`:
new points are placed for triangles of circumradius `rho`, triangles on
existing points are accepted up to `1.25 rho`.

In the signature below, `FT` and `Point_2` are the number and point types of
the geometric traits of the triangulation being meshed. A model need not
define them: any function object callable that way is a model, in particular
a lambda, a `std::function<FT(const Point_2&)>`, or Mesh_2's
`CGAL::Lipschitz_sizing_field_2`.

Since input segments are never split, the field should agree with the
boundary discretization near the boundary, and grow away from it at a bounded
rate; the mesher remains valid for any positive field, including
discontinuous ones, only the quality of the triangles suffers where the field
and the boundary disagree or where the field varies faster than the mesh can
follow.

The mesher keeps its own copy of the field (copy-constructible); a field
holding large data should hold it through a (shared) pointer.

\cgalRefines{CopyConstructible}

\cgalHasModelsBegin
\cgalHasModels{CGAL::Advancing_front_mesh_2::Uniform_sizing_field_2<GeomTraits>}
\cgalHasModels{CGAL::Advancing_front_mesh_2::Size_criteria_sizing_field_2<Criteria, GeomTraits>}
\cgalHasModels{CGAL::Advancing_front_mesh_2::Poisson_sizing_field_2<GeomTraits>}
\cgalHasModels{CGAL::Lipschitz_sizing_field_2<Tr>}
\cgalHasModelsEnd

\sa `CGAL::advancing_front_mesh_2()`, which also accepts a plain number (a
uniform `h`) or a Mesh_2 size criteria object in place of a sizing field.
*/
class AdvancingFrontSizingField_2 {
public:

/// \name Operations
/// @{

/*!
returns the target edge length at `p`, or a value convertible to `FT`
(a `double` will do).

`p` is the midpoint of a front edge, created from two doubles; it lies in the
closed domain.

\pre the value is a positive finite number. This is checked: otherwise the
mesher throws `std::invalid_argument`, leaving the triangulation partially
meshed.
*/
FT operator()(const Point_2& p) const;

/// @}

}; /* end AdvancingFrontSizingField_2 */
