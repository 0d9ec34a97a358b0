#pragma once
// The validated input (docs/design.md §5): the YAML file is read once into these plain structs;
// nothing downstream looks a value up by string.

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "io/contact_treatment.hpp"
#include "io/expression.hpp"
#include "io/mesh.hpp"
#include "io/solver_settings.hpp"

namespace grout {

/// 2D models: plane strain, plane stress (unit thickness) or axisymmetric (x = r >= 0, y = the
/// axis; every volume, surface and mortar integral weighted by 2 pi r: totals over the full
/// circle).
enum class PlaneKind { strain, stress, axisymmetric };
enum class StrainKind { small, finite };

struct ModelInput {
  int dimension = 2;
  PlaneKind plane = PlaneKind::strain;
  StrainKind strain = StrainKind::small;
};

/// linear_elastic: Hooke's law under strain: small, St. Venant-Kirchhoff under strain: finite;
/// neo_hookean: compressible Neo-Hookean (strain: finite only).
enum class MaterialLaw { linear_elastic, neo_hookean };

struct MaterialInput {
  std::string name;   ///< key under `materials`
  std::string block;  ///< element block (Exodus name or id_<n>)
  MaterialLaw law = MaterialLaw::linear_elastic;
  double youngs_modulus = 0.0;
  double poissons_ratio = 0.0;
  double density = 0.0;
};

struct DirichletInput {
  std::string name;
  std::string node_set;
  int component = 0;  ///< 0 = x, 1 = y, 2 = z
  Expression value;   ///< prescribed displacement u(t, x, y, z)
};

enum class LoadKind { pressure, traction };

struct LoadInput {
  std::string name;
  std::string side_set;
  LoadKind type = LoadKind::pressure;
  Expression value;                    ///< pressure p(t,x,y,z), positive into the body
  std::vector<Expression> components;  ///< traction t_i(t,x,y,z), one per dimension
};

enum class ContactKind { frictionless, frictional, tied };
enum class ContactIntegration { exact, collocation };

enum class ContactGeometry { automatic, reference, current };

struct ContactInput {
  std::string name;
  std::string slave;   ///< side set
  std::string master;  ///< side set
  /// `self: <side set>`: self-contact of one surface (slave = master = that side set; each
  /// contacting region picks its slave and master faces, nonlinear/contact_interface.hpp).
  bool self = false;
  /// The side sets of `self: a` or `self: [a, b, ...]` (slave = master = the first): their
  /// union, in this order, is the one self-contact surface (contact_side_sets).
  std::vector<std::string> self_sets;
  ContactKind type = ContactKind::frictionless;
  double friction_coefficient = 0.0;  ///< only for frictional
  /// Complementarity parameters of the normal and tangential NCP functions; 0 = the default
  /// derived from the Young's modulus and the element size (E/h).
  double c_n = 0.0;
  double c_t = 0.0;
  ContactIntegration integration = ContactIntegration::exact;  ///< of the mortar integrals
  /// Where normals, D and M are evaluated: reference (linearised kinematics, consistent
  /// with small strain) or current (large sliding, with the full linearisation); automatic =
  /// reference for strain: small, current for strain: finite.
  ContactGeometry geometry = ContactGeometry::automatic;
  int collocation_points = 0;  ///< per segment, for collocation; 0 = integrator default
  /// At the start of a step (until the first Newton update), a slave node with no pressure and
  /// a gap below start_gap × the mean size of its slave faces counts as active; 0 = off.
  /// Default 0.05, and 0 with dynamics (the mass matrix holds a body held only by contact).
  double start_gap = 0.05;
  /// At a Newton iterate where more nodes close than were active: a closing node whose gap
  /// reaches 0 later than this fraction of the update stays inactive for that iterate (once
  /// per step; nonlinear/first_update_closures.hpp); 1 = off.
  double start_closure = 0.5;
};

struct TimeInput {
  double end = 1.0;
  int steps = 1;               ///< equal steps, or (adaptive) the first step is end / steps
  bool adaptive = false;       ///< `stepping: adaptive`: grow after easy steps
  double max_step_size = 0.0;  ///< adaptive bound on the step size; 0 = none
  /// `predictor: extrapolated`: a quasi-static step starts from the last two converged states
  /// extrapolated to its time (load_stepping.hpp); `last` (default): from the last one.
  bool extrapolate = false;
  /// Smallest step a cut-back may make (exit 3 below it); resolved by the reader: default
  /// min_step_fraction · end, at least min_step_floor · end. end / steps may not be smaller.
  double min_step_size = 0.0;
  static constexpr double min_step_fraction = 1e-6;
  static constexpr double min_step_floor = 1e-12;
};

/// Implicit dynamics (`grout/dynamics`); absent: quasi-static.
enum class DynamicsScheme { newmark, hht, bossak, generalized_alpha, energy_momentum };
enum class MassKind { consistent, lumped };

struct DynamicsInput {
  bool enabled = false;
  DynamicsScheme scheme = DynamicsScheme::newmark;
  double rho_infinity = 1.0;        ///< hht, bossak, generalized_alpha
  double beta = 0.25, gamma = 0.5;  ///< newmark
  MassKind mass = MassKind::consistent;
  /// contact_treatment with velocity_update's sliding
  ContactTreatment contact_treatment = ContactTreatment::stabilized;
};

/// An initial velocity field on the nodes of one element block (`grout/initial_velocity`).
struct InitialVelocityInput {
  std::string name;
  std::string block;
  std::vector<Expression> components;  ///< v_i(x, y, z) at t = 0, one per dimension
};

/// How the Exodus results are laid out over the ranks (docs/input.md, `output/parallel`).
enum class OutputParallel {
  single,   ///< one file, written by rank 0 from the ranks' owned parts
  per_rank  ///< one file per rank (<file>.<ranks>.<rank>, Nemesis I maps), read as one set
};

struct OutputInput {
  std::string file;     ///< Exodus results, resolved against the input file's folder
  std::string summary;  ///< CSV per step, resolved likewise (empty: none)
  OutputParallel parallel = OutputParallel::single;
};

struct Input {
  std::string file;       ///< the YAML file, as given
  std::string directory;  ///< its folder: relative paths are resolved against it
  std::string mesh_file;  ///< resolved path
  ModelInput model;
  std::vector<MaterialInput> materials;
  std::vector<DirichletInput> dirichlet;
  std::vector<LoadInput> loads;
  std::vector<ContactInput> contact;
  TimeInput time;
  DynamicsInput dynamics;
  std::array<double, 3> gravity = {0.0, 0.0, 0.0};  ///< acceleration of gravity
  std::vector<InitialVelocityInput> initial_velocity;
  SolverSettings solver;  ///< `solver`: Newton, the linear solver, NOX/Belos/MueLu sublists
  OutputInput output;
};

/// The side sets of a contact pair's slave side (master = false) or master side: the one the
/// input names, or for `self: [a, b, ...]` all of them (one surface, faces in this order).
/// Inline: the contact core (the embedding API's, without the input checks) uses it too.
inline std::vector<std::string> contact_side_sets(const ContactInput& contact, bool master) {
  if (contact.self && !contact.self_sets.empty()) return contact.self_sets;
  return {master ? contact.master : contact.slave};
}

/// The material assigned to `block` (by name or id_<n>); nullptr if none.
const MaterialInput* find_material(const Input& input, const ElementBlock& block);

/// Read and validate `grout:` from a YAML file. Throws InputError naming the file and key.
/// The file must respect the limits below (checked before it is parsed).
Input read_input(const std::string& path);

/// read_input on `text` given in memory; `path` names the file in messages and is the base
/// of relative mesh and output paths.
Input read_input_text(const std::string& text, const std::string& path);

/// Bounds on an input file, so that hostile input cannot cost unbounded time: the YAML
/// reader's time grows with the square of a token's length.
constexpr std::size_t max_input_bytes = 256 * 1024;
constexpr std::size_t max_input_line_length = 4096;
/// Bound on contact/<pair>/collocation_points (points per slave segment in 2D, per direction
/// of a slave face in 3D): the collocation convergence study needs at most a few hundred.
constexpr int max_collocation_points = 1000;

/// The message of a Teuchos YAML parser exception in a few words:
/// "<path>: YAML error: line L, column C: <what is wrong>".
std::string clean_yaml_message(const std::string& what, const std::string& path);

/// Check every block, side set and node set the input names exists in `mesh`, and that the
/// mesh dimension matches the model. Throws InputError naming the entity and the file.
void check_input_against_mesh(const Input& input, const Mesh& mesh);

/// \brief What check_input_against_mesh needs of one rank's part of a distributed mesh
/// (parallel/distributed_mesh.hpp), whose `local` Mesh holds every block and set, with the
/// entries of its local entities: their global (file) numbers, which elements this rank
/// owns, the sets' sizes in the file, and the largest |x| of the whole mesh.
struct MeshPartNumbers {
  const std::vector<GlobalIndex>& node_gid;     ///< local node -> 0-based file node
  const std::vector<GlobalIndex>& element_gid;  ///< local element -> 0-based file element
  const std::vector<int>& element_owner;        ///< owning rank of each local element
  int rank = 0;
  const std::vector<GlobalIndex>& side_set_size;  ///< entries in the file, per side set
  const std::vector<GlobalIndex>& node_set_size;  ///< entries in the file, per node set
  double x_max = 0.0;                             ///< max |x| over all nodes (axisymmetric)
};

/// \brief The same checks on this rank's part `local` of a distributed mesh (the mesh checks
/// of check_mesh are the reader's): a set is empty when the file's set is; the boundary-face,
/// self-contact and axisymmetric tests run on the owned elements (an element across a face of
/// an owned element shares its nodes, so it is local); elements and nodes are named by their
/// global numbers, as on the replicated mesh. Every rank must call it and agree on the
/// outcome (agree_on_errors): a test on owned entities fails on one rank only.
void check_input_against_mesh(const Input& input, const Mesh& local, const MeshPartNumbers& part);

}  // namespace grout
