#pragma once
/// \file
/// The lateral deviation a displaced structure gives the track (issue 19's test cases, as railway
/// structures deflect in an earthquake): the structure's own shape over consecutive spans,
/// piecewise linear, and the rail that follows it on elastic pads, smoothed over the kinks and
/// offsets at the span ends. The rail is a beam on a foundation that moves with the structure,
/// EI w'''' + k (w − w_s) = 0, so w is w_s convolved with the foundation's Green's function
/// G(x) = (β/2) e^(−β|x|) (cos βx + sin β|x|), β = (k / 4EI)^(1/4). Piecewise linear w_s keeps
/// its straight parts; each slope change Δs adds Δs e^(−β|x|)(cos βx − sin β|x|) / (4β) and
/// each offset Δ smooths into Δ (1 − ½ e^(−βx) cos βx) (ahead of it; ½ e^(βx) cos βx behind):
/// closed forms, smooth, exact for the infinite rail (docs/theory.md, "Structure deviations").

#include <string>
#include <vector>

namespace railfe {

/// Which structural displacement.
enum class DeviationShape {
  none,         ///< no deviation
  bending,      ///< two consecutive spans bent: the pier between them moved by the amplitude
  translation,  ///< one span rotated (0 to the amplitude), the next translated by it
};

/// What the deck gives.
struct StructureDeviationSettings {
  DeviationShape shape = DeviationShape::none;
  double start = 0;              ///< track position s where the first span begins (m)
  double span = 20;              ///< span length (m)
  double amplitude = 0.008;      ///< largest lateral displacement of the structure (m, right)
  double pad_stiffness = 4.6e7;  ///< lateral stiffness of the rail pads per metre of rail (N/m²)
  double rail_inertia = 509e-8;  ///< the rail's second moment about its vertical axis (m⁴)
  double rail_modulus = 2.1e11;  ///< the rail's Young's modulus (Pa)
};

/// The rail's lateral deviation (see the file comment).
class StructureDeviation {
 public:
  /// The deviation of \p settings.
  explicit StructureDeviation(const StructureDeviationSettings& settings);
  /// The structure's own displacement w_s at track position \p s (m).
  double structure(double s) const;
  /// The rail's displacement w at \p s (m).
  double rail(double s) const;
  /// β (1/m).
  double beta() const { return beta_; }

 private:
  struct Kink {
    double at;           ///< s of the slope change or offset
    double slope_jump;   ///< Δs
    double offset_jump;  ///< Δ
  };
  std::vector<Kink> kinks_;
  double beta_;
};

}  // namespace railfe
