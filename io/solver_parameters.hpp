#pragma once
// The names the solver packages behind Grout accept in the `grout/solver` sublists passed
// through to them (docs/input.md, "grout/solver"), as schema keys (io/input_schema.hpp), so that
// a misspelt or mistyped name is an input error with a "did you mean" before anything is built:
// - Belos 13.2: every parameter of every solver of Belos::SolverFactory (each solver manager's
//   getValidParameters()), except those no YAML can give (`Output Stream`, `User Status
//   Tests`); bounds where a value would fail every solve (`Maximum Iterations` ≥ 1, ...).
//   Belos checks the names of one solver at construction (linear_solver.hpp, `type: belos`).
// - MueLu 13.2: the names of MueLu::MasterList::List() (MueLu_MasterList.cpp) and `level <n>`
//   sublists of the same names; the `... params` sublists go on to Ifpack2 and Zoltan2, which
//   check them.
// - NOX 13.2: the sublists and names the NOX documentation gives for the solvers Grout drives
//   (a line-search or trust-region Newton: NOX_Solver_LineSearchBased.H, NOX_LineSearch_*.H,
//   NOX_Direction_Newton.H, NOX_Utils.H); NOX checks the values when it builds its solver.

#include <Teuchos_ParameterList.hpp>
#include <vector>

#include "io/input_schema.hpp"

namespace grout::input_schema {

/// The keys of the `Belos` sublist (`Solver Type` included).
std::vector<Key> belos_keys();

/// The keys of a `MueLu` sublist `given` (its `level <n>` sublists included).
std::vector<Key> muelu_keys(const Teuchos::ParameterList& given);

/// A copy of the list that `section` validated, each `number` key a double (YAML's `1` is an
/// int, which Belos and MueLu refuse where they take a double).
Teuchos::ParameterList typed_copy(const Section& section);

/// The `MueLu` sublist of `linear`, validated (level sublists too) and typed.
Teuchos::ParameterList read_muelu(const Section& linear);

/// The `NOX` sublist of `solver`, validated (its sublists too) and typed.
Teuchos::ParameterList read_nox(const Section& solver);

}  // namespace grout::input_schema
