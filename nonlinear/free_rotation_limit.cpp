#include "nonlinear/free_rotation_limit.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <algorithm>
#include <cmath>
#include <set>

#include "assembly/contact_distribution.hpp"
#include "assembly/contact_surface.hpp"
#include "kernels/small_dense_lu.hpp"

namespace grout {

FreeRotationLimit::FreeRotationLimit(const ContactMesh& mesh, const Input& input,
                                     Teuchos::RCP<const Map> map,
                                     const std::vector<double>& slave_face_size)
    : dim_(mesh.dimension()), distributed_(mesh.distributed()), map_(std::move(map)) {
  const auto& comm = *map_->getComm();
  // Bodies as everywhere else: the connected components of the elements (io/mesh_bodies),
  // those of the sets' faces gathered over the ranks on a distributed part.
  const auto bodies_of = [&](const std::vector<std::string>& sets) {
    std::vector<long long> mine;
    for (const std::string& set : sets)
      for (GlobalIndex b : mesh.local_faces(set).bodies) mine.push_back(b);
    if (distributed_)
      mine = exchange_with_ranks(
          std::vector<std::vector<long long>>(std::size_t(comm.getSize()), mine), mesh.comm());
    return std::set<GlobalIndex>(mine.begin(), mine.end());
  };
  // Bodies a tied, frictional or self-contact pair touches: their rotation is held by it.
  std::set<GlobalIndex> held;
  for (const ContactInput& ci : input.contact) {
    if (ci.type == ContactKind::frictionless && !ci.self) continue;
    for (const bool master : {false, true})
      for (GlobalIndex b : bodies_of(contact_side_sets(ci, master))) held.insert(b);
  }
  const Mesh& local = mesh.mesh();
  // The prescribed components of the local nodes: the input's Dirichlet sets (a missing set
  // is reported by the solid at the first step).
  std::vector<std::array<char, 3>> fixed(std::size_t(local.num_nodes()), {0, 0, 0});
  for (const DirichletInput& bc : input.dirichlet)
    if (const NodeSet* set = local.find_node_set(bc.node_set))
      for (GlobalIndex n : set->nodes) fixed[std::size_t(n)][bc.component] = 1;
  for (std::size_t i = 0; i < input.contact.size(); ++i) {
    const ContactInput& ci = input.contact[i];
    if (ci.type != ContactKind::frictionless || ci.self) continue;
    const std::set<GlobalIndex> slave_bodies = bodies_of({ci.slave});
    if (slave_bodies.empty() || std::any_of(slave_bodies.begin(), slave_bodies.end(),
                                            [&](GlobalIndex b) { return held.count(b) > 0; }))
      continue;
    Body body;
    body.pair = int(i);
    // Ascending: the replicated mesh's nodes, or a part's owned nodes (owned first, ascending).
    for (GlobalIndex n = 0; n < local.num_nodes(); ++n) {
      const GlobalIndex g = mesh.global_node(n);
      if (distributed_ && !map_->isNodeGlobalElement(GO(g) * dim_)) continue;
      if (!slave_bodies.count(mesh.body(n))) continue;
      body.nodes.push_back(g);
      std::array<double, 3> X{0.0, 0.0, 0.0};
      for (int c = 0; c < dim_; ++c) X[c] = local.coordinates[n * dim_ + c];
      body.X.push_back(X);
      body.fixed.push_back(fixed[std::size_t(n)]);
    }
    // X0 = Σ X / count, L² = Σ |X − X0|² / count over the body's nodes.
    double sums[4] = {0.0, 0.0, 0.0, double(body.nodes.size())}, all[4];
    for (const auto& X : body.X)
      for (int c = 0; c < dim_; ++c) sums[c] += X[c];
    if (distributed_)
      Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, 4, sums, all);
    else
      std::copy(sums, sums + 4, all);
    const double count = all[3];
    for (int c = 0; c < dim_; ++c) body.X0[c] = all[c] / count;
    double r2 = 0.0, r2_all = 0.0;
    for (const auto& X : body.X)
      for (int c = 0; c < dim_; ++c) {
        const double d = X[c] - body.X0[c];
        r2 += d * d;
      }
    if (distributed_)
      Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, r2, Teuchos::outArg(r2_all));
    else
      r2_all = r2;
    body.L = std::sqrt(r2_all / count);
    body.h = slave_face_size[i];
    if (!(body.L > 0.0) || !(body.h > 0.0)) continue;
    bodies_.push_back(std::move(body));
  }
}

