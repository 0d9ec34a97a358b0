#pragma once
#include <stdexcept>
#include <string>

namespace grout {

/// An error in what the user gave us (input file, mesh, expression). The message names the
/// file and the key or mesh entity; the driver prints it without a stack trace and exits 2.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace grout
