#pragma once
// Which mesh a run reads (docs/design.md, "The distributed mesh", stage 3): the distributed
// mesh (parallel/distributed_mesh.hpp), each rank its part, for every run: static (load
// stepping) and dynamic, without contact or with frictionless, frictional (Coulomb), tied and
// self-contact pairs; on any linear solver (MUMPS, KLU2 or Belos + MueLu, named or chosen by
// `type: auto`): the iterative path takes its rows' nodes' coordinates and the bodies
// labelled across the ranks (parallel/distributed_bodies.hpp); with contact its rows are the
// displacements' (the multipliers condensed), so the same owned nodes serve. One Exodus file
// (`output/parallel: single`) or one per rank (`per_rank`, each rank's piece cut from its
// part), and the CSV summaries.
//
// The environment variable GROUT_MESH=replicated makes a run read the replicated mesh instead
// (every rank holds all of it), to compare the two paths: tools/compare_results, the ctests
// mesh_paths/*.

#include <string>

#include "io/input.hpp"
#include "parallel/distributed_mesh.hpp"

namespace grout {

/// Whether `type: auto` picks the iterative solver for `unknowns` (false for a named type).
bool iterative_for_unknowns(const Input& input, long long unknowns);

/// Whether a run on a mesh of `num_nodes` nodes, `slave_nodes` of them on contact slave sides,
/// solves its systems with Belos + MueLu: `type: belos`, or `auto` at or above its threshold
/// (nonlinear/linear_solver.hpp; the unknowns are (num_nodes + slave_nodes) × dimension, a
/// multiplier per slave dof, as ContactInterface numbers them). Only then does the distributed
/// mesh's layout carry the nodes' coordinates and bodies.
bool iterative_solver_chosen(const Input& input, long long num_nodes, long long slave_nodes);

/// \brief How the distributed mesh's elements are partitioned for `input`: with contact, the
/// slave side sets of its pairs are the contact surface, and the elements with a face on it are
/// partitioned apart from the others (DistributionOptions::separate_contact), so that each rank
/// evaluates its share of the slave faces and holds its share of the solid (docs/performance.md,
/// "Scale: what a rank holds"). The environment variable GROUT_PARTITION picks another
/// partition, to compare them: `plain` (weights 1, the contact ignored), `weight:W` (contact
/// elements weigh 1 + W), `criteria` (two-criteria RCB), `separate:positions` (the contact
/// elements by one RCB, without the gap bands of DistributionOptions::master_side_sets) or
/// `separate` (the default); any other value is an input error naming it.
DistributionOptions distribution_options(const Input& input);

/// The partition `options` make, in words, for the --timers report.
std::string describe_partition(const DistributionOptions& options);

/// Whether GROUT_MESH=replicated is set; any other value than replicated or distributed (the
/// default) is an input error naming it.
bool replicated_mesh_forced();

}  // namespace grout
