#include "io/expression.hpp"

#include <muParser.h>

#include <cmath>

#include "io/errors.hpp"

namespace grout {

/// The parser and the variables it is bound to. muParser stores the variables' addresses,
/// so an Impl is never moved or copied: a copy of an Expression parses the text again.
struct Expression::Impl {
  mutable double t = 0.0, x = 0.0, y = 0.0, z = 0.0;
  mu::Parser parser;

  Impl(const std::string& text, const std::string& where) {
    try {
      parser.DefineVar("t", &t);
      parser.DefineVar("x", &x);
      parser.DefineVar("y", &y);
      parser.DefineVar("z", &z);
      parser.DefineConst("pi", M_PI);
      parser.DefineConst("_pi", M_PI);  // muParser's own is cut at 3.141592653589 under GCC
      parser.SetExpr(text);
      parser.Eval();  // muParser parses lazily: evaluate once so that errors surface here
    } catch (const mu::Parser::exception_type& e) {
      std::string message = where + ": cannot parse expression '" + text + "': " + e.GetMsg();
      if (e.GetCode() == mu::ecUNASSIGNABLE_TOKEN) {
        message += " (variables: t, x, y, z; constants: pi, _pi, _e)";
      }
      throw InputError(message);
    }
    if (parser.GetNumResults() != 1) {
      throw InputError(where + ": cannot parse expression '" + text +
                       "': expected one value, got " + std::to_string(parser.GetNumResults()) +
                       " separated by commas");
    }
  }
};

Expression::Expression() : text_("0") {}

Expression::Expression(const std::string& text, const std::string& where)
    : text_(text), where_(where), impl_(std::make_unique<Impl>(text, where)) {}

Expression::Expression(const Expression& other)
    : text_(other.text_),
      where_(other.where_),
      impl_(other.impl_ ? std::make_unique<Impl>(other.text_, other.where_) : nullptr) {}

Expression& Expression::operator=(const Expression& other) {
  if (this != &other) {
    impl_ = other.impl_ ? std::make_unique<Impl>(other.text_, other.where_) : nullptr;
    text_ = other.text_;
    where_ = other.where_;
  }
  return *this;
}

Expression::~Expression() = default;

double Expression::operator()(double t, double x, double y, double z) const {
  if (!impl_) return 0.0;  // the default expression "0"
  impl_->t = t;
  impl_->x = x;
  impl_->y = y;
  impl_->z = z;
  return impl_->parser.Eval();
}

}  // namespace grout
