#include "framework/solvers/preconditioners.hpp"

#include <Ifpack2_Factory.hpp>
#include <MueLu_CreateTpetraPreconditioner.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_MultiVector.hpp>

namespace railfe {

namespace {

// Plain (unsmoothed) aggregation with one Chebyshev step per smoothing is the default: on 3-D
// elasticity it set up 3x faster and used half the memory of smoothed aggregation for the same
// total time (docs/solvers.md has the measurements). Smoothed aggregation needs 3-5x fewer
// iterations, which pays when one preconditioner serves many solves.
Teuchos::RCP<TpetraOperator> make_muelu(const Teuchos::RCP<const TpetraMatrix>& A,
                                        const ProblemTraits& traits, bool smoothed) {
  Teuchos::ParameterList parameters;
  parameters.set("verbosity", "none");
  parameters.set("multigrid algorithm", smoothed ? "sa" : "unsmoothed");
  parameters.set("number of equations", traits.dofs_per_node);
  parameters.set("max levels", 10);
  parameters.set("coarse: max size", 1500);
  parameters.set("aggregation: type", "uncoupled");
  parameters.set("aggregation: drop tol", 0.0);
  if (smoothed)
    parameters.set("transpose: use implicit", true);
  // Chebyshev keeps the preconditioner symmetric, as CG requires, and needs no inner solves.
  parameters.set("smoother: type", "CHEBYSHEV");
  parameters.sublist("smoother: params").set("chebyshev: degree", smoothed ? 2 : 1);
  parameters.sublist("smoother: params").set("chebyshev: ratio eigenvalue", 7.0);
  // The coarsest level is solved with Chebyshev sweeps, not Amesos2 KLU2, which gives wrong
  // answers on more than one rank in Trilinos 13.2 (even with every row on one of them). Its
  // largest eigenvalue is estimated with 30 power iterations and a 20 % margin: with the default
  // 10, slender structures got an underestimate, an indefinite preconditioner and a CG
  // breakdown.
  parameters.set("coarse: type", "CHEBYSHEV");
  auto& coarse = parameters.sublist("coarse: params");
  coarse.set("chebyshev: degree", 6);
  coarse.set("chebyshev: ratio eigenvalue", 30.0);
  coarse.set("chebyshev: eigenvalue max iterations", 30);
  coarse.set("chebyshev: boost factor", 1.2);
  parameters.set("repartition: enable", false);
  auto& user = parameters.sublist("user data");
  if (!traits.node_coordinates.is_null()) {
    user.set("Coordinates", Teuchos::rcp_const_cast<TpetraMultiVector>(traits.node_coordinates));
  }
  if (!traits.near_null_space.is_null()) {
    user.set("Nullspace", Teuchos::rcp_const_cast<TpetraMultiVector>(traits.near_null_space));
  }
  auto op =
      Teuchos::rcp_const_cast<TpetraOperator>(Teuchos::rcp_implicit_cast<const TpetraOperator>(A));
  return MueLu::CreateTpetraPreconditioner<double, LocalIndex, GlobalIndex,
                                           Tpetra::Map<>::node_type>(op, parameters);
}

Teuchos::RCP<TpetraOperator> make_ifpack2(const std::string& kind,
                                          const Teuchos::RCP<const TpetraMatrix>& A) {
  Ifpack2::Factory factory;
  Teuchos::ParameterList parameters;
  Teuchos::RCP<Ifpack2::Preconditioner<double, LocalIndex, GlobalIndex>> preconditioner;
  if (kind == "ilu") {
    // Incomplete Cholesky-like ILU(0) on each rank's rows (block Jacobi across ranks).
    preconditioner = factory.create<TpetraMatrix::row_matrix_type>("RILUK", A);
    parameters.set("fact: iluk level-of-fill", 0);
  } else {
    preconditioner = factory.create<TpetraMatrix::row_matrix_type>("RELAXATION", A);
    parameters.set("relaxation: type", "Jacobi");
    parameters.set("relaxation: sweeps", 1);
  }
  preconditioner->setParameters(parameters);
  preconditioner->initialize();
  preconditioner->compute();
  return preconditioner;
}

}  // namespace

Teuchos::RCP<TpetraOperator> make_preconditioner(const std::string& kind,
                                                 const Teuchos::RCP<const TpetraMatrix>& A,
                                                 const ProblemTraits& traits) {
  if (kind == "none")
    return Teuchos::null;
  if (kind == "muelu")
    return make_muelu(A, traits, false);
  if (kind == "muelu-sa")
    return make_muelu(A, traits, true);
  return make_ifpack2(kind, A);
}

std::string preconditioner_description(const std::string& kind) {
  if (kind == "muelu")
    return "MueLu plain aggregation";
  if (kind == "muelu-sa")
    return "MueLu smoothed aggregation";
  if (kind == "ilu")
    return "Ifpack2 ILU(0)";
  if (kind == "jacobi")
    return "Ifpack2 Jacobi";
  return "no preconditioner";
}

}  // namespace railfe
