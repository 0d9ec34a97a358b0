#include "nonlinear/mumps_schur.hpp"

#include <algorithm>
#include <iterator>

namespace grout {

namespace {

// The union over all ranks of sorted 0-based row lists (the same sorted list on every rank).
std::vector<long long> union_over_ranks(const std::vector<long long>& local, MPI_Comm comm) {
  int ranks = 1;
  MPI_Comm_size(comm, &ranks);
  if (ranks == 1) return local;
  int count = int(local.size());
  std::vector<int> counts(static_cast<std::size_t>(ranks), 0), offsets(counts);
  MPI_Allgather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, comm);
  for (int r = 1; r < ranks; ++r) offsets[r] = offsets[r - 1] + counts[r - 1];
  std::vector<long long> all(std::size_t(offsets.back() + counts.back()));
  MPI_Allgatherv(local.data(), count, MPI_LONG_LONG, all.data(), counts.data(), offsets.data(),
                 MPI_LONG_LONG, comm);
  std::sort(all.begin(), all.end());
  all.erase(std::unique(all.begin(), all.end()), all.end());
  return all;
}

// Every rank's Schur deltas on rank 0 (as triplets of doubles: i, j, value).
std::vector<SchurDelta> gather_deltas(const std::vector<SchurDelta>& local, MPI_Comm comm) {
  int ranks = 1, rank = 0;
  MPI_Comm_size(comm, &ranks);
  MPI_Comm_rank(comm, &rank);
  if (ranks == 1) return local;
  std::vector<double> packed;
  for (const SchurDelta& d : local)
    packed.insert(packed.end(), {double(d.i), double(d.j), d.value});
  int count = int(packed.size());
  std::vector<int> counts(static_cast<std::size_t>(ranks), 0), offsets(counts);
  MPI_Gather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, comm);
  for (int r = 1; r < ranks; ++r) offsets[r] = offsets[r - 1] + counts[r - 1];
  std::vector<double> all(rank == 0 ? std::size_t(offsets.back() + counts.back()) : 0);
  MPI_Gatherv(packed.data(), count, MPI_DOUBLE, all.data(), counts.data(), offsets.data(),
              MPI_DOUBLE, 0, comm);
  std::vector<SchurDelta> deltas;
  for (std::size_t k = 0; k + 2 < all.size(); k += 3)
    deltas.push_back({int(all[k]), int(all[k + 1]), all[k + 2]});
  return deltas;
}

}  // namespace

std::vector<long long> rows_changed_on_any_rank(const std::vector<long long>& base_keys,
                                                const std::vector<double>& base_values,
                                                const std::vector<long long>& keys,
                                                const std::vector<double>& values, GO n,
                                                MPI_Comm comm) {
  return union_over_ranks(changed_rows(base_keys, base_values, keys, values, n), comm);
}

bool note_changed_rows(MumpsSchur& schur, const std::vector<long long>& rows, bool have_base) {
  const bool changed_before = have_base && !schur.changed_ever.empty();
  if (!have_base) schur.changed_ever.clear();
  std::vector<long long> joined;
  std::set_union(schur.changed_ever.begin(), schur.changed_ever.end(), rows.begin(), rows.end(),
                 std::back_inserter(joined));
  schur.changed_ever.swap(joined);
  return changed_before;
}

bool schur_pays(std::size_t size, double full_flops) {
  const double nb = double(size);
  return size > 0 && size <= 6000 && nb * nb * nb / 3.0 <= 0.5 * full_flops;
}

std::vector<long long> next_schur_set(const MumpsSchur& schur, const std::vector<long long>& rows,
                                      bool changed_before) {
  if (!changed_before) return {};
  if (schur_pays(schur.changed_ever.size(), schur.full_flops)) return schur.changed_ever;
  if (schur_pays(rows.size(), schur.full_flops)) return rows;
  return {};
}

bool update_schur(MumpsSchur& schur, const MumpsPattern& pattern, const std::vector<double>& values,
                  GO n, MPI_Comm comm) {
  std::vector<int> where(std::size_t(n), -1);
  for (std::size_t k = 0; k < schur.rows.size(); ++k) where[std::size_t(schur.rows[k])] = int(k);
  std::vector<SchurDelta> deltas;
  for (std::size_t p = 0; p < pattern.keys.size(); ++p) {
    const double d = values[p] - schur.base_values[p];
    if (d == 0.0) continue;
    const int i = where[std::size_t(pattern.keys[p] / n)];
    const int j = where[std::size_t(pattern.keys[p] % n)];
    if (i >= 0 && j >= 0) deltas.push_back({i, j, d});
  }
  deltas = gather_deltas(deltas, comm);
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  int ok = rank == 0 ? int(schur.dense.update(deltas)) : 1;
  MPI_Bcast(&ok, 1, MPI_INT, 0, comm);
  return ok != 0;
}

}  // namespace grout
