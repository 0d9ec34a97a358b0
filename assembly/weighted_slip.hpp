#pragma once
// The weighted slip increment of one slave node over a load step, per unit D_jj, and its exact
// derivative with respect to the displacement dofs (Coulomb friction, docs/design.md §2).
//
// Two measures (Gitterle, Popp, Gee, Wall, IJNME 84 (2010) 543, §3.3):
//   standard (small sliding, reference geometry):
//     ū_k = τ_k · (D_jj Δx¹_j − Σ_l M_jl Δx²_l) / D_jj,     Δx = x − x_n;
//   objective (frame-indifferent; large sliding on the current geometry):
//     ū_k = −τ_k · ((D_jj − D_jj,n) x¹_j − Σ_l (M_jl − M_jl,n) x²_l) / D_jj,
// with D, M, τ of the current positions x and D_n, M_n of the last converged step x_n. The
// objective measure is the time-discrete form of the rate −(Ḋ x¹ − Ṁ x²): a rigid motion of
// both bodies leaves D and M, hence ū, unchanged, and a slave node that stays on the same
// material point of the master (stick) keeps M_jl = M_jl,n. The standard measure picks up
// τ·(R − I) v_n under a rigid rotation R when v_n = D x¹ − M x² ≠ 0 (a gap, a curved
// surface). Both give the relative displacement of the slave node against the master surface
// (slave minus master) for a rigid shift of either body.

#include <functional>
#include <utility>
#include <vector>

#include "assembly/contact_mortar.hpp"

namespace grout {

/// D_jj and the row M_jl (master node, value; ascending nodes) of one slave node at the last
/// converged step.
struct MortarRowHistory {
  double D = 0.0;
  std::vector<std::pair<GlobalIndex, double>> M;
};

/// One entry M_jl of the current row: master node l and its value with gradient.
using MortarRowEntry = std::pair<GlobalIndex, const MortarValue*>;
/// Component `c` of the position of a surface node.
using NodePosition = std::function<double(GlobalIndex node, int c)>;

/// \brief ū_k (k < dim − 1) of slave node `node` and dū_k, per unit D_jj: the objective measure
/// when `history` is given, the standard one (with `x_old`) otherwise; formulas above.
/// \pre D.value > 0; `M` ascending by master node; `history->M` ascending by master node.
void weighted_slip_increment(int dim, GlobalIndex node, const SlaveFrame& frame,
                             const MortarValue& D, const std::vector<MortarRowEntry>& M,
                             const MortarRowHistory* history, const NodePosition& x,
                             const NodePosition& x_old, double slip[2], SparseGradient dslip[2]);

}  // namespace grout
