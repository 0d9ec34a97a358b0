#include "assembly/agree_on_errors.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <exception>

#include "io/errors.hpp"

namespace grout {

void agree_on_errors(const Comm& comm, const std::function<void()>& phase) {
  std::exception_ptr error;
  try {
    phase();
  } catch (...) {
    error = std::current_exception();
  }
  if (comm.getSize() == 1) {
    if (error) std::rethrow_exception(error);
    return;
  }
  bool relayed = false;  // an ErrorOnOtherRank: its message was printed elsewhere
  if (error) {
    try {
      std::rethrow_exception(error);
    } catch (const ErrorOnOtherRank&) {
      relayed = true;
    } catch (...) {
    }
  }
  // Reporter: the lowest rank with an error of its own, encoded as rank * 256 + exit code
  // (min over ranks); relayed codes: max over ranks.
  const int rank = comm.getRank(), none = comm.getSize() * 256;
  const int code = error ? exit_code_of(error) & 255 : 0;
  int local[2] = {error && !relayed ? rank * 256 + code : none, relayed ? code : 0};
  int global[2] = {none, 0};
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MIN, 1, &local[0], &global[0]);
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, 1, &local[1], &global[1]);
  if (global[0] == none && global[1] == 0) return;  // no rank failed
  if (global[0] != none && global[0] / 256 == rank) std::rethrow_exception(error);
  throw ErrorOnOtherRank(global[0] != none ? global[0] % 256 : global[1]);
}

}  // namespace grout
