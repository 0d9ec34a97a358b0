// Check 9 of embed_mortar (main.cpp): Grout's contact law at the host's slave rows, filled from
// the coupling's normals, tangents and nodal gaps as docs/embedding.md ("The contact law at the
// slave nodes") shows, against the law's formulas written here (s = n·λ − ĉ g, ξ = τ·λ + c_t ū):
//   a. frictionless, λ = p n with p = 2 ĉ δ (s ≈ ĉ δ > 0): state slip, C_0 = ĉ g, C_k = τ_k·λ ≈ 0,
//      ∂C_0/∂g = ĉ, ∂C_k/∂λ_a = τ_k,a;
//   b. λ = 0 (s = −ĉ g < 0): open, C = λ = 0, identity rows;
//   c. Coulomb, λ = p n + q τ_0 with q = 0.6 p > μ s and ū = 0: slip, C_1 = q − μ s,
//      ∂C_1/∂g = μ ĉ (ξ = (q, 0): ξ_0/|ξ| = 1).

#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <grout/contact_law.hpp>
#include <grout/mortar_coupling.hpp>
#include <vector>

bool check_contact_law(int dim, MPI_Comm comm, double delta, const std::vector<long long>& ids,
                       const grout::MortarCoupling& coupling, const std::vector<double>& D_sum,
                       const std::vector<double>& g_sum) {
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  const double c = 1e3, mu = 0.3, p = 2.0 * c * delta, q = 0.6 * p;
  grout::ContactLawSettings law;
  law.dim = dim;
  law.c_hat = law.c_t_hat = c;
  law.mu = mu;
  law.active_tolerance = 1e-10;

  // The host's rows: this rank's slave rows, with D_jj and g̃_j summed over the ranks.
  const std::size_t n_rows = ids.size();
  std::vector<grout::ContactLawInput> pressed(n_rows), unloaded(n_rows), sliding(n_rows);
  for (std::size_t r = 0; r < n_rows; ++r) {
    grout::ContactLawInput in;
    const double Djj = D_sum[ids[r]];
    in.paired = Djj > 0.0;
    for (int a = 0; a < dim; ++a) {
      in.n[a] = coupling.normals()[r * dim + a];
      for (int k = 0; k < dim - 1; ++k)
        in.t[k][a] = coupling.tangents()[(r * (dim - 1) + k) * dim + a];
    }
    in.gap = g_sum[ids[r]] / Djj;
    unloaded[r] = pressed[r] = sliding[r] = in;
    for (int a = 0; a < dim; ++a) {
      pressed[r].lambda[a] = p * in.n[a];
      sliding[r].lambda[a] = p * in.n[a] + q * in.t[0][a];
    }
  }
  const auto a_rows = grout::contact_law_at_nodes(law, pressed);
  const auto b_rows = grout::contact_law_at_nodes(law, unloaded, false);
  law.law = grout::ContactLawType::coulomb;
  const auto c_rows = grout::contact_law_at_nodes(law, sliding);

  using Col = grout::ContactLawColumn;
  double worst = 0.0;  // relative to the rows' scale p
  bool states_ok = true;
  for (std::size_t r = 0; r < n_rows; ++r) {
    const grout::ContactLawInput& in = pressed[r];
    const grout::ContactLawRows& a = a_rows[r];
    states_ok = states_ok && a.state == grout::ContactNodeState::slip &&
                a.kind[0] == grout::ContactRowKind::constraint;
    worst = std::max(worst, std::abs(a.C[0] - c * in.gap) / p);
    worst = std::max(worst, std::abs(a.dC[0][Col::gap()] - c) / c);
    for (int k = 0; k < dim - 1; ++k) {
      states_ok = states_ok && a.kind[k + 1] == grout::ContactRowKind::tangent;
      worst = std::max(worst, std::abs(a.C[k + 1]) / p);
      for (int d = 0; d < dim; ++d)
        worst = std::max(worst, std::abs(a.dC[k + 1][Col::lambda(d)] - in.t[k][d]));
    }
    const grout::ContactLawRows& b = b_rows[r];
    states_ok = states_ok && b.state == grout::ContactNodeState::open;
    for (int d = 0; d < dim; ++d) {
      states_ok = states_ok && b.kind[d] == grout::ContactRowKind::identity && b.component[d] == d;
      worst = std::max(worst, std::abs(b.C[d]) / p);
    }
    const grout::ContactLawRows& s = c_rows[r];
    states_ok = states_ok && s.state == grout::ContactNodeState::slip &&
                s.kind[1] == grout::ContactRowKind::slip;
    const double s_n = p - c * in.gap;  // n·λ − ĉ g
    worst = std::max(worst, std::abs(s.C[0] - c * in.gap) / p);
    worst = std::max(worst, std::abs(s.C[1] - (q - mu * s_n)) / p);
    worst = std::max(worst, std::abs(s.dC[1][Col::gap()] - mu * c) / (mu * c));
  }
  MPI_Allreduce(MPI_IN_PLACE, &worst, 1, MPI_DOUBLE, MPI_MAX, comm);
  int ok = states_ok && worst <= 1e-12 ? 1 : 0;
  MPI_Allreduce(MPI_IN_PLACE, &ok, 1, MPI_INT, MPI_MIN, comm);
  if (rank == 0)
    std::printf("  contact law: %zu rows (rank 0), worst |C - formula| / p = %.3g %s\n", n_rows,
                worst, ok ? "ok" : "FAILED");
  return ok == 1;
}
