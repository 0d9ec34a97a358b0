#include "io/netcdf_header.hpp"

#include <hdf5.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "io/errors.hpp"

namespace grout {

namespace {

/// The largest factor by which deflate shrinks data (zlib's technical notes: 1032:1), the only
/// filter Exodus applies to netCDF-4 files.
constexpr uint64_t max_deflate_ratio = 1032;
/// Bytes a valid netCDF-4 file may declare without storing them: variables defined and never
/// written (an Exodus writer may leave names or maps unwritten), read as fill values.
constexpr uint64_t max_unbacked_bytes = uint64_t(1) << 20;

// Tags and type codes of the classic format.
constexpr uint32_t tag_dimension = 0x0A, tag_variable = 0x0B, tag_attribute = 0x0C;

/// Bytes of one value of netCDF type `type` (NC_BYTE = 1 ... NC_UINT64 = 11); 0 if unknown.
uint64_t type_size(uint32_t type, bool cdf5) {
  switch (type) {
    case 1:
    case 2:
      return 1;  // byte, char
    case 3:
      return 2;  // short
    case 4:
    case 5:
      return 4;  // int, float
    case 6:
      return 8;  // double
    default:
      break;
  }
  if (!cdf5) return 0;
  switch (type) {
    case 7:
      return 1;  // ubyte
    case 8:
      return 2;  // ushort
    case 9:
      return 4;  // uint
    case 10:
    case 11:
      return 8;  // int64, uint64
    default:
      return 0;
  }
}

/// Big-endian reader over the file that refuses to go past its end.
class HeaderReader {
 public:
  HeaderReader(const std::string& path, uint64_t size)
      : path_(path), file_(path, std::ios::binary), size_(size) {}

  [[noreturn]] void fail(const std::string& what) const {
    throw InputError(path_ + ": corrupt netCDF header: " + what + " (at byte " +
                     std::to_string(position_) + " of " + std::to_string(size_) + ")");
  }

  uint64_t left() const { return size_ - position_; }

  uint64_t u32() { return read(4); }
  /// A count: 4 bytes, or 8 in CDF-5.
  uint64_t count() { return read(cdf5_ ? 8 : 4); }

  /// Skip `n` bytes rounded up to a multiple of 4 (names and attribute values are padded).
  void skip_padded(uint64_t n, const std::string& what) {
    const uint64_t padded = n + (4 - n % 4) % 4;
    if (n > left() || padded > left())
      fail(what + " of " + std::to_string(n) + " bytes runs past the end of the file");
    position_ += padded;
    file_.seekg(std::streamoff(position_));
  }

  /// `n` items of at least `bytes_each` bytes must fit in what is left.
  void need(uint64_t n, uint64_t bytes_each, const std::string& what) const {
    if (n > left() / bytes_each)
      fail(what + ": " + std::to_string(n) + " declared, more than the " + std::to_string(left()) +
           " bytes left can hold");
  }

  /// A name, read (its length checked against the file like any other).
  std::string read_name(const std::string& what) {
    const uint64_t length = count();
    if (length > left())
      fail(what + " name of " + std::to_string(length) + " bytes runs past the end of the file");
    std::string text(std::size_t(length), '\0');
    file_.read(&text[0], std::streamsize(length));
    if (!file_) fail("cannot read the header");
    file_.seekg(std::streamoff(position_));
    skip_padded(length, what + " name");
    return text;
  }

  bool cdf5_ = false;

 private:
  uint64_t read(int bytes) {
    if (uint64_t(bytes) > left()) fail("the header ends early");
    unsigned char buffer[8] = {};
    file_.read(reinterpret_cast<char*>(buffer), bytes);
    if (!file_) fail("cannot read the header");
    position_ += uint64_t(bytes);
    uint64_t value = 0;
    for (int i = 0; i < bytes; ++i) value = (value << 8) | buffer[i];
    return value;
  }

