#include "io/input_schema.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <sstream>

#include "io/errors.hpp"

namespace grout::input_schema {

namespace {

const Teuchos::ParameterList& empty_list() {
  static const Teuchos::ParameterList empty;
  return empty;
}

template <class T>
bool holds(const Teuchos::ParameterEntry& entry) {
  return !entry.isList() && entry.getAny(false).type() == typeid(T);
}
template <class T>
const T& value_of(const Teuchos::ParameterEntry& entry) {
  return Teuchos::any_cast<T>(entry.getAny(false));
}

/// What the user gave, for "got a string 'two'".
std::string describe(const Teuchos::ParameterEntry& entry) {
  if (entry.isList()) return "a section";
  if (holds<std::string>(entry)) return "a string '" + value_of<std::string>(entry) + "'";
  if (holds<int>(entry)) return "an integer '" + std::to_string(value_of<int>(entry)) + "'";
  if (holds<long long>(entry)) {
    return "an integer '" + std::to_string(value_of<long long>(entry)) +
           "' (out of range: at most 2147483647 in magnitude)";
  }
  if (holds<double>(entry)) return "a number '" + format_number(value_of<double>(entry)) + "'";
  if (holds<bool>(entry))
    return std::string("a boolean '") + (value_of<bool>(entry) ? "true" : "false") + "'";
  std::ostringstream text;
  text << entry.getAny(false);
  return "a list '" + text.str() + "'";
}

/// The value alone, for "got '-5'".
std::string value_text(const Teuchos::ParameterEntry& entry) {
  if (holds<int>(entry)) return std::to_string(value_of<int>(entry));
  if (holds<double>(entry)) return format_number(value_of<double>(entry));
  if (holds<std::string>(entry)) return value_of<std::string>(entry);
  return describe(entry);
}

std::string bounds_text(const Key& key) {
  const bool has_lower = key.lower > -std::numeric_limits<double>::infinity();
  const bool has_upper = key.upper < std::numeric_limits<double>::infinity();
  if (has_lower && has_upper) {
    return " in " + std::string(key.lower_open ? "(" : "[") + format_number(key.lower) + ", " +
           format_number(key.upper) + (key.upper_open ? ")" : "]");
  }
  if (has_lower) return std::string(key.lower_open ? " > " : " >= ") + format_number(key.lower);
  if (has_upper) return std::string(key.upper_open ? " < " : " <= ") + format_number(key.upper);
  return "";
}

bool in_bounds(const Key& key, double v) {
  const bool above = key.lower_open ? v > key.lower : v >= key.lower;
  const bool below = key.upper_open ? v < key.upper : v <= key.upper;
  return above && below;
}

std::string expected_type(const Key& key) {
  switch (key.type) {
    case ValueType::string:
      return key.empty_allowed ? "a string" : "a non-empty string";
    case ValueType::integer:
      return "an integer" + bounds_text(key);
    case ValueType::number:
      return "a number" + bounds_text(key);
    case ValueType::expression:
      return "an expression (a string or a number)";
    case ValueType::section:
      return "a section of keys";
    case ValueType::boolean:
      return "true or false";
    case ValueType::array:
      return "a list [a, b, ...]";
    case ValueType::any:
      return "a value";
  }
  return "";
}

std::string expected_list(const std::vector<std::string>& words) {
  if (words.size() == 1) return "expected: " + words.front();
  std::string text = "expected one of: ";
  for (std::size_t i = 0; i < words.size(); ++i) text += (i ? ", " : "") + words[i];
  return text;
}

std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] != b[j - 1])});
      diagonal = up;
    }
  }
  return row[b.size()];
}

}  // namespace

std::string join_or(const std::vector<std::string>& words) {
  std::string text;
  for (std::size_t i = 0; i < words.size(); ++i) {
    if (i > 0) text += (i + 1 == words.size()) ? " or " : ", ";
    text += words[i];
  }
  return text;
}

std::string format_number(double value) {
  char text[32];
  for (int precision = 6; precision <= 17; ++precision) {
    std::snprintf(text, sizeof text, "%.*g", precision, value);
    if (std::strtod(text, nullptr) == value) break;
  }
  return text;
}

Section::Section(const Teuchos::ParameterList& list, std::string path, std::string file,
                 std::vector<Key> keys)
    : list_(list), path_(std::move(path)), file_(std::move(file)), keys_(std::move(keys)) {
  for (auto it = list_.begin(); it != list_.end(); ++it) {
    const std::string& name = list_.name(it);
    const auto known =
        std::find_if(keys_.begin(), keys_.end(), [&](const Key& k) { return k.name == name; });
    if (known == keys_.end()) {
      std::vector<std::string> names;
      std::string closest;
      for (const Key& k : keys_) {
        names.push_back(k.name);
        const std::size_t distance = edit_distance(name, k.name);
        const bool near = distance <= 2 && 2 * distance < name.size();
        const bool cut_short = name.size() >= 4 && k.name.rfind(name, 0) == 0;  // "max_iter"
        if (closest.empty() && (near || cut_short)) closest = k.name;
      }
      std::string message = path_ + ": unknown key '" + name + "'";
      // A pass-through section of a solver package accepts hundreds of names: those are
      // listed in docs/input.md, not in the message.
      constexpr std::size_t max_listed = 16;
      message += names.empty()                ? " (this section has no keys)"
                 : names.size() <= max_listed ? " (" + expected_list(names) + ")"
                                              : " (not one of the " + std::to_string(names.size()) +
                                                    " names it accepts: docs/input.md)";
      if (!closest.empty()) message += "; did you mean '" + closest + "'?";
      throw InputError(file_.empty() ? message : file_ + ": " + message);
    }
    check(*known, list_.entry(it));
  }
  for (const Key& k : keys_) {
    if (k.is_required && !list_.isParameter(k.name)) fail(k.name, "missing required key");
  }
}

