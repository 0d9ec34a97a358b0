#include "drivers/results_output.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_TimeMonitor.hpp>
#include <algorithm>
#include <exception>
#include <iomanip>
#include <numeric>
#include <sstream>
#include <unordered_map>

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

/// This rank's entries of the node set `name`: each one's global node and its position in the
/// file's set, and the set's size in the file. On the replicated mesh every entry, at its
/// place; on a distributed mesh's part the entries of its local nodes (node_set_position).
struct NodeSetEntries {
  std::vector<GlobalIndex> nodes, positions;
  GlobalIndex size = 0;
};
NodeSetEntries node_set_entries(const Mesh& mesh, const DistributedMesh* distributed,
                                const std::string& name) {
  const NodeSet& set = *mesh.find_node_set(name);
  NodeSetEntries entries;
  entries.size = GlobalIndex(set.nodes.size());
  entries.nodes = set.nodes;
  entries.positions.resize(set.nodes.size());
  std::iota(entries.positions.begin(), entries.positions.end(), GlobalIndex(0));
  if (!distributed) return entries;
  const auto s = std::size_t(&set - mesh.node_sets.data());
  entries.size = distributed->node_set_global_size[s];
  for (GlobalIndex& n : entries.nodes) n = distributed->node_gid[std::size_t(n)];
  entries.positions = distributed->node_set_position[s];
  return entries;
}
}  // namespace

ResultsOutput::ResultsOutput(const Mesh& mesh, const Input& input, const SolidProblem& solid,
                             const MechanicsProblem& problem, const DistributedMesh* distributed)
    : mesh_(mesh),
      input_(input),
      solid_(solid),
      problem_(problem),
      distributed_(distributed),
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
  const std::size_t reaction_globals_end = global_names_.size();
  if (input.dynamics.enabled) {
    for (const char* name :
         {"kinetic_energy", "strain_energy", "external_work", "contact_work", "total_energy"})
      global_names_.push_back(name);
    for (int d = 0; d < dim; ++d) global_names_.push_back(std::string("momentum_") + axis[d]);
  }
  profile_wanted_ = !input.output.summary.empty() && problem.has_contact() && dim == 2;

  // Collective set-up first: nothing below it may throw on one rank before a collective call.
  Teuchos::TimeMonitor timer(*Teuchos::TimeMonitor::getNewTimer("grout: results output set-up"));
  const bool per_rank = input.output.parallel == OutputParallel::per_rank;
  exodus_ = std::make_unique<ResultsFile>(mesh, solid, per_rank, distributed);
  const Comm& comm = *solid.comm();
  for (std::size_t g = first_reaction; g < reaction_globals_end; ++g) {
    const std::string& name = global_names_[g];
    const std::string set_name = name.substr(9, name.size() - 11);  // reaction_<set>_<axis>
    SetSum sum;
    sum.axis = name.back() - 'x';
    std::vector<GlobalIndex> positions;  // of this rank's entries in the set
    const NodeSetEntries set = node_set_entries(mesh, distributed, set_name);
    const auto& owned = exodus_->owned_nodes();
    for (std::size_t k = 0; k < set.nodes.size(); ++k) {
      const auto it = std::lower_bound(owned.begin(), owned.end(), set.nodes[k]);
      if (it == owned.end() || *it != set.nodes[k]) continue;
      positions.push_back(set.positions[k]);
      sum.owned.push_back(std::size_t(it - owned.begin()));
    }
    sum.to_root = std::make_unique<RootGather>(comm, positions, set.size);
    reaction_sums_.push_back(std::move(sum));
  }

  // Then this rank's files: under `single` rank 0 writes every file, under `per_rank` each
  // rank its Exodus file and rank 0 the CSV files; a distributed mesh's arrays follow, gathered
  // (collective, so a file error on rank 0 waits until they are through).
  std::exception_ptr error;
  if (per_rank || root_) {
    try {
      open_files(input, nodal);
    } catch (...) {
      error = std::current_exception();
    }
  }
  exodus_->write_mesh();
  if (error) std::rethrow_exception(error);
}

void ResultsOutput::open_files(const Input& input, const std::vector<std::string>& nodal) {
  const Comm& comm = *solid_.comm();
  const SolidProblem& solid = solid_;
  const std::vector<OutputFile> files =
      output_files(input, profile_wanted_, comm.getRank(), comm.getSize());
  check_output_files(input, files);
  commit_ = std::make_unique<OutputCommit>(files);
  // Provenance: QA record (code, version, date, time) and the input and mesh file names.
  ExodusProvenance provenance{"grout", GROUT_VERSION, {}};
  provenance.info = {"grout input: " + input.file, "mesh: " + input.mesh_file};
  exodus_->open(files[0].temporary, {nodal, output_stress_names(solid), global_names_}, provenance);
  if (files.size() > 1) {
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
    }
  }
}

std::size_t ResultsOutput::owned_position(GlobalIndex node) const {
  const auto& owned = exodus_->owned_nodes();
  return std::size_t(std::lower_bound(owned.begin(), owned.end(), node) - owned.begin());
}

std::vector<double> ResultsOutput::component(const Vector& v, int d) const {
  const int dim = solid_.dimension();
  const GO num_u = GO(solid_.num_global_nodes()) * dim;
  std::vector<double> out(exodus_->owned_nodes().size(), 0.0);
  const auto& map = *v.getMap();
  const auto view = v.getLocalViewHost(Tpetra::Access::ReadOnly);
  for (LO i = 0; i < LO(map.getNodeNumElements()); ++i) {
    const GO g = map.getGlobalElement(i);
    if (g < num_u && g % dim == d) out[owned_position(g / dim)] = view(i, 0);
  }
  return out;
}

