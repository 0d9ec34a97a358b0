#pragma once
// The mesh is read on rank 0 and broadcast to every rank (replicated plain data).

#include <functional>

#include "assembly/tpetra_types.hpp"
#include "io/mesh.hpp"

namespace grout {

/// Call `read` on rank 0 and broadcast its mesh. If it throws InputError on rank 0, every
/// rank throws an InputError with the same message (so no rank hangs).
Mesh read_and_broadcast_mesh(const Comm& comm, const std::function<Mesh()>& read);

}  // namespace grout
