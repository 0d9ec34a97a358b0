#include "nonlinear/contact_velocity_update.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <TpetraExt_MatrixMatrix.hpp>
#include <cmath>
#include <unordered_map>

namespace grout {

int project_contact_velocities(MechanicsProblem& problem, const Vector& x,
                               const Vector& lumped_mass, LinearSolver& solver, Vector& v) {
  const GO num_u = problem.num_displacement_dofs();
  const auto& prescribed = problem.prescribed();
  const auto u_map = lumped_mass.getMap();
  const auto comm = u_map->getComm();

  // Which multiplier rows constrain the velocities: per λ dof its slave node and component;
  // status 1 (stick, tied): every component; 2 (slip, frictionless): the normal row (0) only.
  const ContactFields fields = problem.contact_fields();
  const int dim = int(fields.lm.size());
  std::unordered_map<GO, GO> slave_dof_of;
  for (const auto& [lambda, dof] : problem.multiplier_pairing()) slave_dof_of[lambda] = dof;

  Teuchos::RCP<Matrix> J;
  problem.jacobian(x, J);
  const auto& row_map = *J->getRowMap();
  const auto& col_map = *J->getColMap();
  std::vector<GO> rows;
  std::vector<std::vector<std::pair<GO, double>>> entries;
  for (LO i = 0; i < LO(row_map.getNodeNumElements()); ++i) {
    const GO gid = row_map.getGlobalElement(i);
    if (gid < num_u) continue;
    const auto it = slave_dof_of.find(gid);
    if (it == slave_dof_of.end()) continue;
    const GO node = it->second / dim;
    const int component = int(it->second % dim);
    const int status = int(fields.status[node]);
    if (status == 0 || (status == 2 && component != 0)) continue;
    typename Matrix::local_inds_host_view_type indices;
    typename Matrix::values_host_view_type values;
    J->getLocalRowView(i, indices, values);
    std::vector<std::pair<GO, double>> row;
    for (std::size_t k = 0; k < indices.extent(0); ++k) {
      const GO col = col_map.getGlobalElement(indices(k));
      if (col < num_u && std::isnan(prescribed[col]) && values(k) != 0.0)
        row.emplace_back(col, values(k));
    }
    if (row.empty()) continue;
    rows.push_back(gid);
    entries.push_back(std::move(row));
  }
  long long local_rows = static_cast<long long>(rows.size()), total_rows = 0;
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_SUM, local_rows, Teuchos::outArg(total_rows));
  if (total_rows == 0) return 0;

  // G (constraint rows × u dofs) and W = G M_L⁻¹ (prescribed dofs: M⁻¹ = 0, never in G).
  // Constraint rows are numbered contiguously over the ranks (the direct solvers want 0..n−1).
  long long offset = 0;
  Teuchos::scan(*comm, Teuchos::REDUCE_SUM, local_rows, Teuchos::outArg(offset));
  offset -= local_rows;
  for (std::size_t r = 0; r < rows.size(); ++r) rows[r] = offset + GO(r);
  const auto constraint_map = Teuchos::rcp(new Map(GO(total_rows), rows.size(), 0, comm));
  std::vector<std::size_t> counts;
  for (const auto& row : entries) counts.push_back(row.size());
  auto G = Teuchos::rcp(new Matrix(constraint_map, Teuchos::ArrayView<const std::size_t>(counts)));
  auto W = Teuchos::rcp(new Matrix(constraint_map, Teuchos::ArrayView<const std::size_t>(counts)));
  Vector inverse_mass(u_map);
  {
    const auto m = lumped_mass.getLocalViewHost(Tpetra::Access::ReadOnly);
    auto w = inverse_mass.getLocalViewHost(Tpetra::Access::OverwriteAll);
    for (std::size_t i = 0; i < m.extent(0); ++i) w(i, 0) = m(i, 0) > 0.0 ? 1.0 / m(i, 0) : 0.0;
  }
  for (std::size_t r = 0; r < rows.size(); ++r) {
    std::vector<GO> cols;
    std::vector<double> vals;
    for (const auto& [col, value] : entries[r]) cols.push_back(col), vals.push_back(value);
    G->insertGlobalValues(rows[r], Teuchos::ArrayView<const GO>(cols),
                          Teuchos::ArrayView<const double>(vals));
    W->insertGlobalValues(rows[r], Teuchos::ArrayView<const GO>(cols),
                          Teuchos::ArrayView<const double>(vals));
  }
  G->fillComplete(u_map, constraint_map);
  W->fillComplete(u_map, constraint_map);
  W->rightScale(inverse_mass);
  auto S = Teuchos::rcp(new Matrix(constraint_map, 0));
  Tpetra::MatrixMatrix::Multiply(*W, false, *G, true, *S);

  // μ from S μ = G v, then v −= M_L⁻¹ Gᵀ μ.
  Vector Gv(constraint_map), mu(constraint_map), correction(u_map);
  G->apply(v, Gv);
  solver.solve(S, Gv, mu);
  W->apply(mu, correction, Teuchos::TRANS);
  v.update(-1.0, correction, 1.0);
  return int(total_rows);
}

}  // namespace grout
