#pragma once
// A check of the header of a classic netCDF file before the netCDF library reads it.

#include <string>

namespace grout {

/// \brief Check the header of a classic netCDF file (CDF-1, CDF-2 or CDF-5: the formats of
/// Exodus II files other than netCDF-4) against the file's size: every count, name length
/// and attribute length must fit in the bytes left in the file, every dimension id must
/// exist, and each fixed-size variable must fit in the file. The netCDF library allocates
/// what the header declares while it opens a file, so a single corrupt byte could otherwise
/// make it allocate gigabytes. Files of other formats (netCDF-4/HDF5) are not checked here.
/// Layout: "The NetCDF Classic Format Specification" (Unidata, netCDF-C documentation).
/// \throw InputError naming the path, the header item and the limit it exceeds.
void check_netcdf_header(const std::string& path);

}  // namespace grout
