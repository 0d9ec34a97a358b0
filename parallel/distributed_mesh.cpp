// read_distributed_mesh (parallel/distributed_mesh.hpp): slices, centroids, partition,
// migration, checks; and the DistributedMesh look-ups and holdings report.

#include "parallel/distributed_mesh.hpp"
#include "assembly/rank_holdings.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_TimeMonitor.hpp>
#include <algorithm>
#include <cstdio>
#include <optional>
#include <set>

#include "assembly/agree_on_errors.hpp"
#include "io/errors.hpp"
#include "parallel/contact_bands.hpp"
#include "parallel/directory.hpp"
#include "parallel/element_partition.hpp"
#include "parallel/migrate_mesh.hpp"
#include "parallel/slices.hpp"

namespace grout {

namespace {

/// Coordinates (3 per node, unused components 0) of the sorted global `nodes`, from their
/// homes' node slices.
std::vector<double> fetch_coordinates(const Comm& comm, const MeshHeader& h, const MeshSlices& s,
                                      const std::vector<GlobalIndex>& nodes) {
  const DirectoryQuestions q = ask_homes(comm, h.num_nodes, nodes);
  std::vector<std::vector<double>> replies(std::size_t(comm.getSize()));
  for (std::size_t r = 0, at = 0; r < replies.size(); ++r)
    for (int i = 0; i < q.counts[r]; ++i, ++at)
      for (int d = 0; d < 3; ++d)
        replies[r].push_back(
            d < h.dimension
                ? s.coordinates[std::size_t((q.ids[at] - s.node_begin) * h.dimension + d)]
                : 0.0);
  return answer(comm, replies);
}

/// check_mesh's element test on the slice elements (before the partition: a non-finite
/// coordinate would make the centroids meaningless), and their centroids.
std::vector<double> check_and_centroids(const MeshHeader& h, const MeshSlices& s,
                                        const std::vector<GlobalIndex>& nodes,
                                        const std::vector<double>& x) {
  std::vector<double> centroids(std::size_t(3 * s.num_elements()), 0.0);
  const int dim = h.dimension;
  for (GlobalIndex e = 0; e < s.num_elements(); ++e) {
    const ElementBlock& block = h.blocks[std::size_t(s.element_block[e])];
    const GlobalIndex* conn = s.element_nodes.data() + s.element_nodes_offset[e];
    double X[max_element_nodes * 3];
    for (int a = 0; a < block.nodes_per_element; ++a) {
      const auto i =
          std::size_t(std::lower_bound(nodes.begin(), nodes.end(), conn[a]) - nodes.begin());
      for (int d = 0; d < dim; ++d) {
        X[a * dim + d] = x[3 * i + d];
        centroids[std::size_t(3 * e + d)] += x[3 * i + d] / block.nodes_per_element;
      }
    }
    const GlobalIndex gid = s.element_begin + e;
    check_element_geometry(block.topology, dim, X, conn, [&] {
      return "mesh '" + h.file + "': block '" + block.name + "', element " +
             std::to_string(gid - block.first_element + 1) + " (global element " +
             std::to_string(gid + 1) + "): ";
    });
  }
  return centroids;
}

/// The indices of the side sets `names` among the header's side sets (`what`: the role named
/// in the error).
std::vector<std::size_t> find_side_sets(const MeshHeader& h, const std::vector<std::string>& names,
                                        bool skip_missing, const char* what) {
  std::vector<std::size_t> sets;
  for (const std::string& name : names) {
    std::size_t k = 0;
    while (k < h.side_sets.size() && h.side_sets[k].name != name &&
           name != "id_" + std::to_string(h.side_sets[k].id))
      ++k;
    if (k == h.side_sets.size() && skip_missing) continue;
    if (k == h.side_sets.size())
      throw InputError("mesh '" + h.file + "': no side set '" + name + "' (" + what + ")");
    sets.push_back(k);
  }
  return sets;
}

/// The indices of the contact side sets among the header's side sets.
std::vector<std::size_t> contact_sets(const MeshHeader& h, const DistributionOptions& options) {
  if (options.contact_weight == 0.0 && !options.balance_contact && !options.separate_contact)
    return {};
  return find_side_sets(h, options.contact_side_sets, options.skip_missing_sets, "contact surface");
}

/// Collective. Per slice element: 1 when it has a face in one of the side sets `sets` (whose
/// entries the ranks' set slices hold, sent to the elements' slice ranks), else 0.
std::vector<char> contact_marks(const Comm& comm, const MeshHeader& h, const MeshSlices& s,
                                const std::vector<std::size_t>& sets) {
  std::vector<char> contact(std::size_t(s.num_elements()), 0);
  std::vector<std::vector<long long>> marks(std::size_t(comm.getSize()));
  for (std::size_t k : sets)
    for (GlobalIndex e : s.side_set_elements[k])
      marks[std::size_t(slice_rank(h.num_elements, e, comm.getSize()))].push_back(e);
  for (long long e : send_to_ranks(comm, marks)) contact[std::size_t(e - s.element_begin)] = 1;
  return contact;
}

/// Weight 1 per element, 1 + contact_weight for a contact element; with `two`, two weights per
/// element: 1, and 1 on contact elements (0 elsewhere).
std::vector<double> element_weights(const std::vector<char>& contact, double contact_weight,
                                    bool two) {
  std::vector<double> weights;
  for (char c : contact) {
    if (two) {
      weights.push_back(1.0);
      weights.push_back(c ? 1.0 : 0.0);
    } else {
      weights.push_back(c ? 1.0 + contact_weight : 1.0);
    }
  }
  return weights;
}

/// Collective. The contact elements (band[i] >= 0), each group of contact_gap_bands apart,
/// and the others (band[i] = -1) partitioned apart, one RCB each with weights 1
/// (DistributionOptions::separate_contact).
std::vector<int> partition_separately(const Comm& comm, int dimension,
                                      const std::vector<GlobalIndex>& ids,
                                      const std::vector<double>& centroids,
                                      const std::vector<int>& band) {
  int bands = 0, local_bands = 0;
  for (int b : band) local_bands = std::max(local_bands, b + 1);
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, local_bands, Teuchos::outArg(bands));
  // Every contact group is first cut across one axis, the widest of group 0 (the slave elements
  // nearest the other surface, where contact starts): the cuts of neighbouring bands then
  // nearly meet, and few nodes have contact elements on two parts (each part evaluates the
  // slave faces with a node it owns, so a ragged cut evaluates more faces twice). On 2 parts
  // the groups are cut on that coordinate alone; on more, with it stretched twofold, so that
  // RCB's first cut is across it and the later ones across the group's widest extent (slabs
  // along one axis would evaluate ever more faces twice as the parts grow).
  double low[3], high[3], low_all[3], high_all[3];
  for (int d = 0; d < 3; ++d) low[d] = 1e300, high[d] = -1e300;
  for (std::size_t i = 0; i < ids.size(); ++i)
    if (band[i] == 0)
      for (int d = 0; d < 3; ++d)
        low[d] = std::min(low[d], centroids[3 * i + d]),
        high[d] = std::max(high[d], centroids[3 * i + d]);
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MIN, 3, low, low_all);
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, 3, high, high_all);
  int axis = 0;
  for (int d = 1; d < dimension; ++d)
    if (high_all[d] - low_all[d] > high_all[axis] - low_all[axis]) axis = d;
  const bool two = comm.getSize() == 2;
  double contact_scale[3];  // per coordinate, for the contact groups
  for (int d = 0; d < 3; ++d) contact_scale[d] = d == axis ? (two ? 1.0 : 2.0) : (two ? 0.0 : 1.0);
  const double other_scale[3] = {1.0, 1.0, 1.0};
  std::vector<int> part(ids.size(), 0);
  for (int group = -1; group < bands; ++group) {
    const double* scale = group < 0 ? other_scale : contact_scale;
    std::vector<GlobalIndex> group_ids;
    std::vector<double> group_centroids;
    std::vector<std::size_t> at;
    for (std::size_t i = 0; i < ids.size(); ++i) {
      if (band[i] != group) continue;
      at.push_back(i);
      group_ids.push_back(ids[i]);
      for (int d = 0; d < 3; ++d) group_centroids.push_back(scale[d] * centroids[3 * i + d]);
    }
    const std::vector<int> group_part =
        partition_elements_rcb(comm, dimension, group_ids, group_centroids,
                               std::vector<double>(group_ids.size(), 1.0), 1, comm.getSize());
    for (std::size_t j = 0; j < at.size(); ++j) part[at[j]] = group_part[j];
  }
  return part;
}

