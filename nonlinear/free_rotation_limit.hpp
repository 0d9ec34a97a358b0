#pragma once
// The Newton step's limit on a free rigid rotation of a contact body (quasi-static,
// frictionless contact): a step may slide the body's contact nodes by a rigid rotation that
// nothing else holds by at most a tenth of the mean slave face size h.
//
// Why. A body held only on a line through its centre and pressed onto another by
// frictionless contact (a half disc loaded on its flat edge, held there in x) has a rigid
// rotation that moves none of its prescribed dofs and moves its contact nodes along the
// contact surface. No gap row sees it where the slave normals are radial, and the tangential
// hold of the Newton matrix (contact_rows.cpp) resists it only by κ (E/h) D_jj, κ = 1e-11. An
// iterate whose active set is not yet the final one exerts a moment about the body's centre,
// and the step turned the body by that moment over the hold: 1.4 rad in one step
// (inputs/start_family/README.md, random_094). The converged state keeps such a rotation, and
// it is not harmless: with the reference geometry (small strain) a slave node is paired with
// the master faces near it in the reference and in the current configuration (bounding boxes
// grown by half a face), so a slide of the slave surface by a face or more leaves the nodes at
// the edge of the contact zone without a master; the zone then stops at the last paired node,
// which carries a pressure spike (random_094: b 8 % above Hertz).
//
// What. For each slave body of a frictionless pair (the connected components of elements
// that hold its slave faces, io/mesh_bodies.hpp, unless a tied, frictional or self-contact
// pair also touches them; not for a self-contact pair itself), with G and P the
// Gram matrices of its rigid modes over all and over its prescribed dofs (reference
// coordinates, kernels/free_rigid_modes.hpp): if a free rigid mode turns the body, the step δ
// is fitted with rigid modes over the body (β = G⁻¹b), its free part β_f taken, and of that
// the rigid motion w = β_f − τ that moves the contact nodes least along their normals (τ
// along the free translations only: the approach of the body is not touched). The contact
// nodes are the active slave nodes, or all slave nodes where none is active. If w slides a
// contact node by s > h/10, the step loses (1 − h/(10 s)) w on the body's free dofs. Only the
// step changes: F, J and the converged state do not. A Newton step near convergence turns
// such a body by far less (random_094: below 1e-3 h), so the final iterations are untouched;
// removing w altogether stalls Newton (random_094: |F| stays at 1.3), since the step's rigid
// fit also holds part of its deformation.

#include <array>
#include <vector>

#include "assembly/contact_mesh.hpp"
#include "assembly/tpetra_types.hpp"
#include "io/input.hpp"
#include "io/mesh.hpp"
#include "kernels/free_rigid_modes.hpp"

namespace grout {

/// A slave node that stands for the contact, with its unit normal.
struct ContactNode {
  GlobalIndex node = 0;
  double normal[3] = {0.0, 0.0, 0.0};
  double X[3] = {0.0, 0.0, 0.0};  ///< reference coordinates
};

class FreeRotationLimit {
 public:
  /// The slave bodies of the frictionless pairs of `input` (see above) on the replicated mesh
  /// or this rank's part of the distributed one (each body's owned nodes; the sums over a
  /// body are then summed over the ranks); `map` is the problem's (u dofs node * dim + c
  /// first); `slave_face_size` the mean slave face size of each pair. Collective.
  FreeRotationLimit(const ContactMesh& mesh, const Input& input, Teuchos::RCP<const Map> map,
                    const std::vector<double>& slave_face_size);
  /// The same on the replicated mesh, with the slave face sizes of its side sets.
  FreeRotationLimit(const Mesh& mesh, const Input& input, Teuchos::RCP<const Map> map);

  /// Limits `step` (the Newton step, on the problem's map) with, per contact pair of the
  /// input, the active slave nodes this rank owns (`active`) and all slave nodes it owns
  /// (`owned_slave`). Collective. The prescribed dofs are those of the input's Dirichlet sets
  /// (whatever their values). Returns the largest slide s/h over the bodies before the limit
  /// (0: no free rotation).
  double limit(const std::vector<std::vector<ContactNode>>& active,
               const std::vector<std::vector<ContactNode>>& owned_slave, Vector& step) const;

  /// The largest slide per Newton step, in units of the mean slave face size.
  static constexpr double max_slide_per_step = 0.1;
  /// The bodies found (for tests).
  int num_bodies() const { return int(bodies_.size()); }

 private:
  struct Body {
    int pair = 0;                            ///< index in the input's contact list
    std::vector<GlobalIndex> nodes;          ///< sorted (on a distributed part: the owned ones)
    std::vector<std::array<double, 3>> X;    ///< their reference coordinates
    std::vector<std::array<char, 3>> fixed;  ///< their prescribed components (Dirichlet sets)
    double X0[3] = {0.0, 0.0, 0.0};          ///< centroid of the nodes
    double L = 1.0;                          ///< RMS distance of the nodes from X0
    double h = 0.0;                          ///< mean slave face size
  };
  double limit_body(const Body& body, const std::vector<ContactNode>& contact, Vector& step) const;

  int dim_ = 2;
  bool distributed_ = false;
  Teuchos::RCP<const Map> map_;
  std::vector<Body> bodies_;
};

}  // namespace grout
