#pragma once
// A check of a netCDF file before the netCDF library reads it: the header of a classic file,
// the stored data of a netCDF-4 (HDF5) file.

#include <string>

namespace grout {

/// \brief Check a netCDF file before the netCDF library opens it.
///
/// Classic files (CDF-1, CDF-2 or CDF-5): the header against the file's size. Every count,
/// name length and attribute length must fit in the bytes left in the file, every dimension
/// id must exist, each fixed-size variable must fit in the file, and no two dimensions, no
/// two variables and no two attributes of one owner may share a name. The netCDF library
/// allocates what the header declares while it opens a file, so a single corrupt byte could
/// otherwise make it allocate gigabytes; a repeated name makes it find one variable for two.
/// Layout: "The NetCDF Classic Format Specification" (Unidata, netCDF-C documentation).
///
/// netCDF-4 files (HDF5 signature): the values the variables declare must be stored. HDF5
/// returns fill values for chunks never written, so the file size alone does not bound what
/// a reader allocates. The bytes declared beyond 1032 × the bytes stored (deflate's largest
/// ratio) may be at most 1 MiB over all variables (datasets of the root group; netCDF's bare
/// dimensions hold no values and are skipped). libhdf5 itself parses the file.
/// \throw InputError naming the path, the header item or variable and the limit it exceeds.
void check_netcdf_header(const std::string& path);

}  // namespace grout
