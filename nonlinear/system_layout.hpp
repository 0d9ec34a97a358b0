#pragma once
// The layout of a linear system K x = b that the matrix alone does not tell: which unknowns are
// contact multipliers and which slave dofs carry them, where the nodes are, and which body each
// node belongs to. LinearSolver takes it at construction (nonlinear/linear_solver.hpp): it picks
// the direct solver by the dimension, condenses the multipliers with the pairing, and builds the
// iterative path's rigid-body near-null space and body-separating aggregation from the
// coordinates and the bodies.

#include <utility>
#include <vector>

#include "assembly/tpetra_types.hpp"

namespace grout {

class MechanicsProblem;
struct Mesh;

struct SystemLayout {
  /// (λ GID, slave u GID) of every multiplier dof, the same complete list on every rank
  /// (MechanicsProblem::multiplier_pairing). Empty: no multipliers; the system is solved as
  /// given even with `condense_multipliers: true`.
  std::vector<std::pair<GO, GO>> multiplier_pairing;
  /// Slave dofs s of one node share s / dofs_per_node (the mesh dimension for Grout's maps:
  /// node · dim + component).
  int dofs_per_node = 1;
  /// Node coordinates, node-major x0 y0 [z0] x1 ...: every node on every rank (the replicated
  /// mesh), or the nodes of `nodes` (the distributed mesh: each rank its owned nodes, whose
  /// dofs are its rows). Empty: the iterative path's MueLu has no rigid-body near-null space
  /// (its defaults apply).
  std::vector<double> coordinates;
  /// Global ids of the nodes of `coordinates` and `node_bodies`, ascending. Empty: every node,
  /// 0, 1, ... (the replicated mesh).
  std::vector<GO> nodes;
  /// The mesh's node count, all ranks; 0: the nodes of `coordinates` (the replicated mesh).
  long long num_global_nodes = 0;
  /// Spatial dimension of `coordinates`. 0: unknown; `type: auto` then picks as in 2D. In 3D
  /// without it a system goes to KLU2, whose 3D factorisations are 20-80x slower than MUMPS's
  /// (docs/performance.md).
  int dim = 0;
  /// Body index of every node of `coordinates` (io/mesh_bodies.hpp). Empty, or (replicated)
  /// every node in one body: one body. With several, the iterative path's aggregation keeps
  /// the bodies apart (elasticity_preconditioner.hpp). With `nodes` it is empty on every rank
  /// or on none (a rank whose nodes are all in one body may be one of several bodies).
  std::vector<int> node_bodies;
};

/// The layout of the Newton systems of `problem` on `mesh`: its multiplier pairing with
/// mesh.dimension dofs per node, the mesh's coordinates and dimension, and its bodies
/// (io/mesh_bodies.hpp). Collective (MechanicsProblem::multiplier_pairing).
SystemLayout system_layout(const MechanicsProblem& problem, const Mesh& mesh);
/// The same with the pairing given: (λ GID, slave u GID) of every multiplier dof, the same
/// complete list on every rank.
SystemLayout system_layout(std::vector<std::pair<GO, GO>> multiplier_pairing, const Mesh& mesh);

/// The layout of the mass-matrix systems on `mesh` (displacements only): coordinates and
/// dimension, no multipliers and no bodies (the mass matrix has no entry between two bodies).
SystemLayout mass_matrix_layout(const Mesh& mesh);

}  // namespace grout
