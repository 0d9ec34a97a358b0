#include "io/output_files.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>

#include "io/errors.hpp"

namespace grout {

namespace fs = std::filesystem;

namespace {

constexpr const char* temporary_suffix = ".partial";

std::string temporary_name(const std::string& path) {
  const fs::path p(path);
  return (p.parent_path() / ("." + p.filename().string() + temporary_suffix)).string();
}

/// The same file: the same inode when both exist, else the same normalised absolute path.
bool same_file(const std::string& a, const std::string& b) {
  std::error_code error;
  if (fs::exists(a, error) && fs::exists(b, error)) return fs::equivalent(a, b, error);
  return fs::weakly_canonical(fs::absolute(a), error) ==
         fs::weakly_canonical(fs::absolute(b), error);
}

}  // namespace

std::string output_name(const std::string& path) {
  const fs::path p(path);
  const std::string name = p.filename().string(), suffix = temporary_suffix;
  if (name.size() <= 1 + suffix.size() || name[0] != '.' ||
      name.compare(name.size() - suffix.size(), suffix.size(), suffix) != 0)
    return path;
  const std::string final_name = name.substr(1, name.size() - 1 - suffix.size());
  return (p.parent_path() / final_name).string() + " (written as '" + path +
         "' until the first step)";
}

std::string spread_file_name(const std::string& path, int ranks, int rank) {
  if (ranks == 1) return path;  // IOSS opens a set of one as the plain name
  std::string number = std::to_string(rank);
  const std::size_t width = std::to_string(ranks).size();
  if (number.size() < width) number.insert(0, width - number.size(), '0');
  return path + "." + std::to_string(ranks) + "." + number;
}

std::vector<OutputFile> output_files(const Input& input, bool contact_profile, int rank,
                                     int ranks) {
  std::vector<OutputFile> files = {{"grout/output/file", input.output.file, ""}};
  if (input.output.parallel == OutputParallel::per_rank) {
    files[0].key += " (rank " + std::to_string(rank) + "'s file of output/parallel: per_rank)";
    files[0].path = spread_file_name(input.output.file, ranks, rank);
  }
  if (!input.output.summary.empty() && rank == 0) {
    const std::string& summary = input.output.summary;
    const auto dot = summary.rfind('.');
    const auto slash = summary.rfind('/');
    const bool has_extension =
        dot != std::string::npos && (slash == std::string::npos || dot > slash);
    const std::string stem = has_extension ? summary.substr(0, dot) : summary;
    files.push_back({"grout/output/summary", summary, ""});
    files.push_back({"grout/output/summary (its Newton log)", stem + "_newton.csv", ""});
    if (contact_profile)
      files.push_back({"grout/output/summary (its contact profile)", stem + "_contact.csv", ""});
  }
  for (OutputFile& f : files) f.temporary = temporary_name(f.path);
  return files;
}

void check_output_files(const Input& input, const std::vector<OutputFile>& files) {
  const auto fail = [&](const OutputFile& f, const std::string& message) {
    throw InputError(input.file + ": " + f.key + ": '" + f.path + "' " + message);
  };
  for (std::size_t i = 0; i < files.size(); ++i) {
    const OutputFile& f = files[i];
    if (same_file(f.path, input.file)) fail(f, "is the input file itself");
    if (same_file(f.path, input.mesh_file)) fail(f, "is the mesh file (grout/mesh/file)");
    for (std::size_t j = 0; j < i; ++j) {
      if (same_file(f.path, files[j].path)) fail(f, "is also written as " + files[j].key);
    }
    // The temporary is truncated at the start and renamed away at the first step: it must not
    // be an input or another output either.
    const std::string temporary = "is written first as '" + f.temporary + "', which ";
    if (same_file(f.temporary, input.file))
      fail(f, temporary + "is the input file itself ('" + input.file + "')");
    if (same_file(f.temporary, input.mesh_file))
      fail(f, temporary + "is the mesh file '" + input.mesh_file + "' (grout/mesh/file)");
    for (std::size_t j = 0; j < files.size(); ++j) {
      if (j != i && same_file(f.temporary, files[j].path))
        fail(f, temporary + "is also written as " + files[j].key + " ('" + files[j].path + "')");
    }
    std::error_code error;
    const fs::path folder =
        fs::path(f.path).parent_path().empty() ? fs::path(".") : fs::path(f.path).parent_path();
    if (!fs::exists(folder, error)) fail(f, "is in a folder that does not exist");
    if (!fs::is_directory(folder, error)) fail(f, "is in '" + folder.string() + "', not a folder");
    const auto status = fs::symlink_status(f.path, error);
    if (fs::exists(status) && !fs::is_regular_file(fs::status(f.path, error))) {
      fail(f, "exists and is not a regular file (a folder, device or pipe): not overwritten");
    }
  }
}

CheckedTextFile::CheckedTextFile(const std::string& path, const std::string& name)
    : stream_(path, std::ios::out | std::ios::trunc), name_(name.empty() ? path : name) {
  if (!stream_) {
    throw InputError(name_ + ": cannot create the file (" + std::strerror(errno) + ")");
  }
}

void CheckedTextFile::write(const std::string& text) {
  errno = 0;
  stream_ << text << std::flush;
  if (!stream_) {
    const int code = errno;
    throw InputError(name_ + ": write failed (" +
                     (code ? std::strerror(code) : std::string("stream error")) + ")");
  }
}

OutputCommit::~OutputCommit() {
  if (committed_) return;
  std::error_code ignored;
  for (const OutputFile& f : files_) fs::remove(f.temporary, ignored);
}

void OutputCommit::commit() {
  if (committed_) return;
  for (const OutputFile& f : files_) {
    std::error_code error;
    if (!fs::exists(f.temporary, error)) continue;  // not written in this run
    fs::rename(f.temporary, f.path, error);
    if (error) {
      throw InputError(f.path + ": cannot move the results into place from '" + f.temporary +
                       "' (" + error.message() + ")");
    }
  }
  committed_ = true;
}

}  // namespace grout
