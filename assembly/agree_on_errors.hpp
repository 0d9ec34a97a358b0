#pragma once
// Rank-local errors become job-wide errors at a few synchronisation points, so that an
// error one rank alone detects (a file it cannot write, a value it evaluates) never leaves
// the others waiting in a collective.

#include <functional>

#include "assembly/tpetra_types.hpp"

namespace grout {

/// \brief Runs `phase` on every rank of `comm`, then agrees on its outcome (one collective).
/// If `phase` threw on any rank, it throws on every rank: the lowest rank with its own
/// error rethrows it (the driver prints its message, once), every other rank throws
/// ErrorOnOtherRank with that error's exit code (io/errors.hpp). A rank whose `phase`
/// threw ErrorOnOtherRank itself (a nested agreement) only passes the code on.
/// \pre `phase` makes no collective call after a point where it may throw on one rank only.
void agree_on_errors(const Comm& comm, const std::function<void()>& phase);

}  // namespace grout
