#pragma once
// A user expression in t, x, y, z (Dirichlet values, loads), evaluated with muParser.

#include <memory>
#include <string>

namespace grout {

class Expression {
 public:
  Expression();  ///< the constant 0
  /// Parse `text`; `where` (e.g. "input.yaml: grout/dirichlet/left_x/value") is quoted in
  /// errors. Throws InputError on a syntax error or an unknown variable.
  Expression(const std::string& text, const std::string& where);
  Expression(const Expression& other);
  Expression& operator=(const Expression& other);
  ~Expression();

  double operator()(double t, double x, double y, double z) const;
  const std::string& text() const { return text_; }

 private:
  struct Impl;
  std::string text_;
  std::string where_;
  std::unique_ptr<Impl> impl_;
};

}  // namespace grout
