// grout_mesh: write a generated Exodus mesh for tests, verification cases and benchmarks.
//
//   grout_mesh <kind> [--key value ...] [--triangles|--tetrahedra] -o out.exo
//
// Exit codes: 0 written, 1 the file could not be written, 2 bad arguments.

#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "io/contact_meshes.hpp"
#include "io/errors.hpp"
#include "io/exodus.hpp"
#include "io/friction_meshes.hpp"
#include "io/mesh_generators.hpp"

namespace {

constexpr const char* usage_text = R"(usage: grout_mesh <kind> [options] -o <file.exo>

kinds and their options (defaults in brackets):
  rectangle        --nx [4] --ny [4] --x0 [0] --x1 [1] --y0 [0] --y1 [1] --triangles
                   --distortion [0] --seed [1] --block [block]
                   sets: bottom right top left
  box              --nx [4] --ny [4] --nz [4] --x0 --x1 --y0 --y1 --z0 --z1 [0/1]
                   --tetrahedra --distortion [0] --seed [1] --block [block]
                   sets: xmin xmax ymin ymax zmin zmax
  quarter_annulus  --n-radial [4] --n-circ [8] --r-inner [1] --r-outer [2] --block [block]
                   sets: inner outer x_symmetry y_symmetry
  two_blocks_2d    --nx-lower [4] --ny-lower [4] --nx-upper [5] --ny-upper [5] --gap [0]
                   --triangles        blocks lower [0,1]^2, upper [0,1]x[1+gap,2+gap]
  two_blocks_3d    --nx-lower [4] --ny-lower [4] --nz-lower [4] --nx-upper [5]
                   --ny-upper [5] --nz-upper [5] --gap [0] --tetrahedra
  stacked_2d       --nx-lower [4] --ny-lower [4] --nx-upper [5] --ny-upper [5] --width [1]
                   --height-lower [1] --height-upper [1] --gap [0] --triangles-lower
                   --triangles-upper --distortion [0] --seed [1]
                   blocks lower, upper; sets lower_/upper_ bottom right top left
  stacked_3d       --nx-lower [4] --ny-lower [4] --nz-lower [4] --nx-upper [5] --ny-upper [5]
                   --nz-upper [5] --width [1] --height-lower [1] --height-upper [1] --gap [0]
                   --tetrahedra-lower --tetrahedra-upper --distortion [0] --seed [1]
                   sets lower_/upper_ xmin xmax ymin ymax bottom top
  sloped_blocks_2d --nx-lower [4] --ny-lower [3] --nx-upper [5] --ny-upper [3] --width [1]
                   --y-left [0.9] --y-right [1.1] --height [2] --triangles-lower
                   --triangles-upper   interface from (0,y-left) to (width,y-right)
                   sets lower_/upper_ bottom right top left (lower_top = upper_bottom line)
  taylor_patch_2d  --nx-block [8] --ny-block [4] --nx-die [3] --ny-die [2] --die-stretch [0]
                   --triangles-block --triangles-die   block [0,8]x[0,5], die [4,6]x[5,7]
                   sets block_/die_ bottom right top left, block_top_free; node sets
                   block_origin die_anchor
  taylor_patch_3d  --nx-block [8] --ny-block [8] --nz-block [4] --nx-die [3] --ny-die [3]
                   --nz-die [2] --tetrahedra-block --tetrahedra-die
                   block [0,8]^2x[0,4], die [4,6]^2x[4,6]; sets block_/die_ xmin xmax ymin
                   ymax bottom top, block_top_free; node sets block_origin block_x_end
                   die_anchor die_x_end
  hertz_cylinders  --level [1] --radius [8] --gap [0] --contact-width [2.5]
                   half discs upper (centre (0,R+gap)) and lower (centre (0,-R)); sets
                   upper_contact lower_contact upper_top lower_bottom
  cylinder_on_plane --level [1] --radius [6.1237] --contact-width [2.5]
                   half disc cylinder (centre (0,R)) on plane [-2R,2R]x[-2R,0]; sets
                   cylinder_contact cylinder_top plane_top plane_bottom plane_left
                   plane_right; node set plane (all plane nodes)
  sphere_on_plane_axisymmetric --level [1] --radius [6.1237] --contact-width [2.5]
                   x >= 0 half of cylinder_on_plane's cylinder (centre (0,R)) on plane
                   [0,2R]x[-2R,0], for model/plane: axisymmetric; sets sphere_contact
                   sphere_top sphere_axis plane_top plane_bottom plane_left plane_right;
                   node set plane (all plane nodes)
  quarter_disc     --level [1] --radius [1]   quarter disc x >= 0, y <= 0 (a solid sphere,
                   axisymmetric); sets sphere_surface sphere_equator sphere_axis
  dong_blocks      --nx-lower [40] --ny-lower [6] --nx-upper [8] --ny-upper [10]
                   --width-lower [0.35] --height-lower [0.075] --width-upper [0.1]
                   --height-upper [0.125] --x-upper [0] --gap [0] --triangles-lower
                   --triangles-upper   friction base test (Dong 1999): block I "upper" on the
                   longer block II "lower"; sets lower_/upper_ bottom right top left,
                   lower_top_contact (the part of lower_top under block I)
  hertz_cylinders_pinned --level [1] --radius [8] --gap [0] --contact-width [2.5]
                   hertz_cylinders plus single-node node sets upper_top_centre (0,R+gap),
                   upper_top_end (R,R+gap), lower_bottom_centre (0,-R), lower_bottom_end
                   (R,-R) (frictional Hertz: both flat faces loaded, pin + roller)
common: -o|--output <file> (required), -h|--help
sets: each side set X listed above comes with the node set X_nodes of its nodes; the other
node sets (block_origin, plane, ...) keep their names.
distortion (< 0.4) moves nodes randomly by up to distortion x cell size; boundary nodes
stay on their boundary line/plane.
)";