namespace {
std::vector<double> slave_face_sizes(const Mesh& mesh, const Input& input) {
  std::vector<double> sizes;
  for (const ContactInput& ci : input.contact)
    sizes.push_back(mean_face_size(mesh, contact_side_sets(ci, false)));
  return sizes;
}
}  // namespace

FreeRotationLimit::FreeRotationLimit(const Mesh& mesh, const Input& input,
                                     Teuchos::RCP<const Map> map)
    : FreeRotationLimit(ContactMesh(mesh), input, std::move(map), slave_face_sizes(mesh, input)) {}

double FreeRotationLimit::limit(const std::vector<std::vector<ContactNode>>& active,
                                const std::vector<std::vector<ContactNode>>& owned_slave,
                                Vector& step) const {
  double worst = 0.0;
  const auto& comm = *map_->getComm();
  for (const Body& body : bodies_) {
    // Active slave nodes anywhere? Otherwise the slave surface's nodes stand for the contact.
    const double local = double(active[body.pair].size());
    double global = 0.0;
    Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, local, Teuchos::outArg(global));
    const auto& contact = global > 0.0 ? active[body.pair] : owned_slave[body.pair];
    worst = std::max(worst, limit_body(body, contact, step));
  }
  return worst;
}

double FreeRotationLimit::limit_body(const Body& body, const std::vector<ContactNode>& contact,
                                     Vector& step) const {
  const int dim = dim_, n = rigid_mode_count(dim);
  // G and P over the body's dofs (replicated data: the same on every rank; a distributed
  // part's owned nodes, summed over the ranks).
  double G[max_rigid_modes][max_rigid_modes] = {}, P[max_rigid_modes][max_rigid_modes] = {};
  for (std::size_t k = 0; k < body.nodes.size(); ++k) {
    double r[max_rigid_modes][3];
    for (int a = 0; a < n; ++a) rigid_mode_value(dim, a, body.X[k].data(), body.X0, body.L, r[a]);
    for (int c = 0; c < dim; ++c) {
      const bool fixed = body.fixed[k][c] != 0;
      for (int a = 0; a < n; ++a)
        for (int b = 0; b < n; ++b) {
          G[a][b] += r[a][c] * r[b][c];
          if (fixed) P[a][b] += r[a][c] * r[b][c];
        }
    }
  }
  if (distributed_) {
    double GP[2 * max_rigid_modes * max_rigid_modes], all[2 * max_rigid_modes * max_rigid_modes];
    constexpr int m = max_rigid_modes * max_rigid_modes;
    std::copy(&G[0][0], &G[0][0] + m, GP);
    std::copy(&P[0][0], &P[0][0] + m, GP + m);
    Teuchos::reduceAll(*map_->getComm(), Teuchos::REDUCE_SUM, 2 * m, GP, all);
    std::copy(all, all + m, &G[0][0]);
    std::copy(all + m, all + 2 * m, &P[0][0]);
  }
  FreeRigidModes modes;
  if (!free_rigid_modes(dim, G, P, modes) || !modes.rotates) return 0.0;

  // One sum over the ranks: b_a = Σ r_a · δ over the body's owned dofs; over the contact
  // nodes, N = Σ n nᵀ, Q_ca = Σ n_c (n · r_a(X_j)), Σ X_j and their count.
  auto s = step.getLocalViewHost(Tpetra::Access::ReadWrite);
  const auto lid = [&](GlobalIndex node, int c) {
    return map_->getLocalElement(GO(node) * dim + c);  // invalid unless owned
  };
  const auto invalid = Teuchos::OrdinalTraits<LO>::invalid();
  constexpr int nb = 0, nN = max_rigid_modes, nQ = nN + 9, nX = nQ + 3 * max_rigid_modes,
                ncount = nX + 3, nsums = ncount + 1;
  double sums[nsums] = {}, all[nsums] = {};
  for (std::size_t k = 0; k < body.nodes.size(); ++k) {
    const GlobalIndex node = body.nodes[k];
    if (lid(node, 0) == invalid) continue;  // a node's dofs have one owner
    for (int a = 0; a < n; ++a) {
      double r[3];
      rigid_mode_value(dim, a, body.X[k].data(), body.X0, body.L, r);
      for (int c = 0; c < dim; ++c) sums[nb + a] += r[c] * s(lid(node, c), 0);
    }
  }
  for (const ContactNode& cn : contact) {
    const double* Xj = cn.X;
    for (int c = 0; c < dim; ++c) {
      for (int e = 0; e < dim; ++e) sums[nN + 3 * c + e] += cn.normal[c] * cn.normal[e];
      sums[nX + c] += Xj[c];
    }
    for (int a = 0; a < n; ++a) {
      double r[3], nr = 0.0;
      rigid_mode_value(dim, a, Xj, body.X0, body.L, r);
      for (int c = 0; c < dim; ++c) nr += cn.normal[c] * r[c];
      for (int c = 0; c < dim; ++c) sums[nQ + max_rigid_modes * c + a] += cn.normal[c] * nr;
    }
    sums[ncount] += 1.0;
  }
  Teuchos::reduceAll(*map_->getComm(), Teuchos::REDUCE_SUM, nsums, sums, all);
  const double count = all[ncount];
  if (count == 0.0) return 0.0;

  // w = β_f − τ: the free part of the step's rigid fit less the free translation τ that
  // moves the contact nodes least along their normals, min Σ_j (n_j · w(X_j))² + ε Σ_j |w(X_j)|²
  // (ε = 1e-6 picks τ where the normals do not: a translation along the contact surface):
  // (N_FF + ε count I) τ_F = (Q β_f)_F + ε count β_f(X̄)_F over the free translations F.
  double w[max_rigid_modes];
  free_rigid_part(modes, all + nb, w);
  double mean[3] = {0.0, 0.0, 0.0}, at_mean[3];
  for (int c = 0; c < dim; ++c) mean[c] = all[nX + c] / count;
  rigid_motion_value(dim, w, mean, body.X0, body.L, at_mean);
  constexpr double eps = 1e-6;
  int free_c[3], nf = 0;
  for (int c = 0; c < dim; ++c)
    if (modes.translation_free[c]) free_c[nf++] = c;
  if (nf > 0) {
    double A[9] = {}, tau[3] = {};
    int pivot[3];
    for (int i = 0; i < nf; ++i) {
      const int c = free_c[i];
      for (int k = 0; k < nf; ++k) A[i * 3 + k] = all[nN + 3 * c + free_c[k]];
      A[i * 3 + i] += eps * count;
      for (int a = 0; a < n; ++a) tau[i] += all[nQ + max_rigid_modes * c + a] * w[a];
      tau[i] += eps * count * at_mean[c];
    }
    if (small_lu_factor(nf, A, 3, pivot)) {
      small_lu_solve(nf, A, 3, pivot, tau);
      for (int i = 0; i < nf; ++i) w[free_c[i]] -= tau[i];
    }
  }

  double slide = 0.0, slide_all = 0.0;
  for (const ContactNode& cn : contact) {
    double v[3];
    rigid_motion_value(dim, w, cn.X, body.X0, body.L, v);
    double v2 = 0.0;
    for (int c = 0; c < dim; ++c) v2 += v[c] * v[c];
    slide = std::max(slide, std::sqrt(v2));
  }
  Teuchos::reduceAll(*map_->getComm(), Teuchos::REDUCE_MAX, slide, Teuchos::outArg(slide_all));
  const double cap = max_slide_per_step * body.h;
  if (!(slide_all > cap)) return slide_all / body.h;

  const double cut = 1.0 - cap / slide_all;
  for (std::size_t k = 0; k < body.nodes.size(); ++k) {
    const GlobalIndex node = body.nodes[k];
    if (lid(node, 0) == invalid) continue;
    double v[3];
    rigid_motion_value(dim, w, body.X[k].data(), body.X0, body.L, v);
    for (int c = 0; c < dim; ++c)
      if (!body.fixed[k][c]) s(lid(node, c), 0) -= cut * v[c];
  }
  return slide_all / body.h;
}

}  // namespace grout
