#include "nonlinear/jacobi_smoother.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <cmath>
#include <cstdint>
#include <string>

namespace grout {

namespace {

// A start vector entry of row `gid`: ±(0.5 … 1.5) from a hash of the id (splitmix64), so that
// every mode of D⁻¹A, the highest included, has a share, and 1 and 2 ranks start alike.
double start_entry(GO gid) {
  std::uint64_t z = std::uint64_t(gid) + 0x9e3779b97f4a7c15ull;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  z ^= z >> 31;
  const double u = double(z >> 11) * 0x1.0p-53;  // [0, 1)
  return (z & 1 ? 1.0 : -1.0) * (0.5 + u);
}

}  // namespace

double jacobi_lambda_max(const Matrix& A, int steps) {
  const auto& map = *A.getRowMap();
  Vector d(A.getRowMap()), d_inv(A.getRowMap()), x(A.getRowMap()), y(A.getRowMap()),
      dx(A.getRowMap());
  A.getLocalDiagCopy(d);
  int bad = 0;
  {
    const auto dv = d.getLocalViewHost(Tpetra::Access::ReadOnly);
    const auto xv = x.getLocalViewHost(Tpetra::Access::OverwriteAll);
    for (LO i = 0; i < LO(map.getNodeNumElements()); ++i) {
      if (!(dv(i, 0) > 0.0)) bad = 1;
      xv(i, 0) = start_entry(map.getGlobalElement(i));
    }
  }
  int any_bad = 0;
  Teuchos::reduceAll(*map.getComm(), Teuchos::REDUCE_MAX, bad, Teuchos::outArg(any_bad));
  if (any_bad) return 0.0;
  d_inv.reciprocal(d);
  double lambda = 0.0;
  for (int step = 0; step <= steps; ++step) {
    A.apply(x, y);                           // y = A x
    const double xay = x.dot(y);             // xᵀAx
    dx.elementWiseMultiply(1.0, d, x, 0.0);  // D x
    const double xdx = x.dot(dx);            // xᵀDx > 0
    lambda = xay / xdx;
    if (step == steps) break;
    x.elementWiseMultiply(1.0, d_inv, y, 0.0);  // x = D⁻¹ A x
    const double norm = x.norm2();
    if (!(norm > 0.0) || !std::isfinite(norm)) break;
    x.scale(1.0 / norm);
  }
  return std::isfinite(lambda) && lambda > 0.0 ? lambda : 0.0;
}

double jacobi_damping(const Matrix& A) {
  const double lambda = jacobi_lambda_max(A);
  return lambda > 0.0 ? 1.8 / (1.05 * lambda) : 0.0;
}

void set_jacobi_smoother(Teuchos::ParameterList& muelu, double damping, int sweeps) {
  for (const char* when : {"pre", "post"}) {
    muelu.set(std::string("smoother: ") + when + " type", std::string("RELAXATION"));
    Teuchos::ParameterList& relaxation =
        muelu.sublist(std::string("smoother: ") + when + " params");
    relaxation = Teuchos::ParameterList();
    relaxation.set("relaxation: type", std::string("Jacobi"));
    relaxation.set("relaxation: sweeps", sweeps);
    relaxation.set("relaxation: damping factor", damping);
  }
}

}  // namespace grout
