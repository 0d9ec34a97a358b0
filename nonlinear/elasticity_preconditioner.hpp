#pragma once
// MueLu smoothed aggregation set up for small-strain elasticity (the displacement-only
// system: no contact, or the condensed one of nonlinear/condensed_solve.hpp).
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
// - smoother: ILU(0) (Ifpack2 RILUK, on each rank's rows). On the condensed contact
//   systems it needs fewer iterations than symmetric Gauss–Seidel or Chebyshev, whose
//   counts grow more with the mesh (docs/performance.md, "Iterative solver"); a user's
//   `smoother: type` replaces it;
// - coarse solve: KLU2 on one rank. On more ranks the coarse levels are repartitioned
//   (Zoltan2 multi-jagged on the node coordinates) onto one rank with a subcommunicator,
//   where KLU2 is exact (Debian's KLU2 is wrong on a multi-rank communicator, TOOLCHAIN.md;
//   relaxation as the coarse solve lets GMRES stall on the condensed 3D systems). A system
//   no larger than `coarse: max size` has no coarse level: its one level is smoothed.
// Every default is only set when the user's `MueLu` sublist does not set that key.

#include <Teuchos_ParameterList.hpp>
#include <vector>

#include "assembly/tpetra_types.hpp"

namespace grout {

/// The rigid-body modes on `map`, whose GIDs are displacement dofs n*dim + c of the nodes
/// of `coordinates` (node-major x0 y0 [z0] x1 ..., every node on every rank): 3 columns in
/// 2D, 6 in 3D. Throws std::invalid_argument on a GID beyond the nodes.
Teuchos::RCP<MultiVector> rigid_body_modes(const Map& map, int dim,
                                           const std::vector<double>& coordinates);

/// True if every GID of `map` (all ranks) is a displacement dof of the `num_nodes` nodes and
/// every rank owns whole nodes in node-major order (collective).
bool is_nodal_displacement_map(const Map& map, int dim, long long num_nodes);

/// Grout's MueLu defaults for elasticity, merged under the user's `muelu` entries, plus the
/// near-null space in `user data` (`muelu` is modified).
void set_elasticity_defaults(Teuchos::ParameterList& muelu, int dim, int num_ranks,
                             const Teuchos::RCP<MultiVector>& null_space,
                             const Teuchos::RCP<MultiVector>& node_coordinates);

/// The coordinates of the nodes of a nodal displacement map (one row per node of `map`, in
/// its order): MueLu's `Coordinates` for repartitioning.
Teuchos::RCP<MultiVector> node_coordinates(const Map& map, int dim,
                                           const std::vector<double>& coordinates);

}  // namespace grout
