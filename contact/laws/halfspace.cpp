#include "contact/laws/halfspace.hpp"

#include <algorithm>
#include <cmath>

#include <unsupported/Eigen/FFT>

namespace railfe {

namespace {

// Corner functions whose signed sums over a rectangle's corners integrate 1/r, x²/r³, y²/r³
// and xy/r³ over it (the asinh forms avoid the logarithm's singularities on the axes).
double x_asinh(double x, double y) {
  return x == 0 ? 0.0 : x * std::asinh(y / std::abs(x));
}
double integral_inverse_r(double x, double y) {
  return x_asinh(x, y) + x_asinh(y, x);
}
double integral_xx(double x, double y) {  // of x²/r³
  return x_asinh(y, x);
}
double integral_yy(double x, double y) {  // of y²/r³
  return x_asinh(x, y);
}
double integral_xy(double x, double y) {  // of xy/r³
  return -std::hypot(x, y);
}

// The integral over the element centred at the origin, of half-sizes hx, hy, seen from (X, Y).
template <class F>
double over_element(F f, double X, double Y, double hx, double hy) {
  return f(X + hx, Y + hy) - f(X + hx, Y - hy) - f(X - hx, Y + hy) + f(X - hx, Y - hy);
}

// FFT engines keep their plans per length: one per thread, one for real lines (half spectra)
// and one for complex columns.
Eigen::FFT<double>& real_engine() {
  thread_local Eigen::FFT<double> engine(Eigen::default_fft_impl<double>(),
                                         Eigen::FFT<double>::HalfSpectrum);
  return engine;
}
Eigen::FFT<double>& complex_engine() {
  thread_local Eigen::FFT<double> engine;
  return engine;
}

// Transforms column \p k (\p rows entries, stride \p width) of \p data in place.
void column_transform(std::vector<std::complex<double>>& data, int k, int width, int rows,
                      bool inverse) {
  thread_local std::vector<std::complex<double>> line, out;
  line.resize(static_cast<std::size_t>(rows));
  out.resize(static_cast<std::size_t>(rows));
  for (int l = 0; l < rows; ++l)
    line[l] = data[static_cast<std::size_t>(l) * width + k];
  if (inverse)
    complex_engine().inv(out.data(), line.data(), rows);
  else
    complex_engine().fwd(out.data(), line.data(), rows);
  for (int l = 0; l < rows; ++l)
    data[static_cast<std::size_t>(l) * width + k] = out[l];
}

}  // namespace

HalfSpaceKernels::HalfSpaceKernels(const ContactGrid& grid, double G, double nu)
    : grid_(grid), wx_(2 * grid.mx - 1), wy_(2 * grid.my - 1) {
  const std::size_t n = static_cast<std::size_t>(wx_) * wy_;
  zz_.resize(n);
  xx_.resize(n);
  yy_.resize(n);
  xy_.resize(n);
  const double hx = grid.dx / 2, hy = grid.dy / 2;
  // One body's surface (Johnson 3.2, 3.3): Boussinesq (1 - nu) / (2 pi G) ∫ p / r; Cerruti
  // 1 / (2 pi G) ∫ q ((1 - nu) / r + nu x² / r³) along q and nu xy / r³ across. Two bodies of
  // the same material: the surfaces' difference is twice that ((1 - nu) / (pi G) = 1 / (pi E*)).
  const double normal = (1 - nu) / (M_PI * G), shear = 1 / (M_PI * G);
  for (int b = 0; b < wy_; ++b)
    for (int a = 0; a < wx_; ++a) {
      const double X = (a - (grid.mx - 1)) * grid.dx, Y = (b - (grid.my - 1)) * grid.dy;
      const double inverse_r = over_element(integral_inverse_r, X, Y, hx, hy);
      const std::size_t k = static_cast<std::size_t>(b) * wx_ + a;
      zz_[k] = normal * inverse_r;
      xx_[k] = shear * ((1 - nu) * inverse_r + nu * over_element(integral_xx, X, Y, hx, hy));
      yy_[k] = shear * ((1 - nu) * inverse_r + nu * over_element(integral_yy, X, Y, hx, hy));
      xy_[k] = shear * nu * over_element(integral_xy, X, Y, hx, hy);
    }
  // The kernel wrapped onto the padded grid: offset (di, dj) at (di mod 2mx, dj mod 2my).
  const int px = 2 * grid.mx, py = 2 * grid.my;
  std::vector<double> wrapped(static_cast<std::size_t>(px) * py, 0.0);
  for (int dj = -(grid.my - 1); dj < grid.my; ++dj)
    for (int di = -(grid.mx - 1); di < grid.mx; ++di)
      wrapped[static_cast<std::size_t>((dj + py) % py) * px + (di + px) % px] =
          zz_[static_cast<std::size_t>(dj + grid.my - 1) * wx_ + (di + grid.mx - 1)];
  zz_spectrum_ = half_spectrum(wrapped, py);
  const int half = grid.mx + 1;
  for (int k = 0; k < half; ++k)
    column_transform(zz_spectrum_, k, half, py, false);
}

std::vector<std::complex<double>> HalfSpaceKernels::half_spectrum(const std::vector<double>& padded,
                                                                  int rows) const {
  const int px = 2 * grid_.mx, py = 2 * grid_.my, half = grid_.mx + 1;
  std::vector<std::complex<double>> spectrum(static_cast<std::size_t>(half) * py, 0.0);
  for (int j = 0; j < rows; ++j)
    real_engine().fwd(&spectrum[static_cast<std::size_t>(j) * half],
                      &padded[static_cast<std::size_t>(j) * px], px);
  return spectrum;
}

void HalfSpaceKernels::convolve(const std::vector<double>& kernel, const std::vector<double>& in,
                                std::vector<double>& out, bool accumulate) const {
  const int mx = grid_.mx, my = grid_.my;
  if (!accumulate)
    out.assign(in.size(), 0.0);
  for (int l = 0; l < my; ++l)
    for (int k = 0; k < mx; ++k) {
      const double source = in[static_cast<std::size_t>(l) * mx + k];
      if (source == 0)
        continue;
      for (int j = 0; j < my; ++j) {
        const double* row = &kernel[static_cast<std::size_t>(j - l + my - 1) * wx_ + (mx - 1 - k)];
        double* target = &out[static_cast<std::size_t>(j) * mx];
        for (int i = 0; i < mx; ++i)
          target[i] += row[i] * source;
      }
    }
}

std::vector<double> HalfSpaceKernels::normal(const std::vector<double>& p) const {
  const int mx = grid_.mx, my = grid_.my, px = 2 * mx, py = 2 * my, half = mx + 1;
  std::vector<double> padded(static_cast<std::size_t>(px) * my, 0.0);
  for (int j = 0; j < my; ++j)
    std::copy_n(&p[static_cast<std::size_t>(j) * mx], mx,
                &padded[static_cast<std::size_t>(j) * px]);
  std::vector<std::complex<double>> spectrum = half_spectrum(padded, my);
  for (int k = 0; k < half; ++k) {
    column_transform(spectrum, k, half, py, false);
    for (int l = 0; l < py; ++l)
      spectrum[static_cast<std::size_t>(l) * half + k] *=
          zz_spectrum_[static_cast<std::size_t>(l) * half + k];
    column_transform(spectrum, k, half, py, true);
  }
  std::vector<double> u(p.size()), line(static_cast<std::size_t>(px));
  for (int j = 0; j < my; ++j) {
    real_engine().inv(line.data(), &spectrum[static_cast<std::size_t>(j) * half], px);
    std::copy_n(line.data(), mx, &u[static_cast<std::size_t>(j) * mx]);
  }
  return u;
}

std::vector<double> HalfSpaceKernels::normal_direct(const std::vector<double>& p) const {
  std::vector<double> u;
  convolve(zz_, p, u, false);
  return u;
}

void HalfSpaceKernels::tangential(const std::vector<double>& px, const std::vector<double>& py,
                                  std::vector<double>& ux, std::vector<double>& uy) const {
  convolve(xx_, px, ux, false);
  convolve(xy_, py, ux, true);
  convolve(xy_, px, uy, false);
  convolve(yy_, py, uy, true);
}

}  // namespace railfe
