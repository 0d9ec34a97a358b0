#pragma once
// The damped Jacobi smoother of the displacement-only iterative path (CG on K, or on the
// symmetric reduction K̃ of nonlinear/symmetric_condensation.hpp), the default there:
//   x ← x + ω D⁻¹ (b − A x),  D = diag A,
// two sweeps before the coarse correction and two after, on every level (the V-cycle stays
// symmetric, as CG needs). Gauss–Seidel on several ranks sweeps each rank's rows with the other
// ranks' last iterate, so 2 ranks needed more CG iterations than 1 (22 against 20 on a 40³
// HEX8 box, 23 against 20 at twice that size); Jacobi is the same operator on any number of
// ranks (docs/performance.md, "Two ranks against one in 3D"). The processor-block
// Gauss–Seidel's dependence on the partition, and smoothers built from D⁻¹A with a spectral
// bound that do not have it: Adams, Brezina, Hu & Tuminaro 2003, "Parallel multigrid
// smoothing: polynomial versus Gauss–Seidel", J. Comput. Phys. 188.
//
// Its damping must keep ω λ_max(D⁻¹A) below 2, or the smoother amplifies the highest modes
// and CG breaks down. λ_max grows with Poisson's ratio (HEX8: 3.1 / 5.1 / 6.2 at ν = 0.3 /
// 0.45 / 0.49; TET4: 2.5 / 3.3 / 3.8), so ω follows it: ω = 1.8 / λ̂, λ̂ = 1.05 × the
// Rayleigh quotient xᵀAx / xᵀDx after jacobi_power_steps steps of x ← D⁻¹A x (a lower bound
// of λ_max(D⁻¹A) that converges from below: the generalized eigenproblem A x = λ D x, A and D
// symmetric positive definite). The coarse levels take the same ω: their λ_max(D⁻¹A) is lower
// (1.8 and 1.5 under 3.1 on the 40³ box). Gauss–Seidel, forward and backward, broke down on 2
// ranks where this converges (HEX8 at ν = 0.45 and 0.49: inputs/nearly_incompressible).

#include <Teuchos_ParameterList.hpp>

#include "assembly/tpetra_types.hpp"

namespace grout {

constexpr int jacobi_power_steps = 20;

/// The Rayleigh quotient xᵀAx / xᵀDx after `steps` steps of x ← D⁻¹A x from a start vector
/// fixed by the rows' global ids (the same on any number of ranks); collective. 0 when a
/// diagonal entry is not positive (then Jacobi is no smoother for A).
double jacobi_lambda_max(const Matrix& A, int steps = jacobi_power_steps);

/// ω = 1.8 / (1.05 λ) for λ = jacobi_lambda_max(A), or 0 when that is 0.
double jacobi_damping(const Matrix& A);

/// Sets MueLu's pre- and post-smoother to `sweeps` damped Jacobi sweeps with damping
/// `damping` (replacing Grout's Gauss–Seidel defaults of set_elasticity_defaults).
void set_jacobi_smoother(Teuchos::ParameterList& muelu, double damping, int sweeps = 2);

}  // namespace grout
