#pragma once
// Results of every converged step: gathered to rank 0, written to Exodus (docs/design.md §5
// field names) and to the CSV summary, both flushed at once. The files are written under
// temporary names and moved into place at the first converged step (output_files.hpp).

#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "assembly/solid_problem.hpp"
#include "io/exodus.hpp"
#include "io/output_files.hpp"
#include "nonlinear/load_stepping.hpp"

namespace grout {

class ResultsOutput {
 public:
  ResultsOutput(const Mesh& mesh, const Input& input, const SolidProblem& solid,
                const MechanicsProblem& problem);
  void write(const ConvergedStep& step);

 private:
  /// Nodal values [component][node] of an owned dof vector, on every rank.
  std::vector<std::vector<double>> gather_nodal(const Vector& v) const;

  const Mesh& mesh_;
  const Input& input_;
  const SolidProblem& solid_;
  const MechanicsProblem& problem_;
  bool root_ = false;
  std::vector<std::string> global_names_;
  std::size_t reaction_globals_end_ = 0;  ///< reaction sums are [first_reaction, this)
  std::unique_ptr<ExodusWriter> exodus_;
  std::unique_ptr<OutputCommit> commit_;  ///< temporary names -> final names
  CheckedTextFile summary_;
  CheckedTextFile newton_log_;              ///< per Newton iteration of every converged step
  CheckedTextFile profile_;                 ///< 2D: slave-node contact results along the interface
  std::vector<GlobalIndex> profile_nodes_;  ///< slave nodes sorted by x, then y
};

}  // namespace grout
