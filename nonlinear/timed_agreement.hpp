#pragma once
// An agreement on a failure that some ranks may have met inside a phase whose collective
// calls the other ranks are still waiting in. The case it is for: on 2 ranks one rank's
// MueLu V-cycle throws (a Tpetra check of that rank's local sizes) while the other waits in
// the V-cycle's next export for it. A blocking agreement on the phase's communicator would
// wait forever beside that export (and would mismatch it: collectives on one communicator
// must come in the same order on every rank). This one runs on a duplicate of it, and a
// failing rank waits for the others a limited time only, then ends the whole job
// (MPI_Abort) with its message: "an error on one rank ends the whole job" holds where no
// rank can come back to say so.

#include <mpi.h>

#include <string>

#include "assembly/tpetra_types.hpp"

namespace grout {

/// The time a failing rank waits for the others (seconds): the environment variable
/// GROUT_STALL_LIMIT if it holds a positive number, else 30.
double stall_limit_seconds();

class TimedAgreement {
 public:
  /// Collective on `comm`: duplicates it (MPI_COMM_SELF for a serial communicator).
  explicit TimedAgreement(const Comm& comm);
  ~TimedAgreement();
  TimedAgreement(const TimedAgreement&) = delete;
  TimedAgreement& operator=(const TimedAgreement&) = delete;

  /// The highest `code` over the ranks; 0 when no rank failed (every rank calls it, once per
  /// phase, whatever its outcome). A rank whose phase succeeded (`code` 0) waits for the
  /// others without limit: a failing rank either arrives or ends the job. A rank with
  /// `code` > 0 waits at most `limit_s`; when some rank has not arrived by then (it waits
  /// inside the phase for this one), it prints "grout: error: <message> (rank r; ...)" to
  /// standard error and calls MPI_Abort(MPI_COMM_WORLD, exit_code).
  int highest(int code, const std::string& message, int exit_code, double limit_s) const;

  /// Whether it was built on `comm` (the same communicator object's MPI communicator).
  bool built_on(const Comm& comm) const;

 private:
  MPI_Comm parent_ = MPI_COMM_NULL, own_ = MPI_COMM_NULL;
};

}  // namespace grout
