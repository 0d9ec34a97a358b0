#pragma once
// A user expression in t, x, y, z (Dirichlet values, loads), evaluated with muParser.

#include <memory>
#include <string>

namespace grout {

class Expression {
 public:
  Expression();  ///< the constant 0
  /// Parse `text`; `where` (e.g. "input.yaml: grout/dirichlet/left_x/value") is quoted in
  /// errors. Throws InputError on a syntax error, an unknown variable, an assignment
  /// ("t=5") or a constant that is not finite ("0/0", "10/0", "sqrt(-1)").
  Expression(const std::string& text, const std::string& where);
  Expression(const Expression& other);
  Expression& operator=(const Expression& other);
  ~Expression();

  /// The value at (t, x, y, z). Throws InputError naming `where`, the text and the point
  /// when it is not finite (log(x) at x = 0, 1/t at t = 0, ...).
  double operator()(double t, double x, double y, double z) const;
  const std::string& text() const { return text_; }

 private:
  struct Impl;
  std::string text_;
  std::string where_;
  std::unique_ptr<Impl> impl_;
};

}  // namespace grout
