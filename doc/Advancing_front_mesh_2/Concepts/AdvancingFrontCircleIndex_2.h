/*!
\ingroup PkgAdvancingFrontMesh2Concepts
\cgalConcept

A dynamic set of circles, each with a payload, searched for the circles that
contain a point or come near it: the paper's octree over lifted circles
`(x, y, r)` (section 5 and Fig. 11 of Mavriplis's algorithm).
`CGAL::Advancing_front_mesher_2` holds two of them: the circumcircles of the
front triangles (payload: the face handle), in which step 7 finds the
triangles a new point breaks, and the input constraints as diametral circles
(payload: the pair of their end vertices), which decide whether a new point
sees a broken triangle. It names the model for each payload through
`Rebind_payload`, as a triangulation data structure rebinds its vertex and
face bases; the payload the mesher's template argument is declared with does
not matter (`Lifted_circle_octree<>` will do).

Coordinates are doubles; a query may report a few circles slightly beyond
the point (padding of about 1e-9 relative and 1e-12 of the coordinates'
magnitude), and circles with non-finite values are always reported: the
mesher decides with the kernel's exact predicates. A query must never miss
a circle that contains the point (or comes within the inflated distance).
Its order breaks the mesher's ties.

A model that can be saved and loaded (`save()` and `load()` below) lets the
mesher write checkpoints; otherwise `Advancing_front_mesher_2::supports_checkpoints`
is false.

The default model, chosen by `CGAL::Default`, is the package's internal
lifted circle octree (`internal::Lifted_circle_octree`, not part of the
documented interface): a region octree over the lifted circles, which divides
the radius axis only where a leaf's radii differ; it can be saved. The tests
add a brute-force model (`test/Advancing_front_mesh_2/include/afm_brute_force_indices.h`),
the oracle the mesher's test suite also runs with.

\sa `AdvancingFrontPointIndex_2`
*/
class AdvancingFrontCircleIndex_2 {
public:

/// \name Creation
/// @{

/// an empty index (the mesher calls `reset()` before the first insertion)
AdvancingFrontCircleIndex_2();

/// @}

/// \name Types
/// @{

/// what a circle carries (default constructible and copyable)
typedef unspecified_type Payload;

/// the name of a circle held: `std::size_t` (the mesher stores the ids of
/// its circles as `std::size_t` and passes them back)
typedef std::size_t Item_id;

/// the same model for payload `P`, in `Rebind_payload<P>::Other`
template <class P>
struct Rebind_payload { typedef unspecified_type Other; };

/// @}

/// \name Operations
/// @{

/*!
empties the index. The circles to come have their centres in the box
`[xmin, xmax] x [ymin, ymax]` and radii up to `rmax` (nearly all of them);
`leaf_size` is a tuning hint for hierarchical models (the mesher passes 32
for the front triangles and 16 for the constraints, measured best for the
default octree), which other models may ignore.
*/
void reset(double xmin, double ymin, double xmax, double ymax, double rmax, std::size_t leaf_size);

/// adds the circle of centre `(cx, cy)` and radius `r`; returns its id
Item_id insert(double cx, double cy, double r, const Payload& p);

/*!
removes a circle. Its id may be returned again by a later insertion.
\pre `is_alive(id)`
*/
void remove(Item_id id);

/// the number of circles held (not called by the mesher; for tests and
/// diagnostics)
std::size_t size() const;

/// whether `id` names a circle held
bool is_alive(Item_id id) const;

/// the payload of a circle held
const Payload& payload(Item_id id) const;

/// calls `f(payload)` for every circle held
template <class Function>
void for_each_payload(Function f) const;

/*!
calls `f(payload)` for every circle with `|q - c| < r + inflate`, `q = (qx, qy)`
(padded slightly): with `inflate == 0` the circles containing `q`, otherwise
those meeting the disk of radius `inflate` about `q`.
*/
template <class Function>
void query(double qx, double qy, double inflate, Function f) const;

/*!
whether the memory the index holds is mostly left over from a time when it
held more circles; the mesher then calls `rebuild()`.
*/
bool is_sparse() const;

/*!
rebuilds the index for the circles it holds, in memory proportional to their
number; the circles get new ids, and `renamed(payload, new_id)` is called for
each.
*/
template <class Renamed>
void rebuild(Renamed renamed);

/// releases spare capacity (the constraints' index never grows again)
void shrink_to_fit();

/// @}

/// \name Checkpoints (optional)
/// The streams are the package's internal binary checkpoint streams, which
/// have no stable interface yet: only the package's own models support
/// checkpoints; a model written elsewhere leaves these two out.
/// @{

/*!
writes the whole state of the index, such that after `load()` every
sequence of operations behaves exactly as on the saved index;
`write_payload(w, payload)` writes the payload of a circle held.
*/
template <class PayloadWriter>
void save(CGAL::Advancing_front_mesh_2::internal::Binary_writer& w, PayloadWriter write_payload) const;

/*!
replaces the index by one written by `save()`, `read_payload(r)` returning a
payload written by `write_payload`; throws (through `r.fail()`) and leaves
the index unchanged when the data is not a consistent index.
*/
template <class PayloadReader>
void load(CGAL::Advancing_front_mesh_2::internal::Binary_reader& r, PayloadReader read_payload);

/// @}

}; /* end AdvancingFrontCircleIndex_2 */
