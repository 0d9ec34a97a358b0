#include "io/input.hpp"

#include <Teuchos_YamlParameterListCoreHelpers.hpp>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <regex>
#include <sstream>

#include "io/errors.hpp"
#include "io/input_dynamics.hpp"
#include "io/input_schema.hpp"
#include "io/solver_settings.hpp"

namespace grout {

namespace {

using input_schema::Key;
using input_schema::Section;

/// `text` after its first `n` characters ("" when it is shorter).
std::string rest(const std::string& text, std::size_t n) {
  return n < text.size() ? text.substr(n) : std::string();
}

}  // namespace

/// Teuchos' parser messages carry its own source file, line and "Throw test" noise: keep
/// the position in the input and the sentence that says what is wrong.
std::string clean_yaml_message(const std::string& what, const std::string& path) {
  std::vector<std::string> lines;
  std::istringstream stream(what);
  for (std::string line; std::getline(stream, line);) lines.push_back(line);

  std::string position;
  std::smatch match;
  if (!lines.empty() &&
      std::regex_search(lines[0], match, std::regex("line (\\d+) column (\\d+)"))) {
    position = "line " + match[1].str() + ", column " + match[2].str() + ": ";
  }
  std::string detail;
  const auto append = [&](std::string text) {
    text = std::regex_replace(text, std::regex("^\\s+|\\s+$"), "");
    if (!text.empty()) detail += (detail.empty() ? "" : " ") + text;
  };
  const auto throw_test = std::find_if(lines.begin(), lines.end(), [](const std::string& l) {
    return l.rfind("Throw test that evaluated to true", 0) == 0;
  });
  if (throw_test != lines.end()) {
    for (auto it = throw_test + 1; it != lines.end(); ++it) append(*it);
  } else {
    for (std::size_t i = 0; i < lines.size(); ++i) {
      if (i == 1 && !position.empty()) continue;  // the offending line of the input
      const std::string& line = lines[i];
      if (line.rfind("Expected one of", 0) == 0) append("expected one of " + rest(line, 16));
      if (line.rfind("Got:", 0) == 0) append(", got" + rest(line, 4));
    }
  }
  if (detail.empty()) {  // a message in plain words after the position
    for (std::size_t i = 0; i < lines.size(); ++i) {
      std::string line = lines[i];
      if (line.rfind("error: ", 0) == 0) line = line.substr(7);
      const bool echo = i == 1 && !position.empty();  // the offending line of the input
      if (line.rfind("Parser failure", 0) == 0 || echo ||
          line.find_first_not_of(" ^") == std::string::npos || line.rfind("Lexer text", 0) == 0 ||
          line.rfind("Parser was in state", 0) == 0) {
        continue;
      }
      append(line);
    }
  }
  if (detail == "Error!") detail = "unsupported structure (expected 'grout:' and indented keys)";
  detail = std::regex_replace(detail, std::regex("Parameter \"(.*)\" already exists in list .*"),
                              "duplicate key '$1'");
  detail = std::regex_replace(detail, std::regex(" It is strongly recommended not to mix.*"),
                              " (tabs and spaces mixed?)");
  detail = std::regex_replace(detail, std::regex(" , got"), ", got");
  const std::string of_file = " of " + path;
  for (auto at = detail.find(of_file); at != std::string::npos; at = detail.find(of_file)) {
    detail.erase(at, of_file.size());
  }
  return path + ": YAML error: " + position + detail;
}

namespace {

/// The keys at the start of a line, unindented: Teuchos silently drops some of these, so
/// the single top-level key `grout:` is checked on the text itself.
std::vector<std::string> top_level_keys(const std::string& text) {
  std::vector<std::string> keys;
  std::istringstream stream(text);
  const std::regex key("^([^\\s#%{\\-.][^:]*):(\\s|$)");
  std::smatch match;
  for (std::string line; std::getline(stream, line);) {
    if (std::regex_search(line, match, key)) keys.push_back(match[1].str());
  }
  return keys;
}

/// Teuchos' YAML reader treats every `#` as the start of a comment and rejects any non-ASCII
/// byte, even inside a comment. Drop the comments ourselves (same rule), so that comments
/// may say "Lamé" or "§", and name the line of any non-ASCII character left.
std::string strip_comments(const std::string& text, const std::string& path) {
  std::istringstream stream(text);
  std::string line, out;
  for (int number = 1; std::getline(stream, line); ++number) {
    line = line.substr(0, line.find('#'));
    for (unsigned char c : line) {
      if (c >= 0x80) {
        throw InputError(path + ": line " + std::to_string(number) +
                         ": non-ASCII character outside a comment (the YAML reader accepts "
                         "ASCII only): " +
                         line);
      }
    }
    out += line + "\n";
  }
  return out;
}

[[noreturn]] void file_too_large(const std::string& path) {
  throw InputError(path + ": the input file has more than " + std::to_string(max_input_bytes) +
                   " bytes (the limit of its size)");
}

/// Refuse a file or a line longer than the limits of input.hpp, naming the limit.
void check_size(const std::string& raw, const std::string& path) {
  if (raw.size() > max_input_bytes) file_too_large(path);
  std::size_t number = 1, start = 0;
  for (std::size_t end = raw.find('\n'); start <= raw.size(); end = raw.find('\n', start)) {
    if (end == std::string::npos) end = raw.size();
    if (end - start > max_input_line_length) {
      throw InputError(path + ": line " + std::to_string(number) + " has " +
                       std::to_string(end - start) + " characters, more than the limit of " +
                       std::to_string(max_input_line_length));
    }
    start = end + 1;
    ++number;
  }
}

/// The bytes of the input file, at most max_input_bytes of them.
std::string read_text(const std::string& path) {
  std::error_code error;
  std::ifstream file(path, std::ios::binary);
  if (!std::filesystem::is_regular_file(path, error) || !file) {
    throw InputError(path + ": cannot read input file");
  }
  const std::uintmax_t size = std::filesystem::file_size(path, error);
  if (!error && size > max_input_bytes) file_too_large(path);
  std::string raw(max_input_bytes + 1, '\0');  // one more, to see that the limit is exceeded
  file.read(raw.data(), std::streamsize(raw.size()));
  if (file.bad()) throw InputError(path + ": cannot read input file");
  raw.resize(std::size_t(file.gcount()));
  return raw;
}

Teuchos::RCP<Teuchos::ParameterList> parse_yaml(const std::string& raw, const std::string& path) {
  check_size(raw, path);
  const std::string text = strip_comments(raw, path);
  const std::vector<std::string> keys = top_level_keys(text);
  const bool flow_style = std::regex_search(text, std::regex("(^|\n)\\{"));  // {grout: ...}
  if (keys.size() > 1 || (keys.size() == 1 && keys[0] != "grout") ||
      (keys.empty() && !flow_style)) {
    std::string found = keys.empty() ? "none" : "";
    for (const std::string& k : keys) found += (found.empty() ? "'" : ", '") + k + "'";
    throw InputError(path + ": the top level must be the single key 'grout:' (found: " + found +
                     ")");
  }
  Teuchos::RCP<Teuchos::ParameterList> root;
  try {
    root = Teuchos::getParametersFromYamlString(text);
  } catch (const std::exception& e) {
    throw InputError(clean_yaml_message(e.what(), path));
  }
  if (root->name() != "grout") {
    throw InputError(path + ": the top level must be the single key 'grout:'");
  }
  return root;
}

std::string resolve(const std::string& directory, const std::string& file) {
  const std::filesystem::path p(file);
  if (p.is_absolute() || directory.empty()) return p.lexically_normal().string();
  return (std::filesystem::path(directory) / p).lexically_normal().string();
}

ModelInput read_model(const Section& grout) {
  const Section model = grout.section(
      "model",
      {Key::integer("dimension").one_of({"2", "3"}).required(),
       Key::choice("plane", {"strain", "stress", "axisymmetric"}, "plane kind").defaults("strain"),
       Key::choice("strain", {"small", "finite"}, "strain measure").defaults("small")});
  ModelInput m;
  m.dimension = model.integer("dimension");
  const std::string plane = model.string("plane");
  m.plane = plane == "stress"         ? PlaneKind::stress
            : plane == "axisymmetric" ? PlaneKind::axisymmetric
                                      : PlaneKind::strain;
  if (m.plane == PlaneKind::axisymmetric && m.dimension != 2)
    model.fail("plane", "axisymmetric needs dimension: 2 (x = r, y = the axis)");
  m.strain = model.string("strain") == "finite" ? StrainKind::finite : StrainKind::small;
  return m;
}

std::vector<MaterialInput> read_materials(const Section& grout, StrainKind strain) {
  const std::vector<Key> keys = {
      Key::string("block").required(),
      Key::choice("law", {"linear_elastic", "neo_hookean"}, "material law").required(),
      Key::number("youngs_modulus").above(0).required(),
      Key::number("poissons_ratio").above(-1).below(0.5).required(),
      Key::number("density").at_least(0).defaults("0")};
  std::vector<MaterialInput> materials;
  for (const Section& s : grout.named_sections("materials", keys)) {
    MaterialInput m;
    m.name = s.name();
    m.block = s.string("block");
    m.law =
        s.string("law") == "neo_hookean" ? MaterialLaw::neo_hookean : MaterialLaw::linear_elastic;
    if (m.law == MaterialLaw::neo_hookean && strain != StrainKind::finite)
      s.fail("law", "neo_hookean needs grout/model/strain: finite");
    m.youngs_modulus = s.number("youngs_modulus");
    m.poissons_ratio = s.number("poissons_ratio");
    m.density = s.number("density");
    materials.push_back(std::move(m));
  }
  if (materials.empty()) grout.fail("materials", "expected at least one material");
  return materials;
}

/// "x" -> 0, "y" -> 1, "z" -> 2; z only in a 3D model.
int read_component(const Section& s, const std::string& key, int dimension) {
  const std::string c = s.string(key);
  if (c == "z" && dimension < 3) s.fail(key, "component z is not allowed in a 2D model");
  return c == "x" ? 0 : c == "y" ? 1 : 2;
}

std::vector<DirichletInput> read_dirichlet(const Section& grout, int dimension) {
  const std::vector<Key> keys = {Key::string("node_set").required(),
                                 Key::choice("component", {"x", "y", "z"}, "component").required(),
                                 Key::expression("value").required()};
  std::vector<DirichletInput> conditions;
  for (const Section& s : grout.named_sections("dirichlet", keys)) {
    DirichletInput d;
    d.name = s.name();
    d.node_set = s.string("node_set");
    d.component = read_component(s, "component", dimension);
    d.value = s.expression("value");
    conditions.push_back(std::move(d));
  }
  return conditions;
}

std::vector<LoadInput> read_loads(const Section& grout, int dimension) {
  const std::vector<Key> keys = {
      Key::string("side_set").required(),
      Key::choice("type", {"pressure", "traction"}, "load type").required(),
      Key::expression("value"), Key::section("components")};
  std::vector<LoadInput> loads;
  for (const Section& s : grout.named_sections("loads", keys)) {
    LoadInput l;
    l.name = s.name();
    l.side_set = s.string("side_set");
    l.type = s.string("type") == "traction" ? LoadKind::traction : LoadKind::pressure;
    if (l.type == LoadKind::pressure) {
      if (!s.has("value")) s.fail("value", "missing required key (for type pressure)");
      if (s.has("components")) s.fail("components", "only for type traction (use value)");
      l.value = s.expression("value");
    } else {
      if (!s.has("components")) s.fail("components", "missing required key (for type traction)");
      if (s.has("value")) s.fail("value", "only for type pressure (use components)");
      std::vector<Key> component_keys = {Key::expression("x").required(),
                                         Key::expression("y").required()};
      if (dimension == 3) component_keys.push_back(Key::expression("z").required());
      const Section c = s.section("components", component_keys);
      for (int i = 0; i < dimension; ++i)
        l.components.push_back(c.expression(std::string(1, "xyz"[i])));
    }
    loads.push_back(std::move(l));
  }
  return loads;
}

/// `self: a` or `self: [a, b, ...]`: the side sets whose union is the self-contact surface
/// (each a non-empty name, none twice).
std::vector<std::string> self_contact_sets(const Section& s) {
  const Teuchos::ParameterEntry& entry = s.list().getEntry("self");
  const auto wrong = [&] {
    s.fail("self", "expected a side set name or a list [a, b, ...] of side set names");
  };
  std::vector<std::string> sets;
  if (entry.isType<std::string>()) {
    sets.push_back(Teuchos::getValue<std::string>(entry));
  } else if (entry.isType<Teuchos::Array<std::string>>()) {
    const auto& list = Teuchos::getValue<Teuchos::Array<std::string>>(entry);
    sets.assign(list.begin(), list.end());
    if (sets.empty()) wrong();
  } else {
    wrong();
  }
  for (std::size_t i = 0; i < sets.size(); ++i) {
    if (sets[i].empty()) wrong();
    for (std::size_t j = 0; j < i; ++j)
      if (sets[j] == sets[i]) s.fail("self", "side set '" + sets[i] + "' is listed twice");
  }
  return sets;
}

std::vector<ContactInput> read_contact(const Section& grout) {
  const std::vector<Key> keys = {
      Key::string("slave"),
      Key::string("master"),
      Key::any("self"),  // a side set or a list of side sets (self_contact_sets)
      Key::choice("type", {"frictionless", "frictional", "tied"}, "contact type").required(),
      Key::number("friction_coefficient").at_least(0),
      Key::number("c_n").above(0),
      Key::number("c_t").above(0),
      Key::choice("integration", {"exact", "collocation"}, "integration").defaults("exact"),
      Key::integer("collocation_points").at_least(1).at_most(max_collocation_points),
      Key::choice("geometry", {"reference", "current"}, "contact geometry"),
      Key::number("start_gap").at_least(0).below(1),
      Key::number("start_closure").above(0).at_most(1)};
  std::vector<ContactInput> pairs;
  for (const Section& s : grout.named_sections("contact", keys)) {
    ContactInput c;
    c.name = s.name();
    // Self-contact: one side set is both surfaces; the slave and master faces are chosen
    // per contacting region at each step (ContactInterface, docs/input.md).
    if (s.has("self")) {
      for (const char* other : {"slave", "master"})
        if (s.has(other)) s.fail(other, "not with 'self' (a self-contact pair names one side set)");
      c.self = true;
      c.self_sets = self_contact_sets(s);
      c.slave = c.master = c.self_sets.front();
    } else {
      for (const char* side : {"slave", "master"})
        if (!s.has(side)) s.fail(side, "missing required key (or 'self' for self-contact)");
      c.slave = s.string("slave");
      c.master = s.string("master");
    }
    const std::string type = s.string("type");
    c.type = type == "frictional" ? ContactKind::frictional
             : type == "tied"     ? ContactKind::tied
                                  : ContactKind::frictionless;
    if (c.type == ContactKind::frictional && !s.has("friction_coefficient")) {
      s.fail("friction_coefficient", "missing required key (for type frictional)");
    }
    if (c.type != ContactKind::frictional && s.has("friction_coefficient")) {
      s.fail("friction_coefficient", "only for type frictional (this pair is " + type + ")");
    }
    c.friction_coefficient = s.number("friction_coefficient");
    c.c_n = s.number("c_n");
    c.c_t = s.number("c_t");
    c.integration = s.string("integration") == "collocation" ? ContactIntegration::collocation
                                                             : ContactIntegration::exact;
    if (c.integration != ContactIntegration::collocation && s.has("collocation_points")) {
      s.fail("collocation_points", "only for integration: collocation");
    }
    c.collocation_points = s.integer("collocation_points");
    // Dynamics: the mass keeps a body held only by contact from being singular, so the
    // proximity start is off unless asked for (it would only add Newton iterations).
    if (s.has("start_gap"))
      c.start_gap = s.number("start_gap");
    else if (grout.has("dynamics"))
      c.start_gap = 0.0;
    if (s.has("start_closure")) c.start_closure = s.number("start_closure");
    if (s.has("geometry")) {
      c.geometry =
          s.string("geometry") == "current" ? ContactGeometry::current : ContactGeometry::reference;
    }
    if (c.self && c.type == ContactKind::tied) s.fail("type", "self-contact cannot be tied");
    pairs.push_back(std::move(c));
  }
  return pairs;
}

/// `time/min_step_size` (default min_step_fraction · end): a cut-back below it ends the run
/// (exit 3), and the first step end/steps may not be smaller, which bounds `steps`.
void read_min_step_size(const Section& time, TimeInput& t) {
  std::ostringstream text;
  t.min_step_size = time.has("min_step_size") ? time.number("min_step_size")
                                              : TimeInput::min_step_fraction * t.end;
  if (t.min_step_size < TimeInput::min_step_floor * t.end) {
    text << "expected at least " << TimeInput::min_step_floor
         << " · end = " << TimeInput::min_step_floor * t.end << ", got " << t.min_step_size;
    time.fail("min_step_size", text.str());
  }
  if (t.end / t.steps < t.min_step_size) {
    text << t.steps << " steps of " << t.end / t.steps << " each, below the minimum step size "
         << t.min_step_size << " (time/min_step_size"
         << (time.has("min_step_size") ? "" : ", by default 1e-6 · end")
         << "): at most end / min_step_size = " << static_cast<long long>(t.end / t.min_step_size)
         << " steps";
    time.fail("steps", text.str());
  }
}

}  // namespace

Input read_input(const std::string& path) {
  return read_input_text(read_text(path), path);
}

Input read_input_text(const std::string& raw, const std::string& path) {
  const Teuchos::RCP<Teuchos::ParameterList> root = parse_yaml(raw, path);
  const Section grout(*root, "grout", path,
                      {Key::section("mesh").required(), Key::section("model").required(),
                       Key::section("materials").required(), Key::section("dirichlet"),
                       Key::section("loads"), Key::section("contact"), Key::section("time"),
                       Key::section("solver"), Key::section("output"), Key::section("dynamics"),
                       Key::section("gravity"), Key::section("initial_velocity")});
  Input input;
  input.file = path;
  input.directory = std::filesystem::path(path).parent_path().string();
  const std::string stem = std::filesystem::path(path).stem().string();

  const Section mesh = grout.section("mesh", {Key::string("file").required()});
  input.mesh_file = resolve(input.directory, mesh.string("file"));
  input.model = read_model(grout);
  input.materials = read_materials(grout, input.model.strain);
  input.dirichlet = read_dirichlet(grout, input.model.dimension);
  input.loads = read_loads(grout, input.model.dimension);
  input.contact = read_contact(grout);

  const Section time = grout.section(
      "time",
      {Key::number("end").above(0).defaults("1"), Key::integer("steps").at_least(1).defaults("1"),
       Key::choice("stepping", {"fixed", "adaptive"}, "stepping").defaults("fixed"),
       Key::number("max_step_size").above(0), Key::number("min_step_size").above(0),
       Key::choice("predictor", {"last", "extrapolated"}, "predictor").defaults("last")});
  input.time.end = time.number("end");
  input.time.steps = time.integer("steps");
  input.time.adaptive = time.string("stepping") == "adaptive";
  input.time.extrapolate = time.string("predictor") == "extrapolated";
  if (time.has("max_step_size")) {
    if (!input.time.adaptive) time.fail("max_step_size", "only with stepping: adaptive");
    input.time.max_step_size = time.number("max_step_size");
  }
  read_min_step_size(time, input.time);
  read_dynamics(grout, input);
  if (input.time.extrapolate && grout.has("dynamics"))  // the time integrator predicts there
    time.fail("predictor", "extrapolated is for quasi-static analyses (not with grout/dynamics)");
  if (input.model.plane == PlaneKind::axisymmetric) {
    // The mass matrix and the dynamics' rigid-body velocity updates are not weighted by 2 pi r.
    if (grout.has("dynamics"))
      grout.fail("dynamics", "not available with model/plane: axisymmetric (quasi-static only)");
    for (const ContactInput& c : input.contact)
      if (c.integration == ContactIntegration::collocation)
        grout.fail("contact/" + c.name + "/integration",
                   "collocation is not available with model/plane: axisymmetric (use exact)");
  }

  input.solver = solver_settings_from(grout.raw_section("solver"), path);

  const Section output =
      grout.section("output", {Key::string("file").defaults(stem + ".e"),
                               Key::string("summary").may_be_empty().defaults(stem + ".csv"),
                               Key::choice("parallel", {"single", "per_rank"}, "output layout")
                                   .defaults("single")
                                   .suggest_near_miss()});
  input.output.file = resolve(input.directory, output.string("file"));
  const std::string summary = output.string("summary");
  input.output.summary = summary.empty() ? "" : resolve(input.directory, summary);
  if (output.string("parallel") == "per_rank") input.output.parallel = OutputParallel::per_rank;
  return input;
}

}  // namespace grout
