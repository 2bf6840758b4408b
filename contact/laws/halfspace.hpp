#pragma once
/// \file
/// The elastic half-space discretized on a uniform rectangular grid of elements, each carrying a
/// uniform traction: influence coefficients (Love's rectangle solution for pressure, Cerruti's
/// for shear) and their application as a convolution. Two bodies of the same material
/// (quasi-identity) are assumed, so normal and tangential problems decouple; the coefficients
/// give the displacement difference of the two surfaces. Johnson, Contact Mechanics (1985),
/// §3.2 and §3.3; Kalker (1990), §4.

#include <complex>
#include <vector>

namespace railfe {

/// A uniform grid of mx × my rectangular elements.
struct ContactGrid {
  double x0 = 0, y0 = 0;  ///< lower-left corner (m)
  double dx = 0, dy = 0;  ///< element size (m)
  int mx = 0, my = 0;     ///< elements along x (rolling) and y
  /// Number of elements.
  int size() const { return mx * my; }
  /// Centre of element \p i along x.
  double x(int i) const { return x0 + (i + 0.5) * dx; }
  /// Centre of element \p j along y.
  double y(int j) const { return y0 + (j + 0.5) * dy; }
};

/// Influence kernels of a grid: the displacement difference at element (i, j) due to a unit
/// traction on element (k, l) depends on (i - k, j - l) only.
class HalfSpaceKernels {
 public:
  /// Kernels for \p grid, combined shear modulus \p G and Poisson's ratio \p nu of both bodies.
  HalfSpaceKernels(const ContactGrid& grid, double G, double nu);
  /// Normal displacement difference (m) of the pressures \p p (Pa), element-wise: a
  /// convolution, evaluated by FFTW's real transforms on the grid padded to twice its size,
  /// with the plans measured once per size and thread.
  std::vector<double> normal(const std::vector<double>& p) const;
  /// Adds to \p u the normal displacement difference of pressure \p pressure (Pa) on element
  /// \p element alone: a column of the influence matrix, for updates that touch few elements.
  void add_normal_influence(int element, double pressure, std::vector<double>& u) const;
  /// The same by direct summation (for checking the FFT).
  std::vector<double> normal_direct(const std::vector<double>& p) const;
  /// Tangential displacement differences (m) of the shear tractions \p px, \p py (Pa).
  void tangential(const std::vector<double>& px, const std::vector<double>& py,
                  std::vector<double>& ux, std::vector<double>& uy) const;
  /// The grid.
  const ContactGrid& grid() const { return grid_; }
  /// Pointers to the tangential kernels (xx, xy, yy) from offset (\p di, \p dj) on, running
  /// along +x: entry k is the offset (di + k, dj).
  void tangential_rows(int di, int dj, const double*& xx, const double*& xy,
                       const double*& yy) const {
    const std::size_t k = static_cast<std::size_t>(dj + grid_.my - 1) * wx_ + (di + grid_.mx - 1);
    xx = &xx_[k];
    xy = &xy_[k];
    yy = &yy_[k];
  }
  /// The three tangential kernels (xx, xy, yy) for an offset of \p di, \p dj elements.
  void tangential_influence(int di, int dj, double& xx, double& xy, double& yy) const {
    const std::size_t k = static_cast<std::size_t>(dj + grid_.my - 1) * wx_ + (di + grid_.mx - 1);
    xx = xx_[k];
    xy = xy_[k];
    yy = yy_[k];
  }

 private:
  ContactGrid grid_;
  int wx_, wy_;  // kernel widths 2 mx - 1, 2 my - 1
  std::vector<double> zz_, xx_, yy_, xy_;
  // Half spectrum ((mx + 1) × 2my, x fastest) of the normal kernel wrapped onto the grid padded
  // to 2mx × 2my, divided by the padded size (the inverse transform is unnormalised).
  std::vector<std::complex<double>> zz_spectrum_;
  void convolve(const std::vector<double>& kernel, const std::vector<double>& in,
                std::vector<double>& out, bool accumulate) const;
};

}  // namespace railfe
