#include "assembly/contact_sides.hpp"

#include <algorithm>
#include <cmath>

#include "assembly/contact_distribution.hpp"
#include "io/errors.hpp"

namespace grout {

namespace {

/// One side of an interface: the faces of its side sets (one, or those of `self: [...]`) taken
/// one after the other; a face's id is its position in the sets so taken.
struct Side {
  std::vector<SideFaces> sets;
  std::vector<GlobalIndex> first_id;  ///< id of each set's first face
};

// The faces of the side sets, all of them (`all`) or this rank's entries; the checks of
// build_contact_surface (a missing or empty set, a face of an element in no block, a side that
// is not a face) under `key`.
Side read_side(const ContactMesh& mesh, const std::string& key,
               const std::vector<std::string>& set_names, bool all) {
  Side side;
  GlobalIndex first_id = 0;
  for (const std::string& name : set_names) {
    if (!mesh.has_side_set(name))
      throw InputError(key + ": no side set '" + name + "' in mesh '" + mesh.mesh().file + "'");
    side.sets.push_back(all ? mesh.all_faces(name) : mesh.local_faces(name));
    const SideFaces& set = side.sets.back();
    if (set.set_size == 0) throw InputError(key + ": side set '" + name + "' is empty");
    for (std::size_t i = 0; i < set.size(); ++i) {
      if (set.blocks[i] < 0)
        throw InputError(key + ": side set '" + name + "' names element " +
                         std::to_string(set.elements[i] + 1) + ", which is in no block");
      if (set.num_nodes[i] < 2)
        throw InputError(key + ": side set '" + name + "' has side " +
                         std::to_string(set.sides[i]) + " of element " +
                         std::to_string(set.elements[i] + 1) + ", which is not a face");
    }
    side.first_id.push_back(first_id);
    first_id += set.set_size;
  }
  return side;
}

using FaceFilter = std::function<bool(const GlobalIndex* nodes, int n)>;

// The faces of `side` that `keep` accepts, in side-set order, with their nodes' coordinates
// added to X.
SurfaceFaces faces_of(const ContactMesh& mesh, const Side& side, const FaceFilter& keep,
                      std::unordered_map<GlobalIndex, std::array<double, 3>>* X = nullptr) {
  SurfaceFaces faces;
  for (std::size_t s = 0; s < side.sets.size(); ++s) {
    const SideFaces& set = side.sets[s];
    for (std::size_t i = 0; i < set.size(); ++i) {
      if (keep && !keep(set.nodes[i].data(), set.num_nodes[i])) continue;
      faces.nodes.push_back(set.nodes[i]);
      faces.ids.push_back(side.first_id[s] + set.positions[i]);
      faces.num_nodes.push_back(set.num_nodes[i]);
      faces.blocks.push_back(&mesh.mesh().blocks[std::size_t(set.blocks[i])]);
      if (X)
        for (int a = 0; a < set.num_nodes[i]; ++a)
          (*X)[set.nodes[i][a]] = {set.X[i][3 * a], set.X[i][3 * a + 1], set.X[i][3 * a + 2]};
    }
  }
  return faces;
}

std::vector<GlobalIndex> unique_nodes(const SurfaceFaces& faces) {
  std::vector<GlobalIndex> nodes;
  for (std::size_t f = 0; f < faces.size(); ++f)
    nodes.insert(nodes.end(), faces.nodes[f].begin(), faces.nodes[f].begin() + faces.num_nodes[f]);
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  return nodes;
}

// A slave face must not lie on a body that carries master faces (a slave side set with faces
// of both bodies would put a body in contact with itself). `slave`: every slave face;
// `master`: this rank's master faces (the bodies are gathered over the ranks).
void check_bodies(const ContactMesh& mesh, const Input& input, const ContactInput& contact,
                  const SideFaces& slave, const SideFaces& master) {
  std::vector<long long> master_bodies(master.bodies.begin(), master.bodies.end());
  std::sort(master_bodies.begin(), master_bodies.end());
  master_bodies.erase(std::unique(master_bodies.begin(), master_bodies.end()), master_bodies.end());
  if (mesh.distributed()) {
    int n_ranks = 1;
    MPI_Comm_size(mesh.comm(), &n_ranks);
    master_bodies = exchange_with_ranks(
        std::vector<std::vector<long long>>(std::size_t(n_ranks), master_bodies), mesh.comm());
    std::sort(master_bodies.begin(), master_bodies.end());
  }
  for (std::size_t f = 0; f < slave.size(); ++f) {
    if (std::binary_search(master_bodies.begin(), master_bodies.end(), slave.bodies[f])) {
      throw InputError(input.file + ": grout/contact/" + contact.name + "/slave: side set '" +
                       contact.slave + "' has a face (face " + std::to_string(f + 1) + ", node " +
                       std::to_string(slave.nodes[f][0] + 1) +
                       ") on the body of master side set '" + contact.master +
                       "' (slave and master faces must lie on different bodies)");
    }
  }
}

}  // namespace

double face_size_of(int dim, const std::array<double, 3>* x, int n) {
  double extent = 0.0;  // longest edge
  for (int a = 0; a < n; ++a) {
    const std::array<double, 3>&p = x[a], &q = x[(a + 1) % n];
    double d2 = 0.0;
    for (int d = 0; d < dim; ++d) {
      const double dx = p[d] - q[d];
      d2 += dx * dx;
    }
    extent = std::max(extent, std::sqrt(d2));
  }
  return extent;
}

ContactSides read_contact_sides(const ContactMesh& mesh, const Input& input,
                                const ContactInput& contact,
                                const std::function<bool(GlobalIndex)>& owns) {
  const std::string key = input.file + ": grout/contact/" + contact.name + "/";
  const char* const slave_role = contact.self ? "self" : "slave";
  const std::vector<std::string> slave_sets = contact_side_sets(contact, false);
  const std::vector<std::string> master_sets = contact_side_sets(contact, true);
  // The whole slave side (gathered on a part), this rank's master entries.
  const Side slave = read_side(mesh, key + slave_role, slave_sets, true);
  const Side master = read_side(mesh, key + (contact.self ? "self" : "master"), master_sets, false);
  if (!contact.self) check_bodies(mesh, input, contact, slave.sets[0], master.sets[0]);

  ContactSides out;
  ContactSurface& s = out.local.surface;
  s.name = contact.name;
  s.self = contact.self;
  s.type = contact.type;
  s.dimension = mesh.dimension();
  const auto has_owned = [&](const GlobalIndex* nodes, int n) {
    for (int a = 0; a < n; ++a)
      if (owns(nodes[a])) return true;
    return false;
  };
  // Nodes of the faces with an owned node; then every face touching one of them.
  const std::vector<GlobalIndex> near = unique_nodes(faces_of(mesh, slave, has_owned));
  SurfaceFaces slave_faces = faces_of(
      mesh, slave,
      [&](const GlobalIndex* nodes, int n) {
        for (int a = 0; a < n; ++a)
          if (std::binary_search(near.begin(), near.end(), nodes[a])) return true;
        return false;
      },
      &out.X);
  s.integrate.resize(slave_faces.size());
  for (std::size_t f = 0; f < slave_faces.size(); ++f)
    s.integrate[f] = has_owned(slave_faces.nodes[f].data(), slave_faces.num_nodes[f]);
  set_slave_faces(s, std::move(slave_faces));
  LocalContactFaces& local = out.local;
  local.owned_master = faces_of(
      mesh, master,
      [&](const GlobalIndex* nodes, int n) {
        for (int a = 0; a < n && !contact.self; ++a) {
          // an owned slave node?
          if (!owns(nodes[a]) || !s.slave_index.count(nodes[a])) continue;
          if (local.shared_node < 0 || nodes[a] < local.shared_node) local.shared_node = nodes[a];
        }
        return owns(*std::min_element(nodes, nodes + n));
      },
      &out.X);
  s.nodes = s.slave_nodes;

  // The global quantities, from the whole slave side in side-set order.
  const SurfaceFaces all = faces_of(mesh, slave, {});
  out.all_slave_nodes = unique_nodes(all);
  out.num_slave_faces = GlobalIndex(all.size());
  double sum = 0.0;
  for (const SideFaces& set : slave.sets)
    for (std::size_t i = 0; i < set.size(); ++i) {
      std::array<double, 3> x[max_face_nodes];
      for (int a = 0; a < set.num_nodes[i]; ++a)
        x[a] = {set.X[i][3 * a], set.X[i][3 * a + 1], set.X[i][3 * a + 2]};
      sum += face_size_of(mesh.dimension(), x, set.num_nodes[i]);
    }
  out.mean_slave_face_size = all.size() ? sum / double(all.size()) : 0.0;
  out.slave_block = &mesh.mesh().blocks[std::size_t(slave.sets[0].blocks.front())];
  // The master side's first face: its block from the owner of its element.
  int first_block = -1, block = -1;
  const SideFaces& m = master.sets[0];
  if (m.size() > 0 && m.positions[0] == 0) first_block = m.blocks[0];
  if (mesh.distributed())
    MPI_Allreduce(&first_block, &block, 1, MPI_INT, MPI_MAX, mesh.comm());
  else
    block = first_block;
  out.master_block = &mesh.mesh().blocks[std::size_t(block)];
  return out;
}

}  // namespace grout
