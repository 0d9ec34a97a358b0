#pragma once
// MueLu smoothed aggregation set up for small-strain elasticity (the displacement-only
// system: no contact, or the condensed one of nonlinear/condensed_solve.hpp).
// Compiled into the module grout_iterative (nonlinear/iterative_solver.hpp), not grout_nonlinear.
//
// - block size = dimension (`number of equations`): the dofs of a node, n*dim + c, are
//   consecutive in every rank's row map, so MueLu aggregates nodes, not single dofs;
// - near-null space = the rigid-body modes of the nodal coordinates X (3 in 2D, 6 in 3D):
//   translations e_c and rotations ω × (X − X̄) about the centroid X̄ (Vaněk, Mandel &
//   Brezina 1996, "Algebraic multigrid by smoothed aggregation for second and fourth order
//   elliptic problems"). The condensed system keeps them as near-null vectors: the
//   equilibrium rows annihilate rigid motions, and a condensed gap or tie row
//   D_jj u_j − Σ_l M_jl u_l annihilates translations exactly (Σ_l M_jl = D_jj, dual
//   basis) and rotations to O(h);
// - prescribed dofs are identity rows (their columns eliminated): MueLu treats them as
//   Dirichlet rows, the modes keep their values there;
// - smoother, on each rank's rows: ILU(0) (Ifpack2 RILUK) on a system with contact or tie
//   multipliers (condensed): there it needs fewer iterations than symmetric Gauss–Seidel or
//   Chebyshev, whose counts grow more with the mesh (3D stacked blocks, 5.1e4 unknowns:
//   one Newton iteration of 18 GMRES iterations against two of 293 in all for one sweep of
//   SGS); Gauss–Seidel on a displacement-only system, whose set-up is the diagonal only
//   (ILU(0)'s set-up was 44 % of MueLu's; one sweep of symmetric Gauss–Seidel took 17–23 %
//   less CPU for the whole run and 18 % less memory at 2–5e5 unknowns in 3D for 2–3 more CG
//   iterations): one forward sweep before the coarse correction and one backward sweep
//   after, the V-cycle symmetric as CG needs (the backward sweep is the forward one's
//   adjoint), half the sweeps of symmetric Gauss–Seidel on both sides; at 1e6 unknowns on
//   2 ranks 36–37 CG iterations instead of 29, the Krylov phase 0.74× (docs/performance.md,
//   "Iterative solver"). The module replaces that Gauss–Seidel by damped Jacobi, whose
//   damping it estimates from the matrix (nonlinear/jacobi_smoother.hpp). A user's
//   `smoother: type` (or `smoother: pre type` and `post type`) replaces either;
// - coarse solve: KLU2 on one rank. On more ranks the coarse levels are repartitioned
//   (Zoltan2 multi-jagged on the node coordinates) onto ⌊rows / 2000⌋ ranks (at least one, so
//   the coarsest always onto one) with a subcommunicator,
//   where KLU2 is exact (Debian's KLU2 is wrong on a multi-rank communicator, docs/design.md,
//   "Toolchain notes"; relaxation as the coarse solve lets GMRES stall on the condensed 3D
//   systems). A system no larger than `coarse: max size` (Grout's default 500, MueLu's 2000) has no
//   coarse level: its one level is smoothed.
// - bodies kept apart in the aggregation: when the nodes belong to more than one body (the
//   connected components of the mesh, io/mesh_bodies.hpp), MueLu aggregates with the
//   distance-Laplacian graph of coordinates in which body b is moved by b·S along x
//   (S = 1000 × the mesh's bounding-box diagonal), `aggregation: drop tol` 1e-4: a link
//   between nodes of two bodies has a weight 1/S² against ≥ 1/(h²·n) inside a body, and is
//   dropped; links inside a body (aspect ratios below ~25) are kept. No aggregate then
//   spans a contact interface, so the coarse spaces can represent the jump of the tangential
//   displacement across it (an aggregate on both sides ties the two bodies together
//   rigidly, and that error is left to the smoother, at a cost growing like 1/h; measured in
//   docs/performance.md, "Iterative solver"). The contact coupling itself stays in every
//   coarse operator (Galerkin products with the whole matrix), and the prolongator is
//   smoothed with the whole matrix (`sa: use filtered matrix: false`: lumping the dropped
//   entries would leave a condensed gap row with the diagonal D_jj − Σ_l M_jl = 0), and the
//   Jacobi step of that smoothing divides by the absolute row sums Σ_j |A_ij|, not by A_ii
//   (`sa: use rowsumabs diagonal scaling`): a condensed row in the slot of a prescribed slave
//   dof (kind C of nonlinear/condensed_solve.hpp) can have a diagonal ~1e-6 of its row sum;
// Every default is only set when the user's `MueLu` sublist does not set that key.

#include <Teuchos_ParameterList.hpp>
#include <vector>

#include "assembly/tpetra_types.hpp"

namespace grout {

/// The rigid-body modes on `map`, whose GIDs are displacement dofs n*dim + c of the nodes
/// of `coordinates` (node-major x0 y0 [z0] x1 ...): every node on every rank when `nodes` is
/// null (the replicated mesh), else the nodes of the ascending ids `*nodes`, each rank those
/// of its rows (the distributed mesh; collective). 3 columns in 2D, 6 in 3D, the rotations
/// about the centroid of all nodes; `translations_only`: the `dim` translations alone.
/// Throws std::invalid_argument on a GID whose node is not given.
Teuchos::RCP<MultiVector> rigid_body_modes(const Map& map, int dim,
                                           const std::vector<double>& coordinates,
                                           const std::vector<GO>* nodes = nullptr,
                                           bool translations_only = false);

/// True if every GID of `map` (all ranks) is a displacement dof of the `num_nodes` nodes and
/// every rank owns whole nodes in node-major order (collective).
bool is_nodal_displacement_map(const Map& map, int dim, long long num_nodes);

/// Grout's MueLu defaults for elasticity, merged under the user's `muelu` entries, plus the
/// near-null space and the coordinates in `user data` (`muelu` is modified).
/// `separate_bodies`: the coordinates keep the bodies apart (node_coordinates), and the
/// aggregation drops the links between them. `multipliers`: the system holds contact or tie
/// multiplier rows (condensed), smoothed by ILU(0); without, forward Gauss–Seidel before
/// the coarse correction and backward after. Returns whether it set that Gauss–Seidel (no
/// multipliers, no smoother of the user's), which the module replaces by damped Jacobi.
bool set_elasticity_defaults(Teuchos::ParameterList& muelu, int dim, int num_ranks,
                             const Teuchos::RCP<MultiVector>& null_space,
                             const Teuchos::RCP<MultiVector>& node_coordinates,
                             bool separate_bodies = false, bool multipliers = true);

/// The coordinates of the nodes of a nodal displacement map (one row per node of `map`, in
/// its order): MueLu's `Coordinates` for the aggregation and the repartitioning.
/// `coordinates` and `nodes` as rigid_body_modes. With `bodies` (body index per node of
/// `coordinates`, as io/mesh_bodies.hpp; empty: one body) body b is moved by b·S along x,
/// S = 1000 × the bounding-box diagonal of all nodes.
Teuchos::RCP<MultiVector> node_coordinates(const Map& map, int dim,
                                           const std::vector<double>& coordinates,
                                           const std::vector<int>& bodies = {},
                                           const std::vector<GO>* nodes = nullptr);

}  // namespace grout
