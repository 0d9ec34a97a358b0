// Migration to owners with one layer of ghost elements (parallel/migrate_mesh.hpp).
//
// The node directory (home: the rank whose node slice holds the node) learns, for each node,
// the sorted parts of the elements around it, parts(n), and those of its contact elements
// (a face on a contact side set), contact_parts(n). Then
//   owner(n)        = min contact_parts(n), or when it is empty min parts(n), or 0 when parts(n)
//                     is empty (a node of no element);
//   ranks(e)        = union of parts(n) over the nodes n of element e: e is owned on its part
//                     and a ghost on the others, exactly the elements that share a node with
//                     an element the rank owns (the one-layer ghost definition);
//   holders(n)      = the ranks that hold an element with node n (they ask the home for it).
// Set entries travel to their entity's home and on to the ranks holding the entity.

#include "parallel/migrate_mesh.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <algorithm>
#include <array>
#include <iterator>
#include <numeric>

#include "parallel/directory.hpp"
#include "parallel/slices.hpp"

namespace grout {

namespace {

using Messages = std::vector<std::vector<long long>>;

/// Sorted unique values.
template <class T>
void sort_unique(std::vector<T>& v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
}

/// parts(n) and owner(n) for the home's node slice, parts as CRS (offset per slice node).
struct NodeParts {
  std::vector<GlobalIndex> offset;
  std::vector<int> parts;
  std::vector<int> owner;
};

NodeParts gather_node_parts(const Comm& comm, const MeshHeader& h, const MeshSlices& s,
                            const std::vector<int>& element_part,
                            const std::vector<char>& contact) {
  const int ranks = comm.getSize();
  // (node, 2 part + 1), or 2 part for a contact element: each once; merged chunk by chunk so
  // that the pairs of all the element nodes (8 per hex) never sit in memory at once.
  std::vector<std::pair<GlobalIndex, int>> mine, chunk, merged;
  const GlobalIndex chunk_size = std::max<GlobalIndex>(1 << 15, s.num_elements() / 8 + 1);
  for (GlobalIndex first = 0; first < s.num_elements(); first += chunk_size) {
    chunk.clear();
    for (GlobalIndex e = first; e < std::min(s.num_elements(), first + chunk_size); ++e)
      for (GlobalIndex k = s.element_nodes_offset[e]; k < s.element_nodes_offset[e + 1]; ++k)
        chunk.emplace_back(s.element_nodes[k],
                           2 * element_part[e] + (contact.empty() || !contact[e] ? 1 : 0));
    sort_unique(chunk);
    merged.clear();
    std::set_union(mine.begin(), mine.end(), chunk.begin(), chunk.end(),
                   std::back_inserter(merged));
    mine.swap(merged);
  }
  chunk = {};
  merged = {};
  Messages pairs(static_cast<std::size_t>(ranks));
  for (const auto& [n, p] : mine) {
    auto& to = pairs[std::size_t(slice_rank(h.num_nodes, n, ranks))];
    to.push_back(n);
    to.push_back(p);
  }
  mine.clear();
  mine.shrink_to_fit();
  const std::vector<long long> got = send_to_ranks(comm, pairs);
  std::vector<std::pair<GlobalIndex, int>> node_part;
  node_part.reserve(got.size() / 2);
  for (std::size_t i = 0; i < got.size(); i += 2) node_part.emplace_back(got[i], int(got[i + 1]));
  sort_unique(node_part);
  NodeParts result;
  result.offset.assign(std::size_t(s.num_nodes() + 1), 0);
  result.owner.assign(std::size_t(s.num_nodes()), 0);
  std::vector<int> contact_owner(std::size_t(s.num_nodes()), -1);
  for (auto it = node_part.rbegin(); it != node_part.rend(); ++it) {  // descending: min last
    const std::size_t local = std::size_t(it->first - s.node_begin);
    result.owner[local] = it->second / 2;
    if (it->second % 2 == 0) contact_owner[local] = it->second / 2;
  }
  for (std::size_t n = 0; n < contact_owner.size(); ++n)
    if (contact_owner[n] >= 0) result.owner[n] = contact_owner[n];
  // parts(n): each part once.
  for (auto& np : node_part) np.second /= 2;
  sort_unique(node_part);
  for (const auto& [n, p] : node_part) ++result.offset[std::size_t(n - s.node_begin + 1)];
  std::partial_sum(result.offset.begin(), result.offset.end(), result.offset.begin());
  for (const auto& np : node_part) result.parts.push_back(np.second);
  return result;
}

/// Each slice element's ranks (ranks(e), CRS), from the parts of its nodes.
void element_ranks(const Comm& comm, const MeshHeader& h, const MeshSlices& s,
                   const NodeParts& node_parts, std::vector<GlobalIndex>& offset,
                   std::vector<int>& ranks_of) {
  const int ranks = comm.getSize();
  const std::vector<GlobalIndex> nodes = slice_element_nodes(s);
  const DirectoryQuestions q = ask_homes(comm, h.num_nodes, nodes);
  Messages replies(static_cast<std::size_t>(ranks));
  std::size_t at = 0;
  for (int r = 0; r < ranks; ++r)
    for (int i = 0; i < q.counts[std::size_t(r)]; ++i, ++at) {
      const GlobalIndex local = q.ids[at] - s.node_begin;
      const GlobalIndex b = node_parts.offset[local], e = node_parts.offset[local + 1];
      replies[std::size_t(r)].push_back(e - b);
      for (GlobalIndex k = b; k < e; ++k) replies[std::size_t(r)].push_back(node_parts.parts[k]);
    }
  const std::vector<long long> lists = answer(comm, replies);
  std::vector<std::size_t> list_at(nodes.size());
  for (std::size_t i = 0, pos = 0; i < nodes.size(); ++i) {
    list_at[i] = pos;
    pos += std::size_t(lists[pos]) + 1;
  }
  offset.assign(1, 0);
  ranks_of.clear();
  std::vector<int> mine;
  for (GlobalIndex e = 0; e < s.num_elements(); ++e) {
    mine.clear();
    for (GlobalIndex k = s.element_nodes_offset[e]; k < s.element_nodes_offset[e + 1]; ++k) {
      const std::size_t i = std::size_t(
          std::lower_bound(nodes.begin(), nodes.end(), s.element_nodes[k]) - nodes.begin());
      const std::size_t pos = list_at[i];
      for (long long j = 0; j < lists[pos]; ++j) mine.push_back(int(lists[pos + 1 + j]));
    }
    sort_unique(mine);
    ranks_of.insert(ranks_of.end(), mine.begin(), mine.end());
    offset.push_back(GlobalIndex(ranks_of.size()));
  }
}

}  // namespace

std::vector<GlobalIndex> slice_element_nodes(const MeshSlices& s) {
  std::vector<GlobalIndex> nodes(s.element_nodes);
  sort_unique(nodes);
  return nodes;
}

DistributedMesh migrate_mesh(const Comm& comm, const MeshHeader& h, const MeshSlices& s,
                             const std::vector<int>& element_part,
                             const std::vector<char>& contact) {
  const int me = comm.getRank(), ranks = comm.getSize();
  const NodeParts node_parts = gather_node_parts(comm, h, s, element_part, contact);
  std::vector<GlobalIndex> ranks_offset;
  std::vector<int> ranks_of;
  element_ranks(comm, h, s, node_parts, ranks_offset, ranks_of);

  // Elements to the ranks that hold them: [gid, block, owner, nodes...].
  // In rounds of at most 2^16 elements per rank, so that the records in flight (three
  // copies in the all-to-all) stay small next to the mesh.
  Messages outbox(static_cast<std::size_t>(ranks));
  constexpr GlobalIndex round_size = 1 << 16;
  long long my_rounds = (s.num_elements() + round_size - 1) / round_size, rounds = 0;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, 1, &my_rounds, &rounds);
  std::vector<long long> got;
  for (long long round = 0; round < rounds; ++round) {
    const GlobalIndex first = round * round_size;
    for (GlobalIndex e = first; e < std::min(s.num_elements(), first + round_size); ++e)
      for (GlobalIndex k = ranks_offset[e]; k < ranks_offset[e + 1]; ++k) {
        auto& to = outbox[std::size_t(ranks_of[k])];
        to.push_back(s.element_begin + e);
        to.push_back(s.element_block[e]);
        to.push_back(element_part[e]);
        to.insert(to.end(), s.element_nodes.begin() + s.element_nodes_offset[e],
                  s.element_nodes.begin() + s.element_nodes_offset[e + 1]);
      }
    const std::vector<long long> received = send_to_ranks(comm, outbox);
    got.insert(got.end(), received.begin(), received.end());
    outbox.assign(std::size_t(ranks), {});
  }
  // The received records stay in `got`; `records` holds where each starts, sorted block by
  // block, owned first, ascending global id.
  std::vector<std::size_t> records;
  const auto npe_of = [&](std::size_t r) {
    return h.blocks[std::size_t(got[r + 1])].nodes_per_element;
  };
  for (std::size_t at = 0; at < got.size(); at += std::size_t(3 + npe_of(at)))
    records.push_back(at);
  std::sort(records.begin(), records.end(), [&](std::size_t a, std::size_t b) {
    if (got[a + 1] != got[b + 1]) return got[a + 1] < got[b + 1];
    if ((got[a + 2] == me) != (got[b + 2] == me)) return got[a + 2] == me;
    return got[a] < got[b];
  });
  // Nodes: each holder asks the node's home for owner and coordinates; the home remembers
  // who asked (holders(n)) and sends the nodes of no element to rank 0.
  std::vector<GlobalIndex> needed;
  for (std::size_t r : records)
    needed.insert(needed.end(), got.begin() + long(r) + 3, got.begin() + long(r) + 3 + npe_of(r));
  sort_unique(needed);
  const DirectoryQuestions q = ask_homes(comm, h.num_nodes, needed);
  const int dim = h.dimension;
  std::vector<std::vector<double>> node_answers(static_cast<std::size_t>(ranks));
  std::vector<std::pair<GlobalIndex, int>> holders;  // (node, rank)
  const auto owner_of = [&](GlobalIndex local) { return node_parts.owner[std::size_t(local)]; };
  for (int r = 0, at = 0; r < ranks; ++r)
    for (int i = 0; i < q.counts[std::size_t(r)]; ++i, ++at) {
      const GlobalIndex local = q.ids[std::size_t(at)] - s.node_begin;
      auto& to = node_answers[std::size_t(r)];
      to.push_back(owner_of(local));
      for (int d = 0; d < dim; ++d) to.push_back(s.coordinates[std::size_t(local * dim + d)]);
      holders.emplace_back(q.ids[std::size_t(at)], r);
    }
  const std::vector<double> node_data = answer(comm, node_answers);
  node_answers.assign(std::size_t(ranks), {});
  Messages orphans(static_cast<std::size_t>(ranks));
  for (GlobalIndex local = 0; local < s.num_nodes(); ++local)
    if (node_parts.offset[local] == node_parts.offset[local + 1]) {
      orphans[0].push_back(s.node_begin + local);
      for (int d = 0; d < dim; ++d)
        node_answers[0].push_back(s.coordinates[std::size_t(local * dim + d)]);
      holders.emplace_back(s.node_begin + local, 0);
    }
  const std::vector<long long> orphan_ids = send_to_ranks(comm, orphans);
  const std::vector<double> orphan_x = answer(comm, node_answers);
  std::sort(holders.begin(), holders.end());

