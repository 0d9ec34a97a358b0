#pragma once
// The MPI communicator behind a Teuchos communicator, for the few places that call MPI or
// MUMPS directly (MPI_COMM_SELF for a serial one).

#include <mpi.h>

#include <Teuchos_DefaultMpiComm.hpp>

#include "assembly/tpetra_types.hpp"

namespace grout {

inline MPI_Comm raw_mpi_comm(const Comm& comm) {
  if (const auto* mpi = dynamic_cast<const Teuchos::MpiComm<int>*>(&comm))
    return (*mpi->getRawMpiComm())();
  return MPI_COMM_SELF;
}

}  // namespace grout
