// grout::contact_law_at_nodes (grout/contact_law.hpp): the host's nodes converted to the
// kernel's ContactLawNode, the driver's launch evaluate_contact_law (kernels/contact_laws.hpp)
// on the default execution space, the results converted back. No copy of the law.

#include "grout/contact_law.hpp"

#include <Kokkos_Core.hpp>

#include <cmath>
#include <string>

#include "kernels/contact_laws.hpp"

namespace grout {
namespace {

// The public column numbering is the kernel's layout.
constexpr bool same_columns() {
  using C = ContactLawColumn;
  using L = ContactLawLayout;
  bool same = C::count == L::count && C::gap() == L::gap();
  for (int a = 0; a < 3; ++a)
    same = same && C::lambda(a) == L::lambda(a) && C::normal(a) == L::normal(a) &&
           C::tied(a) == L::tied(a) && C::tangent(0, a) == L::tangent(0, a) &&
           C::tangent(1, a) == L::tangent(1, a);
  for (int k = 0; k < 2; ++k) same = same && C::slip(k) == L::slip(k);
  return same;
}
static_assert(same_columns(),
              "grout::ContactLawColumn must number the columns as ContactLawLayout");
static_assert(int(ContactLawType::frictionless) == frictionless_law &&
                  int(ContactLawType::coulomb) == coulomb_law &&
                  int(ContactLawType::tied) == tied_law,
              "grout::ContactLawType must match ContactLawKind");
static_assert(int(ContactNodeState::open) == node_open &&
                  int(ContactNodeState::stick) == node_stick &&
                  int(ContactNodeState::slip) == node_slip,
              "grout::ContactNodeState must match ContactNodeStatus");
static_assert(int(ContactRowKind::identity) == row_identity &&
                  int(ContactRowKind::constraint) == row_constraint &&
                  int(ContactRowKind::slip) == row_slip &&
                  int(ContactRowKind::tangent) == row_tangent,
              "grout::ContactRowKind must match MultiplierRowKind");

[[noreturn]] void fail(const std::string& what) {
  throw ContactLawError("grout::contact_law_at_nodes: " + what);
}

void check_settings(const ContactLawSettings& s) {
  if (s.dim != 2 && s.dim != 3) fail("settings.dim = " + std::to_string(s.dim) + " (2 or 3)");
  const int law = int(s.law);
  if (law != frictionless_law && law != coulomb_law && law != tied_law)
    fail("settings.law = " + std::to_string(law) + " (frictionless, coulomb or tied)");
  if (!(s.c_hat > 0.0) || !std::isfinite(s.c_hat))
    fail("settings.c_hat = " + std::to_string(s.c_hat) + " (finite, > 0)");
  if (!(s.c_t_hat > 0.0) || !std::isfinite(s.c_t_hat))
    fail("settings.c_t_hat = " + std::to_string(s.c_t_hat) + " (finite, > 0)");
  if (!(s.mu >= 0.0) || !std::isfinite(s.mu))
    fail("settings.mu = " + std::to_string(s.mu) + " (finite, >= 0)");
  if (!(s.active_tolerance >= 0.0) || !std::isfinite(s.active_tolerance))
    fail("settings.active_tolerance = " + std::to_string(s.active_tolerance) + " (finite, >= 0)");
}

/// The kernel's node from the host's, every value the law reads checked finite.
ContactLawNode kernel_node(int dim, const ContactLawInput& in, std::size_t i) {
  const auto finite = [&](double x, const char* field, int c) {
    if (!std::isfinite(x))
      fail("node " + std::to_string(i) + ": " + field + "[" + std::to_string(c) +
           "] = " + std::to_string(x) + " (not finite)");
    return x;
  };
  ContactLawNode node = ContactLawNode();
  for (int a = 0; a < dim; ++a) {
    node.lambda[a] = finite(in.lambda[a], "lambda", a);
    node.n[a] = finite(in.n[a], "n", a);
    node.tied[a] = finite(in.tied[a], "tied", a);
    node.prescribed[a] = in.prescribed[a];
    node.free_share[a] = finite(in.free_share[a], "free_share", a);
    if (node.free_share[a] < 0.0)
      fail("node " + std::to_string(i) + ": free_share[" + std::to_string(a) + "] < 0");
    for (int k = 0; k < dim - 1; ++k) node.t[k][a] = finite(in.t[k][a], k ? "t[1]" : "t[0]", a);
  }
  node.gap = finite(in.gap, "gap", 0);
  for (int k = 0; k < dim - 1; ++k) node.slip[k] = finite(in.slip[k], "slip", k);
  node.paired = in.paired;
  node.near = in.near;
  node.held_back = in.held_back;
  return node;
}

ContactLawRows host_rows(const ContactLawResult& r) {
  ContactLawRows out;
  for (int i = 0; i < 3; ++i) {
    out.C[i] = r.C[i];
    for (int q = 0; q < ContactLawColumn::count; ++q) out.dC[i][q] = r.dC[i][q];
    out.kind[i] = ContactRowKind(int(r.kind[i]));
    out.component[i] = r.component[i];
  }
  out.state = ContactNodeState(r.status);
  out.held_axis[0] = r.held_axis[0];
  out.held_axis[1] = r.held_axis[1];
  return out;
}

}  // namespace

void contact_law_at_nodes(const ContactLawSettings& settings, const ContactLawInput* nodes,
                          std::size_t count, bool derivatives, ContactLawRows* rows) {
  check_settings(settings);
  if (count == 0) return;
  if (!nodes || !rows) fail("null nodes or rows for " + std::to_string(count) + " nodes");
  using Space = Kokkos::DefaultExecutionSpace;  // the driver's (nonlinear/contact_interface.hpp)
  using Memory = Space::memory_space;
  Kokkos::View<ContactLawNode*, Memory> law_nodes(
      Kokkos::ViewAllocateWithoutInitializing("grout::contact_law_nodes"), count);
  Kokkos::View<ContactLawResult*, Memory> results(
      Kokkos::ViewAllocateWithoutInitializing("grout::contact_law_results"), count);
  auto nodes_host = Kokkos::create_mirror_view(law_nodes);
  for (std::size_t i = 0; i < count; ++i) nodes_host(i) = kernel_node(settings.dim, nodes[i], i);
  Kokkos::deep_copy(law_nodes, nodes_host);
  ContactLawParameters p;
  p.dim = settings.dim;
  p.kind = int(settings.law);
  p.c_hat = settings.c_hat, p.c_t_hat = settings.c_t_hat;
  p.mu = settings.mu, p.active_tolerance = settings.active_tolerance;
  evaluate_contact_law(Space(), p, Kokkos::View<const ContactLawNode*, Memory>(law_nodes),
                       derivatives, results);
  auto results_host = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), results);
  for (std::size_t i = 0; i < count; ++i) rows[i] = host_rows(results_host(i));
}

std::vector<ContactLawRows> contact_law_at_nodes(const ContactLawSettings& settings,
                                                 const std::vector<ContactLawInput>& nodes,
                                                 bool derivatives) {
  std::vector<ContactLawRows> rows(nodes.size());
  contact_law_at_nodes(settings, nodes.data(), nodes.size(), derivatives, rows.data());
  return rows;
}

}  // namespace grout
