#pragma once
// The prescribed displacements of the current time as one rank holds them: the value of each
// displacement dof that its rows and columns reach, NaN where the dof is free. No rank holds
// an array of the whole mesh's size (docs/design.md, "The distributed mesh").
//
// Held dofs: the solid's column map (owned dofs first, then one ghost layer), and the dofs that
// contact adds beyond that layer (cover): the nodes of the master faces its slave faces are
// paired with, and the columns of the Jacobian's contact entries. The owned values come from
// the solid (SolidProblem::prescribed_displacements, the Dirichlet sets of its nodes at time
// t); every held value is then imported from the dof's owner (a Tpetra Import from the owned
// map onto the held one), so that a dof held by several ranks has the owner's value bit for
// bit. The held set only grows: once a run's contact nodes are covered, later steps import
// over the same Import.
//
// Size per rank: owned + ghost dofs plus the contact nodes' dofs it reaches, O(local part +
// local contact surface); without contact exactly the solid's column map.

#include <Teuchos_RCP.hpp>
#include <cmath>
#include <vector>

#include "assembly/tpetra_types.hpp"

namespace grout {

class PrescribedValues {
 public:
  /// `owned`: the solid's owned displacement dofs; `column`: its column map (owned first).
  /// Holds the column map's dofs, all free until set(). Collective.
  PrescribedValues(Teuchos::RCP<const Map> owned, Teuchos::RCP<const Map> column);

  /// The values of a new time: `column_values` per dof of the column map given to the
  /// constructor (NaN where free); only its owned entries are read, the rest is imported.
  /// Collective.
  void set(const std::vector<double>& column_values);
  /// Holds `dofs` (displacement dofs, any order, repeats allowed) too, their values imported
  /// from their owners. Collective: every rank calls it, with its own dofs.
  void cover(std::vector<GO> dofs);

  bool holds(GO dof) const { return held_->isNodeGlobalElement(dof); }
  /// The value of a held dof (NaN: free). Throws std::logic_error for a dof not held.
  double value(GO dof) const;
  bool fixed(GO dof) const { return !std::isnan(value(dof)); }
  /// Number of held dofs (owned + ghost + contact nodes beyond the ghost layer).
  std::size_t size() const { return values_.size(); }
  /// The held dofs (owned first, in the owned map's order).
  const Teuchos::RCP<const Map>& held_map() const { return held_; }

 private:
  void import_values();

  Teuchos::RCP<const Map> owned_, held_;
  Teuchos::RCP<Import> import_;        ///< owned -> held
  Teuchos::RCP<Vector> owned_values_;  ///< the owned dofs' values of the current time
  std::vector<double> values_;         ///< per held dof (held_'s local index)
};

}  // namespace grout
