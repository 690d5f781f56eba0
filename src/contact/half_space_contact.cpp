#include "contact/half_space_contact.h"
#include "core/error.h"
#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <limits>
#include <numbers>
#include <numeric>
#include <span>
#include <unsupported/Eigen/FFT>

namespace rollcheck::contact
{
namespace
{
using Complex = std::complex<double>;

/// The smallest 2^a 3^b 5^c >= n (the FFT's fast sizes).
std::size_t fast_fft_size(std::size_t n)
{
  for (std::size_t m = std::max<std::size_t>(n, 1);; ++m)
  {
    std::size_t r = m;
    for (std::size_t f : {2, 3, 5})
      while (r % f == 0)
        r /= f;
    if (r == 1)
      return m;
  }
}

/// The smallest multiple of 4 of the fast sizes >= n: Eigen's real FFT
/// takes its half-length complex path only at multiples of 4.
std::size_t fast_real_fft_size(std::size_t n)
{
  return 4 * fast_fft_size((n + 3) / 4);
}

/// One FFT object a thread: it keeps the plans (twiddles) of the sizes it
/// has transformed, and its scratch is not shared between threads.
Eigen::FFT<double>& thread_fft()
{
  thread_local Eigen::FFT<double> fft = [] {
    Eigen::FFT<double> f;
    f.SetFlag(Eigen::FFT<double>::Unscaled);
    f.SetFlag(Eigen::FFT<double>::HalfSpectrum);
    return f;
  }();
  return fft;
}

/// The complex transform along x, forward or inverse (unscaled), of each
/// column of a row-major px x half array, in place.
void transform_columns(std::vector<Complex>& data, std::size_t px, std::size_t half, bool inverse)
{
  Eigen::FFT<double>& fft = thread_fft();
  std::vector<Complex> in(px), out(px);
  for (std::size_t j = 0; j < half; ++j)
  {
    for (std::size_t i = 0; i < px; ++i)
      in[i] = data[i * half + j];
    if (inverse)
      fft.inv(out.data(), in.data(), static_cast<Eigen::DenseIndex>(px));
    else
      fft.fwd(out.data(), in.data(), static_cast<Eigen::DenseIndex>(px));
    for (std::size_t i = 0; i < px; ++i)
      data[i * half + j] = out[i];
  }
}

/// The 2D spectrum of a real row-major array of `rows` x `ny` values, zero
/// beyond them to px x py (py a multiple of 4): each row's half spectrum
/// (py / 2 + 1 values, Hermitian symmetry gives the rest), then the complex
/// transform along x of each of those columns. Row-major px x (py / 2 + 1).
std::vector<Complex> real_spectrum_2d(std::span<const double> values, std::size_t rows, std::size_t ny,
                                      std::size_t px, std::size_t py)
{
  Eigen::FFT<double>& fft = thread_fft();
  const std::size_t half = py / 2 + 1;
  std::vector<Complex> spectrum(px * half, 0.0);
  std::vector<double> row(py, 0.0);
  for (std::size_t i = 0; i < rows; ++i)
  {
    std::copy_n(values.begin() + static_cast<std::ptrdiff_t>(i * ny), ny, row.begin());
    fft.fwd(spectrum.data() + i * half, row.data(), static_cast<Eigen::DenseIndex>(py));
  }
  transform_columns(spectrum, px, half, false);
  return spectrum;
}

/// The first `rows` x `ny` values of the real array whose spectrum
/// real_spectrum_2d gave (unscaled: times px py).
std::vector<double> real_inverse_2d(std::vector<Complex>& spectrum, std::size_t rows, std::size_t ny, std::size_t px,
                                    std::size_t py)
{
  Eigen::FFT<double>& fft = thread_fft();
  const std::size_t half = py / 2 + 1;
  transform_columns(spectrum, px, half, true);
  std::vector<double> values(rows * ny), row(py);
  for (std::size_t i = 0; i < rows; ++i)
  {
    fft.inv(row.data(), spectrum.data() + i * half, static_cast<Eigen::DenseIndex>(py));
    std::copy_n(row.begin(), ny, values.begin() + static_cast<std::ptrdiff_t>(i * ny));
  }
  return values;
}
} // namespace

double love_corner_integral(double s_m, double t_m)
{
  double value = 0;
  if (s_m != 0)
    value += s_m * std::asinh(t_m / std::abs(s_m));
  if (t_m != 0)
    value += t_m * std::asinh(s_m / std::abs(t_m));
  return value;
}

double cell_deflection(double half_x_m, double half_y_m, double x_m, double y_m, double effective_modulus_pa)
{
  const double a = half_x_m, c = half_y_m;
  return (love_corner_integral(x_m + a, y_m + c) - love_corner_integral(x_m + a, y_m - c) - love_corner_integral(x_m - a, y_m + c)
          + love_corner_integral(x_m - a, y_m - c))
         / (std::numbers::pi * effective_modulus_pa);
}

HalfSpaceDeflection::HalfSpaceDeflection(const HalfSpaceGrid& grid, double effective_modulus_pa)
    : grid_(grid), padded_x_(fast_fft_size(2 * grid.nx)), padded_y_(fast_real_fft_size(2 * grid.ny))
{
  if (grid.nx == 0 || grid.ny == 0 || !(grid.cell_x_m > 0) || !(grid.cell_y_m > 0))
    throw InputError(fmt::format("half-space contact: the grid needs cells ({} x {}) of positive size ({} x {} m)",
                                 grid.nx, grid.ny, grid.cell_x_m, grid.cell_y_m));
  if (!(effective_modulus_pa > 0) || !std::isfinite(effective_modulus_pa))
    throw InputError(fmt::format("half-space contact: E* must be positive, got {} Pa", effective_modulus_pa));
  // Circular layout: offsets 0..n-1 first, then -(n-1)..-1 at the end; the
  // padding between never meets a cell of the grid.
  const auto offset = [](std::size_t k, std::size_t n, std::size_t padded) -> double {
    if (k < n)
      return static_cast<double>(k);
    if (k > padded - n)
      return static_cast<double>(k) - static_cast<double>(padded);
    return std::nan("");
  };
  std::vector<double> kernel(padded_x_ * padded_y_, 0.0);
  for (std::size_t i = 0; i < padded_x_; ++i)
  {
    const double di = offset(i, grid.nx, padded_x_);
    if (std::isnan(di))
      continue;
    for (std::size_t j = 0; j < padded_y_; ++j)
    {
      const double dj = offset(j, grid.ny, padded_y_);
      if (!std::isnan(dj))
        kernel[i * padded_y_ + j] = cell_deflection(grid.cell_x_m / 2, grid.cell_y_m / 2, di * grid.cell_x_m,
                                                    dj * grid.cell_y_m, effective_modulus_pa);
    }
  }
  kernel_spectrum_ = real_spectrum_2d(kernel, padded_x_, padded_y_, padded_x_, padded_y_);
  // The inverse transform's 1 / N, once.
  const double scale = 1.0 / static_cast<double>(padded_x_ * padded_y_);
  for (Complex& k : kernel_spectrum_)
    k *= scale;
}

std::vector<double> HalfSpaceDeflection::operator()(std::span<const double> pressure_pa) const
{
  if (pressure_pa.size() != grid_.size())
    throw InputError(fmt::format("half-space contact: {} pressures for a grid of {} cells", pressure_pa.size(),
                                 grid_.size()));
  // The pressure is real and zero beyond the grid's nx rows: half spectra
  // along y, and the rows beyond nx neither transformed nor transformed back.
  std::vector<Complex> work = real_spectrum_2d(pressure_pa, grid_.nx, grid_.ny, padded_x_, padded_y_);
  for (std::size_t k = 0; k < work.size(); ++k)
    work[k] *= kernel_spectrum_[k];
  return real_inverse_2d(work, grid_.nx, grid_.ny, padded_x_, padded_y_);
}

namespace
{
/// InputError for a gap or force the solver cannot take.
void check_problem(std::size_t cells, std::span<const double> gap_m, double force_n)
{
  if (gap_m.size() != cells)
    throw InputError(fmt::format("half-space contact: {} gap values for a grid of {} cells", gap_m.size(), cells));
  if (!(force_n > 0) || !std::isfinite(force_n))
    throw InputError(fmt::format("half-space contact: the force must be positive and finite, got {} N", force_n));
  if (const auto bad = std::ranges::find_if(gap_m, [](double g) { return !std::isfinite(g); }); bad != gap_m.end())
    throw InputError(fmt::format("half-space contact: the gap is not finite at cell {}", bad - gap_m.begin()));
}

/// The iteration's start: `initial_pressure_pa` scaled to F where it carries
/// any, else F spread evenly.
std::vector<double> starting_pressure(std::span<const double> initial_pressure_pa, double force_n, double area,
                                      std::size_t n)
{
  std::vector<double> p(n, force_n / (area * static_cast<double>(n)));
  if (initial_pressure_pa.empty())
    return p;
  if (initial_pressure_pa.size() != n)
    throw InputError("half-space contact: the initial pressure has the wrong size");
  const double total = std::accumulate(initial_pressure_pa.begin(), initial_pressure_pa.end(), 0.0) * area;
  if (total > 0)
    for (std::size_t k = 0; k < n; ++k)
      p[k] = std::max(0.0, initial_pressure_pa[k]) * force_n / total;
  return p;
}

/// Polonsky and Keer (1999), section 3: conjugate gradients on the loaded
/// cells, the gap's mean over them the approach, the force rescaled each step.
class ConstrainedConjugateGradient
{
public:
  ConstrainedConjugateGradient(const HalfSpaceDeflection& deflection, std::span<const double> gap_m, double force_n)
      : deflection_(deflection), gap_m_(gap_m), force_(force_n), area_(deflection.grid().cell_area_m2()),
        direction_(gap_m.size(), 0.0), gap_(gap_m.size())
  {
  }

