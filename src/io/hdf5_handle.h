#pragma once
// RAII for HDF5 identifiers, shared by the HDF5 writers of the io layer.
#include "core/error.h"
#include <fmt/format.h>
#include <hdf5.h>
#include <string>

namespace rollcheck::io::hdf5
{
/// Owns an HDF5 identifier and closes it with the matching H5?close.
class Handle
{
public:
  Handle(hid_t id, herr_t (*close)(hid_t), const std::string& what) : id_(id), close_(close)
  {
    if (id < 0)
      throw rollcheck::ComputationError(fmt::format("HDF5: cannot {}", what));
  }
  Handle(Handle&& other) noexcept : id_(other.id_), close_(other.close_) { other.id_ = H5I_INVALID_HID; }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  Handle& operator=(Handle&&) = delete;
  ~Handle()
  {
    if (id_ >= 0)
      close_(id_);
  }
  operator hid_t() const { return id_; }

private:
  hid_t id_;
  herr_t (*close_)(hid_t);
};

inline void check(herr_t status, const std::string& what)
{
  if (status < 0)
    throw rollcheck::ComputationError(fmt::format("HDF5: cannot {}", what));
}
} // namespace rollcheck::io::hdf5
