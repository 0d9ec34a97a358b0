#include "assembly/partition.hpp"

#include <algorithm>
#include <array>
#include <numeric>

namespace grout {

namespace {

std::vector<std::array<double, 3>> element_centroids(const Mesh& mesh) {
  std::vector<std::array<double, 3>> centroids;
  centroids.reserve(mesh.num_elements());
  const int dim = mesh.dimension;
  for (const auto& block : mesh.blocks) {
    for (GlobalIndex e = 0; e < block.num_elements(); ++e) {
      std::array<double, 3> c{0.0, 0.0, 0.0};
      for (int a = 0; a < block.nodes_per_element; ++a) {
        const GlobalIndex n = block.connectivity[e * block.nodes_per_element + a];
        for (int d = 0; d < dim; ++d) c[d] += mesh.coordinates[n * dim + d];
      }
      for (auto& x : c) x /= block.nodes_per_element;
      centroids.push_back(c);
    }
  }
  return centroids;
}

// Assign parts [first_part, first_part + num_parts) to elements[begin, end).
// Axis of the longest extent of the centroids of elements[begin, end) with `in` set (all if
// `in` is empty); -1 if fewer than two such elements or no extent.
int longest_axis(const std::vector<std::array<double, 3>>& centroids,
                 const std::vector<GlobalIndex>& elements, std::size_t begin, std::size_t end,
                 const std::vector<char>& in) {
  std::array<double, 3> lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
  int count = 0;
  for (std::size_t i = begin; i < end; ++i) {
    if (!in.empty() && !in[elements[i]]) continue;
    ++count;
    for (int d = 0; d < 3; ++d) {
      lo[d] = std::min(lo[d], centroids[elements[i]][d]);
      hi[d] = std::max(hi[d], centroids[elements[i]][d]);
    }
  }
  if (count < 2) return -1;
  int axis = 0;
  for (int d = 1; d < 3; ++d)
    if (hi[d] - lo[d] > hi[axis] - lo[axis]) axis = d;
  return hi[axis] > lo[axis] ? axis : -1;
}

void bisect(const std::vector<std::array<double, 3>>& centroids, std::vector<GlobalIndex>& elements,
            std::size_t begin, std::size_t end, int first_part, int num_parts,
            const std::vector<char>& contact, std::vector<int>& element_part) {
  if (num_parts == 1) {
    for (std::size_t i = begin; i < end; ++i) element_part[elements[i]] = first_part;
    return;
  }
  int axis = contact.empty() ? -1 : longest_axis(centroids, elements, begin, end, contact);
  if (axis < 0) axis = std::max(0, longest_axis(centroids, elements, begin, end, {}));
  const int left_parts = num_parts / 2;
  const std::size_t split = begin + (end - begin) * left_parts / num_parts;
  // Ties broken by element index so that every rank computes the same partition.
  std::nth_element(elements.begin() + begin, elements.begin() + split, elements.begin() + end,
                   [&](GlobalIndex a, GlobalIndex b) {
                     const double ca = centroids[a][axis], cb = centroids[b][axis];
                     return ca < cb || (ca == cb && a < b);
                   });
  bisect(centroids, elements, begin, split, first_part, left_parts, contact, element_part);
  bisect(centroids, elements, split, end, first_part + left_parts, num_parts - left_parts, contact,
         element_part);
}

}  // namespace

Partition partition_mesh(const Mesh& mesh, int num_parts,
                         const std::vector<GlobalIndex>& contact_elements) {
  Partition p;
  p.num_parts = num_parts;
  const GlobalIndex n_elements = mesh.num_elements();
  p.element_part.assign(n_elements, 0);
  if (num_parts > 1) {
    const auto centroids = element_centroids(mesh);
    std::vector<GlobalIndex> elements(n_elements);
    std::iota(elements.begin(), elements.end(), GlobalIndex(0));
    std::vector<char> contact;
    if (!contact_elements.empty()) {
      contact.assign(n_elements, 0);
      for (GlobalIndex e : contact_elements) contact[e] = 1;
    }
    bisect(centroids, elements, 0, elements.size(), 0, num_parts, contact, p.element_part);
  }
  p.node_part.assign(mesh.num_nodes(), num_parts);
  for (const auto& block : mesh.blocks) {
    for (GlobalIndex e = 0; e < block.num_elements(); ++e) {
      const int part = p.element_part[block.first_element + e];
      for (int a = 0; a < block.nodes_per_element; ++a) {
        int& owner = p.node_part[block.connectivity[e * block.nodes_per_element + a]];
        owner = std::min(owner, part);
      }
    }
  }
  for (auto& owner : p.node_part)
    if (owner == num_parts) owner = 0;
  return p;
}

}  // namespace grout
