/*!
\ingroup PkgAdvancingFrontMesh2Concepts
\cgalConcept

A visitor is told by `CGAL::Advancing_front_mesher_2` what happens during a
run: for progress reports, animations, instrumentation or to attach data to
new vertices and faces. The hooks are called statically (no virtual
functions), so a visitor whose hooks are empty costs nothing; derive from
`CGAL::Advancing_front_mesh_2::Default_visitor` and redefine only the hooks
needed.

In the signatures below, `Vertex_handle` and `Face_handle` are the handle
types of the triangulation being meshed.

<b>The triangulation during the run.</b> Between `on_init()` and the end of
the run, the triangulation data structure is partial: the in-domain faces
were deleted and only the faces behind the front exist. The hooks may read
the vertices and faces they are given (points, vertices of a face, constraint
and domain flags), but must not use the triangulation's own functions
(`locate()`, `insert()`, `is_valid()`, iteration over faces), nor modify the
triangulation.

The mesher keeps its own copy of the visitor; it is available through
`Advancing_front_mesher_2::visitor()`. `CGAL::advancing_front_mesh_2()` copies
the visitor given as a named parameter and does not return it: a visitor used
there should keep what it gathers behind a pointer or a reference.

\cgalRefines{CopyConstructible}

\cgalHasModelsBegin
\cgalHasModels{CGAL::Advancing_front_mesh_2::Default_visitor}
\cgalHasModelsEnd
*/
class AdvancingFrontMeshVisitor_2 {
public:

/// \name Operations
/// @{

/*!
called once by `init()`, after the domain has been marked from the seeds,
the in-domain faces removed and the initial front built. `mesher` is the
`CGAL::Advancing_front_mesher_2` that calls the visitor; its `front_size()`
and `statistics()` may be read.
*/
template <class Mesher>
void on_init(const Mesher& mesher);

/*!
called when a point placed ahead of the front (step 6) has been accepted and
its vertex `v` created: after the triangles whose circumcircles it breaks have
been removed (steps 7-9, reported by `on_face_removed()`), before the
triangles about it are built (steps 11-12, reported by `on_face_created()`).
*/
void on_point_inserted(Vertex_handle v);

/*!
called after the face `f` has been created, counter-clockwise and flagged
in the domain. Its neighbours on the unmeshed side are not set yet.

A face can be removed again later, when a new point breaks its circumcircle
(`on_face_removed()`). When a placed point is rejected, the faces removed
for it are created again, and reported again by this function.
*/
void on_face_created(Face_handle f);

/*!
called just before the face `f` is removed because a new point lies
strictly inside its circumcircle (steps 7-9). The new point may still be
rejected by the tests of step 6; then the face is created again (a new face,
reported by `on_face_created()`) and no `on_point_inserted()` follows.
*/
void on_face_removed(Face_handle f);

/*!
streaming mode only (`CGAL::Advancing_front_mesher_2::set_output_sink()`):
called for a finished face `f`, one that no later point is expected to
break, just before it is handed to the sink and removed from the
triangulation. Its vertices and constraint flags may be read; its
neighbours may already be gone.
*/
void on_face_finished(Face_handle f);

/*!
called after each front edge processed by the advancing front, with the
fraction of the domain's area covered by triangles so far, in `[0, 1]`.
*/
void on_progress(double fraction);

/// @}

}; /* end AdvancingFrontMeshVisitor_2 */
