// check_mesh: what every solve relies on in a mesh, checked once after reading it.

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <sstream>

#include "io/errors.hpp"
#include "io/mesh.hpp"
#include "kernels/element_jacobian.hpp"
#include "kernels/linear_elastic.hpp"
#include "kernels/mass_matrix.hpp"

namespace grout {

namespace {

/// Two entities of one kind (blocks, side sets or node sets) must not share an id or a name:
/// a look-up by name (or "id_<n>") would silently pick one.
template <class Entity>
void check_unique(const Mesh& mesh, const std::vector<Entity>& entities, const std::string& kind) {
  std::map<std::string, const Entity*> by_key;
  std::map<int, const Entity*> by_id;
  for (const Entity& e : entities) {
    const auto [it, fresh] = by_id.emplace(e.id, &e);
    if (!fresh) {
      throw InputError("mesh '" + mesh.file + "': " + kind + "s '" + it->second->name + "' and '" +
                       e.name + "' have the same id " + std::to_string(e.id) +
                       " (ids must be unique)");
    }
    for (const std::string& key : {e.name, "id_" + std::to_string(e.id)}) {
      const auto [at, unique] = by_key.emplace(key, &e);
      if (!unique && at->second != &e) {
        throw InputError("mesh '" + mesh.file + "': " + kind + "s with ids " +
                         std::to_string(at->second->id) + " and " + std::to_string(e.id) +
                         " are both named '" + key + "' (names must be unique)");
      }
    }
  }
}

void check_node_sets(const Mesh& mesh) {
  for (const NodeSet& set : mesh.node_sets) {
    std::set<GlobalIndex> seen;
    for (GlobalIndex n : set.nodes) {
      if (n < 0 || n >= mesh.num_nodes()) {
        throw InputError("mesh '" + mesh.file + "': node set '" + set.name + "' names node " +
                         std::to_string(n + 1) + ", which does not exist");
      }
      if (!seen.insert(n).second) {
        throw InputError("mesh '" + mesh.file + "': node set '" + set.name + "' lists node " +
                         std::to_string(n + 1) + " twice (reactions would count it twice)");
      }
    }
  }
}

void check_side_sets(const Mesh& mesh) {
  for (const SideSet& set : mesh.side_sets) {
    std::set<std::pair<GlobalIndex, int>> seen;
    for (std::size_t i = 0; i < set.elements.size(); ++i) {
      if (!seen.emplace(set.elements[i], set.sides[i]).second) {
        throw InputError("mesh '" + mesh.file + "': side set '" + set.name + "' lists side " +
                         std::to_string(set.sides[i]) + " of element " +
                         std::to_string(set.elements[i] + 1) +
                         " twice (its load or contact terms would count twice)");
      }
    }
  }
}

/// Largest coordinate magnitude: an element's volume ~ h^3 must stay a finite double
/// (1e100^3 = 1e300 < 1.8e308); anything larger is a unit or file error.
constexpr double max_coordinate = 1e100;

/// Every element: finite coordinates of at most max_coordinate in magnitude, and det J > 0 at
/// every point of every quadrature rule it is integrated with (check_element_geometry).
void check_elements(const Mesh& mesh) {
  const int dim = mesh.dimension;
  if (dim != 2 && dim != 3) return;  // refused by the reader
  for (const ElementBlock& block : mesh.blocks) {
    const int npe = block.nodes_per_element;
    if (npe != topology_num_nodes(block.topology) || npe > max_element_nodes) continue;
    for (GlobalIndex e = 0; e < block.num_elements(); ++e) {
      double X[max_element_nodes * 3];
      const GlobalIndex* nodes = block.connectivity.data() + e * npe;
      for (int a = 0; a < npe; ++a)
        for (int d = 0; d < dim; ++d) X[a * dim + d] = mesh.coordinates[nodes[a] * dim + d];
      check_element_geometry(block.topology, dim, X, nodes, [&] {
        return "mesh '" + mesh.file + "': block '" + block.name + "', element " +
               std::to_string(e + 1) + " (global element " +
               std::to_string(block.first_element + e + 1) + "): ";
      });
    }
  }
}

}  // namespace

void check_element_geometry(Topology topology, int dim, const double* X, const GlobalIndex* nodes,
                            const std::function<std::string()>& where) {
  if (dim != 2 && dim != 3) return;  // refused by the reader
  const int npe = topology_num_nodes(topology);
  const int degrees[2] = {full_integration_degree(topology), mass_integration_degree(topology)};
  double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
  for (int a = 0; a < npe; ++a) {
    for (int d = 0; d < dim; ++d) {
      const double x = X[a * dim + d];
      if (!std::isfinite(x) || std::abs(x) > max_coordinate) {
        std::ostringstream text;
        text << where()
             << (std::isfinite(x) ? "a node coordinate is out of range"
                                  : "a node coordinate is not a finite number")
             << " (node " << nodes[a] + 1 << ", "
             << "xyz"[d] << " = " << x;
        if (std::isfinite(x)) text << "; at most " << max_coordinate << " in magnitude";
        text << ")";
        throw InputError(text.str());
      }
      lo[d] = a == 0 ? x : std::min(lo[d], x);
      hi[d] = a == 0 ? x : std::max(hi[d], x);
    }
  }
  double h = 0.0;
  for (int d = 0; d < dim; ++d) h = std::max(h, hi[d] - lo[d]);
  const double tolerance = 1e-10 * std::pow(h, dim);
  for (const int degree : degrees) {
    double det_min = 0.0;
    const bool finite = min_jacobian_determinant(topology, dim, X, degree, det_min);
    if (!finite) throw InputError(where() + "a node coordinate is not a finite number");
    if (det_min > tolerance) continue;
    std::ostringstream text;
    text << where()
         << (det_min < -tolerance ? "inverted (det J = " : "degenerate (zero volume, det J = ")
         << det_min << " at a point of the "
         << (degree == degrees[0] ? "stiffness" : "mass matrix's") << " Gauss rule of degree "
         << degree << "; check the node order and coordinates)";
    throw InputError(text.str());
  }
}

void check_mesh(const Mesh& mesh) {
  check_unique(mesh, mesh.blocks, "element block");
  check_unique(mesh, mesh.side_sets, "side set");
  check_unique(mesh, mesh.node_sets, "node set");
  check_node_sets(mesh);
  check_side_sets(mesh);
  check_elements(mesh);
}

}  // namespace grout
