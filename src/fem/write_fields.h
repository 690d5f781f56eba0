#pragma once
// The recovered fields of a solve, with DOLFINx's own writer
// (dolfinx::io::XDMFFile, HDF5 encoding): NAME.xdmf with the mesh and, per
// load step, every field as a node attribute of a temporal collection, its
// data in NAME.h5 beside it. The step's "time" is its number, 1, 2, ...
// (load control's steps overshoot and return: their forces are not
// monotonic). Fields, all P1 and float64: "displacement", "stress" (3x3),
// "von_mises", "max_shear", "contact_pressure". DOLFINx writes one temporal
// collection per function; close() joins them into one whose k-th grid holds
// every field of step k, the layout readers of one collection expect
// (meshio's TimeSeriesReader; ParaView reads either); a series of one step
// becomes one grid, the mesh's, with every field (meshio.read opens it).
//
// Components follow the mesh's axes, so that ParaView's names mean what they
// say: in 3D (x, y, z); in the axisymmetric and plane-strain models, whose
// mesh is (x = r, y = z, the vertical), the stress is written in (r, z, theta)
// (plane strain: (x, y, out of plane)): stress_XX = sigma_rr, stress_YY =
// sigma_zz, stress_ZZ = sigma_theta theta, stress_XY = sigma_rz. (The
// recovery, fem/nodal_fields.h, orders it (r, theta, z).)
//
// The pair is written whole or not at all: into a temporary folder beside
// the target, flushed to the disk and moved into place by close(); the
// target's folder was checked before any computation by the scene's setup
// (fem::validate). A write that fails (a full disk, the folder gone) is a
// ComputationError naming the target (exit 1); the temporary folder is
// removed and a previous NAME.xdmf / NAME.h5 stay as they were. Under MPI
// a write can fail on one rank only (its part of NAME.h5 meets a full disk or
// a file-size limit): every step of the writer is collective, so the ranks
// agree on each one's outcome (fem/first_failure.h) and every rank throws
// the failing rank's message, instead of the others waiting for ever in the
// writer's next collective call. Where the others are held inside the step
// (HDF5 reduces over the ranks within a dataset write), the failed rank
// removes the temporary folder, names the file and, after the write's
// patience (fem/field_output.h write_patience), ends every rank
// (MPI_Abort, exit 1).
#include "fem/nodal_fields.h"
#include <dolfinx/io/XDMFFile.h>
#include <filesystem>
#include <functional>
#include <memory>

namespace rollcheck::fem
{
class FieldSeries
{
public:
  /// Opens the series on the communicator of the fields to come.
  FieldSeries(MPI_Comm comm, const std::filesystem::path& xdmf_path);
  FieldSeries(const FieldSeries&) = delete;
  FieldSeries& operator=(const FieldSeries&) = delete;
  /// Removes the temporary folder if close() was not reached.
  ~FieldSeries();

  /// Appends the fields of load step `step` (1, 2, ...); the mesh is written with the first.
  void write(const NodalFields& fields, int step);

  /// Moves NAME.xdmf and NAME.h5 into place (collective).
  void close();

private:
  void remove_folder();
  /// One collective call of DOLFINx's writer; a failure on any rank is thrown on every rank.
  void call_collectively(const std::function<void()>& call);

  MPI_Comm comm_;
  std::filesystem::path target_, folder_;
  std::unique_ptr<dolfinx::io::XDMFFile> file_;
  bool mesh_written_ = false;
  bool failed_ = false; ///< a write or the close failed: the writer cannot be closed again
};

/// The fields of one state, as a series of one step.
void write_fields(const std::filesystem::path& xdmf_path, const NodalFields& fields);
} // namespace rollcheck::fem
