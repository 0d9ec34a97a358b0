#pragma once
// The mesh is read on rank 0 and broadcast to every rank (replicated plain data).

#include <functional>

#include "assembly/tpetra_types.hpp"
#include "io/mesh.hpp"

namespace grout {

/// Call `read` on rank 0 and broadcast its mesh. If it throws anything on rank 0, every rank
/// throws (agree_on_errors: rank 0 rethrows its error, the others ErrorOnOtherRank with its
/// exit code), so no rank waits for a mesh that will not come.
Mesh read_and_broadcast_mesh(const Comm& comm, const std::function<Mesh()>& read);

}  // namespace grout
