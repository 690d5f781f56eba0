#include "io/results_store.h"
#include "io/hdf5_handle.h"
#include "io/result_fields.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "rollcheck_version.h"
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <limits>
#include <hdf5.h>
#include <optional>

namespace rollcheck::io
{
namespace
{
using hdf5::Handle;
using hdf5::check;

std::string link_name(const std::string& key)
{
  if (key.empty() || key == ".")
    return "_";
  std::string name = key;
  std::replace(name.begin(), name.end(), '/', '_');
  return name;
}

Handle string_type()
{
  Handle type(H5Tcopy(H5T_C_S1), H5Tclose, "copy the string type");
  check(H5Tset_size(type, H5T_VARIABLE), "make a variable-length string type");
  check(H5Tset_cset(type, H5T_CSET_UTF8), "set UTF-8");
  return type;
}

/// The enum h5py reads as numpy bool.
Handle bool_type()
{
  Handle type(H5Tenum_create(H5T_NATIVE_INT8), H5Tclose, "create the boolean enum");
  const std::int8_t no = 0, yes = 1;
  check(H5Tenum_insert(type, "FALSE", &no), "define FALSE");
  check(H5Tenum_insert(type, "TRUE", &yes), "define TRUE");
  return type;
}

enum class Element
{
  boolean,
  integer,
  real
};

/// Shape and element type of a rectangular numeric array; nullopt otherwise.
struct NumericArray
{
  std::vector<hsize_t> shape;
  Element element;
};

std::optional<NumericArray> numeric_array(const nlohmann::json& array)
{
  NumericArray result{{}, Element::boolean};
  // The shape is read along the first elements, then every leaf checked
  // against it.
  for (const nlohmann::json* node = &array; node->is_array(); node = &node->front())
  {
    result.shape.push_back(node->size());
    if (node->empty())
      break;
  }
  bool any_number = false, any_real = false;
  std::function<bool(const nlohmann::json&, std::size_t)> walk = [&](const nlohmann::json& node, std::size_t depth) {
    if (depth == result.shape.size())
    {
      if (node.is_number())
      {
        any_number = true;
        any_real = any_real || node.is_number_float()
                   || (node.is_number_unsigned() && node.get<std::uint64_t>() > std::uint64_t(INT64_MAX));
      }
      else if (!node.is_boolean())
        return false;
      return true;
    }
    if (!node.is_array() || node.size() != result.shape[depth])
      return false;
    for (const nlohmann::json& child : node)
      if (!walk(child, depth + 1))
        return false;
    return true;
  };
  if (!walk(array, 0))
    return std::nullopt;
  if (result.shape.back() == 0) // an empty array holds no type: store it as reals
    result.element = Element::real;
  else
    result.element = any_real ? Element::real : any_number ? Element::integer : Element::boolean;
  return result;
}

void flatten(const nlohmann::json& node, std::vector<const nlohmann::json*>& leaves)
{
  if (node.is_array())
    for (const nlohmann::json& child : node)
      flatten(child, leaves);
  else
    leaves.push_back(&node);
}

void write_attribute(hid_t object, const std::string& name, const nlohmann::json& value);

/// "inf" / "-inf" (the JSON form of an infinite result, core/json_number.h)
/// back to floats, so the store holds numbers as numbers.
nlohmann::json restore_infinities(const nlohmann::json& value)
{
  if (value.is_string() && (value == "inf" || value == "-inf"))
    return value == "inf" ? std::numeric_limits<double>::infinity() : -std::numeric_limits<double>::infinity();
  if (!value.is_structured())
    return value;
  nlohmann::json copy = value;
  for (auto& item : copy.items())
    item.value() = restore_infinities(item.value());
  return copy;
}

/// The attributes the record's schema gives a numeric dataset
/// (io/result_fields.h): its unit, and a table's column names.
void write_field_attributes(hid_t set, const ResultField& field)
{
  write_attribute(set, "units", field.unit);
  if (!field.columns.empty())
    write_attribute(set, "columns", fmt::format("{}", fmt::join(field.columns, ", ")));
}

void write_numeric(hid_t parent, const std::string& name, const nlohmann::json& value, const NumericArray& array,
                   const ResultField& field)
{
  std::vector<const nlohmann::json*> leaves;
  flatten(value, leaves);
  const bool scalar = array.shape.empty();
  Handle space(scalar ? H5Screate(H5S_SCALAR)
                      : H5Screate_simple(static_cast<int>(array.shape.size()), array.shape.data(), nullptr),
               H5Sclose, "create a dataspace for " + name);
  auto write = [&](hid_t file_type, hid_t memory_type, const void* data) {
    Handle set(H5Dcreate2(parent, name.c_str(), file_type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
               H5Dclose, "create dataset " + name);
    if (!leaves.empty())
      check(H5Dwrite(set, memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data), "write dataset " + name);
    write_field_attributes(set, field);
  };
  switch (array.element)
  {
  case Element::boolean:
  {
    std::vector<std::int8_t> data;
    for (const nlohmann::json* leaf : leaves)
      data.push_back(leaf->get<bool>() ? 1 : 0);
    const Handle type = bool_type();
    write(type, type, data.data());
    break;
  }
  case Element::integer:
  {
    std::vector<std::int64_t> data;
    for (const nlohmann::json* leaf : leaves)
      data.push_back(leaf->is_boolean() ? std::int64_t(leaf->get<bool>()) : leaf->get<std::int64_t>());
    write(H5T_STD_I64LE, H5T_NATIVE_INT64, data.data());
    break;
  }
  case Element::real:
  {
    std::vector<double> data;
    for (const nlohmann::json* leaf : leaves)
      data.push_back(leaf->is_boolean() ? double(leaf->get<bool>()) : leaf->get<double>());
    write(H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, data.data());
    break;
  }
  }
}

void write_strings(hid_t parent, const std::string& name, const std::vector<std::string>& strings, bool scalar)
{
  const hsize_t n = strings.size();
  Handle space(scalar ? H5Screate(H5S_SCALAR) : H5Screate_simple(1, &n, nullptr), H5Sclose,
               "create a dataspace for " + name);
  const Handle type = string_type();
  Handle set(H5Dcreate2(parent, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Dclose,
             "create dataset " + name);
  std::vector<const char*> pointers;
  for (const std::string& s : strings)
    pointers.push_back(s.c_str());
  if (!pointers.empty())
    check(H5Dwrite(set, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, pointers.data()), "write dataset " + name);
}

void write_attribute(hid_t object, const std::string& name, const nlohmann::json& value)
{
  Handle space(value.is_null() ? H5Screate(H5S_NULL) : H5Screate(H5S_SCALAR), H5Sclose,
               "create a dataspace for attribute " + name);
  auto write = [&](hid_t file_type, hid_t memory_type, const void* data) {
    Handle attribute(H5Acreate2(object, name.c_str(), file_type, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose,
                     "create attribute " + name);
    if (data)
      check(H5Awrite(attribute, memory_type, data), "write attribute " + name);
  };
  if (value.is_null())
    write(H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, nullptr);
  else if (value.is_boolean())
  {
    const std::int8_t x = value.get<bool>() ? 1 : 0;
    const Handle type = bool_type();
    write(type, type, &x);
  }
  else if (value.is_number_integer()
           && !(value.is_number_unsigned() && value.get<std::uint64_t>() > std::uint64_t(INT64_MAX)))
  {
    const std::int64_t x = value.get<std::int64_t>();
    write(H5T_STD_I64LE, H5T_NATIVE_INT64, &x);
  }
  else if (value.is_number())
  {
    const double x = value.get<double>();
    write(H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, &x);
  }
  else
  {
    // Strings as they are; an array or object as its JSON text.
    const std::string text = value.is_string() ? value.get<std::string>() : value.dump();
    const char* pointer = text.c_str();
    const Handle type = string_type();
    write(type, type, &pointer);
  }
}

/// Groups remember the order their members were written in (JSON arrays,
/// the batch's case order); h5py lists them in that order.
Handle create_group(hid_t parent, const std::string& name)
{
  Handle properties(H5Pcreate(H5P_GROUP_CREATE), H5Pclose, "create group properties");
  check(H5Pset_link_creation_order(properties, H5P_CRT_ORDER_TRACKED | H5P_CRT_ORDER_INDEXED),
        "track creation order");
  return Handle(H5Gcreate2(parent, name.c_str(), H5P_DEFAULT, properties, H5P_DEFAULT), H5Gclose,
                "create group " + name);
}

void write_json_value(hid_t parent, const std::string& parent_name, const std::string& name,
                      const nlohmann::json& value);

/// The members of `object` into `group`, named `group_name` (the field
/// schema's context: convergence/cds is a table).
void write_json_tree(hid_t group, const std::string& group_name, const nlohmann::json& object)
{
  for (const auto& [key, value] : object.items())
    write_json_value(group, group_name, link_name(key), value);
}

void write_json_value(hid_t parent, const std::string& parent_name, const std::string& name,
                      const nlohmann::json& value)
{
  const ResultField field = result_field(parent_name, name);
  if (value.is_object())
  {
    const Handle group = create_group(parent, name);
    write_json_tree(group, name, value);
  }
  else if (value.is_null())
  {
    Handle space(H5Screate(H5S_NULL), H5Sclose, "create a null dataspace");
    Handle set(H5Dcreate2(parent, name.c_str(), H5T_IEEE_F64LE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
               H5Dclose, "create dataset " + name);
  }
  else if (value.is_string())
    write_strings(parent, name, {value.get<std::string>()}, true);
  else if (value.is_boolean() || value.is_number())
    write_numeric(parent, name, value,
                  NumericArray{{}, value.is_boolean()        ? Element::boolean
                                   : value.is_number_float() ? Element::real
                                                             : Element::integer},
                  field);
  else if (field.text_list && value.empty())
    write_strings(parent, name, {}, false);
  else if (const std::optional<NumericArray> array = numeric_array(value))
    write_numeric(parent, name, value, *array, field);
  else if (std::all_of(value.begin(), value.end(), [](const nlohmann::json& x) { return x.is_string(); }))
    write_strings(parent, name, value.get<std::vector<std::string>>(), false);
  else
  {
    const Handle group = create_group(parent, name);
    write_attribute(group, "json_array", 1);
    for (std::size_t i = 0; i < value.size(); ++i)
      write_json_value(group, name, std::to_string(i), value[i]);
  }
}

/// The resolved parameters as the store records them: each input file's
/// SHA-256 beside its path (KEY_sha256, from the record's `inputs`), and a
/// body read from a mesh file named by that file, not by the body option the
/// mesh file overrode.
nlohmann::json stored_parameters(const nlohmann::json& record)
{
  nlohmann::json parameters = record.at("parameters");
  if (!record.contains("inputs"))
    return parameters;
  for (const auto& [key, input] : record.at("inputs").items())
  {
    parameters[key + "_sha256"] = input.at("sha256");
    if (key == "mesh_file" && parameters.contains("body"))
      parameters["body"] = input.at("file");
  }
  return parameters;
}

void write_case(hid_t cases, const StoreEntry& entry)
{
  const Handle group = create_group(cases, link_name(entry.name));
  for (const auto& [key, value] : entry.record.items())
  {
    if (key == "parameters")
    {
      const Handle parameters = create_group(group, "parameters");
      const nlohmann::json stored = stored_parameters(entry.record);
      for (const auto& [name, parameter] : stored.items())
        write_attribute(parameters, link_name(name), parameter);
    }
    else if (key == "summary")
    {
      const Handle summary = create_group(group, "summary");
      write_json_tree(summary, "summary", restore_infinities(value));
    }
    else if (key == "files")
      write_strings(group, "files", value.get<std::vector<std::string>>(), false);
    else
      write_attribute(group, link_name(key), value);
  }
}
} // namespace

void write_results_store(const std::filesystem::path& path, const std::vector<StoreEntry>& entries,
                         const nlohmann::json& attributes)
{
  // Our own messages name the failing object; HDF5's stack dumps would not help.
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  write_atomically(path, [&](const std::filesystem::path& tmp) {
    Handle file(H5Fcreate(tmp.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose,
                fmt::format("create '{}'", tmp.string()));
    write_attribute(file, "layout", "rollcheck-results-1");
    write_attribute(file, "rollcheck_version", ROLLCHECK_VERSION);
    for (const auto& [key, value] : attributes.items())
      write_attribute(file, link_name(key), value);
    const Handle cases = create_group(file, "cases");
    for (const StoreEntry& entry : entries)
      write_case(cases, entry);
    check(H5Fflush(file, H5F_SCOPE_GLOBAL), fmt::format("flush '{}'", tmp.string()));
  });
}

bool is_results_store(const std::filesystem::path& path)
{
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec) || H5Fis_hdf5(path.c_str()) <= 0)
    return false;
  try
  {
    const Handle file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose, "open " + path.string());
    if (H5Aexists(file, "layout") <= 0)
      return false;
    const Handle attribute(H5Aopen(file, "layout", H5P_DEFAULT), H5Aclose, "open the layout attribute");
    const Handle type = string_type();
    char* text = nullptr;
    check(H5Aread(attribute, type, &text), "read the layout attribute");
    const bool ours = text && std::string_view(text).starts_with("rollcheck-results-");
    H5free_memory(text);
    return ours;
  }
  catch (const ComputationError&)
  {
    return false;
  }
}
} // namespace rollcheck::io