  std::string path_;
  std::ifstream file_;
  uint64_t size_ = 0, position_ = 0;
};

/// A list header: its tag (or 0 for ABSENT) and its number of elements.
uint64_t list_length(HeaderReader& in, uint32_t expected_tag, const std::string& what) {
  const uint64_t tag = in.u32();
  const uint64_t n = in.count();
  if (tag == 0 && n == 0) return 0;
  if (tag != expected_tag) in.fail(what + " list has tag " + std::to_string(tag));
  return n;
}

// Global attributes that the Exodus library reads into one number (ex_open, ex_large_model:
// nc_get_att_int/float into a scalar, so a longer attribute overruns its stack; found by
// fuzz_exodus_reader), and the title it reads into a buffer of MAX_LINE_LENGTH + 1 bytes.
bool exodus_scalar_attribute(const std::string& name) {
  return name == "file_size" || name == "api_version" || name == "version" ||
         name == "floating_point_word_size" || name == "maximum_name_length" ||
         name == "int64_status";
}
constexpr uint64_t exodus_max_line_length = 80;

void skip_attributes(HeaderReader& in, const std::string& owner) {
  const bool global = owner == "global";
  const uint64_t n = list_length(in, tag_attribute, owner + " attribute");
  in.need(n, 12, owner + " attributes");  // name length, type, length: 4 bytes each at least
  std::set<std::string> names;
  for (uint64_t a = 0; a < n; ++a) {
    const std::string name = in.read_name(owner + " attribute");
    if (!names.insert(name).second) in.fail(owner + " attribute '" + name + "' is defined twice");
    const uint64_t type = in.u32();
    const uint64_t bytes = type_size(uint32_t(type), in.cdf5_);
    if (bytes == 0) in.fail(owner + " attribute of unknown type " + std::to_string(type));
    const uint64_t length = in.count();
    if (global && exodus_scalar_attribute(name) && length != 1)
      in.fail("global attribute '" + name + "' has " + std::to_string(length) +
              " values (Exodus reads one)");
    if (global && name == "title" && length > exodus_max_line_length)
      in.fail("global attribute 'title' has " + std::to_string(length) + " characters (at most " +
              std::to_string(exodus_max_line_length) + ")");
    in.need(length, bytes, owner + " attribute values");
    in.skip_padded(length * bytes, owner + " attribute values");
  }
}

// ---- netCDF-4 (HDF5) files -------------------------------------------------------------

/// What a netCDF-4 file's variables declare and what its chunks hold.
struct Hdf5Storage {
  uint64_t unbacked_bytes = 0;  ///< declared beyond what the stored bytes can hold, in all
  std::string largest;          ///< the variable with most of them
  uint64_t largest_declared = 0, largest_stored = 0;
};

/// HDF5 handles closed on scope exit.
struct Hdf5Handle {
  hid_t id;
  herr_t (*close)(hid_t);
  ~Hdf5Handle() {
    if (id >= 0) close(id);
  }
};

/// netCDF-4 stores a dimension without a variable of its name as an empty HDF5 dataset of
/// its length (a "dimension scale" whose NAME attribute says so): no values, never read.
bool is_bare_dimension(hid_t dataset) {
  constexpr const char* marker = "This is a netCDF dimension but not a netCDF variable";
  if (H5Aexists(dataset, "NAME") <= 0) return false;
  const Hdf5Handle attribute{H5Aopen(dataset, "NAME", H5P_DEFAULT), H5Aclose};
  const Hdf5Handle type{H5Aget_type(attribute.id), H5Tclose};
  if (attribute.id < 0 || type.id < 0 || H5Tget_class(type.id) != H5T_STRING ||
      H5Tis_variable_str(type.id) > 0)
    return false;
  const std::size_t size = H5Tget_size(type.id);
  if (size == 0 || size > 256) return false;
  std::vector<char> text(size + 1, '\0');
  if (H5Aread(attribute.id, type.id, text.data()) < 0) return false;
  return std::strncmp(text.data(), marker, std::strlen(marker)) == 0;
}

herr_t add_dataset(hid_t group, const char* name, const H5L_info_t*, void* data) {
  auto& storage = *static_cast<Hdf5Storage*>(data);
  H5O_info_t info;
  if (H5Oget_info_by_name(group, name, &info, H5P_DEFAULT) < 0 || info.type != H5O_TYPE_DATASET)
    return 0;  // groups are not read by Exodus; a broken link is left to netCDF
  const Hdf5Handle dataset{H5Dopen2(group, name, H5P_DEFAULT), H5Dclose};
  if (dataset.id < 0 || is_bare_dimension(dataset.id)) return 0;
  const Hdf5Handle space{H5Dget_space(dataset.id), H5Sclose};
  const Hdf5Handle type{H5Dget_type(dataset.id), H5Tclose};
  if (space.id < 0 || type.id < 0) return 0;
  const hssize_t points = H5Sget_simple_extent_npoints(space.id);
  const uint64_t bytes_each = H5Tget_size(type.id);
  if (points <= 0 || bytes_each == 0) return 0;
  const uint64_t declared =
      uint64_t(points) > UINT64_MAX / bytes_each ? UINT64_MAX : uint64_t(points) * bytes_each;
  const uint64_t stored = H5Dget_storage_size(dataset.id);
  const uint64_t holds =
      stored > UINT64_MAX / max_deflate_ratio ? UINT64_MAX : stored * max_deflate_ratio;
  if (declared <= holds) return 0;
  storage.unbacked_bytes += std::min(declared - holds, UINT64_MAX - storage.unbacked_bytes);
  if (declared > storage.largest_declared) {
    storage.largest = name;
    storage.largest_declared = declared;
    storage.largest_stored = stored;
  }
  return 0;
}

/// \brief The variables of a netCDF-4 file must hold the values they declare: the bytes
/// declared beyond H5Dget_storage_size × 1032 (deflate, the only filter Exodus applies,
/// shrinks data by at most 1032) are at most max_unbacked_bytes in all. HDF5 reads chunks
/// that were never written as fill values, so a 1 MB file could otherwise declare 120 M nodes
/// and make the reader allocate gigabytes before any value is known to exist.
void check_netcdf4_storage(const std::string& path) {
  H5E_auto2_t handler = nullptr;
  void* handler_data = nullptr;
  H5Eget_auto2(H5E_DEFAULT, &handler, &handler_data);
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);  // a file HDF5 cannot read is netCDF's to report
  Hdf5Storage storage;
  {
    const Hdf5Handle file{H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose};
    if (file.id >= 0) {
      hsize_t index = 0;
      H5Literate(file.id, H5_INDEX_NAME, H5_ITER_NATIVE, &index, add_dataset, &storage);
    }
  }
  H5Eset_auto2(H5E_DEFAULT, handler, handler_data);
  if (storage.unbacked_bytes > max_unbacked_bytes) {
    throw InputError(path + ": corrupt netCDF-4 file: its variables declare " +
                     std::to_string(storage.unbacked_bytes) +
                     " bytes more than its stored data can hold (at most " +
                     std::to_string(max_unbacked_bytes) + "); the largest, '" + storage.largest +
                     "', declares " + std::to_string(storage.largest_declared) + " bytes in " +
                     std::to_string(storage.largest_stored) +
                     " stored bytes (data never written, or the file is truncated)");
  }
}

}  // namespace

