#include "nonlinear/schur_update.hpp"

#include <Teuchos_LAPACK.hpp>
#include <algorithm>
#include <cmath>
#include <limits>

namespace grout {

std::vector<long long> changed_rows(const std::vector<long long>& old_keys,
                                    const std::vector<double>& old_values,
                                    const std::vector<long long>& new_keys,
                                    const std::vector<double>& new_values, long long n) {
  std::vector<long long> rows;
  const auto mark = [&](long long key) {
    rows.push_back(key / n);
    rows.push_back(key % n);
  };
  // One merge walk over both sorted key lists.
  std::size_t a = 0, b = 0;
  while (a < old_keys.size() || b < new_keys.size()) {
    if (b == new_keys.size() || (a < old_keys.size() && old_keys[a] < new_keys[b])) {
      if (old_values[a] != 0.0) mark(old_keys[a]);
      ++a;
    } else if (a == old_keys.size() || new_keys[b] < old_keys[a]) {
      if (new_values[b] != 0.0) mark(new_keys[b]);
      ++b;
    } else {
      if (old_values[a] != new_values[b]) mark(new_keys[b]);
      ++a, ++b;
    }
  }
  std::sort(rows.begin(), rows.end());
  rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
  return rows;
}

bool rows_within(const std::vector<long long>& rows, const std::vector<long long>& set) {
  return std::includes(set.begin(), set.end(), rows.begin(), rows.end());
}

std::vector<double> DenseSchur::prepare(int size) {
  return std::vector<double>(std::size_t(size) * std::size_t(size),
                             std::numeric_limits<double>::quiet_NaN());
}

bool DenseSchur::set_base(int size, std::vector<double>& mumps_schur) {
  size_ = size;
  const std::size_t m = std::size_t(size);
  // ICNTL(19) = 1 with a symmetric matrix: MUMPS returns the lower triangle of S by rows,
  // i.e. the entries (i, j), i ≤ j, of this column-major array (i + j · size); the other
  // triangle is not defined (zeros, or left-overs of its work). Mirror the defined one.
  for (std::size_t j = 0; j < m; ++j)
    for (std::size_t i = j + 1; i < m; ++i) mumps_schur[i + j * m] = mumps_schur[j + i * m];
  base_.swap(mumps_schur);
  return factorise(base_);
}

bool DenseSchur::update(const std::vector<SchurDelta>& deltas) {
  std::vector<double> s = base_;
  const std::size_t m = std::size_t(size_);
  for (const SchurDelta& d : deltas) {
    s[std::size_t(d.i) + std::size_t(d.j) * m] += d.value;
    if (d.i != d.j) s[std::size_t(d.j) + std::size_t(d.i) * m] += d.value;
  }
  return factorise(std::move(s));
}

bool DenseSchur::factorise(std::vector<double> matrix) {
  if (size_ == 0) return true;
  for (const double v : matrix)
    if (!std::isfinite(v)) return false;
  Teuchos::LAPACK<int, double> lapack;
  int info = 0;
  lapack.POTRF('L', size_, matrix.data(), size_, &info);
  if (info != 0) return false;
  factor_.swap(matrix);
  return true;
}

void DenseSchur::solve(double* x) const {
  if (size_ == 0) return;
  Teuchos::LAPACK<int, double> lapack;
  int info = 0;
  lapack.POTRS('L', size_, 1, factor_.data(), size_, x, size_, &info);
}

}  // namespace grout
