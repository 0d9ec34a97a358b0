#include "assembly/contact_distribution.hpp"

#include <algorithm>
#include <numeric>
#include <stdexcept>

#include "kernels/coarse_search.hpp"

namespace grout {

namespace {

template <class T>
MPI_Datatype mpi_type();
template <>
MPI_Datatype mpi_type<double>() {
  return MPI_DOUBLE;
}
template <>
MPI_Datatype mpi_type<long long>() {
  return MPI_LONG_LONG;
}

template <class T>
std::vector<T> exchange(const std::vector<std::vector<T>>& send, MPI_Comm comm,
                        std::vector<int>* recv_counts) {
  int size = 1;
  MPI_Comm_size(comm, &size);
  if (int(send.size()) != size)
    throw std::invalid_argument("exchange_with_ranks: one message per rank expected");
  std::vector<int> send_counts(size), send_offsets(size + 1, 0), counts(size), offsets(size + 1, 0);
  for (int r = 0; r < size; ++r) send_counts[r] = int(send[r].size());
  MPI_Alltoall(send_counts.data(), 1, MPI_INT, counts.data(), 1, MPI_INT, comm);
  std::partial_sum(send_counts.begin(), send_counts.end(), send_offsets.begin() + 1);
  std::partial_sum(counts.begin(), counts.end(), offsets.begin() + 1);
  std::vector<T> packed(send_offsets.back()), received(offsets.back());
  for (int r = 0; r < size; ++r)
    std::copy(send[r].begin(), send[r].end(), packed.begin() + send_offsets[r]);
  MPI_Alltoallv(packed.data(), send_counts.data(), send_offsets.data(), mpi_type<T>(),
                received.data(), counts.data(), offsets.data(), mpi_type<T>(), comm);
  if (recv_counts) *recv_counts = counts;
  return received;
}

void face_box(const FaceSet& faces, std::size_t f, double factor, double lo[3], double hi[3]) {
  double x[max_face_nodes][3] = {};
  for (int a = 0; a < faces.num_nodes[f]; ++a)
    for (int d = 0; d < 3; ++d) x[a][d] = faces.coordinates[f][3 * a + d];
  face_bounding_box(faces.dimension, faces.num_nodes[f], x, factor, lo, hi);
}

bool overlaps(int dim, const double lo[3], const double hi[3], const SearchRegion& r) {
  if (r.empty) return false;
  for (int d = 0; d < dim; ++d)
    if (lo[d] > r.hi[d] || r.lo[d] > hi[d]) return false;
  return true;
}

constexpr int ids_per_face = 2 + max_face_nodes;  // id, number of nodes, nodes

}  // namespace

void FaceSet::add(GlobalIndex id, int n, const GlobalIndex* face_nodes, const double (*x)[3],
                  const double* node_payload) {
  ids.push_back(id);
  num_nodes.push_back(n);
  std::array<GlobalIndex, max_face_nodes> ns{-1, -1, -1, -1};
  std::array<double, 3 * max_face_nodes> xs{};
  for (int a = 0; a < n; ++a) {
    ns[a] = face_nodes[a];
    for (int d = 0; d < 3; ++d) xs[3 * a + d] = x[a][d];
  }
  nodes.push_back(ns);
  coordinates.push_back(xs);
  const std::size_t per_face = std::size_t(max_face_nodes) * payload_size;
  payload.resize(payload.size() + per_face, 0.0);
  if (node_payload)
    std::copy(node_payload, node_payload + std::size_t(n) * payload_size, payload.end() - per_face);
}

FaceSet merge_face_sets(const FaceSet& a, const FaceSet& b) {
  FaceSet merged;
  merged.dimension = a.dimension;
  merged.payload_size = a.payload_size;
  const std::size_t per_face = std::size_t(max_face_nodes) * a.payload_size;
  const auto append = [&](const FaceSet& from, std::size_t f) {
    merged.ids.push_back(from.ids[f]);
    merged.num_nodes.push_back(from.num_nodes[f]);
    merged.nodes.push_back(from.nodes[f]);
    merged.coordinates.push_back(from.coordinates[f]);
    merged.payload.insert(merged.payload.end(), from.payload.begin() + f * per_face,
                          from.payload.begin() + (f + 1) * per_face);
  };
  std::size_t i = 0, j = 0;
  while (i < a.size() || j < b.size()) {
    if (j == b.size() || (i < a.size() && a.ids[i] <= b.ids[j])) {
      if (j < b.size() && a.ids[i] == b.ids[j]) ++j;
      append(a, i++);
    } else {
      append(b, j++);
    }
  }
  return merged;
}

SearchRegion search_region(const FaceSet& faces, double factor, const std::vector<char>& include) {
  SearchRegion region;
  for (std::size_t f = 0; f < faces.size(); ++f) {
    if (!include.empty() && !include[f]) continue;
    double lo[3], hi[3];
    face_box(faces, f, factor, lo, hi);
    for (int d = 0; d < 3; ++d) {
      region.lo[d] = region.empty ? lo[d] : std::min(region.lo[d], lo[d]);
      region.hi[d] = region.empty ? hi[d] : std::max(region.hi[d], hi[d]);
    }
    region.empty = false;
  }
  return region;
}

FaceSet ghost_master_faces(const FaceSet& owned, const SearchRegion& region, double factor,
                           MPI_Comm comm) {
  int size = 1;
  MPI_Comm_size(comm, &size);
  // 1. All regions: (empty flag, lo, hi) per rank.
  double mine[7] = {region.empty ? 1.0 : 0.0};
  for (int d = 0; d < 3; ++d) mine[1 + d] = region.lo[d], mine[4 + d] = region.hi[d];
  std::vector<double> all(7 * std::size_t(size));
  MPI_Allgather(mine, 7, MPI_DOUBLE, all.data(), 7, MPI_DOUBLE, comm);
  std::vector<SearchRegion> regions(size);
  for (int r = 0; r < size; ++r) {
    regions[r].empty = all[7 * r] != 0.0;
    for (int d = 0; d < 3; ++d)
      regions[r].lo[d] = all[7 * r + 1 + d], regions[r].hi[d] = all[7 * r + 4 + d];
  }

  // 2. Each owned face to every rank whose region its box overlaps.
  const int dim = owned.dimension, p = owned.payload_size;
  const int doubles_per_face = max_face_nodes * (3 + p);
  std::vector<std::vector<long long>> send_ids(size);
  std::vector<std::vector<double>> send_values(size);
  for (std::size_t f = 0; f < owned.size(); ++f) {
    double lo[3], hi[3];
    face_box(owned, f, factor, lo, hi);
    for (int r = 0; r < size; ++r) {
      if (!overlaps(dim, lo, hi, regions[r])) continue;
      send_ids[r].push_back(owned.ids[f]);
      send_ids[r].push_back(owned.num_nodes[f]);
      send_ids[r].insert(send_ids[r].end(), owned.nodes[f].begin(), owned.nodes[f].end());
      send_values[r].insert(send_values[r].end(), owned.coordinates[f].begin(),
                            owned.coordinates[f].end());
      const auto first = owned.payload.begin() + f * std::size_t(max_face_nodes) * p;
      send_values[r].insert(send_values[r].end(), first, first + max_face_nodes * p);
    }
  }
  const std::vector<long long> ids = exchange_with_ranks(send_ids, comm);
  const std::vector<double> values = exchange_with_ranks(send_values, comm);

  // 3. Unpack in face id order.
  const std::size_t n = ids.size() / ids_per_face;
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return ids[a * ids_per_face] < ids[b * ids_per_face];
  });
  FaceSet out;
  out.dimension = dim;
  out.payload_size = p;
  for (std::size_t k : order) {
    const long long* record = &ids[k * ids_per_face];
    const double* v = &values[k * doubles_per_face];
    out.ids.push_back(record[0]);
    out.num_nodes.push_back(int(record[1]));
    std::array<GlobalIndex, max_face_nodes> ns;
    std::array<double, 3 * max_face_nodes> xs;
    for (int a = 0; a < max_face_nodes; ++a) ns[a] = record[2 + a];
    std::copy(v, v + 3 * max_face_nodes, xs.begin());
    out.nodes.push_back(ns);
    out.coordinates.push_back(xs);
    out.payload.insert(out.payload.end(), v + 3 * max_face_nodes, v + doubles_per_face);
  }
  return out;
}

std::vector<double> exchange_with_ranks(const std::vector<std::vector<double>>& send, MPI_Comm comm,
                                        std::vector<int>* recv_counts) {
  return exchange(send, comm, recv_counts);
}

std::vector<long long> exchange_with_ranks(const std::vector<std::vector<long long>>& send,
                                           MPI_Comm comm, std::vector<int>* recv_counts) {
  return exchange(send, comm, recv_counts);
}

}  // namespace grout
