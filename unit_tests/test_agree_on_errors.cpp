// agree_on_errors: an error one rank alone finds ends every rank, with one message (on the
// lowest rank that has its own error) and one exit code. Runs on 1 and 2 ranks.

#include <gtest/gtest.h>

#include <Tpetra_Core.hpp>
#include <stdexcept>
#include <string>

#include "assembly/agree_on_errors.hpp"
#include "io/errors.hpp"

namespace grout {
namespace {

/// The exception agree_on_errors throws on this rank: "" if none, else its message.
std::string outcome(const Comm& comm, const std::function<void()>& phase, int* code = nullptr) {
  try {
    agree_on_errors(comm, phase);
    return "";
  } catch (const ErrorOnOtherRank& e) {
    if (code) *code = e.exit_code();
    return "other rank";
  } catch (...) {
    if (code) *code = exit_code_of(std::current_exception());
    return message_of(std::current_exception());
  }
}

TEST(AgreeOnErrors, NoErrorNoThrow) {
  const auto comm = Tpetra::getDefaultComm();
  int calls = 0;
  EXPECT_EQ(outcome(*comm, [&] { ++calls; }), "");
  EXPECT_EQ(calls, 1);
}

TEST(AgreeOnErrors, AnErrorOnTheLastRankAloneStopsEveryRank) {
  const auto comm = Tpetra::getDefaultComm();
  const int rank = comm->getRank(), last = comm->getSize() - 1;
  int code = 0;
  const std::string what = outcome(
      *comm,
      [&] {
        if (rank == last) throw InputError("f.yaml: found on the last rank");
      },
      &code);
  EXPECT_EQ(code, 2);
  EXPECT_EQ(what, rank == last ? "f.yaml: found on the last rank" : "other rank");
}

TEST(AgreeOnErrors, TheLowestRankWithItsOwnErrorReportsIt) {
  const auto comm = Tpetra::getDefaultComm();
  const int rank = comm->getRank();
  int code = 0;
  const std::string what = outcome(
      *comm, [&] { throw ExitCodeError("rank " + std::to_string(rank), 3); }, &code);
  EXPECT_EQ(code, 3);
  EXPECT_EQ(what, rank == 0 ? "rank 0" : "other rank");
  // Not a std::exception (NOX throws string literals): exit code 1, message kept.
  code = 0;
  const std::string literal = outcome(
      *comm, [&] { throw "NOX Error"; }, &code);
  EXPECT_EQ(code, 1);
  EXPECT_EQ(literal, rank == 0 ? "NOX Error" : "other rank");
}

TEST(AgreeOnErrors, NestedAgreementsRelayTheCode) {
  const auto comm = Tpetra::getDefaultComm();
  const int rank = comm->getRank(), last = comm->getSize() - 1;
  int code = 0;
  const std::string what = outcome(
      *comm,
      [&] {
        agree_on_errors(*comm, [&] {
          if (rank == last) throw InputError("inner");
        });
      },
      &code);
  EXPECT_EQ(code, 2);
  EXPECT_EQ(what, rank == last ? "inner" : "other rank");
}

}  // namespace
}  // namespace grout
