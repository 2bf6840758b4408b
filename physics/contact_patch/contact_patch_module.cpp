#include "physics/contact_patch/contact_patch_module.hpp"

#include "physics/contact_patch/contact_patch_step.hpp"

namespace railfe {

namespace {

ParameterSpec contact_patch_parameters() {
  ParameterSpec spec(
      "One contact patch under several theories: forces, moment, pressure, patch and tractions.");
  spec.choice("Geometry", "curvatures",
              {{"curvatures", "Hertz from the relative curvatures A and B"},
               {"semi-axes", "Hertz from the semi-axes a and b (the curvatures follow)"},
               {"separation",
                "a non-Hertzian patch, the exact solver alone: the undeformed separation A x² + "
                "s(y), s from Separation file (as Kalker's CONTACT takes the profiles' distance), "
                "for profiles whose curvature changes across the patch; a_m and b_m in the "
                "forces file are then the semi-axes of the ellipse with the pressure's second "
                "moments (sqrt(5 <x²>), sqrt(5 <y²>) about its centre)"}},
              "How the patch is given.");
  spec.real("A", 1 / (2 * 0.46), "Relative curvature along the rolling direction.", "1/m",
            Range::positive());
  spec.real("B", 1 / (2 * 0.30), "Relative curvature across.", "1/m", Range::positive());
  spec.text("Separation file", "",
            "CSV relative to the deck's directory: a header line, then rows y (m), s (m) with y "
            "increasing across the rolling direction: the bodies' undeformed separation, normal "
            "to the contact plane (only its differences count). The contact must stay inside "
            "its range of y. A third column R (m), the wheel's rolling radius at y, makes the "
            "longitudinal rigid slip xi - (R(y) - R(0)) / R(0) across the patch (a conformal "
            "contact's radii, which vary nonlinearly), xi then that of y = 0, and the spin "
            "creepage acts across only (phi x); without it the rigid slip is xi - phi y.");
  spec.real("a", 7e-3, "Semi-axis along the rolling direction (Geometry semi-axes).", "m",
            Range::positive());
  spec.real("b", 5e-3, "Semi-axis across (Geometry semi-axes).", "m", Range::positive());
  spec.real("Normal load", 1e5, "Normal force.", "N", Range::positive());
  spec.real("Young's modulus", 210e9, "Of both bodies.", "Pa", Range::positive());
  spec.real("Poisson's ratio", 0.3, "Of both bodies (Kalker's table covers 0 to 0.5).", "",
            Range::closed(0.0, 0.5));
  spec.choice("Prescribe", "creepages",
              {{"creepages", "the creepages; every theory gives the forces"},
               {"forces",
                "the tangential forces and the spin: the exact solver finds the longitudinal and "
                "lateral creepages that carry them (the inverse problem, as Kalker's CONTACT "
                "solves it; needs exact in Theories), and every theory is evaluated at those "
                "creepages"}},
              "What each case prescribes.");
  // Creepages beyond full sliding (|ξ|, |η| > 1) or spins of a patch turned far past the
  // flange's steepest angle over a 0.2 m radius have no rolling-contact meaning.
  spec.real_array("Longitudinal creepage", {1e-3},
                  "ξ per case; arrays of length 1 are repeated to the longest.", "", 0,
                  Range::closed(-1, 1));
  spec.real_array("Lateral creepage", {0}, "η per case.", "", 0, Range::closed(-1, 1));
  spec.real_array("Spin creepage", {0}, "φ per case.", "1/m", 0, Range::closed(-100, 100));
  spec.real_array("Longitudinal force", {0},
                  "Fx per case on body 1 (the wheel), along the rolling direction (Prescribe "
                  "forces); arrays of length 1 are repeated to the longest. With Lateral force it "
                  "must stay below the traction bound: sqrt(Fx² + Fy²) < μs N.",
                  "N");
  spec.real_array("Lateral force", {0}, "Fy per case on body 1 (Prescribe forces).", "N");
  spec.real("Inverse tolerance", 1e-6,
            "Prescribe forces: the creepages found carry the forces to this fraction of μs N.", "",
            Range::closed(1e-10, 1e-2));
  spec.real("Static friction", 0.3, "μs (Coulomb: also μd).", "", Range::open_closed(0, 2));
  spec.real("Dynamic friction", -1, "μd for falling friction (negative = μs: Coulomb).", "");
  spec.real("Friction decay", 0, "c in μ = μd + (μs − μd) exp(−c |v|).", "s/m",
            Range::non_negative());
  spec.real("Rolling speed", 30, "Turns slip into slip velocity (falling friction).", "m/s",
            Range::positive());
  spec.text_array("Theories", {"linear", "shen-hedrick-elkins", "fastsim", "exact"},
                  "Any of linear, shen-hedrick-elkins, polach, fastsim, table (the exact "
                  "solver's creep-force table: a/b 0.2 to 5, Poisson's ratio 0.3), exact.");
  spec.real("Polach adhesion reduction", 1,
            "k_A: Polach's reduction of the creep-force slope in the area of adhesion.", "",
            Range::open_closed(0, 1));
  spec.real("Polach slip reduction", 1,
            "k_S (at most k_A): Polach's reduction of the slope in the area of slip.", "",
            Range::open_closed(0, 1));
  spec.real("Polach friction ratio", 1,
            "A = μ∞ / μ0 in Polach's μ = μ0 ((1 − A) exp(−B w) + A), μ0 the static friction "
            "(1: friction independent of slip velocity w).",
            "", Range::open_closed(0, 1));
  spec.real("Polach friction decay", 0, "B in Polach's friction law.", "s/m",
            Range::non_negative());
  spec.integer("FASTSIM cells", 20, "FASTSIM cells along each strip, and strips.",
               Range::at_least(1));
  spec.choice("FASTSIM bound", "parabolic",
              {{"parabolic", "Kalker's parabolic traction bound"},
               {"elliptic", "Hertz's elliptic pressure"}},
              "FASTSIM's traction bound.");
  spec.integer("Exact grid", 40,
               "Elements per side of the exact solver's grid, which reaches 10 % (and at least "
               "1.5 elements) beyond the Hertz ellipse (Geometry separation: 5 % beyond where "
               "the separation is below the approach).",
               Range::at_least(8));
  spec.flag("Traction fields", true,
            "Write <step>_tractions.csv: per FASTSIM and exact case, every element's position, "
            "pressure, tractions, state and (exact solver) slip.");
  spec.flag("Chart", true,
            "Draw <step>_creep_forces.png and <step>_tractions.png (needs python3 with "
            "matplotlib).");
  spec.only_when("Prescribe", {"creepages"}, {"Longitudinal creepage", "Lateral creepage"});
  spec.only_when("Prescribe", {"forces"},
                 {"Longitudinal force", "Lateral force", "Inverse tolerance"});
  spec.only_when("Geometry", {"curvatures", "separation"}, {"A"});
  spec.only_when("Geometry", {"curvatures"}, {"B"});
  spec.only_when("Geometry", {"separation"}, {"Separation file"});
  spec.only_when("Geometry", {"semi-axes"}, {"a", "b"});
  spec.only_when("Theories", {"exact"}, {"Exact grid", "Dynamic friction", "Friction decay"});
  spec.only_when("Theories", {"exact", "polach"}, {"Rolling speed"});
  spec.only_when("Theories", {"fastsim"}, {"FASTSIM cells", "FASTSIM bound"});
  spec.only_when("Theories", {"fastsim", "exact"}, {"Traction fields"});
  spec.only_when("Theories", {"polach"},
                 {"Polach adhesion reduction", "Polach slip reduction", "Polach friction ratio",
                  "Polach friction decay"});
  return spec;
}

}  // namespace

ModuleDescriptor contact_patch_module() {
  ModuleDescriptor module;
  module.name = "contact patch";
  module.summary =
      "one wheel-rail contact patch under Hertz, Kalker linear, saturation laws, FASTSIM, the "
      "creep-force table and the exact solver; creepages given, or forces (the exact solver "
      "finds the creepages)";
  module.parameters = contact_patch_parameters;
  module.create = [](const Teuchos::ParameterList& parameters) {
    return std::make_unique<ContactPatchStep>(parameters);
  };
  module.needs_mesh = false;
  return module;
}

}  // namespace railfe
