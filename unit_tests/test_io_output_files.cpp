// Output safety: which files a run writes, the checks before writing, checked writes (a full
// disk is an error) and the move into place at the first converged step.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "io/errors.hpp"
#include "io/output_files.hpp"

namespace grout {
namespace {

namespace fs = std::filesystem;

const fs::path test_dir = fs::path(GROUT_BINARY_DIR) / "unit_tests" / "test_io_output_files";

std::string in_test_dir(const std::string& name) {
  return (test_dir / name).string();
}

void write_text(const std::string& path, const std::string& text) {
  std::ofstream(path) << text;
}

std::string read_text(const std::string& path) {
  std::ifstream file(path);
  return {std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
}

Input input_in_test_dir() {
  fs::create_directories(test_dir);
  Input input;
  input.file = in_test_dir("case.yaml");
  input.mesh_file = in_test_dir("mesh.exo");
  write_text(input.file, "grout:\n");
  write_text(input.mesh_file, "mesh");
  input.output.file = in_test_dir("case.e");
  input.output.summary = in_test_dir("case.csv");
  return input;
}

void expect_refused(const Input& input, const std::string& expected) {
  try {
    check_output_files(input, output_files(input, true));
    ADD_FAILURE() << "expected InputError: " << expected;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(expected), std::string::npos)
        << "message: " << e.what() << "\nlacks:   " << expected;
  }
}

TEST(OutputFiles, EveryFileWithItsTemporaryName) {
  const Input input = input_in_test_dir();
  const auto files = output_files(input, true);
  ASSERT_EQ(files.size(), 4u);
  EXPECT_EQ(files[0].path, in_test_dir("case.e"));
  EXPECT_EQ(files[0].temporary, in_test_dir(".case.e.partial"));
  EXPECT_EQ(files[2].path, in_test_dir("case_newton.csv"));
  EXPECT_EQ(files[3].path, in_test_dir("case_contact.csv"));
  EXPECT_NO_THROW(check_output_files(input, files));
}

// SEACAS's spread naming (decomp, IOSS): <file>.<ranks>.<rank>, the rank zero-padded to the
// digits of the rank count.
TEST(OutputFiles, SpreadNamesPadTheRankToTheDigitsOfTheRankCount) {
  EXPECT_EQ(spread_file_name("out/case.e", 1, 0), "out/case.e");  // IOSS: one file, no suffix
  EXPECT_EQ(spread_file_name("case.e", 2, 1), "case.e.2.1");
  EXPECT_EQ(spread_file_name("case.e", 10, 3), "case.e.10.03");
  EXPECT_EQ(spread_file_name("case.e", 12, 11), "case.e.12.11");
  EXPECT_EQ(spread_file_name("case.e", 100, 7), "case.e.100.007");
}

// output/parallel: per_rank: each rank its own Exodus file (with its temporary), the CSV files
// on rank 0 only.
TEST(OutputFiles, PerRankEachRankItsExodusFileAndRankZeroTheSummaries) {
  Input input = input_in_test_dir();
  input.output.parallel = OutputParallel::per_rank;
  const auto zero = output_files(input, true, 0, 3);
  ASSERT_EQ(zero.size(), 4u);
  EXPECT_EQ(zero[0].path, in_test_dir("case.e.3.0"));
  EXPECT_EQ(zero[0].temporary, in_test_dir(".case.e.3.0.partial"));
  EXPECT_EQ(zero[1].path, in_test_dir("case.csv"));
  const auto two = output_files(input, true, 2, 3);
  ASSERT_EQ(two.size(), 1u);
  EXPECT_EQ(two[0].path, in_test_dir("case.e.3.2"));
  EXPECT_NE(two[0].key.find("rank 2"), std::string::npos) << two[0].key;
  EXPECT_NO_THROW(check_output_files(input, zero));
}

TEST(OutputFiles, RefusesInputsOtherOutputsAndWhatIsNotARegularFile) {
  Input input = input_in_test_dir();
  input.output.summary = input.mesh_file;
  expect_refused(input, "case.yaml: grout/output/summary: '" + input.mesh_file +
                            "' is the mesh file (grout/mesh/file)");
  input = input_in_test_dir();
  input.output.file = in_test_dir("sub/../case.yaml");  // the input, spelt differently
  expect_refused(input, "grout/output/file: '" + input.output.file + "' is the input file itself");
  input = input_in_test_dir();
  input.output.summary = input.output.file;
  expect_refused(input, "grout/output/summary: '" + input.output.file +
                            "' is also written as grout/output/file");
  input = input_in_test_dir();
  input.output.file = in_test_dir("case_newton.csv");  // the summary's Newton log
  expect_refused(input, "(its Newton log): '" + in_test_dir("case_newton.csv") +
                            "' is also written as grout/output/file");
  input = input_in_test_dir();
  input.output.file = "/dev/null";
  expect_refused(input, "grout/output/file: '/dev/null' exists and is not a regular file");
  input = input_in_test_dir();
  input.output.file = test_dir.string();  // a folder
  expect_refused(input, "exists and is not a regular file");
  input = input_in_test_dir();
  input.output.file = in_test_dir("no_such_folder/case.e");
  expect_refused(input, "is in a folder that does not exist");
  input = input_in_test_dir();
  input.output.file = in_test_dir("case.yaml/case.e");  // under a regular file
  expect_refused(input, "not a folder");
}

TEST(OutputFiles, AFullDiskIsAnErrorNamingTheFile) {
  CheckedTextFile full("/dev/full", "summary.csv");
  try {
    full.write("step,time\n");
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "summary.csv: write failed (No space left on device)");
  }
}

TEST(OutputFiles, PreviousResultsStayUntilTheFirstCommit) {
  const Input input = input_in_test_dir();
  const auto files = output_files(input, false);
  write_text(input.output.summary, "previous results");
  {  // a run that fails before its first converged step
    OutputCommit commit(files);
    CheckedTextFile summary(files[1].temporary, files[1].path);
    summary.write("new");
  }
  EXPECT_EQ(read_text(input.output.summary), "previous results");
  EXPECT_FALSE(fs::exists(files[1].temporary));
  {  // a run that converges a step
    OutputCommit commit(files);
    CheckedTextFile summary(files[1].temporary, files[1].path);
    summary.write("step 1\n");
    commit.commit();
    summary.write("step 2\n");  // still the same (renamed) file
  }
  EXPECT_EQ(read_text(input.output.summary), "step 1\nstep 2\n");
  EXPECT_FALSE(fs::exists(files[1].temporary));
}

}  // namespace
}  // namespace grout
