#include "contact/laws/halfspace.hpp"

#include <fftw3.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <mutex>
#include <new>

namespace railfe {

namespace {

// x asinh(y / |x|): at an element's corners, with the arguments either way round, its signed
// sum integrates y²/r³ or x²/r³ over the element, and the two together 1/r (the asinh form
// avoids the logarithm's singularities on the axes); -r's signed sum integrates xy/r³.
double x_asinh(double x, double y) {
  return x == 0 ? 0.0 : x * std::asinh(y / std::abs(x));
}

// FFTW plans for one padded size, with the aligned buffers they run on. Each thread keeps its
// own per size, so the solves of a run plan once. FFTW_ESTIMATE: measuring the plans (seconds
// on a busy machine) bought no measurable speed on these sizes. FFTW's planner is not
// thread-safe: planning holds a lock.
class PaddedTransform {
 public:
  PaddedTransform(int px, int py)
      : real_count_(static_cast<std::size_t>(px) * py),
        complex_count_(static_cast<std::size_t>(px / 2 + 1) * py) {
    std::lock_guard<std::mutex> lock(planner_mutex());
    real_ = fftw_alloc_real(real_count_);
    spectrum_ = fftw_alloc_complex(complex_count_);
    if (!real_ || !spectrum_)
      throw std::bad_alloc();
    forward_ = fftw_plan_dft_r2c_2d(py, px, real_, spectrum_, FFTW_ESTIMATE);
    inverse_ = fftw_plan_dft_c2r_2d(py, px, spectrum_, real_, FFTW_ESTIMATE);
  }
  ~PaddedTransform() {
    std::lock_guard<std::mutex> lock(planner_mutex());
    fftw_destroy_plan(forward_);
    fftw_destroy_plan(inverse_);
    fftw_free(real_);
    fftw_free(spectrum_);
  }
  PaddedTransform(const PaddedTransform&) = delete;
  PaddedTransform& operator=(const PaddedTransform&) = delete;
  /// The padded real grid (py rows of px) the forward transform reads and the inverse writes.
  double* real() { return real_; }
  /// The half spectrum (py rows of px / 2 + 1).
  std::complex<double>* spectrum() { return reinterpret_cast<std::complex<double>*>(spectrum_); }
  std::size_t spectrum_size() const { return complex_count_; }
  void forward() { fftw_execute(forward_); }
  void inverse() { fftw_execute(inverse_); }
  /// This thread's transform for a px × py padded grid.
  static PaddedTransform& of(int px, int py) {
    thread_local std::map<std::pair<int, int>, std::unique_ptr<PaddedTransform>> cache;
    std::unique_ptr<PaddedTransform>& t = cache[{px, py}];
    if (!t)
      t = std::make_unique<PaddedTransform>(px, py);
    return *t;
  }

