/*!
\ingroup PkgAdvancingFrontMesh2Concepts
\cgalConcept

The close-point search of step 4 of Mavriplis's algorithm (the paper's
quadtree of front points): a dynamic set of points named by dense integer
ids, searched by disk. `CGAL::Advancing_front_mesher_2` keeps in it the
<em>active</em> vertices, those on the front and the free points, with their
internal coordinates (doubles, the user's divided by a power of two); ids are
reused once a vertex lies behind the front, and renumbered densely now and
then (`renumber()`).

Each point also carries a <em>reach</em>, a non-negative length: the mesher
sets a front vertex's reach to the length of its longest outgoing front edge,
so that a search that also reports the points within the radius plus their
reach leads, through their outgoing edges, to every front edge near the disk
(the visibility tests need them). One search per front edge thus finds both
the candidate points and the front edges that may block them.

Coordinates are doubles and the answers of a model may include a few points
slightly beyond the disk (a padding of about 1e-9 relative and 1e-12 of the
coordinates' magnitude): every decision on the points it reports is taken by
the mesher with the kernel's exact predicates. What a model must never do is
miss a point within the disk, or within the radius plus its reach. The
order of the answers breaks the mesher's ties: a mesher is deterministic for
a given model, and two models may give different (equally valid) meshes.

A model that can also be saved and loaded (`save()` and `load()` below) lets
the mesher write checkpoints; with any other model
`Advancing_front_mesher_2::supports_checkpoints` is false and
`set_checkpoint()`, `write_checkpoint()` and `resume()` throw
`std::logic_error`.

\cgalHasModelsBegin
\cgalHasModels{CGAL::Advancing_front_mesh_2::Kd_tree_point_index (CGAL's Kd_tree with Fuzzy_sphere queries; it cannot be saved)}
\cgalHasModelsEnd

The default model, chosen by `CGAL::Default`, is the package's internal
dynamic point quadtree (`internal::Dynamic_point_quadtree`, not part of the
documented interface): a bucketed point-region quadtree with O(1) removal and
a reach bound per node; it can be saved. The tests add a brute-force model (`test/Advancing_front_mesh_2/include/afm_brute_force_indices.h`),
the oracle the mesher's test suite also runs with.

\sa `AdvancingFrontCircleIndex_2`
*/
class AdvancingFrontPointIndex_2 {
public:

/// \name Creation
/// @{

/// an empty index
AdvancingFrontPointIndex_2();

/// @}

/// \name Operations
/// @{

/*!
empties the index. The points to come lie in the box
`[xmin, xmax] x [ymin, ymax]` (nearly all of them: the mesher's new points
lie in the domain); `leaf_size` is a tuning hint for hierarchical models,
the number of points a leaf holds before it is divided (the mesher passes 16,
measured best for the default quadtree), which other models may ignore.
*/
void reset(double xmin, double ymin, double xmax, double ymax, std::size_t leaf_size);

/// empties the index
void clear();

/// adds the point `id` at `(x, y)` with reach 0; does nothing if `id` is held
void insert(std::size_t id, double x, double y);

/// removes the point `id`; does nothing if it is not held
void remove(std::size_t id);

/// whether the point `id` is held
bool contains(std::size_t id) const;

/// the number of points held
std::size_t size() const;

/*!
sets the reach of the point `id` (a non-negative length; NaN counts as
infinite).
\pre `contains(id)`
*/
void set_reach(std::size_t id, double reach);

/*!
the reach of the point `id`.
\pre `contains(id)`
*/
double reach(std::size_t id) const;

/*!
calls `f(id, px, py, in_disk)` for every point within `radius` plus its
reach of `(x, y)`, with `in_disk` true when it is within `radius`; both
distances may be padded slightly. Points with non-finite coordinates are
reported as in the disk.
*/
template <class Function>
void query_with_reach(double x, double y, double radius, Function f) const;

/*!
renames the points: the point `id` becomes `new_id[id]` (an id not held is
not read). The new ids are distinct. The model may release the memory it
held for a larger set here.
*/
template <class Id_map>
void renumber(const Id_map& new_id);

/// @}

/// \name Checkpoints (optional)
/// The streams are the package's internal binary checkpoint streams, which
/// have no stable interface yet: only the package's own models support
/// checkpoints; a model written elsewhere leaves these two out.
/// @{

/*!
writes the whole state of the index, such that after `load()` every
sequence of operations behaves exactly as on the saved index (answers in the
same order).
*/
void save(CGAL::Advancing_front_mesh_2::internal::Binary_writer& w) const;

/*!
replaces the index by one written by `save()`; throws (through `r.fail()`)
and leaves the index unchanged when the data is not a consistent index.
*/
void load(CGAL::Advancing_front_mesh_2::internal::Binary_reader& r);

/// @}

}; /* end AdvancingFrontPointIndex_2 */
