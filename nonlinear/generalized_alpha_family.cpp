#include "nonlinear/generalized_alpha_family.hpp"

namespace grout {

void GeneralizedAlphaFamily::acceleration(const Vector& u_next, const Vector& u_n,
                                          const Vector& v_n, const Vector& a_n, double dt,
                                          Vector& a_next) const {
  const auto u = u_next.getLocalViewHost(Tpetra::Access::ReadOnly);
  const auto un = u_n.getLocalViewHost(Tpetra::Access::ReadOnly);
  const auto vn = v_n.getLocalViewHost(Tpetra::Access::ReadOnly);
  const auto an = a_n.getLocalViewHost(Tpetra::Access::ReadOnly);
  auto out = a_next.getLocalViewHost(Tpetra::Access::OverwriteAll);
  const std::size_t n = u_next.getLocalLength();
  for (std::size_t i = 0; i < n; ++i) {
    const double du = u(i, 0) - un(i, 0);
    out(i, 0) = (du - dt * vn(i, 0)) / (beta_ * dt * dt) - (0.5 / beta_ - 1.0) * an(i, 0);
  }
}

void GeneralizedAlphaFamily::velocity(const Vector& v_n, const Vector& a_n, const Vector& a_next,
                                      double dt, Vector& v_next) const {
  v_next.assign(v_n);
  v_next.update(dt * (1.0 - gamma_), a_n, dt * gamma_, a_next, 1.0);
}

}  // namespace grout
