#pragma once
// The files a run writes: checked before anything is computed, written under temporary
// names, renamed into place at the first converged step. A run that fails earlier leaves
// the previous results (and every input) as they were.

#include <fstream>
#include <string>
#include <vector>

#include "io/input.hpp"

namespace grout {

struct OutputFile {
  std::string key;        ///< the input key that names it ("grout/output/summary")
  std::string path;       ///< where it ends up
  std::string temporary;  ///< where it is written until the first converged step
};

/// \brief Every file the run writes: the Exodus file; with a summary, the summary, its
/// `_newton.csv` and (2D contact) its `_contact.csv`. The temporary name of `dir/name` is
/// `dir/.name.partial`. Under `output/parallel: per_rank` these are the files rank `rank` of
/// `ranks` writes: its own Exodus file (spread_file_name) and, on rank 0, the CSV files.
std::vector<OutputFile> output_files(const Input& input, bool contact_profile, int rank = 0,
                                     int ranks = 1);

/// \brief The name of rank `rank`'s file in a set of `ranks` files (SEACAS's spread naming,
/// as decomp and IOSS write them): `<path>.<ranks>.<rank>`, the rank zero-padded to the
/// number of digits of `ranks` (`case.e.2.1`, `case.e.12.03`); a set of one file is `path`
/// itself (as IOSS names it: ParaView's IOSS reader opens `case.e.1.0` as `case.e`).
std::string spread_file_name(const std::string& path, int ranks, int rank);

/// \brief How errors name a file being written: `dir/.name.partial` (a temporary of
/// output_files) is "dir/name (written as 'dir/.name.partial' until the first step)", so that a
/// message names the output the user asked for; any other path is returned as it is.
std::string output_name(const std::string& path);

/// \brief Refuses (InputError naming the input file and key) an output whose folder does not
/// exist or is not a folder, that exists and is not a regular file (a folder, a device, a
/// pipe), or that is the same file as an input (the YAML, the mesh) or as another output, or
/// whose temporary is an input or another output.
void check_output_files(const Input& input, const std::vector<OutputFile>& files);

/// A text file written line by line: every write is flushed and checked (a full disk is an
/// error naming the file, not a truncated file and exit 0).
class CheckedTextFile {
 public:
  CheckedTextFile() = default;
  /// Creates (truncates) `path`; `name` is what errors call it (defaults to `path`).
  explicit CheckedTextFile(const std::string& path, const std::string& name = "");
  bool is_open() const { return stream_.is_open(); }
  /// Writes `text`, flushes, and throws InputError when the file did not take it.
  void write(const std::string& text);

 private:
  std::ofstream stream_;
  std::string name_;
};

/// Moves the temporary files into place once (commit); removes them if destroyed before.
class OutputCommit {
 public:
  explicit OutputCommit(std::vector<OutputFile> files) : files_(std::move(files)) {}
  ~OutputCommit();
  OutputCommit(const OutputCommit&) = delete;
  OutputCommit& operator=(const OutputCommit&) = delete;
  /// Renames every temporary file to its final name (no-op after the first call); throws
  /// InputError naming the file when a rename fails.
  void commit();
  bool committed() const { return committed_; }

 private:
  std::vector<OutputFile> files_;
  bool committed_ = false;
};

}  // namespace grout