/// check_mesh's set tests on the owned entities (every entry of an owned entity is here):
/// no node twice in a node set, no (element, side) twice in a side set.
void check_sets(const DistributedMesh& m) {
  const std::string& file = m.local.file;
  for (const NodeSet& set : m.local.node_sets) {
    std::set<GlobalIndex> seen;
    for (GlobalIndex n : set.nodes)
      if (m.owns_node(n) && !seen.insert(n).second)
        throw InputError("mesh '" + file + "': node set '" + set.name + "' lists node " +
                         std::to_string(m.node_gid[n] + 1) +
                         " twice (reactions would count it twice)");
  }
  for (const SideSet& set : m.local.side_sets) {
    std::set<std::pair<GlobalIndex, int>> seen;
    for (std::size_t i = 0; i < set.elements.size(); ++i)
      if (m.owns_element(set.elements[i]) && !seen.emplace(set.elements[i], set.sides[i]).second)
        throw InputError("mesh '" + file + "': side set '" + set.name + "' lists side " +
                         std::to_string(set.sides[i]) + " of element " +
                         std::to_string(m.element_gid[set.elements[i]] + 1) +
                         " twice (its load or contact terms would count twice)");
  }
}

}  // namespace

GlobalIndex DistributedMesh::num_owned_elements() const {
  GlobalIndex n = 0;
  for (GlobalIndex k : num_owned_in_block) n += k;
  return n;
}