  // Node records (gid, owner, coordinates), owned first, ascending id.
  struct NodeRecord {
    GlobalIndex gid;
    int owner;
    std::size_t x;  ///< into node_data (needed) or orphan_x (orphans, offset by flag)
    bool orphan;
  };
  std::vector<NodeRecord> nodes;
  for (std::size_t i = 0; i < needed.size(); ++i)
    nodes.push_back({needed[i], int(node_data[i * (dim + 1)]), i * (dim + 1) + 1, false});
  for (std::size_t i = 0; i < orphan_ids.size(); ++i)
    nodes.push_back({orphan_ids[i], 0, i * dim, true});
  std::sort(nodes.begin(), nodes.end(), [me](const NodeRecord& a, const NodeRecord& b) {
    if ((a.owner == me) != (b.owner == me)) return a.owner == me;
    return a.gid < b.gid;
  });

  DistributedMesh m;
  m.rank = me;
  m.num_ranks = ranks;
  m.global_num_nodes = h.num_nodes;
  m.global_num_elements = h.num_elements;
  m.block_global_size = h.block_size;
  m.side_set_global_size = h.side_set_size;
  m.node_set_global_size = h.node_set_size;
  m.local.file = h.file;
  m.local.dimension = dim;
  for (const auto& n : nodes) {
    m.node_gid.push_back(n.gid);
    m.node_owner.push_back(n.owner);
    if (n.owner == me) ++m.num_owned_nodes;
    const double* x = (n.orphan ? orphan_x.data() : node_data.data()) + n.x;
    m.local.coordinates.insert(m.local.coordinates.end(), x, x + dim);
  }
  nodes.clear();
  nodes.shrink_to_fit();

