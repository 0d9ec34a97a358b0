#pragma once
// The launch of contact_law.hpp over the slave nodes of an interface: each node's multiplier
// rows, status and row kinds, and optionally the rows' derivatives with respect to the node's
// law variables (ContactLawLayout) by AD (docs/design.md, "Contact conditions").

#include <Kokkos_Core.hpp>

#include "kernels/contact_law.hpp"

namespace grout {

/// \brief The contact law at every node, launch "grout::contact_law", one work item per node:
/// results(i) = contact_law(params, nodes(i), derivatives) (dC = 0 without derivatives).
/// \return false (and nothing launched) if results is shorter than nodes.
template <class ExecSpace>
bool evaluate_contact_law(
    const ExecSpace& space, const ContactLawParameters& params,
    Kokkos::View<const ContactLawNode*, typename ExecSpace::memory_space> nodes, bool derivatives,
    Kokkos::View<ContactLawResult*, typename ExecSpace::memory_space> results) {
  if (results.extent(0) < nodes.extent(0)) return false;
  Kokkos::parallel_for(
      "grout::contact_law", Kokkos::RangePolicy<ExecSpace>(space, 0, nodes.extent(0)),
      KOKKOS_LAMBDA(const int i) {
        ContactLawResult r;
        contact_law(params, nodes(i), derivatives, r);
        results(i) = r;
      });
  return true;
}

}  // namespace grout
