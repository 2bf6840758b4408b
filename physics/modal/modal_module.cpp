#include "physics/modal/modal_module.hpp"

#include "physics/common/solid_beam_ties.hpp"
#include "physics/elements/node_set_springs.hpp"
#include "physics/modal/modal_step.hpp"

namespace railfe {

namespace {

ParameterSpec classification_parameters() {
  ParameterSpec spec(
      "Names the modes of a body of revolution (a wheel, a ring) as (nodal circles, nodal "
      "diameters) in the axial, radial or circumferential family.");
  spec.flag("Axisymmetric", false, "Classify the modes (the body must be a body of revolution).");
  spec.real_array("Axis origin", {0, 0, 0}, "A point on the axis of revolution.", "m", 3);
  spec.real_array("Axis direction", {0, 1, 0}, "Direction of the axis of revolution.", "", 3);
  spec.real("Rim fraction", 0.2,
            "Nodal diameters and the family are judged on the rim: the outer part of the radius "
            "range, as a fraction of it.",
            "", Range::open(0.0, 1.0));
  spec.real_array("Web radii", {0, 0},
                  "Radial range {inner, outer} along which nodal circles are counted (0 = the "
                  "body's inner or outer radius).",
                  "m", 2, Range::non_negative());
  spec.real("Dominance", 0.6,
            "Share of the rim's power the strongest circumferential harmonic needs to give the "
            "number of nodal diameters; below it the mode is ambiguous.",
            "", Range::open(0.0, 1.0));
  spec.real("Family dominance", 0.6,
            "Share of the rim's energy a displacement component needs to name the family "
            "(out of plane vs in plane, then radial vs circumferential).",
            "", Range::open(0.5, 1.0));
  spec.real("Noise fraction", 0.05,
            "Values below this share of the largest on the nodal-circle line count as zero.", "",
            Range::closed_open(0.0, 1.0));
  spec.only_when("Axisymmetric", {"true"},
                 {"Axis origin", "Axis direction", "Rim fraction", "Web radii", "Dominance",
                  "Family dominance", "Noise fraction"});
  return spec;
}

ParameterSpec modal_parameters() {
  ParameterSpec spec("Natural frequencies and mode shapes of hex8 solids (K phi = omega^2 M phi).");
  spec.integer("Modes", 0,
               "Number of lowest modes (above the shift) to compute; with a Frequency band, the "
               "first batch of the search (the next batch is sized from the growth of the mode "
               "count with frequency). 0 = automatic: 10 without a band; with one, up to 16, "
               "then the whole band as extrapolated from them, solved again in one batch.",
               Range::at_least(0));
  spec.real_array("Frequency band", {},
                  "{low, high}: compute every mode in this band instead of a fixed number.", "Hz",
                  2, Range::non_negative());
  spec.real("Shift", -1.0,
            "Shift of the inverted problem, as a signed frequency f: sigma = sign(f) (2 pi f)^2. "
            "Modes nearest it converge first. With the cholmod inner solver it must lie below "
            "the lowest mode; negative values allow free bodies (rigid-body modes at 0 Hz).",
            "Hz");
  spec.choice("Mass", "consistent",
              {{"consistent", "consistent mass matrix (frequencies converge from above)"},
               {"lumped",
                "row-sum lumped mass (diagonal; frequencies usually converge from "
                "below)"}},
              "Mass matrix.");
  spec.choice("Inner solver", "cholmod",
              {{"cholmod", "supernodal Cholesky (CHOLMOD, METIS) of K - sigma M on rank 0"},
               {"cg", "conjugate gradients with MueLu smoothed aggregation, to 1e-12"},
               {"klu2", "sparse LU (Amesos2 KLU2) on rank 0: slow on 3-D solids"}},
              "How (K - sigma M) x = b is solved at every Krylov step. With cholmod, a model of at "
              "most 400 free DOFs (Block size and Krylov blocks automatic) is solved densely "
              "instead, all its modes at once, once the factorization has shown K - sigma M "
              "positive definite.");
  spec.integer("Block size", 0,
               "Vectors per Krylov block; 2 or more finds both members of a doublet together. "
               "0 = automatic from each batch's modes: 2 below 32, 4 below 96, 8 from 96 "
               "(narrower where the model has too few free DOFs).",
               Range::at_least(0));
  spec.integer("Krylov blocks", 0,
               "Blocks in the Krylov space (0 = enough for about three times the modes wanted; "
               "with a Frequency band, three times all the band's modes found and wanted, and "
               "at least 48 vectors more than them; at most the model's free DOFs). The space "
               "may not exceed the free DOFs.",
               Range::at_least(0));
  spec.integer("Maximum restarts", 100, "Krylov-Schur restarts before giving up.",
               Range::at_least(0));
  spec.real("Tolerance", 1e-10, "Convergence tolerance of the Ritz residuals (relative).", "",
            Range::open(0.0, 1.0));

  spec.text_array("Blocks", {},
                  "Element blocks whose modes are computed (none = every block): the elements "
                  "of other blocks are left out and their nodes carry no unknowns, so a wheel's "
                  "modes come from the mesh a later step rolls on a rail. Supports and "
                  "Classification act on these blocks.");
  ParameterSpec support("Fixes components of a node set (zero displacement).");
  support.required_text("Node set", "The nodes.");
  support.text("Components", "xyz", "Fixed components: letters of 'xyz'.");
  spec.named_sublists("Supports", support, "Fixed node sets (none = a free body).");
  spec.named_sublists("Springs", node_set_spring_parameters(),
                      "Node sets on springs to the ground (rail pads, ballast) or to another node "
                      "set (a pad over a sleeper, a stuck contact patch), as in a statics step: "
                      "their stiffness is added to K.");

  spec.real("Backward error limit", 1e-8,
            "A returned pair fails its check when ||K phi - lambda M phi|| / ((||K|| + |lambda| "
            "||M||) ||phi||) exceeds this.",
            "", Range::open(0.0, 1.0));
  spec.real("Orthogonality limit", 1e-8,
            "A returned pair fails its check when |phi_i^T M phi_j| exceeds this for another "
            "returned mode j.",
            "", Range::open(0.0, 1.0));
  spec.real("Rigid-body limit", 0.1,
            "Modes below this frequency are rigid-body modes (a free body has six, found at "
            "round-off level): they count as 0 Hz in the band and have no doublet partner.",
            "Hz", Range::non_negative());
  spec.real("Doublet tolerance", 1e-6,
            "Two eigenvalues closer than this (relative) form a doublet (repeated pair).", "",
            Range::open(0.0, 1.0));
  spec.flag("Sturm check", false,
            "Count the eigenvalues below the highest reported mode with an LDL^T factorization "
            "(Sylvester's inertia) and fail if the eigensolver missed any. Costs a simplicial "
            "factorization, several times the Cholesky one.");
  spec.choice("On failed check", "error",
              {{"error", "the run fails (exit status 2) and says which modes failed"},
               {"warn", "the modes are written with status 'failed' and the run goes on"}},
              "What a failed check, a missing doublet partner or an unconverged mode does.");
  spec.sublist("Classification", classification_parameters(), "Wheel-mode naming.");
  ParameterSpec reference("A measured or published frequency to compare with.");
  reference.required_choice("Family",
                            {{"axial", "out of plane"},
                             {"radial", "in plane, radial"},
                             {"circumferential", "in plane, circumferential"}},
                            "Family of the reference mode.");
  reference.integer("Nodal circles", 0, "m of the reference mode.", Range::at_least(0));
  reference.integer("Nodal diameters", 0, "n of the reference mode.", Range::at_least(0));
  reference.required_real("Frequency", "The reference frequency.", "Hz", Range::positive());
  spec.named_sublists("References", reference,
                      "Reference modes: the run writes <step>_validation.csv with the computed "
                      "mode of the same family, m and n beside each.");
  spec.flag("Exodus", true, "Write the mode shapes to <step>.exo (one output time per mode).");
  spec.flag("Export matrices", false,
            "Write the constrained K and M as Matrix Market files <step>_K.mtx and <step>_M.mtx "
            "(for comparisons with other eigensolvers).");
  spec.flag("Chart", true,
            "With classification: draw <step>_modes.png, frequency against nodal diameters per "
            "family (needs python3 with matplotlib).");
  add_solid_beam_tie_parameters(spec);
  return spec;
}

}  // namespace

ModuleDescriptor modal_module() {
  ModuleDescriptor module;
  module.name = "modal";
  module.summary = "natural frequencies and mode shapes (Anasazi block Krylov-Schur, shift-invert)";
  module.parameters = modal_parameters;
  module.create = [](const Teuchos::ParameterList& parameters) {
    return std::make_unique<ModalStep>(parameters);
  };
  return module;
}

}  // namespace railfe
