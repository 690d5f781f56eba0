#include "fem/write_fields.h"
#include "core/error.h"
#include <dolfinx/io/XDMFFile.h>
#include <fmt/format.h>
#include <unistd.h>

namespace rollcheck::fem
{
void write_fields(const std::filesystem::path& xdmf_path, const NodalFields& fields)
{
  namespace fs = std::filesystem;
  const auto mesh = fields.pressure->function_space()->mesh();
  MPI_Comm comm = mesh->comm();
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  const fs::path target = fs::absolute(xdmf_path);
  if (target.extension() != ".xdmf")
    throw InputError(fmt::format("hertz: the field output '{}' must end in .xdmf", xdmf_path.string()));
  const fs::path dir = target.parent_path();
  if (!fs::is_directory(dir))
    throw InputError(fmt::format("hertz: the folder of the field output '{}' does not exist", xdmf_path.string()));

  // One scratch folder name for all ranks (rank 0's pid).
  int pid = static_cast<int>(::getpid());
  MPI_Bcast(&pid, 1, MPI_INT, 0, comm);
  const fs::path scratch = dir / fmt::format(".{}.tmp{}", target.stem().string(), pid);
  const fs::path h5 = fs::path(target).replace_extension(".h5");
  if (rank == 0)
    fs::create_directories(scratch);
  MPI_Barrier(comm);
  int failed = 0;
  std::string message;
  try
  {
    dolfinx::io::XDMFFile file(comm, scratch / target.filename(), "w");
    file.write_mesh(*mesh);
    for (const auto& f : {fields.displacement, fields.stress, fields.von_mises, fields.max_shear, fields.pressure})
      file.write_function(*f, 0.0);
    file.close();
  }
  catch (const std::exception& e)
  {
    failed = 1;
    message = e.what();
  }
  MPI_Allreduce(MPI_IN_PLACE, &failed, 1, MPI_INT, MPI_MAX, comm);
  if (rank == 0)
  {
    if (!failed)
    {
      fs::rename(scratch / h5.filename(), h5);
      fs::rename(scratch / target.filename(), target);
    }
    fs::remove_all(scratch);
  }
  MPI_Barrier(comm);
  if (failed)
    throw ComputationError(fmt::format("writing fields to '{}' failed: {}", xdmf_path.string(), message));
}
} // namespace rollcheck::fem
