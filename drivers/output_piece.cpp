#include "drivers/output_piece.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <algorithm>
#include <map>
#include <unordered_map>

#include "assembly/raw_mpi_comm.hpp"

namespace grout {

namespace {

/// The position of `value` in the sorted `sorted`, or -1.
long long position(const std::vector<GlobalIndex>& sorted, GlobalIndex value) {
  const auto it = std::lower_bound(sorted.begin(), sorted.end(), value);
  return it != sorted.end() && *it == value ? it - sorted.begin() : -1;
}

/// MPI_Alltoallv of long longs: `send[r]` to rank r; returns what each rank sent here.
std::vector<std::vector<long long>> all_to_all(MPI_Comm comm,
                                               const std::vector<std::vector<long long>>& send) {
  const int ranks = int(send.size());
  std::vector<int> send_counts(ranks), recv_counts(ranks), send_offsets(ranks), recv_offsets(ranks);
  std::vector<long long> send_buffer;
  for (int r = 0; r < ranks; ++r) {
    send_counts[r] = int(send[r].size());
    send_offsets[r] = int(send_buffer.size());
    send_buffer.insert(send_buffer.end(), send[r].begin(), send[r].end());
  }
  MPI_Alltoall(send_counts.data(), 1, MPI_INT, recv_counts.data(), 1, MPI_INT, comm);
  int total = 0;
  for (int r = 0; r < ranks; ++r) {
    recv_offsets[r] = total;
    total += recv_counts[r];
  }
  std::vector<long long> recv_buffer(total);
  MPI_Alltoallv(send_buffer.data(), send_counts.data(), send_offsets.data(), MPI_LONG_LONG,
                recv_buffer.data(), recv_counts.data(), recv_offsets.data(), MPI_LONG_LONG, comm);
  std::vector<std::vector<long long>> received(ranks);
  for (int r = 0; r < ranks; ++r)
    received[r].assign(recv_buffer.begin() + recv_offsets[r],
                       recv_buffer.begin() + recv_offsets[r] + recv_counts[r]);
  return received;
}

/// For each of `nodes` (this rank's file nodes, ascending), the other ranks whose files hold
/// it: each node's owner (the solid's owned map) collects who holds it and answers.
std::vector<std::vector<int>> sharers(const SolidProblem& solid,
                                      const std::vector<GlobalIndex>& nodes) {
  const Comm& comm = *solid.comm();
  const int ranks = comm.getSize(), rank = comm.getRank(), dim = solid.dimension();
  std::vector<GO> dofs(nodes.size());
  for (std::size_t i = 0; i < nodes.size(); ++i) dofs[i] = GO(nodes[i]) * dim;
  std::vector<int> owner(nodes.size());
  solid.owned_map()->getRemoteIndexList(Teuchos::ArrayView<const GO>(dofs),
                                        Teuchos::ArrayView<int>(owner));
  std::vector<std::vector<long long>> requests(ranks);
  for (std::size_t i = 0; i < nodes.size(); ++i) requests[owner[i]].push_back(nodes[i]);
  const MPI_Comm raw = raw_mpi_comm(comm);
  const auto asked = all_to_all(raw, requests);
  // Owner: the ranks holding each owned node that anyone asked about, in rank order.
  std::unordered_map<long long, std::vector<int>> holders;
  for (int r = 0; r < ranks; ++r)
    for (long long node : asked[r]) holders[node].push_back(r);
  // Answer every request with: count, then the holders.
  std::vector<std::vector<long long>> answers(ranks);
  for (int r = 0; r < ranks; ++r)
    for (long long node : asked[r]) {
      const auto& h = holders[node];
      answers[r].push_back(static_cast<long long>(h.size()));
      answers[r].insert(answers[r].end(), h.begin(), h.end());
    }
  const auto answered = all_to_all(raw, answers);
  std::vector<std::vector<int>> out(nodes.size());
  std::vector<std::size_t> next(ranks, 0);  // read position in each owner's answer
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    const auto& a = answered[owner[i]];
    std::size_t& at = next[owner[i]];
    const long long count = a[at++];
    for (long long k = 0; k < count; ++k, ++at)
      if (a[at] != rank) out[i].push_back(int(a[at]));
  }
  return out;
}

}  // namespace

