#pragma once
// Contiguous slices of a global range [0, n) over the ranks: rank r holds
// [n r / P, n (r + 1) / P), the reading distribution of the distributed mesh
// (parallel/exodus_slices.hpp) and the home of an entity in its directory exchanges.

#include "io/mesh.hpp"

namespace grout {

/// First index of rank `rank`'s slice of [0, n) over `ranks` ranks.
inline GlobalIndex slice_begin(GlobalIndex n, int rank, int ranks) {
  return GlobalIndex(static_cast<__int128>(n) * rank / ranks);
}

/// The rank whose slice holds index `i` of [0, n): the largest r with slice_begin(r) <= i.
inline int slice_rank(GlobalIndex n, GlobalIndex i, int ranks) {
  int r = int(static_cast<__int128>(i) * ranks / (n > 0 ? n : 1));
  while (r + 1 < ranks && slice_begin(n, r + 1, ranks) <= i) ++r;
  while (r > 0 && slice_begin(n, r, ranks) > i) --r;
  return r;
}

}  // namespace grout
