#pragma once
// A small table-driven schema for the YAML input (after deal.II's declare_entry): each key of
// a section is declared once with its type, whether it is required, its default and the
// values it admits; a Section validates a Teuchos::ParameterList against such a table and
// then hands out typed values. Private to io/ (read_input is the public entry point).

#include <Teuchos_ParameterList.hpp>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "io/expression.hpp"

namespace grout::input_schema {

enum class ValueType {
  string,      ///< a YAML string
  integer,     ///< a YAML integer
  number,      ///< a YAML integer or floating-point number
  expression,  ///< a YAML string or number, parsed by muParser
  section,     ///< a map of keys (a Teuchos sublist)
  boolean,     ///< true or false
  array,       ///< a YAML sequence [a, b, ...] (passed through to a solver package)
  any          ///< any value or section (passed through to a solver package, which checks it)
};

/// One key of a section. Built fluently: Key::number("youngs_modulus").above(0).required().
struct Key {
  std::string name;
  ValueType type = ValueType::string;
  bool is_required = false;
  std::string default_value;         ///< text form; used when the key is absent
  std::vector<std::string> choices;  ///< admitted values of a string or integer (empty: any)
  std::string choice_noun;           ///< "material law" in "unknown material law 'x'"
  bool empty_allowed = false;        ///< a string may be ""
  bool suggests = false;             ///< an unknown choice names a near miss (did you mean)
  double lower = -std::numeric_limits<double>::infinity();
  double upper = std::numeric_limits<double>::infinity();
  bool lower_open = false, upper_open = false;

  static Key string(std::string name) { return make(std::move(name), ValueType::string); }
  static Key integer(std::string name) { return make(std::move(name), ValueType::integer); }
  static Key number(std::string name) { return make(std::move(name), ValueType::number); }
  static Key expression(std::string name) { return make(std::move(name), ValueType::expression); }
  static Key section(std::string name) { return make(std::move(name), ValueType::section); }
  static Key boolean(std::string name) { return make(std::move(name), ValueType::boolean); }
  static Key array(std::string name) { return make(std::move(name), ValueType::array); }
  static Key any(std::string name) { return make(std::move(name), ValueType::any); }
  /// A string that must be one of `values`; `noun` names it in errors.
  static Key choice(std::string name, std::vector<std::string> values, std::string noun) {
    Key k = make(std::move(name), ValueType::string);
    k.choices = std::move(values);
    k.choice_noun = std::move(noun);
    return k;
  }

  Key required() && { return is_required = true, std::move(*this); }
  Key defaults(std::string value) && { return default_value = std::move(value), std::move(*this); }
  Key one_of(std::vector<std::string> values) && {
    return choices = std::move(values), std::move(*this);
  }
  Key may_be_empty() && { return empty_allowed = true, std::move(*this); }
  Key suggest_near_miss() && { return suggests = true, std::move(*this); }
  Key above(double v) && { return lower = v, lower_open = true, std::move(*this); }
  Key at_least(double v) && { return lower = v, lower_open = false, std::move(*this); }
  Key below(double v) && { return upper = v, upper_open = true, std::move(*this); }
  Key at_most(double v) && { return upper = v, upper_open = false, std::move(*this); }

 private:
  static Key make(std::string name, ValueType type) {
    Key k;
    k.name = std::move(name);
    k.type = type;
    return k;
  }
};

/// A validated section of the input. The constructor checks every key against the table
/// (unknown keys, with a "did you mean" for a near miss; missing required keys, types, bounds,
/// admitted values) and throws an InputError "<file>: <path>/<key>: <what is wrong>" (without
/// "<file>: " when `file` is empty); the getters then cannot fail.
class Section {
 public:
  Section(const Teuchos::ParameterList& list, std::string path, std::string file,
          std::vector<Key> keys);

  const std::string& path() const { return path_; }
  const std::string& file() const { return file_; }
  const std::vector<Key>& keys() const { return keys_; }
  const Teuchos::ParameterList& list() const { return list_; }
  /// The last component of the path: the user's name of a material, condition, pair, ...
  std::string name() const;
  /// "<file>: <path>/<key>" ("<path>/<key>" without a file), the prefix of an error about `key`.
  std::string where(const std::string& key) const;
  [[noreturn]] void fail(const std::string& key, const std::string& message) const;

  bool has(const std::string& key) const { return list_.isParameter(key); }
  std::string string(const std::string& key) const;
  int integer(const std::string& key) const;
  double number(const std::string& key) const;
  Expression expression(const std::string& key) const;
  bool boolean(const std::string& key) const;
  /// The sublist `key` (an empty list when absent) validated against `keys`.
  Section section(const std::string& key, std::vector<Key> keys) const;
  /// The sublist `key` itself, unvalidated (an empty list when absent).
  const Teuchos::ParameterList& raw_section(const std::string& key) const;
  /// Every entry of the sublist `key`, each a section named by the user and validated
  /// against `keys` (materials/<name>, dirichlet/<name>, ...). Empty when `key` is absent.
  std::vector<Section> named_sections(const std::string& key, const std::vector<Key>& keys) const;

 private:
  const Key& key(const std::string& name) const;
  void check(const Key& key, const Teuchos::ParameterEntry& entry) const;

  const Teuchos::ParameterList& list_;
  std::string path_;
  std::string file_;
  std::vector<Key> keys_;
};

/// "a", "a or b", "a, b or c".
std::string join_or(const std::vector<std::string>& words);
/// A double as the shortest text that reads back to the same value ("0.4", "1000", "1e-06").
std::string format_number(double value);

}  // namespace grout::input_schema
