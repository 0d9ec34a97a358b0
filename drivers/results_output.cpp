#include "drivers/results_output.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <iomanip>

#include "io/errors.hpp"

namespace grout {

namespace {
const char* const axis[3] = {"x", "y", "z"};
}

ResultsOutput::ResultsOutput(const Mesh& mesh, const Input& input, const SolidProblem& problem)
    : mesh_(mesh), input_(input), problem_(problem), root_(problem.comm()->getRank() == 0) {
  const int dim = mesh.dimension;
  std::vector<std::string> nodal;
  for (int d = 0; d < dim; ++d) nodal.push_back(std::string("displ_") + axis[d]);
  for (int d = 0; d < dim; ++d) nodal.push_back(std::string("reaction_") + axis[d]);
  global_names_ = {"newton_iterations", "linear_iterations", "residual"};
  for (const auto& bc : input.dirichlet)
    for (int d = 0; d < dim; ++d) global_names_.push_back("reaction_" + bc.node_set + "_" + axis[d]);
  // One column per node set, even when several conditions share it.
  std::sort(global_names_.begin() + 3, global_names_.end());
  global_names_.erase(std::unique(global_names_.begin() + 3, global_names_.end()), global_names_.end());
  if (!root_) return;
  exodus_ = std::make_unique<ExodusWriter>(input.output.file, mesh, nodal, problem.stress_names(),
                                           global_names_);
  if (!input.output.summary.empty()) {
    summary_.open(input.output.summary);
    if (!summary_) throw InputError(input.output.summary + ": cannot write the summary file");
    summary_ << "step,time";
    for (const auto& name : global_names_) summary_ << "," << name;
    summary_ << "\n" << std::flush;
  }
}

std::vector<std::vector<double>> ResultsOutput::gather_nodal(const Vector& v) const {
  const int dim = problem_.dimension();
  const GlobalIndex n = problem_.num_global_nodes();
  std::vector<double> local(n * dim, 0.0), global(n * dim, 0.0);
  const auto& map = *v.getMap();
  const auto view = v.getLocalViewHost(Tpetra::Access::ReadOnly);
  for (LO i = 0; i < LO(map.getNodeNumElements()); ++i) local[map.getGlobalElement(i)] = view(i, 0);
  Teuchos::reduceAll(*problem_.comm(), Teuchos::REDUCE_SUM, int(local.size()), local.data(),
                     global.data());
  std::vector<std::vector<double>> out(dim, std::vector<double>(n));
  for (GlobalIndex k = 0; k < n; ++k)
    for (int d = 0; d < dim; ++d) out[d][k] = global[k * dim + d];
  return out;
}

void ResultsOutput::write(const StepResult& step) {
  const int dim = problem_.dimension();
  auto nodal = gather_nodal(*step.displacement);
  auto reaction = gather_nodal(*step.reaction);

  const auto names = problem_.stress_names();
  const GlobalIndex n_elements = mesh_.num_elements();
  std::vector<std::vector<double>> stress(names.size(), std::vector<double>(n_elements, 0.0));
  problem_.element_stresses(*step.displacement, stress);
  for (auto& s : stress) {
    std::vector<double> sum(s.size(), 0.0);
    Teuchos::reduceAll(*problem_.comm(), Teuchos::REDUCE_SUM, int(s.size()), s.data(), sum.data());
    s.swap(sum);
  }

  // Reaction sums per node set of the Dirichlet conditions (each node counted once).
  std::vector<double> globals = {double(step.newton_iterations), double(step.linear_iterations),
                                 step.residual};
  for (std::size_t g = 3; g < global_names_.size(); ++g) {
    const std::string& name = global_names_[g];
    const std::string set_name = name.substr(9, name.size() - 11);  // reaction_<set>_<axis>
    const int d = name.back() - 'x';
    double sum = 0.0;
    for (GlobalIndex node : mesh_.find_node_set(set_name)->nodes) sum += reaction[d][node];
    globals.push_back(sum);
  }
  if (!root_) return;
  for (int d = 0; d < dim; ++d) nodal.push_back(std::move(reaction[d]));
  exodus_->write_step(step.time, nodal, stress, globals);
  if (summary_.is_open()) {
    summary_ << step.step << "," << std::setprecision(17) << step.time;
    for (double value : globals) summary_ << "," << value;
    summary_ << "\n" << std::flush;
  }
}

}  // namespace grout
