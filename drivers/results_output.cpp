#include "drivers/results_output.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <iomanip>
#include <sstream>

#include "io/errors.hpp"
#include "nonlinear/dynamic_problem.hpp"

namespace grout {

namespace {
const char* const axis[3] = {"x", "y", "z"};
constexpr int first_reaction = 4;  ///< index of the first reaction sum in the globals

/// \brief Element stress names as written: the solid's (2D: xx yy zz xy), and in 2D also
/// `stress_yz` and `stress_zx`, zero in plane strain and plane stress. ParaView's IOSS reader
/// groups `stress_xx yy zz xy yz zx` into one array `stress` (IOSS type sym_tensor_33) and
/// ParaView 5.11 labels a 6-component array XX YY ZZ XY YZ XZ; the four components of 2D
/// form a 4-component array (IOSS sym_tensor_31) that it labels 0 1 2 3, as it names the
/// components of 3-, 6- and 9-component arrays only (the reader sets no names of its own).
std::vector<std::string> output_stress_names(const SolidProblem& solid) {
  std::vector<std::string> names = solid.stress_names();
  if (solid.dimension() == 2) names.insert(names.end(), {"stress_yz", "stress_zx"});
  return names;
}
}  // namespace

ResultsOutput::ResultsOutput(const Mesh& mesh, const Input& input, const SolidProblem& solid,
                             const MechanicsProblem& problem)
    : mesh_(mesh),
      input_(input),
      solid_(solid),
      problem_(problem),
      root_(solid.comm()->getRank() == 0) {
  const int dim = mesh.dimension;
  std::vector<std::string> nodal;
  for (int d = 0; d < dim; ++d) nodal.push_back(std::string("displ_") + axis[d]);
  for (int d = 0; d < dim; ++d) nodal.push_back(std::string("reaction_") + axis[d]);
  if (problem.has_contact()) {
    for (const char* name : {"contact_pressure", "normal_gap", "contact_status"})
      nodal.push_back(name);
    for (int d = 0; d < dim; ++d) nodal.push_back(std::string("lm_") + axis[d]);
    for (int d = 0; d < dim; ++d) nodal.push_back(std::string("slip_") + axis[d]);
  }
  if (input.dynamics.enabled) {
    for (int d = 0; d < dim; ++d) nodal.push_back(std::string("velocity_") + axis[d]);
    for (int d = 0; d < dim; ++d) nodal.push_back(std::string("acceleration_") + axis[d]);
  }
  global_names_ = {"newton_iterations", "linear_iterations", "residual", "active_nodes"};
  for (const auto& bc : input.dirichlet)
    for (int d = 0; d < dim; ++d)
      global_names_.push_back("reaction_" + bc.node_set + "_" + axis[d]);
  // One column per node set, even when several conditions share it.
  std::sort(global_names_.begin() + first_reaction, global_names_.end());
  global_names_.erase(std::unique(global_names_.begin() + first_reaction, global_names_.end()),
                      global_names_.end());
  reaction_globals_end_ = global_names_.size();
  if (input.dynamics.enabled) {
    for (const char* name :
         {"kinetic_energy", "strain_energy", "external_work", "contact_work", "total_energy"})
      global_names_.push_back(name);
    for (int d = 0; d < dim; ++d) global_names_.push_back(std::string("momentum_") + axis[d]);
  }
  if (!root_) return;
  const std::vector<OutputFile> files = output_files(input, problem.has_contact() && dim == 2);
  check_output_files(input, files);
  commit_ = std::make_unique<OutputCommit>(files);
  // Provenance: QA record (code, version, date, time) and the input and mesh file names.
  ExodusProvenance provenance{"grout", GROUT_VERSION, {}};
  provenance.info = {"grout input: " + input.file, "mesh: " + input.mesh_file};
  exodus_ = std::make_unique<ExodusWriter>(files[0].temporary, mesh, nodal,
                                           output_stress_names(solid), global_names_, provenance);
  if (!input.output.summary.empty()) {
    summary_ = CheckedTextFile(files[1].temporary, files[1].path);
    std::string header = "step,time";
    for (const auto& name : global_names_) header += "," + name;
    summary_.write(header + "\n");
    // <summary>_newton.csv: the residual history and active set of every Newton iteration.
    newton_log_ = CheckedTextFile(files[2].temporary, files[2].path);
    newton_log_.write("step,time,iteration,residual,active_nodes,active_changes,step_length\n");
    // <summary>_contact.csv (2D): the contact results along the interface, every step.
    if (files.size() > 3) {
      profile_ = CheckedTextFile(files[3].temporary, files[3].path);
      profile_.write(
          "step,time,node,x,y,contact_pressure,normal_gap,contact_status,lm_x,lm_y,"
          "slip_x,slip_y\n");
      profile_nodes_ = problem.slave_nodes();
      const auto& X = mesh.coordinates;
      std::sort(profile_nodes_.begin(), profile_nodes_.end(), [&](GlobalIndex a, GlobalIndex b) {
        return X[2 * a] < X[2 * b] || (X[2 * a] == X[2 * b] && X[2 * a + 1] < X[2 * b + 1]);
      });
    }
  }
}

std::vector<std::vector<double>> ResultsOutput::gather_nodal(const Vector& v) const {
  const int dim = solid_.dimension();
  const GlobalIndex n = solid_.num_global_nodes();
  std::vector<double> local(n * dim, 0.0), global(n * dim, 0.0);
  const auto& map = *v.getMap();
  const auto view = v.getLocalViewHost(Tpetra::Access::ReadOnly);
  for (LO i = 0; i < LO(map.getNodeNumElements()); ++i) local[map.getGlobalElement(i)] = view(i, 0);
  Teuchos::reduceAll(*solid_.comm(), Teuchos::REDUCE_SUM, int(local.size()), local.data(),
                     global.data());
  std::vector<std::vector<double>> out(dim, std::vector<double>(n));
  for (GlobalIndex k = 0; k < n; ++k)
    for (int d = 0; d < dim; ++d) out[d][k] = global[k * dim + d];
  return out;
}

void ResultsOutput::write(const ConvergedStep& step) {
  const int dim = solid_.dimension();
  Vector u(solid_.owned_map());
  problem_.displacement(*step.state, u);
  auto nodal = gather_nodal(u);
  auto reaction = gather_nodal(problem_.reactions());

  const auto names = solid_.stress_names();
  const GlobalIndex n_elements = mesh_.num_elements();
  std::vector<std::vector<double>> stress(names.size(), std::vector<double>(n_elements, 0.0));
  solid_.element_stresses(u, stress);
  for (auto& s : stress) {
    std::vector<double> sum(s.size(), 0.0);
    Teuchos::reduceAll(*solid_.comm(), Teuchos::REDUCE_SUM, int(s.size()), s.data(), sum.data());
    s.swap(sum);
  }
  stress.resize(output_stress_names(solid_).size(), std::vector<double>(n_elements, 0.0));
  const ContactFields contact = problem_.contact_fields();

  // Reaction sums per node set of the Dirichlet conditions (each node counted once).
  const NewtonReport& newton = *step.newton;
  std::vector<double> globals = {
      double(newton.iterations), double(newton.linear_iterations),
      newton.residual_history.empty() ? 0.0 : newton.residual_history.back(),
      double(contact.active_nodes)};
  for (std::size_t g = first_reaction; g < reaction_globals_end_; ++g) {
    const std::string& name = global_names_[g];
    const std::string set_name = name.substr(9, name.size() - 11);  // reaction_<set>_<axis>
    const int d = name.back() - 'x';
    double sum = 0.0;
    for (GlobalIndex node : mesh_.find_node_set(set_name)->nodes) sum += reaction[d][node];
    globals.push_back(sum);
  }
  std::vector<std::vector<double>> velocity, acceleration;
  if (step.dynamics) {
    velocity = gather_nodal(step.dynamics->velocity());
    acceleration = gather_nodal(step.dynamics->acceleration());
    const EnergyBalance& b = step.dynamics->balance();
    for (double value : {b.kinetic, b.strain, b.external_work, b.contact_work, b.total})
      globals.push_back(value);
    for (int d = 0; d < dim; ++d) globals.push_back(b.momentum[d]);
  }
  if (!root_) return;
  for (int d = 0; d < dim; ++d) nodal.push_back(std::move(reaction[d]));
  if (problem_.has_contact()) {
    nodal.push_back(contact.pressure);
    nodal.push_back(contact.gap);
    nodal.push_back(contact.status);
    for (int d = 0; d < dim; ++d) nodal.push_back(contact.lm[d]);
    for (int d = 0; d < dim; ++d) nodal.push_back(contact.slip[d]);
  }
  for (auto& field : velocity) nodal.push_back(std::move(field));
  for (auto& field : acceleration) nodal.push_back(std::move(field));
  exodus_->write_step(step.time, nodal, stress, globals);
  if (summary_.is_open()) {
    std::ostringstream row;
    row << step.step << "," << std::setprecision(17) << step.time;
    for (double value : globals) row << "," << value;
    summary_.write(row.str() + "\n");
  }
  if (profile_.is_open()) {
    std::ostringstream rows;
    for (GlobalIndex n : profile_nodes_) {
      rows << step.step << "," << std::setprecision(17) << step.time << "," << n + 1 << ","
           << mesh_.coordinates[2 * n] << "," << mesh_.coordinates[2 * n + 1] << ","
           << contact.pressure[n] << "," << contact.gap[n] << "," << contact.status[n] << ","
           << contact.lm[0][n] << "," << contact.lm[1][n] << "," << contact.slip[0][n] << ","
           << contact.slip[1][n] << "\n";
    }
    profile_.write(rows.str());
  }
  if (newton_log_.is_open()) {
    std::ostringstream rows;
    for (std::size_t k = 0; k < newton.residual_history.size(); ++k) {
      rows << step.step << "," << std::setprecision(17) << step.time << "," << k << ","
           << newton.residual_history[k] << ","
           << (k < newton.active_set_history.size() ? newton.active_set_history[k] : 0) << ","
           << (k < newton.active_change_history.size() ? newton.active_change_history[k] : 0) << ","
           << (k < newton.step_length_history.size() ? newton.step_length_history[k] : 1.0) << "\n";
    }
    newton_log_.write(rows.str());
  }
  commit_->commit();  // the first converged step replaces the previous results
}

}  // namespace grout
