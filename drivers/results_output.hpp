#pragma once
// Results of every converged step, written to Exodus (docs/design.md §5 field names; one file
// by rank 0 or one per rank, results_file.hpp) and to the CSV summary (rank 0), flushed at
// once. Each rank hands over what it owns, one variable at a time: no rank holds a
// whole-mesh array but rank 0, for the variable it is writing. The files are written under
// temporary names and moved into place at the first converged step (output_files.hpp).

#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "assembly/solid_problem.hpp"
#include "drivers/results_file.hpp"
#include "drivers/root_gather.hpp"
#include "io/exodus.hpp"
#include "io/output_files.hpp"
#include "nonlinear/load_stepping.hpp"

namespace grout {

class ResultsOutput {
 public:
  /// Collective. `distributed`: `mesh` is this rank's part of that mesh (both must outlive the
  /// ResultsOutput); nullptr: the replicated mesh.
  ResultsOutput(const Mesh& mesh, const Input& input, const SolidProblem& solid,
                const MechanicsProblem& problem, const DistributedMesh* distributed = nullptr);
  void write(const ConvergedStep& step);

 private:
  /// Component `d` of a dof vector at the owned nodes (ResultsFile::owned_nodes order).
  std::vector<double> component(const Vector& v, int d) const;
  /// This rank's files under their temporary names (not collective; may throw).
  void open_files(const Input& input, const std::vector<std::string>& nodal);
  /// Position of a global node among the owned nodes.
  std::size_t owned_position(GlobalIndex node) const;

  /// A reaction sum reaction_<set>_<axis>: the set's entries this rank owns, summed on
  /// rank 0 in the order of the set (as one rank would).
  struct SetSum {
    int axis = 0;
    std::vector<std::size_t> owned;  ///< owned position of each of this rank's entries
    std::unique_ptr<RootGather> to_root;
  };

  const Mesh& mesh_;
  const Input& input_;
  const SolidProblem& solid_;
  const MechanicsProblem& problem_;
  const DistributedMesh* distributed_ = nullptr;
  bool root_ = false;
  bool profile_wanted_ = false;  ///< 2D contact with a summary (every rank knows)
  std::vector<std::string> global_names_;
  std::vector<SetSum> reaction_sums_;  ///< one per global in [first_reaction, ...)
  std::unique_ptr<ResultsFile> exodus_;
  std::unique_ptr<OutputCommit> commit_;  ///< temporary names -> final names (this rank's files)
  CheckedTextFile summary_;
  CheckedTextFile newton_log_;  ///< per Newton iteration of every converged step
  CheckedTextFile profile_;     ///< 2D: slave-node contact results along the interface
  std::unique_ptr<RootGather> profile_to_root_;  ///< this rank's slave nodes, in received order
  std::vector<double> profile_x_, profile_y_;    ///< rank 0: their coordinates, as received
  std::vector<std::size_t> profile_order_;       ///< rank 0: received entries by x, then y
};

}  // namespace grout
