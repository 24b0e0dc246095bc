// Damaging copies of HDF5 products for the readers' tests, through the HDF5
// C library (Debian's libhdf5-dev, the library GDAL's HDF5 driver uses):
// GDAL cannot write HDF5. Test-only: ris itself reads HDF5 through GDAL.
//
// Example:
//   h5_set(copy, "/science/LSAR/SLC/swaths/frequencyA/slantRange", {3}, NAN);
//   h5_replace_with_undeclared(copy, ".../slantRange", {2'000'000'000});
#pragma once

#include <hdf5.h>

#include <algorithm>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace ris::test {

namespace detail {

inline void h5_require(bool ok, const std::string& what) {
  if (!ok) throw std::runtime_error("HDF5 test helper: " + what);
}

// An HDF5 file opened for writing, closed at scope end.
class H5File {
 public:
  explicit H5File(const std::filesystem::path& p)
      : id_(H5Fopen(p.c_str(), H5F_ACC_RDWR, H5P_DEFAULT)) {
    h5_require(id_ >= 0, "cannot open " + p.string());
  }
  ~H5File() { H5Fclose(id_); }
  H5File(const H5File&) = delete;
  H5File& operator=(const H5File&) = delete;
  hid_t id() const { return id_; }

 private:
  hid_t id_;
};

}  // namespace detail

// Writes `value` into one element (at `coord`; {} for a scalar dataset) of a
// numeric dataset, converted to the dataset's own type.
inline void h5_set(const std::filesystem::path& file, const std::string& dataset,
                   const std::vector<hsize_t>& coord, double value) {
  const detail::H5File f(file);
  const hid_t d = H5Dopen2(f.id(), dataset.c_str(), H5P_DEFAULT);
  detail::h5_require(d >= 0, "no dataset " + dataset);
  const hid_t space = H5Dget_space(d);
  herr_t status = 0;
  if (coord.empty()) {
    status = H5Dwrite(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, &value);
  } else {
    status = H5Sselect_elements(space, H5S_SELECT_SET, 1, coord.data());
    const hsize_t one = 1;
    const hid_t mem = H5Screate_simple(1, &one, nullptr);
    if (status >= 0) status = H5Dwrite(d, H5T_NATIVE_DOUBLE, mem, space, H5P_DEFAULT, &value);
    H5Sclose(mem);
  }
  H5Sclose(space);
  H5Dclose(d);
  detail::h5_require(status >= 0, "cannot write " + dataset);
}

// Replaces a dataset by one of the same type declaring `dims`, chunked and
// never written: the file stays small whatever the size it declares (the
// hostile input of issue 37: a 4 MB file declaring 2e9 elements).
inline void h5_replace_with_undeclared(const std::filesystem::path& file,
                                       const std::string& dataset,
                                       const std::vector<hsize_t>& dims) {
  const detail::H5File f(file);
  const hid_t old = H5Dopen2(f.id(), dataset.c_str(), H5P_DEFAULT);
  detail::h5_require(old >= 0, "no dataset " + dataset);
  const hid_t type = H5Dget_type(old);
  H5Dclose(old);
  detail::h5_require(H5Ldelete(f.id(), dataset.c_str(), H5P_DEFAULT) >= 0, "cannot unlink");
  const hid_t space = H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr);
  const hid_t dcpl = H5Pcreate(H5P_DATASET_CREATE);
  std::vector<hsize_t> chunk;
  for (hsize_t n : dims) chunk.push_back(std::min<hsize_t>(n, 1024));
  H5Pset_chunk(dcpl, static_cast<int>(chunk.size()), chunk.data());
  const hid_t d = H5Dcreate2(f.id(), dataset.c_str(), type, space, H5P_DEFAULT, dcpl, H5P_DEFAULT);
  detail::h5_require(d >= 0, "cannot create " + dataset);
  H5Dclose(d);
  H5Pclose(dcpl);
  H5Sclose(space);
  H5Tclose(type);
}

}  // namespace ris::test
