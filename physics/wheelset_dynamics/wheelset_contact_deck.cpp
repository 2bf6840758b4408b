#include "physics/wheelset_dynamics/wheelset_contact_deck.hpp"

#include "framework/base/error.hpp"

namespace railfe {

ParameterSpec contact_parameters() {
  ParameterSpec spec("The contact element.");
  spec.real("Young's modulus", 210e9, "Of wheel and rail.", "Pa", Range::positive());
  spec.real("Poisson's ratio", 0.3,
            "Of wheel and rail (the creep-force table is made for 0.3; Kalker's coefficients "
            "cover 0 to 0.5).",
            "", Range::closed(0.0, 0.5));
  spec.real("Friction", 0.3, "μ.", "", Range::open_closed(0, 2));
  spec.choice("Creep theory", "table",
              {{"table", "the exact steady-rolling solver's creep-force table (the seed's choice)"},
               {"linear", "Kalker's linear theory, unbounded"},
               {"shen-hedrick-elkins", "Kalker's linear theory saturated by Shen-Hedrick-Elkins"},
               {"polach", "Polach's model (k_A = k_S = 1, friction independent of slip)"},
               {"fastsim", "Kalker's FASTSIM"}},
              "Tangential forces from the creepages.");
  spec.integer("FASTSIM cells", 10, "Cells per strip and strips.", Range::at_least(2));
  spec.only_when("Creep theory", {"fastsim"}, {"FASTSIM cells"});
  spec.real("Curvature ratio limit", 10,
            "Where wheel and rail are nearly conformal (the flange root), Hertz's smaller relative "
            "curvature is raised to the larger / this ratio, keeping the ellipse within a/b of "
            "about 1/5 to 5 (the creep-force table's range); such contacts are counted in the "
            "summary. 0: stop the run there instead.",
            "", Range::non_negative());
  spec.flag("Lookup table", true,
            "A rigid contact table over lateral shifts (±Table half range) predicts jumps between "
            "tread and flange and starts the search there (the deeper contact wins).");
  spec.real("Table half range", 0.02, "Lateral shifts the table covers.", "m",
            Range::open_closed(0, 0.05));
  spec.only_when("Lookup table", {"true"}, {"Table half range"});
  spec.choice("Creep tangent", "consistent",
              {{"consistent", "forward differences of the creep theory (Newton's own tangent)"},
               {"Kalker damping",
                "Kalker's linear damping matrix at the current ellipse, as the seed model does "
                "(exact for the linear theory)"}},
              "The creep forces' share of Newton's matrix (the residual is the same).");
  spec.choice("Search", "trust-region",
              {{"trust-region", "Newton on the wheel parameter within a trust region"},
               {"plain Newton", "full Newton steps, clipped to the part (for comparison)"}},
              "The contact-point search (contact/geometry/contact_search.hpp).");
  spec.choice("Geometry", "online search",
              {{"online search", "every evaluation searches the contact points on the profiles"},
               {"offline table",
                "the contact points are the lookup table's at the wheelset's lateral shift, the "
                "gap taken there (the offline-table model of programs such as DIASTARS; needs "
                "Lookup table)"}},
              "Where the contact points come from.");
  spec.choice("Yaw", "neglected",
              {{"neglected", "the contact search ignores yaw (the seed's choice)"},
               {"exact", "the search works on the yawed wheel's contact locus"}},
              "Yaw in the contact geometry (creepages always take it).");
  return spec;
}

WheelRailContactSettings contact_settings(const Teuchos::ParameterList& step) {
  const auto& c = step.sublist("Contact");
  WheelRailContactSettings settings;
  settings.wheel = settings.rail =
      ElasticBody{c.get<double>("Young's modulus"), c.get<double>("Poisson's ratio")};
  settings.friction = c.get<double>("Friction");
  settings.theory = creep_theory_from_name(c.get<std::string>("Creep theory"));
  settings.yaw_exact = c.get<std::string>("Yaw") == "exact";
  settings.fastsim_cells = c.get<int>("FASTSIM cells");
  settings.curvature_ratio_limit = c.get<double>("Curvature ratio limit");
  settings.trust_region = c.get<std::string>("Search") == "trust-region";
  settings.kalker_damping = c.get<std::string>("Creep tangent") == "Kalker damping";
  settings.offline_table = c.get<std::string>("Geometry") == "offline table";
  return settings;
}

void check_contact_parameters(const Teuchos::ParameterList& step, const std::string& source,
                              const std::string& path) {
  const auto& c = step.sublist("Contact");
  if (c.get<std::string>("Geometry") == "offline table" && !c.get<bool>("Lookup table"))
    throw_input_error(source, path + "/Contact/Geometry",
                      "'offline table' takes its contact points from the lookup table, which "
                      "Lookup table = false switches off",
                      "Lookup table true with it, or 'online search'");
}

}  // namespace railfe
