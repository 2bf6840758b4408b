#include "contact/laws/halfspace.hpp"

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
  zz_spectrum_.assign(static_cast<std::size_t>(px) * py, 0.0);
  for (int dj = -(grid.my - 1); dj < grid.my; ++dj)
    for (int di = -(grid.mx - 1); di < grid.mx; ++di)
      zz_spectrum_[static_cast<std::size_t>((dj + py) % py) * px + (di + px) % px] =
          zz_[static_cast<std::size_t>(dj + grid.my - 1) * wx_ + (di + grid.mx - 1)];
  fft2(zz_spectrum_, false);
}

void HalfSpaceKernels::fft2(std::vector<std::complex<double>>& data, bool inverse) const {
  const int px = 2 * grid_.mx, py = 2 * grid_.my;
  Eigen::FFT<double> fft;
  std::vector<std::complex<double>> line, out;
  for (int direction = 0; direction < 2; ++direction) {
    const int length = direction == 0 ? px : py, count = direction == 0 ? py : px;
    line.resize(static_cast<std::size_t>(length));
    for (int c = 0; c < count; ++c) {
      auto at = [&](int k) -> std::complex<double>& {
        return direction == 0 ? data[static_cast<std::size_t>(c) * px + k]
                              : data[static_cast<std::size_t>(k) * px + c];
      };
      for (int k = 0; k < length; ++k)
        line[k] = at(k);
      if (inverse)
        fft.inv(out, line);
      else
        fft.fwd(out, line);
      for (int k = 0; k < length; ++k)
        at(k) = out[k];
    }
  }
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
  const int px = 2 * grid_.mx, py = 2 * grid_.my;
  std::vector<std::complex<double>> padded(static_cast<std::size_t>(px) * py, 0.0);
  for (int j = 0; j < grid_.my; ++j)
    for (int i = 0; i < grid_.mx; ++i)
      padded[static_cast<std::size_t>(j) * px + i] = p[static_cast<std::size_t>(j) * grid_.mx + i];
  fft2(padded, false);
  for (std::size_t k = 0; k < padded.size(); ++k)
    padded[k] *= zz_spectrum_[k];
  fft2(padded, true);
  std::vector<double> u(p.size());
  for (int j = 0; j < grid_.my; ++j)
    for (int i = 0; i < grid_.mx; ++i)
      u[static_cast<std::size_t>(j) * grid_.mx + i] =
          padded[static_cast<std::size_t>(j) * px + i].real();
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
