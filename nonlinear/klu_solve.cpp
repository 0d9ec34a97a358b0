#include "nonlinear/klu_solve.hpp"

#include <assert.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <Teuchos_ScalarTraits.hpp>

#include <complex>
#include <stdexcept>
#include <string>
#include <vector>

// KLU2's headers declare their templates in the enclosing namespace; Amesos2 includes them in
// namespace KLU2 (Amesos2_KLU2_TypeMap.hpp, Amesos2_KLU2_FunctionMap.hpp), and so does this
// file, after the system headers they include (their include guards then keep those out).
// clang-format off
namespace KLU2 {
#include <klu2_ext.hpp>
#include <klu2_defaults.hpp>
#include <klu2_analyze.hpp>
#include <klu2_factor.hpp>
#include <klu2_tsolve.hpp>
#include <klu2_free_symbolic.hpp>
#include <klu2_free_numeric.hpp>
}  // namespace KLU2
// clang-format on

namespace grout {

namespace {

// Frees KLU's symbolic and numeric objects however the solve ends.
struct KluObjects {
  KLU2::klu_common<double, int> common;
  KLU2::klu_symbolic<double, int>* symbolic = nullptr;
  KLU2::klu_numeric<double, int>* numeric = nullptr;
  ~KluObjects() {
    if (numeric) KLU2::klu_free_numeric<double, int>(&numeric, &common);
    if (symbolic) KLU2::klu_free_symbolic<double, int>(&symbolic, &common);
  }
};

}  // namespace

void klu_solve(const Matrix& K, const Vector& b, Vector& x) {
  if (K.getComm()->getSize() != 1 || !K.getColMap()->isSameAs(*K.getRowMap()))
    throw std::logic_error("klu_solve: the matrix must be on one rank, columns as its rows");
  const auto local = K.getLocalMatrixHost();
  const int n = int(K.getNodeNumRows());
  // KLU's Int row pointers (Amesos2 converts them the same way).
  std::vector<int> row_ptr(std::size_t(n) + 1);
  for (int i = 0; i <= n; ++i) row_ptr[std::size_t(i)] = int(local.graph.row_map(i));
  int* cols = const_cast<int*>(local.graph.entries.data());
  double* values = const_cast<double*>(local.values.data());

  KluObjects klu;
  KLU2::klu_defaults<double, int>(&klu.common);
  klu.symbolic = KLU2::klu_analyze<double, int>(n, row_ptr.data(), cols, &klu.common);
  if (!klu.symbolic)
    throw std::runtime_error("KLU2 analysis failed (status " + std::to_string(klu.common.status) +
                             ")");
  klu.numeric =
      KLU2::klu_factor<double, int>(row_ptr.data(), cols, values, klu.symbolic, &klu.common);
  if (!klu.numeric || klu.common.status != KLU_OK)
    throw std::runtime_error("KLU2 factorisation failed (status " +
                             std::to_string(klu.common.status) +
                             (klu.common.status == KLU_SINGULAR ? ": singular matrix)" : ")"));
  auto bv = b.getLocalViewHost(Tpetra::Access::ReadOnly);
  auto xv = x.getLocalViewHost(Tpetra::Access::OverwriteAll);
  // The CRS arrays are the CCS of Kᵀ: the transposed solve gives K x = b.
  KLU2::klu_tsolve2<double, int>(klu.symbolic, klu.numeric, n, 1, const_cast<double*>(&bv(0, 0)),
                                 &xv(0, 0), &klu.common);
  if (klu.common.status != KLU_OK)
    throw std::runtime_error("KLU2 solve failed (status " + std::to_string(klu.common.status) +
                             ")");
}

}  // namespace grout
