#include "drivers/results_file.hpp"

#include <stdexcept>
#include <utility>

#include "drivers/gathered_geometry.hpp"

namespace grout {

ResultsFile::ResultsFile(const Mesh& mesh, const SolidProblem& solid, bool per_rank,
                         const DistributedMesh* distributed)
    : mesh_(mesh), comm_(*solid.comm()), per_rank_(per_rank), distributed_(distributed) {
  const Comm& comm = comm_;
  for (int k = 0; k < solid.num_owned_nodes(); ++k) owned_nodes_.push_back(solid.column_node(k));
  if (!per_rank) {
    nodes_to_root_ = std::make_unique<RootGather>(comm, owned_nodes_, solid.num_global_nodes());
    elements_to_root_ =
        std::make_unique<RootGather>(comm, solid.owned_elements(), solid.num_global_elements());
    return;
  }
  piece_ = std::make_unique<OutputPiece>(make_output_piece(mesh, solid, distributed));
  const std::vector<GO> owned(owned_nodes_.begin(), owned_nodes_.end());
  const std::vector<GO> file_nodes(piece_->exodus.node_ids.begin(), piece_->exodus.node_ids.end());
  const auto invalid = Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid();
  node_map_ = Teuchos::rcp(
      new Map(GO(solid.num_global_nodes()), owned.data(), owned.size(), 0, solid.comm()));
  file_node_map_ =
      Teuchos::rcp(new Map(invalid, file_nodes.data(), file_nodes.size(), 0, solid.comm()));
  to_file_nodes_ = Teuchos::rcp(new Import(node_map_, file_node_map_));
}

void ResultsFile::open(const std::string& path, const ResultsFileNames& names,
                       const ExodusProvenance& provenance) {
  if (per_rank_) {
    writer_ = std::make_unique<ExodusWriter>(path, piece_->mesh, names.nodal, names.element,
                                             names.global, provenance, &piece_->exodus);
    piece_.reset();
  } else if (distributed_) {
    writer_ = std::make_unique<ExodusWriter>(path, distributed_outline(*distributed_), names.nodal,
                                             names.element, names.global, provenance);
  } else {
    writer_ = std::make_unique<ExodusWriter>(path, mesh_, names.nodal, names.element, names.global,
                                             provenance);
  }
}

void ResultsFile::write_mesh() {
  if (!distributed_ || per_rank_) return;  // a piece is written whole by open()
  const DistributedMesh& mesh = *distributed_;
  for (int d = 0; d < mesh.local.dimension; ++d) {
    const std::vector<double> x = gather_coordinates(comm_, mesh, d);
    guarded([&](ExodusWriter& w) { w.put_coordinates(d, x); });
  }
  for (std::size_t b = 0; b < mesh.local.blocks.size(); ++b) {
    const std::vector<GlobalIndex> nodes = gather_connectivity(comm_, mesh, b);
    guarded([&](ExodusWriter& w) { w.put_connectivity(b, nodes); });
  }
  for (std::size_t s = 0; s < mesh.local.side_sets.size(); ++s) {
    const auto set = gather_side_set(comm_, mesh, s);  // (elements, sides)
    guarded([&](ExodusWriter& w) { w.put_side_set(s, set.first, set.second); });
  }
  for (std::size_t s = 0; s < mesh.local.node_sets.size(); ++s) {
    const std::vector<GlobalIndex> nodes = gather_node_set(comm_, mesh, s);
    guarded([&](ExodusWriter& w) { w.put_node_set(s, nodes); });
  }
}

template <class Write>
void ResultsFile::guarded(Write&& write) {
  if (!writer_ || error_) return;
  try {
    write(*writer_);
  } catch (...) {
    error_ = std::current_exception();
  }
}

void ResultsFile::begin_step(double time) {
  guarded([&](ExodusWriter& w) { w.begin_step(time); });
}

void ResultsFile::nodal(std::size_t v, const std::vector<double>& owned) {
  if (!per_rank_) {
    const std::vector<double> whole = nodes_to_root_->gather(owned);
    guarded([&](ExodusWriter& w) { w.put_nodal(v, whole); });
    return;
  }
  Vector source(node_map_), target(file_node_map_);
  {
    auto view = source.getLocalViewHost(Tpetra::Access::OverwriteAll);
    for (std::size_t k = 0; k < owned.size(); ++k) view(k, 0) = owned[k];
  }
  target.doImport(source, *to_file_nodes_, Tpetra::INSERT);
  const auto view = target.getLocalViewHost(Tpetra::Access::ReadOnly);
  const std::vector<double> values(view.data(), view.data() + view.extent(0));
  guarded([&](ExodusWriter& w) { w.put_nodal(v, values); });
}

void ResultsFile::element(std::size_t v, const std::vector<double>& owned) {
  if (!per_rank_) {
    const std::vector<double> whole = elements_to_root_->gather(owned);
    guarded([&](ExodusWriter& w) { w.put_element(v, whole); });
    return;
  }
  guarded([&](ExodusWriter& w) { w.put_element(v, owned); });
}

void ResultsFile::globals(const std::vector<double>& values) {
  guarded([&](ExodusWriter& w) { w.put_globals(values); });
}

void ResultsFile::end_step() {
  guarded([&](ExodusWriter& w) { w.end_step(); });
  if (error_) std::rethrow_exception(std::exchange(error_, nullptr));
}

}  // namespace grout
