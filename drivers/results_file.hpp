#pragma once
// The Exodus results of a run, written from what each rank owns (docs/input.md,
// `output/parallel`): `single`, one file that rank 0 writes, receiving one variable at a
// time (RootGather); `per_rank`, one file per rank with its own elements and their nodes
// (make_output_piece), node values brought from their owners by a Tpetra Import. From the
// distributed mesh under `single` rank 0 writes the mesh too as it receives it, one array at
// a time (drivers/gathered_geometry.hpp); under `per_rank` each rank cuts its piece from its
// part.
//
// Every call is collective. A file error on one rank is kept and thrown by end_step() after
// the step's last collective call, so that no rank waits in a gather (agree_on_errors).

#include <exception>
#include <memory>
#include <string>
#include <vector>

#include "assembly/solid_problem.hpp"
#include "drivers/output_piece.hpp"
#include "drivers/root_gather.hpp"
#include "io/exodus.hpp"
#include "parallel/distributed_mesh.hpp"

namespace grout {

struct ResultsFileNames {
  std::vector<std::string> nodal, element, global;
};

class ResultsFile {
 public:
  /// Collective: what each rank contributes, and under per_rank its piece of the mesh.
  /// `distributed`: `mesh` is this rank's part of that mesh (it must outlive write_mesh());
  /// nullptr: `mesh` is the replicated mesh.
  ResultsFile(const Mesh& mesh, const SolidProblem& solid, bool per_rank,
              const DistributedMesh* distributed = nullptr);
  /// Not collective: creates the file this rank writes (`path`, a temporary name; under
  /// `single` rank 0 only), and throws InputError naming it when it cannot.
  void open(const std::string& path, const ResultsFileNames& names,
            const ExodusProvenance& provenance);
  /// Collective, after open() on rank 0 (or its failure): the distributed mesh's arrays into
  /// the file; nothing for the replicated mesh, which open() writes whole. A file error is
  /// kept for end_step(), as a step's.
  void write_mesh();

  /// The global nodes whose values nodal() takes, ascending (the solid's owned nodes).
  const std::vector<GlobalIndex>& owned_nodes() const { return owned_nodes_; }

  void begin_step(double time);
  /// Nodal variable `v` (constructor order): one value per owned node.
  void nodal(std::size_t v, const std::vector<double>& owned);
  /// Element variable `v`: one value per element of SolidProblem::owned_elements().
  void element(std::size_t v, const std::vector<double>& owned);
  /// The globals, the same on every rank.
  void globals(const std::vector<double>& values);
  /// Flushes the step; throws the first file error of the step on the rank that had it.
  void end_step();

 private:
  template <class Write>
  void guarded(Write&& write);

  const Mesh& mesh_;
  const Comm& comm_;
  bool per_rank_ = false;
  const DistributedMesh* distributed_ = nullptr;
  std::unique_ptr<OutputPiece> piece_;  ///< per_rank, until open()
  std::vector<GlobalIndex> owned_nodes_;
  std::unique_ptr<RootGather> nodes_to_root_, elements_to_root_;  ///< single
  Teuchos::RCP<const Map> node_map_, file_node_map_;              ///< per_rank
  Teuchos::RCP<Import> to_file_nodes_;                            ///< per_rank
  std::unique_ptr<ExodusWriter> writer_;                          ///< where this rank writes
  std::exception_ptr error_;
};

}  // namespace grout
