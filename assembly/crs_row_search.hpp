#pragma once
// Position of a column in one row of a CRS graph whose rows hold their local columns sorted
// (Tpetra's local graphs after fillComplete): a binary search, usable inside a Kokkos kernel.

#include <Kokkos_Core.hpp>

namespace grout {

/// \brief The first position p in [begin, end) with entries(p) ≥ column (end if there is none).
template <class Entries, class Offset>
KOKKOS_INLINE_FUNCTION Offset lower_bound_in_row(const Entries& entries, Offset begin, Offset end,
                                                 int column) {
  while (begin < end) {
    const Offset mid = begin + (end - begin) / 2;
    if (entries(mid) < column)
      begin = mid + 1;
    else
      end = mid;
  }
  return begin;
}

}  // namespace grout
