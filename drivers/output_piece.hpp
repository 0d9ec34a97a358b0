#pragma once
// This rank's file of `output/parallel: per_rank` (docs/input.md): its own elements and the
// nodes they use, as a mesh in local numbering, with their place in the whole mesh (global
// ids, Nemesis I counts, border nodes and the ranks that share them).

#include "assembly/solid_problem.hpp"
#include "io/exodus.hpp"
#include "parallel/distributed_mesh.hpp"

namespace grout {

struct OutputPiece {
  Mesh mesh;           ///< the piece: every block and set of the mesh, possibly empty
  ExodusPiece exodus;  ///< node_ids ascending; element_ids as SolidProblem::owned_elements()
};

/// \brief Collective. The piece of this rank: the elements it owns (SolidProblem's partition),
/// the nodes they use and, on the rank that owns it, any node of no element (so that every
/// node is in some file); side-set entries of its elements and node-set entries of its
/// nodes. A node is a border node when another rank's file holds it too (found by asking
/// each node's owner who holds it); an element is a border element when it uses one.
/// `mesh`: the replicated mesh, or this rank's part of `distributed` (its sets' entries in
/// local numbers, taken to global ones by the part's maps; both give the same piece for the
/// same partition).
OutputPiece make_output_piece(const Mesh& mesh, const SolidProblem& solid,
                              const DistributedMesh* distributed = nullptr);

}  // namespace grout