 private:
  static std::mutex& planner_mutex() {
    static std::mutex m;
    return m;
  }
  std::size_t real_count_, complex_count_;
  double* real_ = nullptr;
  fftw_complex* spectrum_ = nullptr;
  fftw_plan forward_, inverse_;
};

}  // namespace

HalfSpaceKernels::HalfSpaceKernels(const ContactGrid& grid, double G, double nu)
    : grid_(grid), wx_(2 * grid.mx - 1), wy_(2 * grid.my - 1) {
  const std::size_t n = static_cast<std::size_t>(wx_) * wy_;
  zz_.resize(n);
  xx_.resize(n);
  yy_.resize(n);
  xy_.resize(n);
  // The corner functions on the lattice of element corners (offsets of half-integer elements):
  // each kernel entry is a signed sum over four neighbouring corners, so every corner function is
  // evaluated once instead of four times; and only on one quadrant, the lattice being symmetric
  // and x asinh(y / |x|) odd in x and in y (r even). (Fresh memory is slow to touch here: no
  // full-lattice copies.)
  const int mx = grid.mx, my = grid.my;
  std::vector<double> along_y(static_cast<std::size_t>(mx) * my), along_x(along_y.size()),
      radius(along_y.size());
  for (int d = 0; d < my; ++d)
    for (int c = 0; c < mx; ++c) {
      const double x = (c + 0.5) * grid.dx, y = (d + 0.5) * grid.dy;
      const std::size_t k = static_cast<std::size_t>(d) * mx + c;
      along_y[k] = x_asinh(x, y);  // integral of y²/r³
      along_x[k] = x_asinh(y, x);  // integral of x²/r³
      radius[k] = std::hypot(x, y);
    }
  // Corner (c, d) of the full lattice (0 <= c <= 2 mx - 1) from the quadrant, with its sign.
  const auto corner = [mx, my](const std::vector<double>& f, int c, int d, bool odd) {
    const int qc = c >= mx ? c - mx : mx - 1 - c, qd = d >= my ? d - my : my - 1 - d;
    const double value = f[static_cast<std::size_t>(qd) * mx + qc];
    return odd && (c >= mx) != (d >= my) ? -value : value;
  };
  const auto over = [&corner](const std::vector<double>& f, int a, int b, bool odd) {
    return corner(f, a + 1, b + 1, odd) - corner(f, a + 1, b, odd) - corner(f, a, b + 1, odd) +
           corner(f, a, b, odd);
  };
  // One body's surface (Johnson 3.2, 3.3): Boussinesq (1 - nu) / (2 pi G) ∫ p / r; Cerruti
  // 1 / (2 pi G) ∫ q ((1 - nu) / r + nu x² / r³) along q and nu xy / r³ across. Two bodies of
  // the same material: the surfaces' difference is twice that ((1 - nu) / (pi G) = 1 / (pi E*)).
  const double normal = (1 - nu) / (M_PI * G), shear = 1 / (M_PI * G);
  for (int b = 0; b < wy_; ++b)
    for (int a = 0; a < wx_; ++a) {
      const double xx = over(along_x, a, b, true), yy = over(along_y, a, b, true);
      const double inverse_r = xx + yy;
      const std::size_t k = static_cast<std::size_t>(b) * wx_ + a;
      zz_[k] = normal * inverse_r;
      xx_[k] = shear * ((1 - nu) * inverse_r + nu * xx);
      yy_[k] = shear * ((1 - nu) * inverse_r + nu * yy);
      xy_[k] = -shear * nu * over(radius, a, b, false);
    }
  // The kernel wrapped onto the padded grid: offset (di, dj) at (di mod 2mx, dj mod 2my); its
  // spectrum carries the inverse transform's 1 / (2mx 2my).
  const int px = 2 * grid.mx, py = 2 * grid.my;
  PaddedTransform& transform = PaddedTransform::of(px, py);
  double* wrapped = transform.real();
  std::fill_n(wrapped, static_cast<std::size_t>(px) * py, 0.0);
  for (int dj = -(grid.my - 1); dj < grid.my; ++dj)
    for (int di = -(grid.mx - 1); di < grid.mx; ++di)
      wrapped[static_cast<std::size_t>((dj + py) % py) * px + (di + px) % px] =
          zz_[static_cast<std::size_t>(dj + grid.my - 1) * wx_ + (di + grid.mx - 1)];
  transform.forward();
  const double inverse_size = 1.0 / (static_cast<double>(px) * py);
  zz_spectrum_.assign(transform.spectrum(), transform.spectrum() + transform.spectrum_size());
  for (std::complex<double>& z : zz_spectrum_)
    z *= inverse_size;
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
  const int mx = grid_.mx, my = grid_.my, px = 2 * mx, py = 2 * my;
  PaddedTransform& transform = PaddedTransform::of(px, py);
  double* padded = transform.real();
  std::fill_n(padded, static_cast<std::size_t>(px) * py, 0.0);
  for (int j = 0; j < my; ++j)
    std::copy_n(&p[static_cast<std::size_t>(j) * mx], mx,
                &padded[static_cast<std::size_t>(j) * px]);
  transform.forward();
  std::complex<double>* spectrum = transform.spectrum();
  for (std::size_t k = 0; k < zz_spectrum_.size(); ++k)
    spectrum[k] *= zz_spectrum_[k];
  transform.inverse();
  std::vector<double> u(p.size());
  for (int j = 0; j < my; ++j)
    std::copy_n(&padded[static_cast<std::size_t>(j) * px], mx,
                &u[static_cast<std::size_t>(j) * mx]);
  return u;
}

void HalfSpaceKernels::add_normal_influence(int element, double pressure,
                                            std::vector<double>& u) const {
  const int mx = grid_.mx, my = grid_.my, k = element % mx, l = element / mx;
  for (int j = 0; j < my; ++j) {
    const double* row = &zz_[static_cast<std::size_t>(j - l + my - 1) * wx_ + (mx - 1 - k)];
    double* target = &u[static_cast<std::size_t>(j) * mx];
    for (int i = 0; i < mx; ++i)
      target[i] += row[i] * pressure;
  }
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