void ResultsOutput::write(const ConvergedStep& step) {
  Teuchos::TimeMonitor timer(*Teuchos::TimeMonitor::getNewTimer("grout: results output"));
  const int dim = solid_.dimension();
  const Comm& comm = *solid_.comm();
  Vector u(solid_.owned_map());
  problem_.displacement(*step.state, u);
  const Vector& reaction = problem_.reactions();
  const ContactFields contact = problem_.contact_fields();

  // Globals, on rank 0, then on every rank (each per-rank file holds them).
  const NewtonReport& newton = *step.newton;
  std::vector<double> globals = {
      double(newton.iterations), double(newton.linear_iterations),
      newton.residual_history.empty() ? 0.0 : newton.residual_history.back(),
      double(contact.active_nodes)};
  for (const SetSum& s : reaction_sums_) {  // each node counted once, in the set's order
    const std::vector<double> r = component(reaction, s.axis);
    std::vector<double> mine;
    for (std::size_t k : s.owned) mine.push_back(r[k]);
    double sum = 0.0;
    for (double value : s.to_root->gather(mine)) sum += value;
    globals.push_back(sum);
  }
  if (step.dynamics) {
    const EnergyBalance& b = step.dynamics->balance();
    for (double value : {b.kinetic, b.strain, b.external_work, b.contact_work, b.total})
      globals.push_back(value);
    for (int d = 0; d < dim; ++d) globals.push_back(b.momentum[d]);
  }
  Teuchos::broadcast(comm, 0, int(globals.size()), globals.data());

  // The 2D contact profile: every slave node's results, on rank 0.
  std::vector<std::vector<double>> profile;  // rank 0: [field][received entry]
  if (profile_wanted_) {
    if (!profile_to_root_) {
      // The slave nodes (each from its owner) with their coordinates, on rank 0 sorted by x,
      // then y (a surface-sized gather, once).
      profile_to_root_ = std::make_unique<RootGather>(comm, contact.nodes, 0);
      std::vector<double> x, y;
      for (GlobalIndex n : contact.nodes) {
        const GlobalIndex local = distributed_ ? distributed_->local_node(n) : n;
        x.push_back(mesh_.coordinates[std::size_t(2 * local)]);
        y.push_back(mesh_.coordinates[std::size_t(2 * local + 1)]);
      }
      profile_x_ = profile_to_root_->gather(x);
      profile_y_ = profile_to_root_->gather(y);
      const std::vector<GlobalIndex>& received = profile_to_root_->received_ids();
      profile_order_.resize(received.size());
      std::iota(profile_order_.begin(), profile_order_.end(), std::size_t(0));
      std::sort(profile_order_.begin(), profile_order_.end(),
                [&](std::size_t a, std::size_t b) { return received[a] < received[b]; });
      const auto& X = profile_x_;
      const auto& Y = profile_y_;
      std::sort(profile_order_.begin(), profile_order_.end(), [&](std::size_t a, std::size_t b) {
        return X[a] < X[b] || (X[a] == X[b] && Y[a] < Y[b]);
      });
    }
    for (const auto* field : {&contact.pressure, &contact.gap, &contact.status, &contact.lm[0],
                              &contact.lm[1], &contact.slip[0], &contact.slip[1]})
      profile.push_back(profile_to_root_->gather(*field));
  }

  // The Exodus step, one variable at a time.
  ResultsFile& file = *exodus_;
  std::size_t v = 0;
  file.begin_step(step.time);
  for (int d = 0; d < dim; ++d) file.nodal(v++, component(u, d));
  for (int d = 0; d < dim; ++d) file.nodal(v++, component(reaction, d));
  if (problem_.has_contact()) {
    const auto at_owned_nodes = [&](const std::vector<double>& entries) {
      std::vector<double> out(file.owned_nodes().size(), 0.0);
      for (std::size_t i = 0; i < entries.size(); ++i)
        out[owned_position(contact.nodes[i])] = entries[i];
      return out;
    };
    file.nodal(v++, at_owned_nodes(contact.pressure));
    file.nodal(v++, at_owned_nodes(contact.gap));
    file.nodal(v++, at_owned_nodes(contact.status));
    for (int d = 0; d < dim; ++d) file.nodal(v++, at_owned_nodes(contact.lm[d]));
    for (int d = 0; d < dim; ++d) file.nodal(v++, at_owned_nodes(contact.slip[d]));
  }
  if (step.dynamics) {
    for (int d = 0; d < dim; ++d) file.nodal(v++, component(step.dynamics->velocity(), d));
    for (int d = 0; d < dim; ++d) file.nodal(v++, component(step.dynamics->acceleration(), d));
  }
  std::vector<std::vector<double>> stress = solid_.element_stresses(u);
  const std::size_t num_owned_elements = stress.empty() ? 0 : stress[0].size();
  stress.resize(output_stress_names(solid_).size(), std::vector<double>(num_owned_elements, 0.0));
  for (std::size_t c = 0; c < stress.size(); ++c) file.element(c, stress[c]);
  file.globals(globals);
  file.end_step();  // throws this rank's file error, after the last collective call

  if (summary_.is_open()) {
    std::ostringstream row;
    row << step.step << "," << std::setprecision(17) << step.time;
    for (double value : globals) row << "," << value;
    summary_.write(row.str() + "\n");
  }
  if (profile_.is_open()) {
    const auto& received = profile_to_root_->received_ids();
    std::ostringstream rows;
    for (std::size_t i : profile_order_) {
      rows << step.step << "," << std::setprecision(17) << step.time << "," << received[i] + 1
           << "," << profile_x_[i] << "," << profile_y_[i];
      for (const auto& field : profile) rows << "," << field[i];
      rows << "\n";
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
  if (commit_) commit_->commit();  // the first converged step replaces the previous results
}

}  // namespace grout
