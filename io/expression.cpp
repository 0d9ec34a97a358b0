#include "io/expression.hpp"

#include <muParser.h>

#include <cmath>
#include <sstream>

#include "io/errors.hpp"

namespace grout {

namespace {

std::string describe(double value) {
  return std::isnan(value) ? "not a number (NaN)" : value > 0 ? "+infinity" : "-infinity";
}

}  // namespace

/// The parser and the variables it is bound to. muParser stores the variables' addresses,
/// so an Impl is never moved or copied: a copy of an Expression parses the text again.
struct Expression::Impl {
  mutable double t = 0.0, x = 0.0, y = 0.0, z = 0.0;
  mu::Parser parser;

  Impl(const std::string& text, const std::string& where) {
    // muParser accepts assignments to its variables ("t=5"); a value is a formula only.
    for (std::size_t i = 0; i < text.size(); ++i) {
      if (text[i] != '=') continue;
      const char before = i > 0 ? text[i - 1] : ' ',
                 after = i + 1 < text.size() ? text[i + 1] : ' ';
      if (after == '=' || before == '=' || before == '<' || before == '>' || before == '!')
        continue;
      throw InputError(where + ": cannot parse expression '" + text +
                       "': assignment '=' at position " + std::to_string(i + 1) +
                       " (a value is a formula in t, x, y, z; compare with ==)");
    }
    try {
      parser.DefineVar("t", &t);
      parser.DefineVar("x", &x);
      parser.DefineVar("y", &y);
      parser.DefineVar("z", &z);
      parser.DefineConst("pi", M_PI);
      parser.DefineConst("_pi", M_PI);  // muParser's own is cut at 3.141592653589 under GCC
      parser.SetExpr(text);
      const double value = parser.Eval();  // muParser parses lazily: errors surface here
      if (parser.GetUsedVar().empty() && !std::isfinite(value)) {
        throw InputError(where + ": expression '" + text + "' is " + describe(value) +
                         " (a constant that is not a finite number)");
      }
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
  const double value = impl_->parser.Eval();
  if (!std::isfinite(value)) {
    std::ostringstream text;
    text << where_ << ": expression '" << text_ << "' is " << describe(value) << " at t = " << t
         << ", x = " << x << ", y = " << y << ", z = " << z;
    throw InputError(text.str());
  }
  return value;
}

}  // namespace grout
