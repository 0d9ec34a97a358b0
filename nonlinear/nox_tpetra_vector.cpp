#include "nonlinear/nox_tpetra_vector.hpp"

#include <Teuchos_ScalarTraits.hpp>
#include <cmath>
#include <ostream>

namespace grout {

const grout::Vector& NoxTpetraVector::tpetra(const NOX::Abstract::Vector& v) {
  return dynamic_cast<const NoxTpetraVector&>(v).tpetra();
}

NOX::Abstract::Vector& NoxTpetraVector::init(double gamma) {
  v_->putScalar(gamma);
  return *this;
}

NOX::Abstract::Vector& NoxTpetraVector::random(bool use_seed, int seed) {
  if (use_seed) Teuchos::ScalarTraits<double>::seedrandom(static_cast<unsigned>(seed));
  v_->randomize();
  return *this;
}

NOX::Abstract::Vector& NoxTpetraVector::abs(const NOX::Abstract::Vector& y) {
  v_->abs(tpetra(y));
  return *this;
}

NOX::Abstract::Vector& NoxTpetraVector::operator=(const NOX::Abstract::Vector& y) {
  const grout::Vector& source = tpetra(y);
  if (&source != v_.get()) Tpetra::deep_copy(*v_, source);
  return *this;
}

NOX::Abstract::Vector& NoxTpetraVector::reciprocal(const NOX::Abstract::Vector& y) {
  v_->reciprocal(tpetra(y));
  return *this;
}

NOX::Abstract::Vector& NoxTpetraVector::scale(double gamma) {
  v_->scale(gamma);
  return *this;
}

NOX::Abstract::Vector& NoxTpetraVector::scale(const NOX::Abstract::Vector& a) {
  const auto av = tpetra(a).getLocalViewHost(Tpetra::Access::ReadOnly);
  auto xv = v_->getLocalViewHost(Tpetra::Access::ReadWrite);
  for (std::size_t i = 0; i < xv.extent(0); ++i) xv(i, 0) *= av(i, 0);
  return *this;
}

NOX::Abstract::Vector& NoxTpetraVector::update(double alpha, const NOX::Abstract::Vector& a,
                                               double gamma) {
  v_->update(alpha, tpetra(a), gamma);
  return *this;
}

NOX::Abstract::Vector& NoxTpetraVector::update(double alpha, const NOX::Abstract::Vector& a,
                                               double beta, const NOX::Abstract::Vector& b,
                                               double gamma) {
  v_->update(alpha, tpetra(a), beta, tpetra(b), gamma);
  return *this;
}

Teuchos::RCP<NOX::Abstract::Vector> NoxTpetraVector::clone(NOX::CopyType type) const {
  auto copy = Teuchos::rcp(new grout::Vector(v_->getMap()));  // zero-filled
  if (type == NOX::DeepCopy) Tpetra::deep_copy(*copy, *v_);
  return Teuchos::rcp(new NoxTpetraVector(copy));
}

double NoxTpetraVector::norm(NOX::Abstract::Vector::NormType type) const {
  switch (type) {
    case NOX::Abstract::Vector::OneNorm:
      return v_->norm1();
    case NOX::Abstract::Vector::MaxNorm:
      return v_->normInf();
    default:
      return v_->norm2();
  }
}

double NoxTpetraVector::norm(const NOX::Abstract::Vector& weights) const {
  const auto wv = tpetra(weights).getLocalViewHost(Tpetra::Access::ReadOnly);
  const auto xv = v_->getLocalViewHost(Tpetra::Access::ReadOnly);
  double local = 0.0;
  for (std::size_t i = 0; i < xv.extent(0); ++i) local += wv(i, 0) * xv(i, 0) * xv(i, 0);
  double global = 0.0;
  Teuchos::reduceAll(*v_->getMap()->getComm(), Teuchos::REDUCE_SUM, local, Teuchos::outArg(global));
  return std::sqrt(global);
}

double NoxTpetraVector::innerProduct(const NOX::Abstract::Vector& y) const {
  return v_->dot(tpetra(y));
}

NOX::size_type NoxTpetraVector::length() const {
  return static_cast<NOX::size_type>(v_->getGlobalLength());
}

void NoxTpetraVector::print(std::ostream& stream) const {
  // No norms here: print() may run on one rank only, and norms are collective.
  stream << "grout::NoxTpetraVector, global length " << v_->getGlobalLength() << '\n';
}

}  // namespace grout
