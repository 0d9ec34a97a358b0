#include "parallel/distributed_bodies.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <algorithm>
#include <numeric>

namespace grout {

namespace {

// Union-find root with path halving.
GlobalIndex root(std::vector<GlobalIndex>& parent, GlobalIndex n) {
  while (parent[n] != n) n = parent[n] = parent[parent[n]];
  return n;
}

// The local component of each local node: the root of a union-find over the local elements.
std::vector<GlobalIndex> local_components(const Mesh& local) {
  std::vector<GlobalIndex> parent(local.num_nodes());
  std::iota(parent.begin(), parent.end(), GlobalIndex(0));
  for (const ElementBlock& block : local.blocks) {
    const int k = block.nodes_per_element;
    for (std::size_t e = 0; k > 0 && e + k <= block.connectivity.size(); e += k) {
      const GlobalIndex first = root(parent, block.connectivity[e]);
      for (int a = 1; a < k; ++a) {
        const GlobalIndex other = root(parent, block.connectivity[e + a]);
        if (other != first) parent[other] = first;
      }
    }
  }
  for (GlobalIndex n = 0; n < GlobalIndex(parent.size()); ++n) parent[n] = root(parent, n);
  return parent;
}

}  // namespace

std::vector<GlobalIndex> distributed_node_body_labels(const Comm& comm,
                                                      const DistributedMesh& mesh) {
  const auto comm_rcp = Teuchos::rcpFromRef(comm);
  const std::size_t num_local = mesh.node_gid.size(), num_owned = std::size_t(mesh.num_owned_nodes);
  const std::vector<GO> gids(mesh.node_gid.begin(), mesh.node_gid.end());
  const auto invalid = Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid();
  const auto owned_map = Teuchos::rcp(new Map(invalid, gids.data(), num_owned, 0, comm_rcp));
  const auto local_map = Teuchos::rcp(new Map(invalid, gids.data(), num_local, 0, comm_rcp));
  const Import importer(owned_map, local_map);

  // A label l is held as N - l (N: the mesh's node count), positive, exact in a double, so
  // that Tpetra's ABSMAX takes the lowest label (Tpetra has no MIN).
  const double N = double(mesh.global_num_nodes);
  std::vector<GlobalIndex> label(mesh.node_gid.begin(), mesh.node_gid.end());
  const std::vector<GlobalIndex> component = local_components(mesh.local);
  std::vector<GlobalIndex> lowest(num_local);
  Vector local_labels(local_map), owned_labels(owned_map);
  for (int changed = 1; changed;) {
    // Each local component's lowest label, to all its nodes.
    for (std::size_t n = 0; n < num_local; ++n) lowest[n] = label[n];
    for (std::size_t n = 0; n < num_local; ++n)
      lowest[component[n]] = std::min(lowest[component[n]], label[n]);
    {
      auto v = local_labels.getLocalViewHost(Tpetra::Access::OverwriteAll);
      for (std::size_t n = 0; n < num_local; ++n) v(n, 0) = N - double(lowest[component[n]]);
    }
    // The lowest label of each shared node over the ranks that hold it, then back to them.
    owned_labels.putScalar(0.0);
    owned_labels.doExport(local_labels, importer, Tpetra::ABSMAX);
    local_labels.doImport(owned_labels, importer, Tpetra::INSERT);
    int changed_here = 0;
    {
      auto v = local_labels.getLocalViewHost(Tpetra::Access::ReadOnly);
      for (std::size_t n = 0; n < num_local; ++n) {
        const GlobalIndex l = GlobalIndex(N - v(n, 0));
        if (l != label[n]) changed_here = 1;
        label[n] = l;
      }
    }
    Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, changed_here, Teuchos::outArg(changed));
  }
  return label;
}

DistributedBodies distributed_node_bodies(const Comm& comm, const DistributedMesh& mesh) {
  const std::size_t num_owned = std::size_t(mesh.num_owned_nodes);
  const std::vector<GlobalIndex> label = distributed_node_body_labels(comm, mesh);

  // Roots: owned nodes labelled with their own id, one per body; a body's index is its root's
  // place among all roots in ascending id (node_bodies's numbering).
  std::vector<long long> roots;
  for (std::size_t n = 0; n < num_owned; ++n)
    if (label[n] == mesh.node_gid[n]) roots.push_back(mesh.node_gid[n]);
  const int ranks = comm.getSize();
  const int count = int(roots.size());
  std::vector<int> counts(ranks), offsets(ranks + 1, 0);
  Teuchos::gatherAll(comm, 1, &count, ranks, counts.data());
  for (int r = 0; r < ranks; ++r) offsets[r + 1] = offsets[r] + counts[r];
  std::vector<long long> all_roots(static_cast<std::size_t>(offsets[ranks]));
  Teuchos::gatherv(roots.data(), count, all_roots.data(), counts.data(), offsets.data(), 0, comm);
  Teuchos::broadcast(comm, 0, int(all_roots.size()), all_roots.data());
  std::sort(all_roots.begin(), all_roots.end());

  DistributedBodies bodies;
  bodies.num_bodies = int(all_roots.size());
  bodies.owned_node_body.resize(num_owned);
  for (std::size_t n = 0; n < num_owned; ++n)
    bodies.owned_node_body[n] =
        int(std::lower_bound(all_roots.begin(), all_roots.end(), label[n]) - all_roots.begin());
  return bodies;
}

}  // namespace grout
