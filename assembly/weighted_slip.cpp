#include "assembly/weighted_slip.hpp"

namespace grout {

namespace {

// Standard: w = D Δx_j − Σ_l M_jl Δx_l, ū_k = τ_k·w / D (r = 1/D),
//   dū_k = r w·dτ_k + τ_k·dx_j + r (τ_k·Δx_j − ū_k) dD − r Σ_l (τ_k·Δx_l dM_jl + M_jl τ_k·dx_l).
void standard_slip(int dim, GlobalIndex node, const SlaveFrame& fr, const MortarValue& D,
                   const std::vector<MortarRowEntry>& M, const NodePosition& x,
                   const NodePosition& x_old, double slip[2], SparseGradient dslip[2]) {
  const double r = 1.0 / D.value;
  double w[3] = {0.0, 0.0, 0.0}, dx_j[3] = {0.0, 0.0, 0.0};
  for (int a = 0; a < dim; ++a) {
    dx_j[a] = x(node, a) - x_old(node, a);
    w[a] = D.value * dx_j[a];
  }
  for (const auto& [l, value] : M)
    for (int a = 0; a < dim; ++a) w[a] -= value->value * (x(l, a) - x_old(l, a));
  for (int k = 0; k < dim - 1; ++k) {
    SparseGradient& g = dslip[k];
    slip[k] = 0.0;
    double t_dx = 0.0;  // τ_k·Δx_j
    for (int a = 0; a < dim; ++a) {
      slip[k] += r * fr.t[k][a] * w[a];
      t_dx += fr.t[k][a] * dx_j[a];
      for (const auto& [dof, dt] : fr.dt[k][a]) g.emplace_back(dof, r * w[a] * dt);
      g.emplace_back(node * dim + a, fr.t[k][a]);
    }
    for (const auto& [dof, dD] : D.gradient) g.emplace_back(dof, r * (t_dx - slip[k]) * dD);
    for (const auto& [l, value] : M) {
      double t_dxl = 0.0;
      for (int a = 0; a < dim; ++a) {
        t_dxl += fr.t[k][a] * (x(l, a) - x_old(l, a));
        g.emplace_back(l * dim + a, -r * fr.t[k][a] * value->value);
      }
      for (const auto& [dof, dM] : value->gradient) g.emplace_back(dof, -r * t_dxl * dM);
    }
    compress_gradient(g);
  }
}

// Objective: W = (D − D_n) x_j − Σ_l (M_jl − M_jl,n) x_l over the master nodes of either row,
// ū_k = −r τ_k·W,
//   dū_k = −r W·dτ_k − r (τ_k·x_j + ū_k) dD − r (D − D_n) τ_k·dx_j
//          + r Σ_l (τ_k·x_l dM_jl + (M_jl − M_jl,n) τ_k·dx_l).
void objective_slip(int dim, GlobalIndex node, const SlaveFrame& fr, const MortarValue& D,
                    const std::vector<MortarRowEntry>& M, const MortarRowHistory& old,
                    const NodePosition& x, double slip[2], SparseGradient dslip[2]) {
  const double r = 1.0 / D.value;
  // The union of the two rows, ascending: (l, M_jl − M_jl,n, current entry or null).
  struct Term {
    GlobalIndex l;
    double dM;
    const MortarValue* now;
  };
  std::vector<Term> terms;
  std::size_t ia = 0, ib = 0;
  while (ia < M.size() || ib < old.M.size()) {
    if (ib == old.M.size() || (ia < M.size() && M[ia].first < old.M[ib].first)) {
      terms.push_back({M[ia].first, M[ia].second->value, M[ia].second});
      ++ia;
    } else if (ia == M.size() || old.M[ib].first < M[ia].first) {
      terms.push_back({old.M[ib].first, -old.M[ib].second, nullptr});
      ++ib;
    } else {
      terms.push_back({M[ia].first, M[ia].second->value - old.M[ib].second, M[ia].second});
      ++ia, ++ib;
    }
  }
  double W[3] = {0.0, 0.0, 0.0};
  for (int a = 0; a < dim; ++a) W[a] = (D.value - old.D) * x(node, a);
  for (const Term& t : terms)
    for (int a = 0; a < dim; ++a) W[a] -= t.dM * x(t.l, a);
  for (int k = 0; k < dim - 1; ++k) {
    SparseGradient& g = dslip[k];
    slip[k] = 0.0;
    double t_x = 0.0;  // τ_k·x_j
    for (int a = 0; a < dim; ++a) {
      slip[k] -= r * fr.t[k][a] * W[a];
      t_x += fr.t[k][a] * x(node, a);
      for (const auto& [dof, dt] : fr.dt[k][a]) g.emplace_back(dof, -r * W[a] * dt);
      g.emplace_back(node * dim + a, -r * (D.value - old.D) * fr.t[k][a]);
    }
    for (const auto& [dof, dD] : D.gradient) g.emplace_back(dof, -r * (t_x + slip[k]) * dD);
    for (const Term& t : terms) {
      double t_xl = 0.0;
      for (int a = 0; a < dim; ++a) {
        t_xl += fr.t[k][a] * x(t.l, a);
        g.emplace_back(t.l * dim + a, r * t.dM * fr.t[k][a]);
      }
      if (t.now)
        for (const auto& [dof, dM] : t.now->gradient) g.emplace_back(dof, r * t_xl * dM);
    }
    compress_gradient(g);
  }
}

}  // namespace

void weighted_slip_increment(int dim, GlobalIndex node, const SlaveFrame& frame,
                             const MortarValue& D, const std::vector<MortarRowEntry>& M,
                             const MortarRowHistory* history, const NodePosition& x,
                             const NodePosition& x_old, double slip[2], SparseGradient dslip[2]) {
  for (int k = 0; k < 2; ++k) slip[k] = 0.0, dslip[k].clear();
  if (history)
    objective_slip(dim, node, frame, D, M, *history, x, slip, dslip);
  else
    standard_slip(dim, node, frame, D, M, x, x_old, slip, dslip);
}

}  // namespace grout