/// Bad command line: reported with the usage text, exit code 2.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// The options given, with typed look-ups that name the option on a bad value.
class Options {
 public:
  Options(int argc, char** argv, const std::set<std::string>& valued,
          const std::set<std::string>& flags) {
    for (int i = 2; i < argc; ++i) {
      const std::string given = argv[i];
      const std::string key = given == "-o" ? "--output" : given;
      if (flags.count(key)) {
        values_[key] = "1";
      } else if (valued.count(key) || key == "--output") {
        if (i + 1 >= argc) throw UsageError("option " + given + " needs a value");
        values_[key] = argv[++i];
      } else {
        throw UsageError("unknown option '" + key + "' for kind '" + argv[1] + "'");
      }
    }
    if (!values_.count("--output")) throw UsageError("missing -o <file.exo>");
  }
  std::string text(const std::string& key, const std::string& fallback) const {
    const auto it = values_.find(key);
    return it == values_.end() ? fallback : it->second;
  }
  bool flag(const std::string& key) const { return values_.count(key) > 0; }
  double real(const std::string& key, double fallback) const {
    const auto it = values_.find(key);
    if (it == values_.end()) return fallback;
    try {
      std::size_t used = 0;
      const double v = std::stod(it->second, &used);
      if (used == it->second.size()) return v;
    } catch (const std::exception&) {
    }
    throw UsageError("option " + key + ": '" + it->second + "' is not a number");
  }
  long long integer(const std::string& key, long long fallback, long long minimum = 1) const {
    const auto it = values_.find(key);
    if (it == values_.end()) return fallback;
    long long v = 0;
    try {
      std::size_t used = 0;
      v = std::stoll(it->second, &used);
      if (used != it->second.size()) throw std::invalid_argument("");
    } catch (const std::exception&) {
      throw UsageError("option " + key + ": '" + it->second + "' is not an integer");
    }
    if (v < minimum)
      throw UsageError("option " + key + ": " + it->second + " is less than " +
                       std::to_string(minimum));
    return v;
  }

 private:
  std::map<std::string, std::string> values_;
};

const char* type_name(grout::Topology t) {
  switch (t) {
    case grout::Topology::quad4:
      return "QUAD4";
    case grout::Topology::tri3:
      return "TRI3";
    case grout::Topology::hex8:
      return "HEX8";
    case grout::Topology::tet4:
      return "TET4";
    case grout::Topology::line2:
      return "LINE2";
  }
  return "?";
}

