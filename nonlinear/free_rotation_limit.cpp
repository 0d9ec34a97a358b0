#include "nonlinear/free_rotation_limit.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <algorithm>
#include <cmath>
#include <set>

#include "assembly/contact_surface.hpp"
#include "io/mesh_bodies.hpp"
#include "kernels/small_dense_lu.hpp"

namespace grout {

FreeRotationLimit::FreeRotationLimit(const Mesh& mesh, const Input& input,
                                     Teuchos::RCP<const Map> map)
    : mesh_(mesh), dim_(mesh.dimension), map_(std::move(map)) {
  // Bodies as everywhere else: the connected components of the elements (io/mesh_bodies).
  const std::vector<int> body_of = node_bodies(mesh);
  const auto bodies_of = [&](const std::vector<std::string>& sets) {
    std::set<int> out;
    for (GlobalIndex n : side_set_nodes(mesh, sets)) out.insert(body_of[std::size_t(n)]);
    return out;
  };
  // Bodies a tied, frictional or self-contact pair touches: their rotation is held by it.
  std::set<int> held;
  for (const ContactInput& ci : input.contact) {
    if (ci.type == ContactKind::frictionless && !ci.self) continue;
    for (const bool master : {false, true})
      for (int b : bodies_of(contact_side_sets(ci, master))) held.insert(b);
  }
  for (std::size_t i = 0; i < input.contact.size(); ++i) {
    const ContactInput& ci = input.contact[i];
    if (ci.type != ContactKind::frictionless || ci.self) continue;
    const std::set<int> slave_bodies = bodies_of({ci.slave});
    if (slave_bodies.empty() || std::any_of(slave_bodies.begin(), slave_bodies.end(),
                                            [&](int b) { return held.count(b) > 0; }))
      continue;
    Body body;
    body.pair = int(i);
    for (GlobalIndex n = 0; n < mesh.num_nodes(); ++n)  // ascending: sorted
      if (slave_bodies.count(body_of[std::size_t(n)])) body.nodes.push_back(n);
    for (GlobalIndex n : body.nodes)
      for (int c = 0; c < dim_; ++c) body.X0[c] += mesh.coordinates[n * dim_ + c];
    for (int c = 0; c < dim_; ++c) body.X0[c] /= double(body.nodes.size());
    double r2 = 0.0;
    for (GlobalIndex n : body.nodes)
      for (int c = 0; c < dim_; ++c) {
        const double d = mesh.coordinates[n * dim_ + c] - body.X0[c];
        r2 += d * d;
      }
    body.L = std::sqrt(r2 / double(body.nodes.size()));
    body.h = mean_face_size(mesh, std::vector<std::string>{ci.slave});
    if (!(body.L > 0.0) || !(body.h > 0.0)) continue;
    bodies_.push_back(std::move(body));
  }
}

double FreeRotationLimit::limit(const std::vector<double>& prescribed,
                                const std::vector<std::vector<ContactNode>>& active,
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
    worst = std::max(worst, limit_body(body, prescribed, contact, step));
  }
  return worst;
}

double FreeRotationLimit::limit_body(const Body& body, const std::vector<double>& prescribed,
                                     const std::vector<ContactNode>& contact, Vector& step) const {
  const int dim = dim_, n = rigid_mode_count(dim);
  const double* X = mesh_.coordinates.data();
  // G and P over the body's dofs (replicated data: the same on every rank).
  double G[max_rigid_modes][max_rigid_modes] = {}, P[max_rigid_modes][max_rigid_modes] = {};
  for (GlobalIndex node : body.nodes) {
    double r[max_rigid_modes][3];
    for (int a = 0; a < n; ++a) rigid_mode_value(dim, a, X + node * dim, body.X0, body.L, r[a]);
    for (int c = 0; c < dim; ++c) {
      const bool fixed = !std::isnan(prescribed[node * dim + c]);
      for (int a = 0; a < n; ++a)
        for (int b = 0; b < n; ++b) {
          G[a][b] += r[a][c] * r[b][c];
          if (fixed) P[a][b] += r[a][c] * r[b][c];
        }
    }
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
  for (GlobalIndex node : body.nodes) {
    if (lid(node, 0) == invalid) continue;  // a node's dofs have one owner
    for (int a = 0; a < n; ++a) {
      double r[3];
      rigid_mode_value(dim, a, X + node * dim, body.X0, body.L, r);
      for (int c = 0; c < dim; ++c) sums[nb + a] += r[c] * s(lid(node, c), 0);
    }
  }
  for (const ContactNode& cn : contact) {
    const double* Xj = X + cn.node * dim;
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
    rigid_motion_value(dim, w, X + cn.node * dim, body.X0, body.L, v);
    double v2 = 0.0;
    for (int c = 0; c < dim; ++c) v2 += v[c] * v[c];
    slide = std::max(slide, std::sqrt(v2));
  }
  Teuchos::reduceAll(*map_->getComm(), Teuchos::REDUCE_MAX, slide, Teuchos::outArg(slide_all));
  const double cap = max_slide_per_step * body.h;
  if (!(slide_all > cap)) return slide_all / body.h;

  const double cut = 1.0 - cap / slide_all;
  for (GlobalIndex node : body.nodes) {
    if (lid(node, 0) == invalid) continue;
    double v[3];
    rigid_motion_value(dim, w, X + node * dim, body.X0, body.L, v);
    for (int c = 0; c < dim; ++c)
      if (std::isnan(prescribed[node * dim + c])) s(lid(node, c), 0) -= cut * v[c];
  }
  return slide_all / body.h;
}

}  // namespace grout