void check_netcdf_header(const std::string& path) {
  std::error_code error;
  const uint64_t size = std::filesystem::file_size(path, error);
  if (error || size < 4) return;  // left to the netCDF library to report
  {
    char signature[8] = {};
    std::ifstream(path, std::ios::binary).read(signature, sizeof signature);
    if (std::memcmp(signature, "\x89HDF\r\n\x1a\n", 8) == 0) return check_netcdf4_storage(path);
  }
  HeaderReader in(path, size);
  const uint64_t magic = in.u32();
  if ((magic >> 8) != 0x434446) return;  // not "CDF" and not HDF5: not netCDF at all
  const uint64_t version = magic & 0xff;
  if (version != 1 && version != 2 && version != 5) return;  // netCDF reports it
  in.cdf5_ = version == 5;
  const uint64_t offset_bytes = version == 1 ? 4 : 8;

  const uint64_t records = in.count();  // may be "streaming" (all ones): not used below

  const uint64_t num_dims = list_length(in, tag_dimension, "dimension");
  in.need(num_dims, 8, "dimensions");
  std::vector<uint64_t> dims(num_dims);
  std::map<std::string, uint64_t> dimension;  // name -> length
  for (uint64_t& length : dims) {
    const std::string name = in.read_name("dimension");
    length = in.count();
    // Names are unique in a valid netCDF file; a repeated one makes the library return the
    // first while Exodus expects another (a fuzzed file with num_nod_ns2 renamed num_nod_ns1).
    if (!dimension.emplace(name, length).second)
      in.fail("dimension '" + name + "' is defined twice");
  }

  skip_attributes(in, "global");

  const uint64_t num_vars = list_length(in, tag_variable, "variable");
  in.need(num_vars, 16, "variables");
  std::set<std::string> variables;
  for (uint64_t v = 0; v < num_vars; ++v) {
    std::string what = "variable " + std::to_string(v + 1);
    const std::string name = in.read_name(what);
    // A repeated variable name (one flipped bit: side_ss2 read as side_ss3) makes the library
    // find one variable for two, and Exodus then reads a set of one size into an array of
    // another (heap corruption in read_side_sets, found by flipping bits of valid meshes).
    if (!variables.insert(name).second) in.fail("variable '" + name + "' is defined twice");
    what += " ('" + name + "')";
    const uint64_t rank = in.count();
    in.need(rank, in.cdf5_ ? 8 : 4, what + " dimensions");
    uint64_t values = 1;
    bool record = false;
    for (uint64_t r = 0; r < rank; ++r) {
      const uint64_t id = in.count();
      if (id >= dims.size()) in.fail(what + " refers to dimension " + std::to_string(id));
      if (dims[id] == 0) {
        record = true;  // the unlimited dimension: its length is the record count
        continue;
      }
      if (values > std::numeric_limits<uint64_t>::max() / dims[id])
        in.fail(what + " has more values than fit in 64 bits");
      values *= dims[id];
    }
    skip_attributes(in, what);
    const uint64_t type = in.u32();
    const uint64_t bytes = type_size(uint32_t(type), in.cdf5_);
    if (bytes == 0) in.fail(what + " has unknown type " + std::to_string(type));
    in.count();  // vsize: redundant (and clipped for large variables)
    const uint64_t begin = offset_bytes == 4 ? in.u32() : (uint64_t(in.u32()) << 32 | in.u32());
    // A fixed-size variable's values lie at [begin, begin + values * bytes); each record of
    // a record variable holds `values` values.
    if (values > size / bytes || begin > size || (!record && values * bytes > size - begin))
      in.fail(what + " declares " + std::to_string(values) + " values of " + std::to_string(bytes) +
              " bytes from byte " + std::to_string(begin) + ", past the end of the file");
  }
  (void)records;
}

}  // namespace grout