  /// One step from p (in place); the change A sum |p_new - p_old| / F.
  double step(std::vector<double>& p)
  {
    const std::size_t loaded = centre_gap(p);
    const double length = step_length(p, loaded);
    const std::vector<double> p_old = p;
    bool overlap = false;
    for (std::size_t k = 0; k < p.size(); ++k)
    {
      if (p[k] > 0)
        p[k] = std::max(0.0, p[k] - length * direction_[k]);
      else if (gap_[k] < 0)
      {
        // An unloaded cell the surfaces pass through joins the contact.
        p[k] = -length * gap_[k];
        overlap = true;
      }
    }
    conjugate_ = !overlap;
    const double total = std::accumulate(p.begin(), p.end(), 0.0) * area_;
    if (!(total > 0))
      throw ComputationError("half-space contact: the iteration lost every loaded cell");
    double change = 0;
    for (std::size_t k = 0; k < p.size(); ++k)
    {
      p[k] *= force_ / total;
      change += std::abs(p[k] - p_old[k]);
    }
    return change * (area_ / force_);
  }

private:
  /// The gap h + u less its mean over the loaded cells; their number.
  std::size_t centre_gap(const std::vector<double>& p)
  {
    const std::vector<double> u = deflection_(p);
    double mean = 0;
    std::size_t loaded = 0;
    for (std::size_t k = 0; k < p.size(); ++k)
    {
      gap_[k] = gap_m_[k] + u[k];
      if (p[k] > 0)
      {
        mean += gap_[k];
        ++loaded;
      }
    }
    if (loaded == 0)
      throw ComputationError("half-space contact: no cell carries load");
    mean /= static_cast<double>(loaded);
    for (std::size_t k = 0; k < p.size(); ++k)
      gap_[k] -= mean;
    return loaded;
  }

