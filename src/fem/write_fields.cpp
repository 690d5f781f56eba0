#include "fem/write_fields.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "fem/field_output.h"
#include "fem/first_failure.h"
#include <dolfinx/fem/FunctionSpace.h>
#include <dolfinx/mesh/Mesh.h>
#include <fmt/format.h>
#include <hdf5.h>
#include <pugixml.hpp>
#include <sstream>
#include <string_view>
#include <unistd.h>

namespace rollcheck::fem
{
namespace
{
/// The stress in the mesh's axes: (r, theta, z) -> (r, z, theta) on a 2D mesh.
std::shared_ptr<dolfinx::fem::Function<double>> stress_in_mesh_axes(const dolfinx::fem::Function<double>& stress)
{
  auto out = std::make_shared<dolfinx::fem::Function<double>>(stress.function_space());
  out->name = "stress";
  std::span<const double> in = stress.x()->array();
  std::span<double> to = out->x()->mutable_array();
  if (stress.function_space()->mesh()->geometry().dim() == 3)
  {
    std::copy(in.begin(), in.end(), to.begin());
    return out;
  }
  constexpr int axis[3] = {0, 2, 1}; // component k of the output is component axis[k] of the recovery
  for (std::size_t node = 0; node < in.size() / 9; ++node)
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        to[9 * node + 3 * i + j] = in[9 * node + 3 * axis[i] + axis[j]];
  return out;
}

/// DOLFINx's one temporal collection per function, joined into one whose k-th
/// grid holds the k-th attribute of every function (they share the steps); a
/// single step becomes the mesh grid's attributes.
void join_collections(const std::filesystem::path& xdmf)
{
  pugi::xml_document doc;
  if (!doc.load_file(xdmf.c_str()))
    throw ComputationError(fmt::format("cannot read back '{}'", xdmf.string()));
  pugi::xml_node domain = doc.child("Xdmf").child("Domain");
  std::vector<pugi::xml_node> collections;
  for (pugi::xml_node grid : domain.children("Grid"))
    if (std::string_view(grid.attribute("CollectionType").value()) == "Temporal")
      collections.push_back(grid);
  if (collections.size() < 2)
    return;
  const auto steps_of = [](pugi::xml_node collection) {
    std::vector<pugi::xml_node> steps;
    for (pugi::xml_node step : collection.children("Grid"))
      steps.push_back(step);
    return steps;
  };
  std::vector<pugi::xml_node> joined = steps_of(collections.front()); // handles: appended to, not reassigned
  for (std::size_t c = 1; c < collections.size(); ++c)
  {
    const std::vector<pugi::xml_node> steps = steps_of(collections[c]);
    if (steps.size() != joined.size())
      throw ComputationError(fmt::format("'{}': fields with different numbers of steps", xdmf.string()));
    for (std::size_t k = 0; k < steps.size(); ++k)
      joined[k].append_copy(steps[k].child("Attribute"));
    domain.remove_child(collections[c]);
  }
  collections.front().attribute("Name").set_value("fields");
  for (std::size_t k = 0; k < joined.size(); ++k)
    joined[k].attribute("Name").set_value(fmt::format("step {}", k + 1).c_str());
  if (joined.size() == 1)
  {
    // A series of one step is one grid: the mesh's, with every field (meshio.read opens it).
    pugi::xml_node mesh = domain.find_child_by_attribute("Grid", "GridType", "Uniform");
    for (pugi::xml_node field : joined.front().children("Attribute"))
      mesh.append_copy(field);
    domain.remove_child(collections.front());
  }
  // pugixml's save_file does not see a write that fails when its buffer is
  // flushed (a full disk): the text goes through the checked writer.
  std::ostringstream text;
  doc.save(text, "  ");
  write_file_atomically(xdmf, text.str());
}

/// Every rank's failure becomes every rank's (fem/first_failure.h): a
/// collective step that failed on one rank must not leave the others waiting
/// in the next one. `failure`: this rank's message, empty if it succeeded.
void agree(MPI_Comm comm, const std::string& failure)
{
  if (const std::optional<RankFailure> first = first_failure(comm, failure.empty() ? 0 : 1, failure, write_patience()))
    throw ComputationError(first->rank == 0 ? first->message
                                            : fmt::format("{} (on rank {})", first->message, first->rank));
}

/// What DOLFINx's writer threw (std::runtime_error "Failed to create HDF5
/// file.", from HDF5 on a full disk or a vanished folder) as a message
/// naming the file.
std::string write_failure(const std::filesystem::path& target, const std::exception& e)
{
  return fmt::format("cannot write the fields '{}': {}", target.string(), e.what());
}
} // namespace

FieldSeries::FieldSeries(MPI_Comm comm, const std::filesystem::path& xdmf_path) : comm_(comm), target_(xdmf_path)
{
  // Our messages name the file; HDF5's own error stack would only repeat it.
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  // One temporary folder for all ranks, named by rank 0's process.
  long pid = static_cast<long>(::getpid());
  MPI_Bcast(&pid, 1, MPI_LONG, 0, comm);
  folder_ = target_.parent_path() / fmt::format(".{}.tmp{}", target_.stem().string(), pid);
  std::error_code error;
  if (rank == 0)
    std::filesystem::create_directories(folder_, error);
  agree(comm, error ? fmt::format("writing fields: cannot create '{}': {}", folder_.string(), error.message()) : "");
  try
  {
    call_collectively([&] { file_ = std::make_unique<dolfinx::io::XDMFFile>(comm, folder_ / target_.filename(), "w"); });
  }
  catch (const ComputationError&)
  {
    // Where the file was opened, closing it is a collective call the rank
    // that failed does not make: abandoned, as after a failed write.
    static_cast<void>(file_.release());
    remove_folder();
    throw;
  }
}

FieldSeries::~FieldSeries()
{
  // After a failed write, closing the HDF5 file fails again and would throw
  // out of this destructor: the writer is abandoned (its handle stays open
  // until the process ends) and only the temporary folder is removed.
  if (file_ && !failed_)
    try
    {
      file_->close();
    }
    catch (const std::exception&)
    {
      failed_ = true;
    }
  if (failed_)
    static_cast<void>(file_.release());
  file_.reset();
  remove_folder();
}

void FieldSeries::remove_folder()
{
  int rank = 0;
  MPI_Comm_rank(comm_, &rank);
  std::error_code ignored;
  if (rank == 0)
    std::filesystem::remove_all(folder_, ignored);
}

void FieldSeries::call_collectively(const std::function<void()>& call)
{
  std::string failure;
  try
  {
    call();
  }
  catch (const std::exception& e)
  {
    failure = write_failure(target_, e);
    // The other ranks may be held inside the writer, and the agreement end
    // every rank: the temporary folder goes first (a shared file system
    // shows it to every rank; elsewhere there is nothing to remove).
    std::error_code ignored;
    std::filesystem::remove_all(folder_, ignored);
  }
  try
  {
    agree(comm_, failure);
  }
  catch (const ComputationError&)
  {
    // Closing the file would be a collective call the failed rank may not
    // make: the writer is abandoned on every rank alike.
    failed_ = true;
    throw;
  }
}

void FieldSeries::write(const NodalFields& fields, int step)
{
  if (!mesh_written_)
  {
    call_collectively([&] { file_->write_mesh(*fields.pressure->function_space()->mesh()); });
    mesh_written_ = true;
  }
  for (const auto& field : {fields.displacement, stress_in_mesh_axes(*fields.stress), fields.von_mises,
                            fields.max_shear, fields.pressure})
    call_collectively([&] { file_->write_function(*field, step); });
}

void FieldSeries::close()
{
  call_collectively([&] { file_->close(); }); // HDF5 writes what it buffered here: a full disk fails here
  file_.reset();
  int rank = 0;
  MPI_Comm_rank(comm_, &rank);
  std::string message;
  if (rank == 0)
  {
    try
    {
      join_collections(folder_ / target_.filename());
      std::filesystem::path h5 = target_;
      h5.replace_extension(".h5");
      // The .h5 first: the .xdmf, which names it, appears only when its data are in place.
      move_into_place(folder_ / h5.filename(), h5);
      move_into_place(folder_ / target_.filename(), target_);
    }
    catch (const std::exception& e)
    {
      message = fmt::format("writing fields: cannot move the fields to '{}': {}", target_.string(), e.what());
    }
  }
  agree(comm_, message);
}

void write_fields(const std::filesystem::path& xdmf_path, const NodalFields& fields)
{
  FieldSeries series(fields.pressure->function_space()->mesh()->comm(), xdmf_path);
  series.write(fields, 1);
  series.close();
}
} // namespace rollcheck::fem
