#include "nonlinear/mumps_pattern.hpp"

#include <algorithm>
#include <iterator>

namespace grout {

namespace {

// The position in `pattern` (sorted, unique) of every key; false if a key is not in it.
// The increasing keys[0 .. sorted) are found in one forward walk, the others by binary search.
bool locate(const std::vector<long long>& pattern, const std::vector<long long>& keys,
            std::size_t sorted, std::vector<std::size_t>& position) {
  position.assign(keys.size(), 0);
  auto it = pattern.begin();
  for (std::size_t k = 0; k < keys.size(); ++k) {
    if (k < sorted) {
      while (it != pattern.end() && *it < keys[k]) ++it;
    } else {
      it = std::lower_bound(pattern.begin(), pattern.end(), keys[k]);
    }
    if (it == pattern.end() || *it != keys[k]) return false;
    position[k] = std::size_t(it - pattern.begin());
  }
  return true;
}

}  // namespace

bool pattern_misses(MumpsPattern& pattern, bool valid, const std::vector<long long>& keys,
                    std::size_t sorted_prefix, MPI_Comm comm) {
  int missing = 0;
  if (!(valid && keys == pattern.last_keys))
    missing = int(!(valid && locate(pattern.keys, keys, sorted_prefix, pattern.position)));
  MPI_Allreduce(MPI_IN_PLACE, &missing, 1, MPI_INT, MPI_MAX, comm);
  return missing != 0;
}

void rebuild_pattern(MumpsPattern& pattern, bool valid, const std::vector<long long>& keys,
                     std::size_t sorted_prefix, GO n, MPI_Comm comm) {
  std::vector<long long> sorted = keys;
  if (sorted_prefix != keys.size()) {  // the unsorted tail sorted, then merged with the prefix
    const auto middle = sorted.begin() + std::ptrdiff_t(sorted_prefix);
    std::sort(middle, sorted.end());
    std::inplace_merge(sorted.begin(), middle, sorted.end());
  }
  sorted.erase(std::unique(sorted.begin(), sorted.end()), sorted.end());
  std::vector<long long> merged;
  if (valid)
    std::set_union(pattern.keys.begin(), pattern.keys.end(), sorted.begin(), sorted.end(),
                   std::back_inserter(merged));
  int use_union = int(!merged.empty() && merged.size() <= 2 * sorted.size());
  MPI_Allreduce(MPI_IN_PLACE, &use_union, 1, MPI_INT, MPI_MIN, comm);
  pattern.keys = use_union ? std::move(merged) : std::move(sorted);
  pattern.irn.resize(pattern.keys.size());
  pattern.jcn.resize(pattern.keys.size());
  for (std::size_t e = 0; e < pattern.keys.size(); ++e) {
    pattern.irn[e] = int(pattern.keys[e] / n) + 1;
    pattern.jcn[e] = int(pattern.keys[e] % n) + 1;
  }
  locate(pattern.keys, keys, sorted_prefix, pattern.position);
}

std::vector<double> values_in_pattern(const MumpsPattern& pattern,
                                      const std::vector<double>& entry_values) {
  std::vector<double> values(pattern.keys.size(), 0.0);
  for (std::size_t k = 0; k < entry_values.size(); ++k)
    values[pattern.position[k]] += entry_values[k];
  return values;
}

}  // namespace grout
