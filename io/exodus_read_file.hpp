#pragma once
// The pieces of the Exodus mesh reader that the whole-file reader (io/exodus_reader.cpp) and
// the slice reader (parallel/exodus_slices.cpp) share: the file opened read-only with its
// size-based count limits, the header counts and the element-block header checks. Internal to
// io/ and parallel/; the public interface is io/exodus.hpp.

#include <exodusII.h>

#include <cstdint>
#include <string>
#include <vector>

#include "io/mesh.hpp"

namespace grout::exodus_read {

static_assert(sizeof(GlobalIndex) == sizeof(int64_t), "grout: GlobalIndex must be 64-bit");

/// Throws InputError("<path>: <what>").
[[noreturn]] void fail(const std::string& path, const std::string& what);

/// Throw InputError when an Exodus call failed (negative status; positive is a warning).
void check(int status, const std::string& path, const std::string& what);

/// \brief An Exodus file opened for reading (EX_ALL_INT64_API, doubles), closed when it goes
/// out of scope. The netCDF header is checked before netCDF allocates what it declares.
class ReadOnlyFile {
 public:
  explicit ReadOnlyFile(const std::string& path);
  ~ReadOnlyFile();
  ReadOnlyFile(const ReadOnlyFile&) = delete;
  ReadOnlyFile& operator=(const ReadOnlyFile&) = delete;

  int id() const { return id_; }
  const std::string& path() const { return path_; }
  void check(int status, const std::string& what) const { exodus_read::check(status, path_, what); }

  /// Refuse `count` entries of `what` (from the header), `values_each` stored values each,
  /// when the file is too small to hold them: the header is corrupt, and allocating for it
  /// could exhaust the memory.
  void check_count(int64_t count, const std::string& what, int64_t values_each = 1) const;

  /// The ids of `count` entities of `type`; each must fit in an int (ElementBlock::id and the
  /// sets' ids are int: 2^32 + 1 would otherwise read as 1, a false "same id").
  std::vector<int64_t> ids(ex_entity_type type, int64_t count, const std::string& what) const;

  /// Names of all entities of one type; an empty name becomes "id_<n>".
  std::vector<std::string> names(ex_entity_type type, const std::vector<int64_t>& ids) const;

  std::vector<std::string> variable_names(ex_entity_type type) const;

 private:
  std::string path_;
  int64_t max_values_ = 0;
  int id_ = -1;
  int name_length_ = MAX_NAME_LENGTH;
};

/// Map an Exodus element type string to a Topology; false when unsupported.
bool parse_topology(const std::string& exodus_type, Topology& topology);

struct Counts {
  int64_t dimension = 0, nodes = 0, elements = 0, blocks = 0, node_sets = 0, side_sets = 0;
};

/// The header's counts, checked: dimension 2 or 3, every count possible for the file's size.
Counts read_counts(const ReadOnlyFile& file);

/// \brief Element block `id` (named `name`) without its connectivity: name, id, topology,
/// nodes per element and first_element = `first`; its element count in `num_elements`.
/// Refuses an empty block, an unsupported or mismatched element type, a wrong node count and
/// a connectivity the file cannot hold.
ElementBlock read_block_header(const ReadOnlyFile& file, const Counts& counts, int64_t id,
                               const std::string& name, GlobalIndex first, int64_t& num_elements);

/// "element block '<name>' (id <id>)", the reader's name of a block in its messages.
std::string block_label(const std::string& name, int64_t id);

}  // namespace grout::exodus_read
