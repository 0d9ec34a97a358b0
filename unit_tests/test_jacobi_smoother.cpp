// The damped Jacobi smoother's damping (nonlinear/jacobi_smoother.hpp), on 1 and 2 ranks:
// the power estimate of λ_max(D⁻¹A) is a lower bound that the damping's 1.05 margin covers
// (ω λ_max < 2, the smoother's condition) on the Laplacians whose top spectrum is densest
// (λ_max known in closed form), it is the same on any number of ranks, and it refuses a
// matrix with a diagonal entry that is not positive.

#include <gtest/gtest.h>

#include <Teuchos_DefaultMpiComm.hpp>
#include <Tpetra_Core.hpp>
#include <cmath>
#include <optional>
#include <utility>
#include <vector>

#include "nonlinear/jacobi_smoother.hpp"

namespace grout {
namespace {

// The (2·dim + 1)-point Laplacian on an n^dim grid (Dirichlet outside), rows spread over
// `comm`'s ranks; `row0_diagonal` replaces the diagonal of row 0. D⁻¹A's eigenvalues are
// 1 − Σ_d cos(k_d π / (n + 1)) / dim, k_d = 1 … n: λ_max = 1 + cos(π / (n + 1)).
Teuchos::RCP<Matrix> laplacian(const Teuchos::RCP<const Comm>& comm, int dim, int n,
                               std::optional<double> row0_diagonal = std::nullopt) {
  GO size = 1;
  for (int d = 0; d < dim; ++d) size *= n;
  const auto map = Teuchos::rcp(new Map(size, 0, comm));
  auto A = Teuchos::rcp(new Matrix(map, 2 * dim + 1));
  for (LO i = 0; i < LO(map->getNodeNumElements()); ++i) {
    const GO row = map->getGlobalElement(i);
    std::vector<GO> cols{row};
    std::vector<double> vals{row == 0 && row0_diagonal ? *row0_diagonal : 2.0 * dim};
    GO stride = 1;
    for (int d = 0; d < dim; ++d, stride *= n) {
      const GO k = (row / stride) % n;
      if (k > 0) cols.push_back(row - stride), vals.push_back(-1.0);
      if (k < n - 1) cols.push_back(row + stride), vals.push_back(-1.0);
    }
    A->insertGlobalValues(row, Teuchos::ArrayView<const GO>(cols),
                          Teuchos::ArrayView<const double>(vals));
  }
  A->fillComplete();
  return A;
}

double exact_lambda_max(int n) {
  return 1.0 + std::cos(M_PI / (n + 1));
}

TEST(JacobiSmoother, TheDampingKeepsTheLaplaciansHighestModeDamped) {
  const auto comm = Tpetra::getDefaultComm();
  for (const auto& [dim, n] : {std::pair{1, 400}, std::pair{2, 40}, std::pair{3, 14}}) {
    const auto A = laplacian(comm, dim, n);
    const double estimate = jacobi_lambda_max(*A), exact = exact_lambda_max(n);
    const double damping = jacobi_damping(*A);
    EXPECT_LE(estimate, exact * (1.0 + 1e-12)) << dim << "D";  // a Rayleigh quotient
    EXPECT_LT(damping * exact, 2.0) << dim << "D: the highest mode would grow";
    // Not needlessly small either: at least 1.5 / λ_max (the damping 1.8 / (1.05 λ̂)).
    EXPECT_GT(damping * exact, 1.5) << dim << "D";
    if (comm->getRank() == 0)
      std::printf("[jacobi] %dD Laplacian: estimate %.5f, exact %.5f, damping x lambda %.3f\n", dim,
                  estimate, exact, damping * exact);
  }
}

TEST(JacobiSmoother, TheSameOnAnyNumberOfRanks) {
  const auto comm = Tpetra::getDefaultComm();
  const auto self = Teuchos::rcp(new Teuchos::MpiComm<int>(MPI_COMM_SELF));
  const double spread = jacobi_lambda_max(*laplacian(comm, 3, 11));
  const double alone = jacobi_lambda_max(*laplacian(self, 3, 11));
  EXPECT_NEAR(spread, alone, 1e-12 * alone);
}

TEST(JacobiSmoother, RefusesADiagonalThatIsNotPositive) {
  const auto comm = Tpetra::getDefaultComm();
  for (const double diagonal : {0.0, -1.0}) {
    const auto A = laplacian(comm, 2, 10, diagonal);
    EXPECT_EQ(jacobi_lambda_max(*A), 0.0);
    EXPECT_EQ(jacobi_damping(*A), 0.0);
  }
}

TEST(JacobiSmoother, SetsMueLusPreAndPostSmoother) {
  Teuchos::ParameterList muelu;
  muelu.sublist("smoother: pre params").set("relaxation: backward mode", true);
  set_jacobi_smoother(muelu, 0.55);
  for (const char* when : {"pre", "post"}) {
    EXPECT_EQ(muelu.get<std::string>(std::string("smoother: ") + when + " type"), "RELAXATION");
    const auto& p = muelu.sublist(std::string("smoother: ") + when + " params");
    EXPECT_EQ(p.get<std::string>("relaxation: type"), "Jacobi");
    EXPECT_EQ(p.get<int>("relaxation: sweeps"), 2);
    EXPECT_EQ(p.get<double>("relaxation: damping factor"), 0.55);
    EXPECT_FALSE(p.isParameter("relaxation: backward mode"));  // the old entries are gone
  }
}

}  // namespace
}  // namespace grout
