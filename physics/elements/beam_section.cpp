#include "physics/elements/beam_section.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "framework/base/constants.hpp"

namespace railfe {
namespace {

void require_positive(double value, const char* name) {
  if (!(value > 0) || !std::isfinite(value))
    throw std::invalid_argument(std::string("section ") + name + " must be positive and finite");
}

void require_poisson(double poisson) {
  if (!(poisson > -1 && poisson < 0.5))
    throw std::invalid_argument("Poisson's ratio of a section must lie in (-1, 0.5)");
}

// Cowper's coefficient of a solid rectangle (independent of its aspect ratio).
double rectangle_shear_coefficient(double poisson) {
  return 10 * (1 + poisson) / (12 + 11 * poisson);
}

}  // namespace

BeamSection euler_bernoulli(BeamSection section) {
  section.shear_area_y = std::numeric_limits<double>::infinity();
  section.shear_area_z = std::numeric_limits<double>::infinity();
  return section;
}

void check_section(const BeamSection& section) {
  require_positive(section.area, "area A");
  require_positive(section.iy, "inertia Iy");
  require_positive(section.iz, "inertia Iz");
  require_positive(section.torsion, "torsion constant J");
  if (!(section.shear_area_y > 0) || !(section.shear_area_z > 0))
    throw std::invalid_argument("section shear areas must be positive (or infinite: no shear)");
}

double rectangle_torsion_constant(double a, double b) {
  require_positive(a, "side");
  require_positive(b, "side");
  const double p = std::max(a, b) / 2, q = std::min(a, b) / 2;
  const double r = q / p;
  return p * q * q * q * (16.0 / 3 - 3.36 * r * (1 - std::pow(r, 4) / 12));
}

BeamSection rectangle_section(double width, double height, double poisson) {
  require_positive(width, "width");
  require_positive(height, "height");
  require_poisson(poisson);
  BeamSection s;
  s.area = width * height;
  s.iy = width * height * height * height / 12;
  s.iz = height * width * width * width / 12;
  s.torsion = rectangle_torsion_constant(width, height);
  s.shear_area_y = s.shear_area_z = rectangle_shear_coefficient(poisson) * s.area;
  return s;
}

BeamSection circle_section(double diameter, double poisson) {
  require_positive(diameter, "diameter");
  require_poisson(poisson);
  const double r = diameter / 2;
  BeamSection s;
  s.area = kPi * r * r;
  s.iy = s.iz = kPi * std::pow(r, 4) / 4;
  s.torsion = 2 * s.iy;
  s.shear_area_y = s.shear_area_z = 6 * (1 + poisson) / (7 + 6 * poisson) * s.area;
  return s;
}

BeamSection tube_section(double outer_diameter, double wall, double poisson) {
  require_positive(outer_diameter, "outer diameter");
  require_positive(wall, "wall thickness");
  require_poisson(poisson);
  const double ro = outer_diameter / 2, ri = ro - wall;
  if (!(ri > 0))
    throw std::invalid_argument("tube wall thickness must be less than its outer radius");
  BeamSection s;
  s.area = kPi * (ro * ro - ri * ri);
  s.iy = s.iz = kPi * (std::pow(ro, 4) - std::pow(ri, 4)) / 4;
  s.torsion = 2 * s.iy;
  const double m = ri / ro, c = (1 + m * m) * (1 + m * m);
  const double kappa =
      6 * (1 + poisson) * c / ((7 + 6 * poisson) * c + (20 + 12 * poisson) * m * m);
  s.shear_area_y = s.shear_area_z = kappa * s.area;
  return s;
}

BeamSection i_section(double depth, double flange_width, double flange_thickness,
                      double web_thickness, double poisson) {
  require_positive(depth, "depth");
  require_positive(flange_width, "flange width");
  require_positive(flange_thickness, "flange thickness");
  require_positive(web_thickness, "web thickness");
  require_poisson(poisson);
  const double d = depth, b = flange_width, tf = flange_thickness, tw = web_thickness;
  if (!(2 * tf < d) || !(tw <= b))
    throw std::invalid_argument(
        "I-section flanges must be thinner than half the depth and the web no wider than them");
  const double web = d - 2 * tf;  // clear height of the web
  BeamSection s;
  s.area = 2 * b * tf + web * tw;
  s.iy = (b * d * d * d - (b - tw) * web * web * web) / 12;
  s.iz = (2 * tf * b * b * b + web * tw * tw * tw) / 12;
  const double h = d - tf;  // distance between the flanges' centre lines
  s.torsion = (2 * b * tf * tf * tf + h * tw * tw * tw) / 3;
  const double m = 2 * b * tf / (h * tw), n = b / h, nu = poisson;
  const double kappa = 10 * (1 + nu) * (1 + 3 * m) * (1 + 3 * m) /
                       ((12 + 72 * m + 150 * m * m + 90 * m * m * m) +
                        nu * (11 + 66 * m + 135 * m * m + 90 * m * m * m) +
                        30 * n * n * (m + m * m) + 5 * nu * n * n * (8 * m + 9 * m * m));
  s.shear_area_z = kappa * s.area;
  s.shear_area_y = 2 * rectangle_shear_coefficient(poisson) * b * tf;
  return s;
}

}  // namespace railfe