OutputPiece make_output_piece(const Mesh& mesh, const SolidProblem& solid,
                              const DistributedMesh* distributed) {
  const Comm& comm = *solid.comm();
  const int dim = solid.dimension();
  OutputPiece piece;
  ExodusPiece& ex = piece.exodus;
  ex.processor = comm.getRank();
  ex.num_processors = comm.getSize();
  ex.num_global_nodes = solid.num_global_nodes();
  const auto& blocks = solid.local_blocks();

  // Nodes: those of the owned elements, and owned nodes of no local element (no element at
  // all: a local block holds every element touching an owned node).
  const auto coordinates = solid.column_coordinates();
  const std::size_t num_column = coordinates.extent(0);
  std::vector<char> used(num_column, 0);
  for (const auto& b : blocks)
    for (std::size_t e = 0; e < b.nodes.extent(0); ++e)
      for (int a = 0; a < b.nodes_per_element; ++a) used[b.nodes(e, a)] |= b.owned(e) ? 3 : 1;
  std::vector<std::pair<GlobalIndex, int>> nodes;  // (global, column index)
  for (std::size_t k = 0; k < num_column; ++k)
    if ((used[k] & 2) || (used[k] == 0 && int(k) < solid.num_owned_nodes()))
      nodes.emplace_back(solid.column_node(int(k)), int(k));
  std::sort(nodes.begin(), nodes.end());
  std::vector<int> local_of_column(num_column, -1);
  piece.mesh.file = mesh.file;
  piece.mesh.dimension = dim;
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    ex.node_ids.push_back(nodes[i].first);
    local_of_column[nodes[i].second] = int(i);
    for (int d = 0; d < dim; ++d) piece.mesh.coordinates.push_back(coordinates(nodes[i].second, d));
  }

  // Elements, block by block (the solid's blocks are the mesh's, in order).
  std::unordered_map<GlobalIndex, GlobalIndex> local_element;
  std::vector<GlobalIndex> block_counts;
  for (std::size_t b = 0; b < blocks.size(); ++b) {
    const LocalBlock& lb = blocks[b];
    ElementBlock block;
    block.name = mesh.blocks[b].name;
    block.id = mesh.blocks[b].id;
    block.topology = lb.topology;
    block.nodes_per_element = lb.nodes_per_element;
    block.first_element = GlobalIndex(ex.element_ids.size());
    for (std::size_t e = 0; e < lb.nodes.extent(0); ++e) {
      if (!lb.owned(e)) continue;
      local_element[lb.global(e)] = GlobalIndex(ex.element_ids.size());
      ex.element_ids.push_back(lb.global(e));
      for (int a = 0; a < lb.nodes_per_element; ++a)
        block.connectivity.push_back(local_of_column[lb.nodes(e, a)]);
    }
    block_counts.push_back(block.num_elements());
    piece.mesh.blocks.push_back(std::move(block));
  }

  // Sets: the entries of this piece; whole-mesh sizes from the entries each rank owns. A
  // part's sets hold the file's entries of its local entities, in the file's order.
  const auto global_element = [&](GlobalIndex e) {
    return distributed ? distributed->element_gid[std::size_t(e)] : e;
  };
  const auto global_node = [&](GlobalIndex n) {
    return distributed ? distributed->node_gid[std::size_t(n)] : n;
  };
  std::vector<GlobalIndex> set_counts;
  for (const SideSet& set : mesh.side_sets) {
    SideSet s{set.name, set.id, {}, {}};
    for (std::size_t i = 0; i < set.elements.size(); ++i) {
      const auto it = local_element.find(global_element(set.elements[i]));
      if (it == local_element.end()) continue;
      s.elements.push_back(it->second);
      s.sides.push_back(set.sides[i]);
    }
    set_counts.push_back(GlobalIndex(s.elements.size()));
    piece.mesh.side_sets.push_back(std::move(s));
  }
  const auto owned_map = solid.owned_map();
  for (const NodeSet& set : mesh.node_sets) {
    NodeSet s{set.name, set.id, {}};
    GlobalIndex owned = 0;
    for (GlobalIndex local_node : set.nodes) {
      const GlobalIndex node = global_node(local_node);
      const long long i = position(ex.node_ids, node);
      if (i >= 0) s.nodes.push_back(i);
      owned += owned_map->isNodeGlobalElement(GO(node) * dim) ? 1 : 0;
    }
    set_counts.push_back(owned);
    piece.mesh.node_sets.push_back(std::move(s));
  }
  block_counts.push_back(GlobalIndex(ex.element_ids.size()));
  std::vector<GlobalIndex> totals(block_counts.size() + set_counts.size());
  std::vector<GlobalIndex> local(block_counts);
  local.insert(local.end(), set_counts.begin(), set_counts.end());
  Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, int(local.size()), local.data(), totals.data());
  const std::size_t nb = mesh.blocks.size(), nss = mesh.side_sets.size();
  ex.global_block_sizes.assign(totals.begin(), totals.begin() + nb);
  ex.num_global_elements = totals[nb];
  ex.global_side_set_sizes.assign(totals.begin() + nb + 1, totals.begin() + nb + 1 + nss);
  ex.global_node_set_sizes.assign(totals.begin() + nb + 1 + nss, totals.end());

  // Border nodes and elements, and one communication map per neighbouring rank.
  const auto shared = sharers(solid, ex.node_ids);
  ex.border_node.assign(ex.node_ids.size(), 0);
  std::map<int, std::vector<GlobalIndex>> maps;
  for (std::size_t i = 0; i < shared.size(); ++i) {
    ex.border_node[i] = shared[i].empty() ? 0 : 1;
    for (int r : shared[i]) maps[r].push_back(GlobalIndex(i));
  }
  for (auto& [r, list] : maps) ex.node_maps.push_back({r, std::move(list)});
  for (const auto& block : piece.mesh.blocks)
    for (GlobalIndex e = 0; e < block.num_elements(); ++e) {
      char border = 0;
      for (int a = 0; a < block.nodes_per_element; ++a)
        border |= ex.border_node[block.connectivity[e * block.nodes_per_element + a]];
      ex.border_element.push_back(border);
    }
  return piece;
}

}  // namespace grout