void Section::check(const Key& key, const Teuchos::ParameterEntry& entry) const {
  const auto wrong_type = [&] {
    fail(key.name, "expected " + expected_type(key) + ", got " + describe(entry));
  };
  switch (key.type) {
    case ValueType::section:
      if (!entry.isList()) wrong_type();
      return;
    case ValueType::boolean:
      if (!holds<bool>(entry)) wrong_type();
      return;
    case ValueType::any:
      return;
    case ValueType::array:  // a YAML sequence: a Teuchos::Array of some scalar type
      if (entry.isList() || holds<std::string>(entry) || holds<int>(entry) ||
          holds<long long>(entry) || holds<double>(entry) || holds<bool>(entry))
        wrong_type();
      return;
    case ValueType::expression:
      if (!holds<std::string>(entry) && !holds<int>(entry) && !holds<double>(entry)) wrong_type();
      return;
    case ValueType::string: {
      if (!holds<std::string>(entry)) wrong_type();
      const std::string& v = value_of<std::string>(entry);
      if (v.empty() && !key.empty_allowed) wrong_type();
      if (!key.choices.empty() &&
          std::find(key.choices.begin(), key.choices.end(), v) == key.choices.end()) {
        const std::string noun = key.choice_noun.empty() ? "value" : key.choice_noun;
        std::string message =
            "unknown " + noun + " '" + v + "' (" + expected_list(key.choices) + ")";
        for (const std::string& choice : key.suggests ? key.choices : std::vector<std::string>{}) {
          const std::size_t distance = edit_distance(v, choice);
          if (distance <= 2 && 2 * distance < v.size()) {
            message += "; did you mean '" + choice + "'?";
            break;
          }
        }
        fail(key.name, message);
      }
      return;
    }
    case ValueType::integer: {
      if (!holds<int>(entry)) wrong_type();
      const int v = value_of<int>(entry);
      const std::string text = std::to_string(v);
      if (!key.choices.empty() &&
          std::find(key.choices.begin(), key.choices.end(), text) == key.choices.end()) {
        fail(key.name, "expected " + join_or(key.choices) + ", got '" + text + "'");
      }
      if (!in_bounds(key, v)) wrong_type();
      return;
    }
    case ValueType::number: {
      if (!holds<int>(entry) && !holds<double>(entry)) wrong_type();
      const double v = holds<int>(entry) ? value_of<int>(entry) : value_of<double>(entry);
      if (!std::isfinite(v) || !in_bounds(key, v)) {
        fail(key.name, "expected " + expected_type(key) + ", got '" + value_text(entry) + "'");
      }
      return;
    }
  }
}

std::string Section::name() const {
  return path_.substr(path_.find_last_of('/') + 1);
}

std::string Section::where(const std::string& key) const {
  return (file_.empty() ? "" : file_ + ": ") + path_ + "/" + key;
}

void Section::fail(const std::string& key, const std::string& message) const {
  throw InputError(where(key) + ": " + message);
}

const Key& Section::key(const std::string& name) const {
  for (const Key& k : keys_) {
    if (k.name == name) return k;
  }
  throw std::logic_error("grout: input schema of '" + path_ + "' has no key '" + name + "'");
}

std::string Section::string(const std::string& name) const {
  const Key& k = key(name);
  if (!has(name)) return k.default_value;
  return value_of<std::string>(list_.getEntry(name));
}

int Section::integer(const std::string& name) const {
  const Key& k = key(name);
  if (!has(name)) return k.default_value.empty() ? 0 : std::stoi(k.default_value);
  return value_of<int>(list_.getEntry(name));
}

double Section::number(const std::string& name) const {
  const Key& k = key(name);
  if (!has(name)) return k.default_value.empty() ? 0.0 : std::stod(k.default_value);
  const Teuchos::ParameterEntry& entry = list_.getEntry(name);
  return holds<int>(entry) ? value_of<int>(entry) : value_of<double>(entry);
}

bool Section::boolean(const std::string& name) const {
  const Key& k = key(name);
  if (!has(name)) return k.default_value == "true";
  return value_of<bool>(list_.getEntry(name));
}

Expression Section::expression(const std::string& name) const {
  const Key& k = key(name);
  if (!has(name)) return Expression(k.default_value.empty() ? "0" : k.default_value, where(name));
  const Teuchos::ParameterEntry& entry = list_.getEntry(name);
  return Expression(value_text(entry), where(name));
}

const Teuchos::ParameterList& Section::raw_section(const std::string& name) const {
  key(name);
  return has(name) ? list_.sublist(name) : empty_list();
}

Section Section::section(const std::string& name, std::vector<Key> keys) const {
  return Section(raw_section(name), path_ + "/" + name, file_, std::move(keys));
}

std::vector<Section> Section::named_sections(const std::string& name,
                                             const std::vector<Key>& keys) const {
  const Teuchos::ParameterList& list = raw_section(name);
  const std::string path = path_ + "/" + name;
  std::vector<Section> sections;
  for (auto it = list.begin(); it != list.end(); ++it) {
    const Teuchos::ParameterEntry& entry = list.entry(it);
    if (!entry.isList()) {
      throw InputError((file_.empty() ? "" : file_ + ": ") + path + "/" + list.name(it) +
                       ": expected a section of keys, got " + describe(entry));
    }
    sections.emplace_back(Teuchos::getValue<Teuchos::ParameterList>(entry),
                          path + "/" + list.name(it), file_, keys);
  }
  return sections;
}

}  // namespace grout::input_schema
