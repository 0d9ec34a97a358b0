#include "drivers/mesh_choice.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>

#include "io/errors.hpp"
#include "nonlinear/linear_solver.hpp"

namespace grout {

bool iterative_solver_chosen(const Input& input, long long num_nodes, long long slave_nodes) {
  return input.solver.linear.type == LinearSolverType::belos ||
         iterative_for_unknowns(input, (num_nodes + slave_nodes) * input.model.dimension);
}

bool iterative_for_unknowns(const Input& input, long long unknowns) {
  return input.solver.linear.type == LinearSolverType::automatic &&
         auto_linear_solver_type(unknowns, input.model.dimension) == "belos";
}

DistributionOptions distribution_options(const Input& input) {
  DistributionOptions options;
  options.skip_missing_sets = true;  // check_input_against_mesh names them with their key
  // A self-contact surface is partitioned with the rest of its body: it is much of the body
  // (the S profile's folds: half its elements), and cut apart from the other elements it left
  // each of 2 ranks ghosting the whole mesh, against 53.5 % with the plain cut, for the same
  // slave faces evaluated per rank.
  for (const ContactInput& c : input.contact) {
    if (c.self) continue;
    const auto add = [](std::vector<std::string>& sets, const std::string& set) {
      if (std::find(sets.begin(), sets.end(), set) == sets.end()) sets.push_back(set);
    };
    for (const std::string& set : contact_side_sets(c, false)) add(options.contact_side_sets, set);
    for (const std::string& set : contact_side_sets(c, true)) add(options.master_side_sets, set);
  }
  const char* env = std::getenv("GROUT_PARTITION");
  const std::string value = env ? env : "";
  const auto bad = [&] {
    return InputError(
        "GROUT_PARTITION=" + value +
        ": expected separate (the default), separate:positions, plain, criteria or weight:W "
        "(W >= 0)");
  };
  if (value.empty() || value == "separate") {
    options.separate_contact = true;
  } else if (value == "separate:positions") {  // without the gap bands
    options.separate_contact = true;
    options.master_side_sets.clear();
  } else if (value == "criteria") {
    options.balance_contact = true;
  } else if (value.rfind("weight:", 0) == 0) {
    const std::string w = value.substr(7);
    char* end = nullptr;
    options.contact_weight = std::strtod(w.c_str(), &end);
    if (w.empty() || *end != '\0' || !(options.contact_weight >= 0.0)) throw bad();
  } else if (value != "plain") {
    throw bad();
  }
  if (options.contact_side_sets.empty()) return DistributionOptions{};  // weights 1
  return options;
}

std::string describe_partition(const DistributionOptions& options) {
  if (options.contact_side_sets.empty()) return "RCB, weights 1";
  std::string sets;
  for (const std::string& set : options.contact_side_sets) sets += (sets.empty() ? "" : ", ") + set;
  std::string masters;
  for (const std::string& set : options.master_side_sets)
    masters += (masters.empty() ? "" : ", ") + set;
  if (options.separate_contact)
    return "RCB, the elements on " + sets + " apart from the others" +
           (masters.empty() ? "" : ", in bands of their distance to " + masters);
  if (options.balance_contact) return "two-criteria RCB: elements and elements on " + sets;
  if (options.contact_weight > 0.0) {
    char weight[32];
    std::snprintf(weight, sizeof weight, "%g", 1.0 + options.contact_weight);
    return "RCB, elements on " + sets + " weighing " + weight;
  }
  return "RCB, weights 1";
}

bool replicated_mesh_forced() {
  const char* value = std::getenv("GROUT_MESH");
  if (!value || std::string(value).empty() || std::string(value) == "distributed") return false;
  if (std::string(value) == "replicated") return true;
  throw InputError(std::string("GROUT_MESH=") + value +
                   ": expected replicated or distributed (the default)");
}

}  // namespace grout
