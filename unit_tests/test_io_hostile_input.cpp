// Hostile input: the readers refuse what would cost unbounded time or memory, and naming a
// YAML error never fails itself. Inputs that the fuzzers found are replayed by the ctest
// entries fuzz/replay/* (fuzz/regressions/).

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "io/errors.hpp"
#include "io/exodus.hpp"
#include "io/input.hpp"
#include "io/netcdf_header.hpp"
#include "io/output_files.hpp"

namespace grout {
namespace {

const std::filesystem::path test_dir =
    std::filesystem::path(GROUT_BINARY_DIR) / "unit_tests" / "test_io_hostile_input";

/// The InputError message of `action` ("" and a test failure when it does not throw one).
std::string input_error(const std::function<void()>& action) {
  try {
    action();
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected an InputError";
  return "";
}

void expect_contains(const std::string& message, const std::vector<std::string>& parts) {
  for (const std::string& part : parts) {
    EXPECT_NE(message.find(part), std::string::npos)
        << "message: " << message << "\nlacks:   " << part;
  }
}

const std::string minimal = R"yaml(grout:
  mesh: {file: mesh.exo}
  model: {dimension: 2}
  materials:
    steel: {block: body, law: linear_elastic, youngs_modulus: 200, poissons_ratio: 0.3}
)yaml";

// Teuchos' message for `printf 'grout:\n  mesh: {file: a, b\nExpected one of\n'`: the echo of
// the input line is itself "Expected one of", which once made the cleaner read past its end.
const std::string parser_failure =
    "error: Parser failure at line 3 column 1 of parseYamlStream\n"
    "Expected one of\n"
    "Expected one of {:}\n"
    "Got: NEWLINE\n"
    "Lexer text: \"\n\"\n"
    "Parser was in state 139\n";

TEST(YamlMessage, InputLineLikeAHeadingIsNotReadAsOne) {
  EXPECT_EQ(clean_yaml_message(parser_failure, "case.yaml"),
            "case.yaml: YAML error: line 3, column 1: expected one of {:}, got NEWLINE");
}

TEST(YamlMessage, TruncatedMessagesDoNotThrow) {
  for (const std::string what :
       {"", "\n", "Expected one of", "Got:", "Expected one of\nGot:", "error: ",
        "error: Parser failure at line 1 column 1 of x", "Throw test that evaluated to true",
        "error: Parser failure at line 9 column 9 of x\nExpected one of\nExpected one of"}) {
    SCOPED_TRACE(what);
    std::string message;
    EXPECT_NO_THROW(message = clean_yaml_message(what, "case.yaml"));
    EXPECT_EQ(message.rfind("case.yaml: YAML error: ", 0), 0u) << message;
  }
}

TEST(YamlMessage, ReaderNamesTheLineOfTheFuzzedInput) {
  const std::string message = input_error(
      [] { read_input_text("grout:\n  mesh: {file: a, b\nExpected one of\n", "fuzzed.yaml"); });
  expect_contains(message, {"fuzzed.yaml: YAML error: line 3, column 1: expected one of"});
}

TEST(InputLimits, LongLineIsRefusedNamingTheLimit) {
  // A 1 MB string value took 23 s in the YAML lexer (quadratic in a token's length).
  const std::string before = "  output: {file: \"", after = "\"}";
  const std::string value(max_input_line_length + 1 - before.size() - after.size(), 'a');
  const std::string text = minimal + before + value + after + "\n";
  expect_contains(input_error([&] { read_input_text(text, "long.yaml"); }),
                  {"long.yaml: line 6 has 4097 characters, more than the limit of 4096"});
  // One character less is accepted (and a comment line of the same length too).
  const std::string ok = minimal + before + value.substr(1) + after + "\n# " +
                         std::string(max_input_line_length - 2, '#') + "\n";
  EXPECT_EQ(read_input_text(ok, "long.yaml").output.file, value.substr(1));
}

TEST(InputLimits, LargeFileIsRefusedBeforeItIsRead) {
  std::filesystem::create_directories(test_dir);
  const std::string path = (test_dir / "large.yaml").string();
  {
    std::ofstream file(path);
    file << minimal;
    const std::string comment = "# " + std::string(78, '-') + "\n";
    for (std::size_t size = minimal.size(); size <= max_input_bytes; size += comment.size())
      file << comment;
  }
  expect_contains(input_error([&] { read_input(path); }),
                  {"large.yaml: the input file has more than 262144 bytes"});
  // The same text given in memory.
  std::ifstream in(path);
  const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  expect_contains(input_error([&] { read_input_text(text, "large.yaml"); }),
                  {"more than 262144 bytes"});
}

TEST(InputLimits, CollocationPointsAreBounded) {
  const std::string pair =
      "  contact:\n    pair: {slave: a, master: b, type: frictionless, integration: "
      "collocation, collocation_points: ";
  expect_contains(
      input_error([&] { read_input_text(minimal + pair + "2000000000}\n", "c.yaml"); }),
      {"c.yaml: grout/contact/pair/collocation_points: expected an integer in [1, 1000]",
       "2000000000"});
  EXPECT_EQ(read_input_text(minimal + pair + "1000}\n", "c.yaml").contact.at(0).collocation_points,
            1000);
}

TEST(InputLimits, TextAndFileReadersAgree) {
  std::filesystem::create_directories(test_dir);
  const std::string path = (test_dir / "same.yaml").string();
  std::ofstream(path) << minimal;
  const Input from_file = read_input(path);
  const Input from_text = read_input_text(minimal, path);
  EXPECT_EQ(from_file.mesh_file, from_text.mesh_file);
  EXPECT_EQ(from_file.output.file, from_text.output.file);
  EXPECT_EQ(from_file.materials.at(0).youngs_modulus, from_text.materials.at(0).youngs_modulus);
}

/// The seed mesh fuzz/corpus/exodus/quad4.exo with the 4 bytes after `name`'s padded text
/// (or, with `before`, the 4 bytes before it: its length) set to `value`, written to `file`.
std::string corrupted_mesh(const std::string& file, const std::string& name, uint32_t value,
                           bool before = false) {
  std::ifstream in(std::string(GROUT_SOURCE_DIR) + "/fuzz/corpus/exodus/quad4.exo",
                   std::ios::binary);
  std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  const std::size_t at = bytes.find(name);
  EXPECT_NE(at, std::string::npos) << name;
  const std::size_t where = before ? at - 4 : at + (name.size() + 3) / 4 * 4;
  for (int i = 0; i < 4; ++i) bytes[where + i] = char((value >> (24 - 8 * i)) & 0xff);
  std::filesystem::create_directories(test_dir);
  const std::string path = (test_dir / file).string();
  std::ofstream(path, std::ios::binary) << bytes;
  return path;
}

TEST(ExodusLimits, SeedMeshPassesTheHeaderCheck) {
  const std::string path = std::string(GROUT_SOURCE_DIR) + "/fuzz/corpus/exodus/quad4.exo";
  EXPECT_NO_THROW(check_netcdf_header(path));
  EXPECT_EQ(read_exodus(path).num_nodes(), 9);
}

TEST(ExodusLimits, DimensionBeyondTheFileIsRefused) {
  // One flipped byte of the node count: 9 -> 2^30 nodes.
  const std::string path = corrupted_mesh("nodes.exo", "num_nodes", 0x40000000u);
  expect_contains(input_error([&] { read_exodus(path); }),
                  {"nodes.exo: corrupt netCDF header: variable", "1073741824 values",
                   "past the end of the file"});
}

TEST(ExodusLimits, NameLengthBeyondTheFileIsRefused) {
  // A name length of 1.6e9 made netCDF allocate 1.6 GB while opening the file.
  const std::string path = corrupted_mesh("name.exo", "num_nodes", 1601401957u, true);
  expect_contains(input_error([&] { read_exodus(path); }),
                  {"name.exo: corrupt netCDF header: dimension name of 1601401957 bytes runs "
                   "past the end of the file"});
}

TEST(ExodusLimits, RepeatedVariableNameIsRefused) {
  // One flipped bit of the seed mesh (side_ss2 -> side_ss3, inputs/hostile_input): two
  // variables of one name made Exodus read a side set into an array of another's size.
  const std::string path = std::string(GROUT_SOURCE_DIR) +
                           "/fuzz/regressions/exodus/repeated_variable_name_side_ss3.exo";
  expect_contains(input_error([&] { read_exodus(path); }),
                  {"repeated_variable_name_side_ss3.exo: corrupt netCDF header: variable "
                   "'side_ss3' is defined twice"});
}

/// One HEX8 on the unit cube with node 7 moved to (0.573, 0.573, 0.573): det J > 0 at the
/// 2x2x2 Gauss points of the stiffness, < 0 at a point of the mass matrix's 3x3x3 rule
/// (inputs/hostile_input/hostile_meshes.py finds the same node by search).
Mesh hex_inverted_at_the_mass_points() {
  Mesh mesh;
  mesh.file = "hex.exo";
  mesh.dimension = 3;
  mesh.coordinates = {0, 0, 0, 1, 0, 0, 1,     1,     0,     0, 1, 0,
                      0, 0, 1, 1, 0, 1, 0.573, 0.573, 0.573, 0, 1, 1};
  ElementBlock block;
  block.name = "body";
  block.id = 1;
  block.topology = Topology::hex8;
  block.nodes_per_element = 8;
  block.connectivity = {0, 1, 2, 3, 4, 5, 6, 7};
  mesh.blocks.push_back(block);
  return mesh;
}

TEST(MeshLimits, ElementInvertedOnlyAtTheMassPointsIsRefused) {
  const Mesh mesh = hex_inverted_at_the_mass_points();
  expect_contains(input_error([&] { check_mesh(mesh); }),
                  {"mesh 'hex.exo': block 'body', element 1 (global element 1): inverted",
                   "mass matrix's Gauss rule of degree 4"});
  Mesh moved_less = mesh;  // node 7 at 0.7: positive everywhere
  for (int d = 0; d < 3; ++d) moved_less.coordinates[6 * 3 + d] = 0.7;
  EXPECT_NO_THROW(check_mesh(moved_less));
}

TEST(MeshLimits, HugeCoordinateIsOutOfRangeNotDegenerate) {
  Mesh mesh = hex_inverted_at_the_mass_points();
  mesh.coordinates[6 * 3 + 0] = mesh.coordinates[6 * 3 + 1] = mesh.coordinates[6 * 3 + 2] = 1.0;
  mesh.coordinates[0] = 1e300;  // was "degenerate (zero volume, det J = 6.6e+298)"
  expect_contains(input_error([&] { check_mesh(mesh); }),
                  {"element 1 (global element 1): a node coordinate is out of range (node 1, "
                   "x = 1e+300; at most 1e+100 in magnitude)"});
  mesh.coordinates[0] = 1e100;  // the largest allowed: volumes stay finite, and the element
  // (one node 1e100 away) is degenerate relative to its size
  expect_contains(input_error([&] { check_mesh(mesh); }), {"degenerate (zero volume"});
}

TEST(OutputLimits, TemporaryOfAnOutputMayNotBeAnInput) {
  std::filesystem::create_directories(test_dir);
  Input input;
  input.file = (test_dir / ".case.e.partial").string();  // the Exodus output's temporary
  input.mesh_file = (test_dir / "mesh.exo").string();
  input.output.file = (test_dir / "case.e").string();
  std::ofstream(input.file) << "grout: {}\n";
  std::ofstream(input.mesh_file) << "mesh";
  expect_contains(input_error([&] { check_output_files(input, output_files(input, false)); }),
                  {"grout/output/file: '" + input.output.file + "' is written first as '" +
                   input.file + "', which is the input file itself"});
  input.file = (test_dir / "case.yaml").string();
  input.mesh_file = (test_dir / ".res.csv.partial").string();  // the summary's temporary
  input.output.summary = (test_dir / "res.csv").string();
  std::ofstream(input.mesh_file) << "mesh";
  expect_contains(input_error([&] { check_output_files(input, output_files(input, false)); }),
                  {"grout/output/summary: '" + input.output.summary + "' is written first as '" +
                   input.mesh_file + "', which is the mesh file"});
  input.mesh_file = (test_dir / "mesh.exo").string();
  EXPECT_NO_THROW(check_output_files(input, output_files(input, false)));
}

TEST(OutputLimits, ErrorsNameTheOutputNotItsTemporary) {
  EXPECT_EQ(output_name("out/.case.e.partial"),
            "out/case.e (written as 'out/.case.e.partial' until the first step)");
  EXPECT_EQ(output_name("out/case.e"), "out/case.e");
  EXPECT_EQ(output_name(".partial"), ".partial");
  // A folder the Exodus file cannot be created in: the output's name and the reason.
  try {
    Mesh mesh = hex_inverted_at_the_mass_points();
    ExodusWriter writer("/proc/no_such_folder/.case.e.partial", mesh, {"u"}, {}, {});
    ADD_FAILURE() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "/proc/no_such_folder/case.e (written as '/proc/no_such_folder/.case.e.partial' "
              "until the first step): cannot create Exodus file (No such file or directory)");
  }
}

}  // namespace
}  // namespace grout