GlobalIndex DistributedMesh::local_node(GlobalIndex gid) const {
  const auto find = [&](auto begin, auto end) -> GlobalIndex {
    const auto it = std::lower_bound(begin, end, gid);
    return it != end && *it == gid ? GlobalIndex(it - node_gid.begin()) : -1;
  };
  const GlobalIndex owned = find(node_gid.begin(), node_gid.begin() + num_owned_nodes);
  return owned >= 0 ? owned : find(node_gid.begin() + num_owned_nodes, node_gid.end());
}

GlobalIndex DistributedMesh::local_element(GlobalIndex gid) const {
  for (std::size_t b = 0; b < local.blocks.size(); ++b) {
    if (gid < block_global_first[b] || gid >= block_global_first[b] + block_global_size[b])
      continue;
    const auto first = element_gid.begin() + local.blocks[b].first_element;
    const auto mid = first + num_owned_in_block[b], last = first + local.blocks[b].num_elements();
    for (const auto& [begin, end] : {std::make_pair(first, mid), std::make_pair(mid, last)}) {
      const auto it = std::lower_bound(begin, end, gid);
      if (it != end && *it == gid) return GlobalIndex(it - element_gid.begin());
    }
    return -1;
  }
  return -1;
}

DistributedMesh read_distributed_mesh(const Comm& comm, const std::string& path,
                                      const DistributionOptions& options) {
  using Teuchos::TimeMonitor;
  static const auto read_time = TimeMonitor::getNewTimer("grout: distributed mesh: read slices");
  static const auto partition_time = TimeMonitor::getNewTimer("grout: distributed mesh: partition");
  static const auto migrate_time = TimeMonitor::getNewTimer("grout: distributed mesh: migrate");
  std::optional<TimeMonitor> timer(std::in_place, *read_time);
  const MeshHeader header = read_mesh_header(comm, path);
  const MeshSlices slices = read_mesh_slices(comm, header);
  timer.emplace(*partition_time);
  std::vector<int> part;
  std::vector<char> contact;
  {
    const std::vector<GlobalIndex> nodes = slice_element_nodes(slices);
    const std::vector<double> x = fetch_coordinates(comm, header, slices, nodes);
    std::vector<double> centroids;
    std::vector<std::size_t> sets, master_sets;
    agree_on_errors(comm, [&] {
      centroids = check_and_centroids(header, slices, nodes, x);
      sets = contact_sets(header, options);
      if (options.separate_contact)
        master_sets = find_side_sets(header, options.master_side_sets, options.skip_missing_sets,
                                     "contact master surface");
    });
    contact = contact_marks(comm, header, slices, sets);
    std::vector<GlobalIndex> ids(std::size_t(slices.num_elements()));
    for (std::size_t i = 0; i < ids.size(); ++i) ids[i] = slices.element_begin + GlobalIndex(i);
    if (options.separate_contact) {
      // With master side sets their elements are contact elements too, all in gap bands; the
      // same on every rank (the same header and options).
      const std::vector<char> slave = contact;
      const std::vector<char> master = master_sets.empty()
                                           ? std::vector<char>(contact.size(), 0)
                                           : contact_marks(comm, header, slices, master_sets);
      for (std::size_t i = 0; i < contact.size(); ++i) contact[i] = slave[i] || master[i];
      const std::vector<int> band = contact_gap_bands(comm, ids, centroids, slave, master);
      part = partition_separately(comm, header.dimension, ids, centroids, band);
    } else
      part = partition_elements_rcb(
          comm, header.dimension, ids, centroids,
          element_weights(contact, options.contact_weight, options.balance_contact),
          options.balance_contact ? 2 : 1, comm.getSize());
  }
  timer.emplace(*migrate_time);
  DistributedMesh mesh = migrate_mesh(comm, header, slices, part, contact);
  agree_on_errors(comm, [&] { check_sets(mesh); });
  return mesh;
}

MeshHoldings mesh_holdings(const DistributedMesh& m) {
  MeshHoldings h;
  h.owned_nodes = m.num_owned_nodes;
  h.ghost_nodes = m.num_local_nodes() - m.num_owned_nodes;
  h.owned_elements = m.num_owned_elements();
  h.ghost_elements = m.num_local_elements() - h.owned_elements;
  for (const SideSet& set : m.local.side_sets)
    for (GlobalIndex e : set.elements) h.owned_side_set_entries += m.owns_element(e);
  return h;
}

std::string describe_holdings(const Comm& comm, const DistributedMesh& m) {
  const MeshHoldings h = mesh_holdings(m);
  RankHoldings mine;
  mine.owned_nodes = h.owned_nodes, mine.ghost_nodes = h.ghost_nodes;
  mine.owned_elements = h.owned_elements, mine.ghost_elements = h.ghost_elements;
  mine.side_set_faces = h.owned_side_set_entries;
  return describe_rank_holdings(comm, "mesh", mine, m.global_num_nodes, m.global_num_elements);
}

}  // namespace grout
