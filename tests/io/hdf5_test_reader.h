#pragma once
// An HDF5 file opened read-only and read with the plain C API, independently
// of the io layer's writers, for the tests of the stores they write.
#include <algorithm>
#include <filesystem>
#include <gtest/gtest.h>
#include <hdf5.h>
#include <string>
#include <type_traits>
#include <vector>

class Hdf5TestReader
{
public:
  explicit Hdf5TestReader(const std::filesystem::path& path) : file_(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT))
  {
  }
  ~Hdf5TestReader()
  {
    if (file_ >= 0)
      H5Fclose(file_);
  }
  Hdf5TestReader(const Hdf5TestReader&) = delete;
  Hdf5TestReader& operator=(const Hdf5TestReader&) = delete;

  bool ok() const { return file_ >= 0; }
  bool exists(const std::string& path) const { return H5Lexists(file_, path.c_str(), H5P_DEFAULT) > 0; }

  H5T_class_t type_class(const std::string& path) const
  {
    return with_dataset(path, [](hid_t set, hid_t) {
      const hid_t type = H5Dget_type(set);
      const H5T_class_t c = H5Tget_class(type);
      H5Tclose(type);
      return c;
    });
  }

  std::vector<hsize_t> shape(const std::string& path) const
  {
    return with_dataset(path, [](hid_t, hid_t space) {
      std::vector<hsize_t> dims(static_cast<std::size_t>(std::max(0, H5Sget_simple_extent_ndims(space))));
      H5Sget_simple_extent_dims(space, dims.data(), nullptr);
      return dims;
    });
  }

  H5S_class_t space_class(const std::string& path) const
  {
    return with_dataset(path, [](hid_t, hid_t space) { return H5Sget_simple_extent_type(space); });
  }

  template <typename T>
  std::vector<T> numbers(const std::string& path, hid_t memory_type) const
  {
    return with_dataset(path, [&](hid_t set, hid_t space) {
      std::vector<T> data(static_cast<std::size_t>(H5Sget_simple_extent_npoints(space)));
      H5Dread(set, memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data());
      return data;
    });
  }

  std::vector<double> doubles(const std::string& path) const { return numbers<double>(path, H5T_NATIVE_DOUBLE); }

  std::vector<std::string> strings(const std::string& path) const
  {
    return with_dataset(path, [](hid_t set, hid_t space) {
      const hid_t type = utf8_string_type();
      std::vector<char*> data(static_cast<std::size_t>(H5Sget_simple_extent_npoints(space)));
      H5Dread(set, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data());
      std::vector<std::string> out(data.begin(), data.end());
      H5Dvlen_reclaim(type, space, H5P_DEFAULT, data.data());
      H5Tclose(type);
      return out;
    });
  }

  std::string string_attribute(const std::string& object, const std::string& name) const
  {
    const hid_t attribute = H5Aopen_by_name(file_, object.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT);
    const hid_t type = utf8_string_type();
    char* text = nullptr;
    H5Aread(attribute, type, &text);
    std::string out = text ? text : "";
    H5free_memory(text);
    H5Tclose(type);
    H5Aclose(attribute);
    return out;
  }

  template <typename T>
  T number_attribute(const std::string& object, const std::string& name, hid_t memory_type) const
  {
    const hid_t attribute = H5Aopen_by_name(file_, object.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT);
    T value{};
    H5Aread(attribute, memory_type, &value);
    H5Aclose(attribute);
    return value;
  }

  /// Member names of a group in the order they were created.
  std::vector<std::string> members_in_creation_order(const std::string& group) const
  {
    const hid_t g = H5Gopen2(file_, group.c_str(), H5P_DEFAULT);
    H5G_info_t info;
    H5Gget_info(g, &info);
    std::vector<std::string> names;
    for (hsize_t i = 0; i < info.nlinks; ++i)
    {
      char name[256];
      H5Lget_name_by_idx(g, ".", H5_INDEX_CRT_ORDER, H5_ITER_INC, i, name, sizeof name, H5P_DEFAULT);
      names.emplace_back(name);
    }
    H5Gclose(g);
    return names;
  }

private:
  /// read(dataset, dataspace) on the dataset at `path`; both closed after.
  template <typename Read>
  std::invoke_result_t<Read, hid_t, hid_t> with_dataset(const std::string& path, Read read) const
  {
    const hid_t set = H5Dopen2(file_, path.c_str(), H5P_DEFAULT);
    EXPECT_GE(set, 0) << path;
    const hid_t space = H5Dget_space(set);
    auto result = read(set, space);
    H5Sclose(space);
    H5Dclose(set);
    return result;
  }

  /// Variable-length UTF-8 strings: HDF5 converts no strings between
  /// character sets, so the reader asks for the set the writers use.
  static hid_t utf8_string_type()
  {
    const hid_t type = H5Tcopy(H5T_C_S1);
    H5Tset_size(type, H5T_VARIABLE);
    H5Tset_cset(type, H5T_CSET_UTF8);
    return type;
  }

  hid_t file_;
};
