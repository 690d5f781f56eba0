#pragma once
// The plane-strain slice (fem/scenes/slice_contact.h) as one nondimensional problem.
//
// A slice of radius R pressed onto the rigid plane by the line load q is, in
// small-strain linear elasticity with frictionless contact, the same problem
// at every scale: measure lengths in R and stresses in E*, and its only data
// are the load ratio and Poisson's ratio,
//     lambda = q / (E* R).
// The discrete problem scales with it: the mesh is graded from the Hertz
// half-width b = R sqrt(4 lambda / pi) and sized in R (fem/scenes/hertz_setup.h),
// and the penalty kappa = c E / h_c follows the contact elements. Hence
//     p_fem(R, q) = p_hertz(R, q) g(lambda),
//     p_hertz = sqrt(q E* / (pi R)) = E* sqrt(lambda / pi)
// (K. L. Johnson, "Contact Mechanics", CUP 1985, eq. 4.45), with one FEM
// correction g for each lambda, whatever R: every slice of every orientation
// of a rolling loop is one of these problems. (Test: R and q doubled together
// give the same g to 1e-6.)
//
// g is tabulated at the nodes lambda_k = 10^(k / nodes_per_decade), solved at
// the unit radius on demand (`cover`), or read where another process of the
// job solved them (fem/scenes/slice_table_store.h, serial runs), and
// interpolated linearly in log lambda between them. Each node is a SliceFem: the settings' mesh level and one
// finer. Every other node (`stride` 2) is the table with half the nodes, so
// the table's own convergence costs nothing extra.
#include "contact/load_ratio.h"
#include "fem/scenes/slice_contact.h"
#include <array>
#include <map>
#include <mpi.h>
#include <vector>

namespace rollcheck::fem
{
class SliceScaling
{
public:
  /// The least load ratio the table solves: below it b / R < 4e-6 and the
  /// plane-strain solver's LU fails (measured: 1.65e-11 solves, 1e-12 does
  /// not). Smaller ratios take g at this one: g tends to a constant as
  /// b / R -> 0 (the half-space limit; measured 1.001-1.003 from 1e-11 to
  /// 1e-8), and callers count the points held there.
  static constexpr double smallest_load_ratio = 1e-11;

  /// `settings` as for solve_slices; E* is the slices' (rigid or elastic plane).
  SliceScaling(const SliceSettings& settings, int nodes_per_decade);
  // The index points into the nodes: a copy's would point into this one's.
  SliceScaling(const SliceScaling&) = delete;
  SliceScaling& operator=(const SliceScaling&) = delete;
  SliceScaling(SliceScaling&&) = default;
  SliceScaling& operator=(SliceScaling&&) = default;

  /// Solves the nodes not yet solved that the tables of stride 1 and 2 need to
  /// interpolate over [lambda_min, lambda_max]. Collective on `comm` (the
  /// ranks share the nodes); ComputationError from a failed solve.
  void cover(MPI_Comm comm, double lambda_min, double lambda_max);

  /// Doubles the nodes per decade, keeping every solved node (k becomes 2k).
  void double_nodes();

  /// g(lambda) from every `stride`-th node; `refined` from the finer level.
  /// ComputationError outside the covered range.
  double ratio(double lambda, int stride = 1, bool refined = false) const;
  /// {ratio(lambda, 1), ratio(lambda, 2)}, equal to theirs to the bit, with
  /// one logarithm: the table and its half, read at every Gauss point of a loop.
  std::array<double, 2> ratios(double lambda) const;

  struct Node
  {
    int k = 0;                ///< lambda = 10^(k / nodes_per_decade)
    double lambda = 0;
    SliceFem fem;             ///< at the unit radius
    double ratio = 0;         ///< g: FEM peak / Hertz peak
    double refined_ratio = 0; ///< the same one mesh level finer
  };
  const std::map<int, Node>& nodes() const { return nodes_; }
  int nodes_per_decade() const { return nodes_per_decade_; }
  double effective_modulus_pa() const { return effective_modulus_pa_; }
  /// Seconds spent solving nodes in `cover`, summed over its calls.
  double wall_s() const { return wall_s_; }
  /// Nodes read from another process's solves (slice_table_store.h), not solved here.
  std::size_t nodes_read() const { return nodes_read_; }

private:
  SliceSettings settings_;
  int nodes_per_decade_;
  double effective_modulus_pa_;
  std::map<int, Node> nodes_;
  /// nodes_ by k - first_k_ (null where no node is solved): ratio() is
  /// called at every Gauss point of every loop sample.
  int first_k_ = 0;
  std::vector<const Node*> by_k_;
  void index_nodes();
  /// ratio() at `position` = nodes_per_decade * log10(lambda).
  double interpolate(double lambda, double position, int stride, bool refined) const;
  void add_node(int k, const SliceFem& fem);
  double wall_s_ = 0;
  std::size_t nodes_read_ = 0;
};
} // namespace rollcheck::fem