  GlobalIndex next = 0;
  std::size_t at = 0;
  for (std::size_t b = 0; b < h.blocks.size(); ++b) {
    ElementBlock block = h.blocks[b];
    m.block_global_first.push_back(block.first_element);
    block.first_element = next;
    GlobalIndex owned = 0;
    for (; at < records.size() && got[records[at] + 1] == GlobalIndex(b); ++at, ++next) {
      const std::size_t r = records[at];
      m.element_gid.push_back(got[r]);
      m.element_owner.push_back(int(got[r + 2]));
      owned += got[r + 2] == me;
      for (int a = 0; a < block.nodes_per_element; ++a)
        block.connectivity.push_back(m.local_node(got[r + 3 + std::size_t(a)]));
    }
    m.num_owned_in_block.push_back(owned);
    m.local.blocks.push_back(std::move(block));
  }
  records = {};

  // Side-set entries [set, position, element, side] go to the element's home, which knows
  // ranks(e); node-set entries [set, position, node] go to the node's home, which knows
  // holders(n).
  for (std::size_t k = 0; k < s.side_set_elements.size(); ++k)
    for (std::size_t i = 0; i < s.side_set_elements[k].size(); ++i) {
      const GlobalIndex e = s.side_set_elements[k][i];
      auto& to = outbox[std::size_t(slice_rank(h.num_elements, e, ranks))];
      to.insert(to.end(),
                {(long long)k, s.side_set_begin[k] + GlobalIndex(i), e, s.side_set_sides[k][i]});
    }
  got = send_to_ranks(comm, outbox);
  outbox.assign(std::size_t(ranks), {});
  for (std::size_t i = 0; i < got.size(); i += 4) {
    const GlobalIndex e = got[i + 2] - s.element_begin;
    for (GlobalIndex k = ranks_offset[e]; k < ranks_offset[e + 1]; ++k)
      outbox[std::size_t(ranks_of[k])].insert(outbox[std::size_t(ranks_of[k])].end(),
                                              got.begin() + long(i), got.begin() + long(i) + 4);
  }
  got = send_to_ranks(comm, outbox);
  outbox.assign(std::size_t(ranks), {});
  {
    std::vector<std::array<long long, 4>> entries;
    for (std::size_t i = 0; i < got.size(); i += 4)
      entries.push_back({got[i], got[i + 1], got[i + 2], got[i + 3]});
    std::sort(entries.begin(), entries.end());
    m.local.side_sets = h.side_sets;
    m.side_set_position.resize(h.side_sets.size());
    for (const auto& [k, position, e, side] : entries) {
      m.local.side_sets[std::size_t(k)].elements.push_back(m.local_element(e));
      m.local.side_sets[std::size_t(k)].sides.push_back(int(side));
      m.side_set_position[std::size_t(k)].push_back(position);
    }
  }
  for (std::size_t k = 0; k < s.node_set_nodes.size(); ++k)
    for (std::size_t i = 0; i < s.node_set_nodes[k].size(); ++i) {
      const GlobalIndex n = s.node_set_nodes[k][i];
      auto& to = outbox[std::size_t(slice_rank(h.num_nodes, n, ranks))];
      to.insert(to.end(), {(long long)k, s.node_set_begin[k] + GlobalIndex(i), n});
    }
  got = send_to_ranks(comm, outbox);
  outbox.assign(std::size_t(ranks), {});
  for (std::size_t i = 0; i < got.size(); i += 3) {
    const GlobalIndex n = got[i + 2];
    auto it = std::lower_bound(holders.begin(), holders.end(), std::make_pair(n, -1));
    for (; it != holders.end() && it->first == n; ++it)
      outbox[std::size_t(it->second)].insert(outbox[std::size_t(it->second)].end(),
                                             got.begin() + long(i), got.begin() + long(i) + 3);
  }
  got = send_to_ranks(comm, outbox);
  {
    std::vector<std::array<long long, 3>> entries;
    for (std::size_t i = 0; i < got.size(); i += 3)
      entries.push_back({got[i], got[i + 1], got[i + 2]});
    std::sort(entries.begin(), entries.end());
    m.local.node_sets = h.node_sets;
    m.node_set_position.resize(h.node_sets.size());
    for (const auto& [k, position, n] : entries) {
      m.local.node_sets[std::size_t(k)].nodes.push_back(m.local_node(n));
      m.node_set_position[std::size_t(k)].push_back(position);
    }
  }
  return m;
}

}  // namespace grout
