#pragma once
// The validated input (DESIGN.md §5): the YAML file is read once into these plain structs;
// nothing downstream looks a value up by string.

#include <Teuchos_ParameterList.hpp>
#include <Teuchos_RCP.hpp>
#include <array>
#include <string>
#include <vector>

#include "io/expression.hpp"
#include "io/mesh.hpp"

namespace grout {

enum class PlaneKind { strain, stress };
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
};

struct TimeInput {
  double end = 1.0;
  int steps = 1;               ///< equal steps, or (adaptive) the first step is end / steps
  bool adaptive = false;       ///< `stepping: adaptive`: grow after easy steps
  double max_step_size = 0.0;  ///< adaptive bound on the step size; 0 = none
};

struct OutputInput {
  std::string file;     ///< Exodus results, resolved against the input file's folder
  std::string summary;  ///< CSV per step, resolved likewise (empty: none)
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
  Teuchos::RCP<Teuchos::ParameterList> solver;  ///< `solver` sublist, passed through
  OutputInput output;
};

/// The material assigned to `block` (by name or id_<n>); nullptr if none.
const MaterialInput* find_material(const Input& input, const ElementBlock& block);

/// Read and validate `grout:` from a YAML file. Throws InputError naming the file and key.
Input read_input(const std::string& path);

/// Check every block, side set and node set the input names exists in `mesh`, and that the
/// mesh dimension matches the model. Throws InputError naming the entity and the file.
void check_input_against_mesh(const Input& input, const Mesh& mesh);

}  // namespace grout
