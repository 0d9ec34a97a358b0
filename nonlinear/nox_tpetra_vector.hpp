#pragma once
// NOX::Abstract::Vector over a Tpetra::Vector (docs/design.md, "Toolchain notes": NOX route B).
// Private to nonlinear/*.cpp: NOX headers must not leak into headers other libraries include.

#include <NOX_Abstract_Vector.H>
#include <Teuchos_RCP.hpp>

#include "assembly/tpetra_types.hpp"

namespace grout {

class NoxTpetraVector : public NOX::Abstract::Vector {
 public:
  /// Wraps `v` (shared, not copied).
  explicit NoxTpetraVector(const Teuchos::RCP<grout::Vector>& v) : v_(v) {}
  NoxTpetraVector(const NoxTpetraVector&) = delete;  // use clone()

  grout::Vector& tpetra() { return *v_; }
  const grout::Vector& tpetra() const { return *v_; }
  static const grout::Vector& tpetra(const NOX::Abstract::Vector& v);

  NOX::Abstract::Vector& init(double gamma) override;
  NOX::Abstract::Vector& random(bool use_seed = false, int seed = 1) override;
  NOX::Abstract::Vector& abs(const NOX::Abstract::Vector& y) override;
  NOX::Abstract::Vector& operator=(const NOX::Abstract::Vector& y) override;
  /// Deep copy (the implicit one would call the base's pure operator=).
  NoxTpetraVector& operator=(const NoxTpetraVector& y) {
    *this = static_cast<const NOX::Abstract::Vector&>(y);
    return *this;
  }
  NOX::Abstract::Vector& reciprocal(const NOX::Abstract::Vector& y) override;
  NOX::Abstract::Vector& scale(double gamma) override;
  NOX::Abstract::Vector& scale(const NOX::Abstract::Vector& a) override;
  NOX::Abstract::Vector& update(double alpha, const NOX::Abstract::Vector& a,
                                double gamma = 0.0) override;
  NOX::Abstract::Vector& update(double alpha, const NOX::Abstract::Vector& a, double beta,
                                const NOX::Abstract::Vector& b, double gamma = 0.0) override;
  Teuchos::RCP<NOX::Abstract::Vector> clone(NOX::CopyType type = NOX::DeepCopy) const override;
  double norm(NOX::Abstract::Vector::NormType type = TwoNorm) const override;
  /// sqrt(Σ wᵢ xᵢ²)
  double norm(const NOX::Abstract::Vector& weights) const override;
  double innerProduct(const NOX::Abstract::Vector& y) const override;
  NOX::size_type length() const override;
  void print(std::ostream& stream) const override;

 private:
  Teuchos::RCP<grout::Vector> v_;
};

}  // namespace grout
