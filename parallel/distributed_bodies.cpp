#include "parallel/distributed_bodies.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_Vector.hpp>
#include <numeric>

namespace grout {

namespace {

GlobalIndex root(std::vector<GlobalIndex>& parent, GlobalIndex n) {
  while (parent[n] != n) n = parent[n] = parent[parent[n]];
  return n;
}

}  // namespace

std::vector<GlobalIndex> distributed_node_bodies(const Comm& comm, const DistributedMesh& mesh) {
  const GlobalIndex n_local = mesh.num_local_nodes();
  // The local components (union-find over the local elements' nodes), fixed.
  std::vector<GlobalIndex> parent(static_cast<std::size_t>(n_local));
  std::iota(parent.begin(), parent.end(), GlobalIndex(0));
  for (const ElementBlock& block : mesh.local.blocks) {
    const int k = block.nodes_per_element;
    for (std::size_t e = 0; k > 0 && e + k <= block.connectivity.size(); e += k) {
      GlobalIndex first = root(parent, block.connectivity[e]);
      for (int a = 1; a < k; ++a) {
        const GlobalIndex other = root(parent, block.connectivity[e + a]);
        if (other != first) parent[std::max(other, first)] = std::min(other, first);
        first = std::min(other, first);
      }
    }
  }
  std::vector<GlobalIndex> component(static_cast<std::size_t>(n_local));
  for (GlobalIndex n = 0; n < n_local; ++n) component[n] = root(parent, n);

  // Labels as values N − label on the nodes' maps, so that the largest (Tpetra's ABSMAX) is the
  // lowest label (node numbers below 2^53 are exact in a double).
  const auto rcp_comm = Teuchos::rcpFromRef(comm);
  const auto invalid = Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid();
  std::vector<GO> owned(mesh.node_gid.begin(), mesh.node_gid.begin() + mesh.num_owned_nodes);
  std::vector<GO> held(mesh.node_gid.begin(), mesh.node_gid.end());
  const auto owned_map = Teuchos::rcp(new Map(invalid, owned.data(), owned.size(), 0, rcp_comm));
  const auto held_map = Teuchos::rcp(new Map(invalid, held.data(), held.size(), 0, rcp_comm));
  const Import import(owned_map, held_map);
  const double N = double(mesh.global_num_nodes);
  std::vector<GlobalIndex> label(mesh.node_gid.begin(), mesh.node_gid.end());
  Vector on_owned(owned_map), on_held(held_map);
  for (;;) {
    // The lowest label of each local component.
    std::vector<GlobalIndex> lowest(std::size_t(n_local), mesh.global_num_nodes);
    for (GlobalIndex n = 0; n < n_local; ++n)
      lowest[component[n]] = std::min(lowest[component[n]], label[n]);
    {
      auto v = on_held.getLocalViewHost(Tpetra::Access::OverwriteAll);
      for (GlobalIndex n = 0; n < n_local; ++n) v(n, 0) = N - double(lowest[component[n]]);
    }
    on_owned.putScalar(0.0);
    on_owned.doExport(on_held, import, Tpetra::ABSMAX);
    on_held.doImport(on_owned, import, Tpetra::INSERT);
    int changed = 0, changed_any = 0;
    {
      const auto v = on_held.getLocalViewHost(Tpetra::Access::ReadOnly);
      for (GlobalIndex n = 0; n < n_local; ++n) {
        const auto l = GlobalIndex(N - v(n, 0));
        if (l != label[n]) changed = 1;
        label[n] = l;
      }
    }
    Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, changed, Teuchos::outArg(changed_any));
    if (!changed_any) return label;
  }
}

}  // namespace grout