/// "12 QUAD4, 30 TRI3": elements per type, in the order the types first appear.
std::string element_counts(const grout::Mesh& mesh) {
  std::vector<std::pair<std::string, long long>> counts;
  for (const auto& block : mesh.blocks) {
    const std::string type = type_name(block.topology);
    auto it =
        std::find_if(counts.begin(), counts.end(), [&](const auto& c) { return c.first == type; });
    if (it == counts.end()) it = counts.insert(counts.end(), {type, 0});
    it->second += block.num_elements();
  }
  std::string text;
  for (const auto& [type, n] : counts)
    text += (text.empty() ? "" : ", ") + std::to_string(n) + " " + type;
  return text;
}

/// Build the mesh of `kind` from the command line.
grout::Mesh generate(const std::string& kind, int argc, char** argv, std::string& output) {
  if (kind == "rectangle") {
    const Options o(
        argc, argv,
        {"--nx", "--ny", "--x0", "--x1", "--y0", "--y1", "--distortion", "--seed", "--block"},
        {"--triangles"});
    output = o.text("--output", "");
    return grout::rectangle_mesh(
        int(o.integer("--nx", 4)), int(o.integer("--ny", 4)), o.real("--x0", 0), o.real("--x1", 1),
        o.real("--y0", 0), o.real("--y1", 1), o.flag("--triangles"), o.real("--distortion", 0),
        o.integer("--seed", 1, 0), o.text("--block", "block"));
  }
  if (kind == "box") {
    const Options o(argc, argv,
                    {"--nx", "--ny", "--nz", "--x0", "--x1", "--y0", "--y1", "--z0", "--z1",
                     "--distortion", "--seed", "--block"},
                    {"--tetrahedra"});
    output = o.text("--output", "");
    const grout::BoxBounds bounds{o.real("--x0", 0), o.real("--x1", 1), o.real("--y0", 0),
                                  o.real("--y1", 1), o.real("--z0", 0), o.real("--z1", 1)};
    return grout::box_mesh(int(o.integer("--nx", 4)), int(o.integer("--ny", 4)),
                           int(o.integer("--nz", 4)), bounds, o.flag("--tetrahedra"),
                           o.real("--distortion", 0), o.integer("--seed", 1, 0),
                           o.text("--block", "block"));
  }
  if (kind == "quarter_annulus") {
    const Options o(argc, argv, {"--n-radial", "--n-circ", "--r-inner", "--r-outer", "--block"},
                    {});
    output = o.text("--output", "");
    return grout::quarter_annulus_mesh(int(o.integer("--n-radial", 4)),
                                       int(o.integer("--n-circ", 8)), o.real("--r-inner", 1),
                                       o.real("--r-outer", 2), o.text("--block", "block"));
  }
  if (kind == "two_blocks_2d") {
    const Options o(argc, argv, {"--nx-lower", "--ny-lower", "--nx-upper", "--ny-upper", "--gap"},
                    {"--triangles"});
    output = o.text("--output", "");
    return grout::two_block_mesh_2d(
        int(o.integer("--nx-lower", 4)), int(o.integer("--ny-lower", 4)),
        int(o.integer("--nx-upper", 5)), int(o.integer("--ny-upper", 5)), o.flag("--triangles"),
        o.real("--gap", 0));
  }
  if (kind == "two_blocks_3d") {
    const Options o(argc, argv,
                    {"--nx-lower", "--ny-lower", "--nz-lower", "--nx-upper", "--ny-upper",
                     "--nz-upper", "--gap"},
                    {"--tetrahedra"});
    output = o.text("--output", "");
    return grout::two_block_mesh_3d(
        int(o.integer("--nx-lower", 4)), int(o.integer("--ny-lower", 4)),
        int(o.integer("--nz-lower", 4)), int(o.integer("--nx-upper", 5)),
        int(o.integer("--ny-upper", 5)), int(o.integer("--nz-upper", 5)), o.flag("--tetrahedra"),
        o.real("--gap", 0));
  }
  if (kind == "stacked_2d" || kind == "stacked_3d") {
    const bool three = kind == "stacked_3d";
    const std::string simplex = three ? "--tetrahedra" : "--triangles";
    std::set<std::string> valued = {
        "--nx-lower",     "--ny-lower",     "--nx-upper", "--ny-upper",   "--width",
        "--height-lower", "--height-upper", "--gap",      "--distortion", "--seed"};
    if (three) valued.insert({"--nz-lower", "--nz-upper"});
    const Options o(argc, argv, valued, {simplex + "-lower", simplex + "-upper"});
    output = o.text("--output", "");
    grout::StackedBlocks s;
    s.nx_lower = int(o.integer("--nx-lower", 4));
    s.ny_lower = int(o.integer("--ny-lower", 4));
    s.nz_lower = int(o.integer("--nz-lower", 4));
    s.nx_upper = int(o.integer("--nx-upper", 5));
    s.ny_upper = int(o.integer("--ny-upper", 5));
    s.nz_upper = int(o.integer("--nz-upper", 5));
    s.width = o.real("--width", 1);
    s.height_lower = o.real("--height-lower", 1);
    s.height_upper = o.real("--height-upper", 1);
    s.gap = o.real("--gap", 0);
    s.simplex_lower = o.flag(simplex + "-lower");
    s.simplex_upper = o.flag(simplex + "-upper");
    s.distortion = o.real("--distortion", 0);
    s.seed = o.integer("--seed", 1, 0);
    return three ? grout::stacked_blocks_3d(s) : grout::stacked_blocks_2d(s);
  }
  if (kind == "sloped_blocks_2d") {
    const Options o(argc, argv,
                    {"--nx-lower", "--ny-lower", "--nx-upper", "--ny-upper", "--width", "--y-left",
                     "--y-right", "--height"},
                    {"--triangles-lower", "--triangles-upper"});
    output = o.text("--output", "");
    grout::SlopedBlocks s;
    s.nx_lower = int(o.integer("--nx-lower", 4));
    s.ny_lower = int(o.integer("--ny-lower", 3));
    s.nx_upper = int(o.integer("--nx-upper", 5));
    s.ny_upper = int(o.integer("--ny-upper", 3));
    s.width = o.real("--width", 1);
    s.y_left = o.real("--y-left", 0.9);
    s.y_right = o.real("--y-right", 1.1);
    s.height = o.real("--height", 2);
    s.triangles_lower = o.flag("--triangles-lower");
    s.triangles_upper = o.flag("--triangles-upper");
    return grout::sloped_blocks_2d(s);
  }
  if (kind == "taylor_patch_2d") {
    const Options o(argc, argv,
                    {"--nx-block", "--ny-block", "--nx-die", "--ny-die", "--die-stretch"},
                    {"--triangles-block", "--triangles-die"});
    output = o.text("--output", "");
    grout::TaylorPatch s;
    s.nx_block = int(o.integer("--nx-block", 8));
    s.ny_block = int(o.integer("--ny-block", 4));
    s.nx_die = int(o.integer("--nx-die", 3));
    s.ny_die = int(o.integer("--ny-die", 2));
    s.die_stretch = o.real("--die-stretch", 0);
    s.simplex_block = o.flag("--triangles-block");
    s.simplex_die = o.flag("--triangles-die");
    return grout::taylor_patch_2d(s);
  }
  if (kind == "taylor_patch_3d") {
    const Options o(argc, argv,
                    {"--nx-block", "--ny-block", "--nz-block", "--nx-die", "--ny-die", "--nz-die"},
                    {"--tetrahedra-block", "--tetrahedra-die"});
    output = o.text("--output", "");
    grout::TaylorPatch s;
    s.nx_block = int(o.integer("--nx-block", 8));
    s.ny_block = int(o.integer("--ny-block", 8));
    s.nz_block = int(o.integer("--nz-block", 4));
    s.nx_die = int(o.integer("--nx-die", 3));
    s.ny_die = int(o.integer("--ny-die", 3));
    s.nz_die = int(o.integer("--nz-die", 2));
    s.simplex_block = o.flag("--tetrahedra-block");
    s.simplex_die = o.flag("--tetrahedra-die");
    return grout::taylor_patch_3d(s);
  }
  if (kind == "hertz_cylinders") {
    const Options o(argc, argv, {"--level", "--radius", "--gap", "--contact-width"}, {});
    output = o.text("--output", "");
    return grout::hertz_cylinders_mesh(int(o.integer("--level", 1)), o.real("--radius", 8),
                                       o.real("--gap", 0), o.real("--contact-width", 2.5));
  }
  if (kind == "cylinder_on_plane") {
    const Options o(argc, argv, {"--level", "--radius", "--contact-width"}, {});
    output = o.text("--output", "");
    return grout::cylinder_on_plane_mesh(int(o.integer("--level", 1)), o.real("--radius", 6.1237),
                                         o.real("--contact-width", 2.5));
  }
  if (kind == "sphere_on_plane_axisymmetric") {
    const Options o(argc, argv, {"--level", "--radius", "--contact-width"}, {});
    output = o.text("--output", "");
    return grout::sphere_on_plane_axisymmetric_mesh(
        int(o.integer("--level", 1)), o.real("--radius", 6.1237), o.real("--contact-width", 2.5));
  }
  if (kind == "quarter_disc") {
    const Options o(argc, argv, {"--level", "--radius"}, {});
    output = o.text("--output", "");
    return grout::quarter_disc_mesh(int(o.integer("--level", 1)), o.real("--radius", 1.0));
  }
  if (kind == "dong_blocks") {
    const Options o(argc, argv,
                    {"--nx-lower", "--ny-lower", "--nx-upper", "--ny-upper", "--width-lower",
                     "--height-lower", "--width-upper", "--height-upper", "--x-upper", "--gap"},
                    {"--triangles-lower", "--triangles-upper"});
    output = o.text("--output", "");
    grout::DongBlocks s;
    s.nx_lower = int(o.integer("--nx-lower", s.nx_lower));
    s.ny_lower = int(o.integer("--ny-lower", s.ny_lower));
    s.nx_upper = int(o.integer("--nx-upper", s.nx_upper));
    s.ny_upper = int(o.integer("--ny-upper", s.ny_upper));
    s.width_lower = o.real("--width-lower", s.width_lower);
    s.height_lower = o.real("--height-lower", s.height_lower);
    s.width_upper = o.real("--width-upper", s.width_upper);
    s.height_upper = o.real("--height-upper", s.height_upper);
    s.x_upper = o.real("--x-upper", s.x_upper);
    s.gap = o.real("--gap", s.gap);
    s.triangles_lower = o.flag("--triangles-lower");
    s.triangles_upper = o.flag("--triangles-upper");
    return grout::dong_blocks_2d(s);
  }
  if (kind == "hertz_cylinders_pinned") {
    const Options o(argc, argv, {"--level", "--radius", "--gap", "--contact-width"}, {});
    output = o.text("--output", "");
    return grout::hertz_cylinders_pinned(int(o.integer("--level", 1)), o.real("--radius", 8),
                                         o.real("--gap", 0), o.real("--contact-width", 2.5));
  }
  throw UsageError("unknown mesh kind '" + kind + "'");
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::cerr << usage_text;
    return 2;
  }
  const std::string kind = argv[1];
  if (kind == "-h" || kind == "--help") {
    std::cout << usage_text;
    return 0;
  }
  grout::Mesh mesh;
  std::string output;
  try {
    mesh = generate(kind, argc, argv, output);
  } catch (const UsageError& e) {
    std::cerr << "grout_mesh: " << e.what() << "\n\n" << usage_text;
    return 2;
  } catch (const std::invalid_argument& e) {  // a generator rejected the parameters
    std::cerr << "grout_mesh: " << e.what() << "\n";
    return 2;
  }
  try {
    grout::name_node_sets_apart(mesh);  // a side set "top" and its node set "top_nodes"
  } catch (const std::invalid_argument& e) {
    std::cerr << "grout_mesh: " << e.what() << "\n";
    return 2;
  }
  try {
    grout::write_exodus_mesh(output, mesh);
  } catch (const grout::InputError& e) {
    std::cerr << "grout_mesh: " << e.what() << "\n";
    return 1;
  }
  std::cout << "grout_mesh: wrote " << output << " (" << kind << ", " << mesh.dimension << "D, "
            << mesh.num_nodes() << " nodes, " << mesh.num_elements() << " elements ("
            << element_counts(mesh) << ") in " << mesh.blocks.size() << " block(s), "
            << mesh.side_sets.size() << " side sets, " << mesh.node_sets.size() << " node sets)\n";
  return 0;
}
