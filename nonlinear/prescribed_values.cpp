#include "nonlinear/prescribed_values.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>

namespace grout {

namespace {
constexpr double free_value = std::numeric_limits<double>::quiet_NaN();
}

PrescribedValues::PrescribedValues(Teuchos::RCP<const Map> owned, Teuchos::RCP<const Map> column)
    : owned_(std::move(owned)), held_(std::move(column)) {
  const std::size_t n_owned = owned_->getNodeNumElements();
  if (held_->getNodeNumElements() < n_owned)
    throw std::logic_error("PrescribedValues: the column map lacks owned dofs");
  for (std::size_t i = 0; i < n_owned; ++i)
    if (held_->getGlobalElement(LO(i)) != owned_->getGlobalElement(LO(i)))
      throw std::logic_error("PrescribedValues: the column map does not begin with the owned dofs");
  import_ = Teuchos::rcp(new Import(owned_, held_));
  owned_values_ = Teuchos::rcp(new Vector(owned_));
  owned_values_->putScalar(free_value);
  values_.assign(held_->getNodeNumElements(), free_value);
}

void PrescribedValues::set(const std::vector<double>& column_values) {
  {
    auto v = owned_values_->getLocalViewHost(Tpetra::Access::OverwriteAll);
    for (std::size_t i = 0; i < v.extent(0); ++i) v(i, 0) = column_values.at(i);
  }
  import_values();
}

void PrescribedValues::import_values() {
  Vector held(held_);
  held.putScalar(free_value);  // a dof no rank owns (no element's node) stays free
  held.doImport(*owned_values_, *import_, Tpetra::INSERT);  // copies: bit for bit
  const auto v = held.getLocalViewHost(Tpetra::Access::ReadOnly);
  values_.assign(v.data(), v.data() + v.extent(0));
}

void PrescribedValues::cover(std::vector<GO> dofs) {
  std::sort(dofs.begin(), dofs.end());
  dofs.erase(std::unique(dofs.begin(), dofs.end()), dofs.end());
  dofs.erase(std::remove_if(dofs.begin(), dofs.end(), [&](GO g) { return holds(g); }), dofs.end());
  // A new held map, and its Import, only where some rank lacks a dof (Import is collective).
  const int missing = dofs.empty() ? 0 : 1;
  int missing_any = 0;
  Teuchos::reduceAll(*held_->getComm(), Teuchos::REDUCE_MAX, missing, Teuchos::outArg(missing_any));
  if (!missing_any) return;
  // The held dofs keep their local indices; the new ones follow, ascending.
  std::vector<GO> gids(held_->getNodeElementList().begin(), held_->getNodeElementList().end());
  gids.insert(gids.end(), dofs.begin(), dofs.end());
  held_ = Teuchos::rcp(new Map(Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid(),
                               gids.data(), gids.size(), 0, held_->getComm()));
  import_ = Teuchos::rcp(new Import(owned_, held_));
  import_values();
}

double PrescribedValues::value(GO dof) const {
  const LO i = held_->getLocalElement(dof);
  if (i == Teuchos::OrdinalTraits<LO>::invalid())
    throw std::logic_error("PrescribedValues: dof " + std::to_string(dof) +
                           " is not held on this rank");
  return values_[std::size_t(i)];
}

}  // namespace grout