  /// The conjugate direction over the loaded cells and the step along it.
  double step_length(const std::vector<double>& p, std::size_t loaded)
  {
    const std::size_t n = p.size();
    double gap_norm = 0;
    for (std::size_t k = 0; k < n; ++k)
      if (p[k] > 0)
        gap_norm += gap_[k] * gap_[k];
    for (std::size_t k = 0; k < n; ++k)
      direction_[k] = p[k] > 0 ? gap_[k] + (conjugate_ ? gap_norm / gap_norm_old_ : 0.0) * direction_[k] : 0.0;
    gap_norm_old_ = gap_norm;
    const std::vector<double> response = deflection_(direction_);
    double response_mean = 0;
    for (std::size_t k = 0; k < n; ++k)
      if (p[k] > 0)
        response_mean += response[k];
    response_mean /= static_cast<double>(loaded);
    double numerator = 0, denominator = 0;
    for (std::size_t k = 0; k < n; ++k)
      if (p[k] > 0)
      {
        numerator += gap_[k] * direction_[k];
        denominator += (response[k] - response_mean) * direction_[k];
      }
    return denominator != 0 ? numerator / denominator : 0.0;
  }

  const HalfSpaceDeflection& deflection_;
  std::span<const double> gap_m_;
  double force_, area_;
  std::vector<double> direction_, gap_;
  double gap_norm_old_ = 1.0;
  bool conjugate_ = false;
};

/// The solved pressure's deflection, approach and largest gap violation into
/// `result`; ContactBeyondGrid where a border cell carries load.
void finish(HalfSpaceContact& result, const HalfSpaceDeflection& deflection, std::span<const double> gap_m,
            std::vector<double> p, const HalfSpaceContactSettings& settings)
{
  const HalfSpaceGrid& grid = deflection.grid();
  const std::size_t n = grid.size();
  result.deflection_m = deflection(p);
  result.approach_m = 0;
  std::size_t loaded = 0;
  for (std::size_t k = 0; k < n; ++k)
    if (p[k] > 0)
    {
      result.approach_m += gap_m[k] + result.deflection_m[k];
      ++loaded;
    }
  result.approach_m /= static_cast<double>(loaded);
  result.largest_gap_violation_m = -std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < n; ++k)
    if (p[k] <= 0)
      result.largest_gap_violation_m =
          std::max(result.largest_gap_violation_m, result.approach_m - gap_m[k] - result.deflection_m[k]);
  for (std::size_t i = 0; i < grid.nx; ++i)
    for (std::size_t j = 0; j < grid.ny; ++j)
    {
      const bool border = i == 0 || j == 0 || j + 1 == grid.ny || (i + 1 == grid.nx && !settings.contact_continues_past_last_x);
      if (border && p[i * grid.ny + j] > 0)
        throw ContactBeyondGrid(fmt::format("half-space contact: the contact reaches the grid's border at cell ({}, "
                                            "{}) (x = {:.4g} m, y = {:.4g} m): the grid must hold the whole contact",
                                            i, j, grid.x(i), grid.y(j)),
                                j == 0 || j + 1 == grid.ny);
    }
  result.pressure_pa = std::move(p);
}
} // namespace

HalfSpaceContact solve_half_space_contact(const HalfSpaceDeflection& deflection, std::span<const double> gap_m,
                                          double force_n, const HalfSpaceContactSettings& settings,
                                          std::span<const double> initial_pressure_pa)
{
  const std::size_t n = deflection.grid().size();
  check_problem(n, gap_m, force_n);
  std::vector<double> p = starting_pressure(initial_pressure_pa, force_n, deflection.grid().cell_area_m2(), n);
  ConstrainedConjugateGradient iteration(deflection, gap_m, force_n);
  HalfSpaceContact result;
  for (int k = 1;; ++k)
  {
    result.iterations = k;
    result.change = iteration.step(p);
    if (result.change < settings.tolerance)
      break;
    if (k >= settings.max_iterations || !std::isfinite(result.change))
      throw ComputationError(fmt::format("half-space contact: no convergence in {} iterations (change {:.3g}, "
                                         "tolerance {:.3g})",
                                         k, result.change, settings.tolerance));
  }
  finish(result, deflection, gap_m, std::move(p), settings);
  return result;
}
} // namespace rollcheck::contact
