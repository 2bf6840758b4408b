#include "framework/solvers/linear_solver.hpp"

#include <Tpetra_MultiVector.hpp>
#include <Tpetra_Vector.hpp>

#include <algorithm>

#include "framework/solvers/direct_solvers.hpp"
#include "framework/solvers/krylov_solver.hpp"

namespace railfe {

ParameterSpec linear_solver_parameters(const std::string& default_method) {
  ParameterSpec spec("How linear systems are solved.");
  spec.choice("Method", default_method,
              {{"cg", "conjugate gradients (Belos), for symmetric positive definite systems"},
               {"gmres", "restarted GMRES (Belos), for any nonsingular system"},
               {"cholmod",
                "supernodal sparse Cholesky (SuiteSparse CHOLMOD, METIS ordering) "
                "gathered on rank 0: exact, best below a few 10^5 DOFs"},
               {"klu2",
                "sparse LU (Amesos2 KLU2) gathered on rank 0: general but 50-100x "
                "slower than CHOLMOD on 3-D elasticity"}},
              "Solution method.");
  spec.choice("Preconditioner", "muelu",
              {{"muelu",
                "algebraic multigrid (MueLu), plain aggregation with rigid-body modes: "
                "least memory and set-up time"},
               {"muelu-sa",
                "algebraic multigrid (MueLu), smoothed aggregation: 3-5x fewer "
                "iterations for 2x the memory and set-up time"},
               {"ilu", "incomplete LU, ILU(0), on each rank's rows"},
               {"jacobi", "diagonal scaling"},
               {"none", "no preconditioner"}},
              "Preconditioner of cg and gmres.");
  spec.real("Relative tolerance", 1e-10,
            "Iterative methods stop when ||b - A x|| / ||b|| is below this.", "",
            Range::open(0.0, 1.0));
  spec.integer("Maximum iterations", 2000,
               "Iterative methods fail with an error after this many iterations.",
               Range::at_least(1));
  spec.integer("Restart", 100, "GMRES Krylov space size before a restart.", Range::at_least(2));
  spec.real("Backward error limit", 1e-10,
            "Direct methods fail with an error when ||b - A x||inf / (||A||inf ||x||inf + "
            "||b||inf) exceeds this (a sound factorization gives about 1e-16).",
            "", Range::open(0.0, 1.0));
  spec.only_when("Method", {"cg", "gmres"},
                 {"Preconditioner", "Relative tolerance", "Maximum iterations"});
  spec.only_when("Method", {"gmres"}, {"Restart"});
  spec.only_when("Method", {"cholmod", "klu2"}, {"Backward error limit"});
  return spec;
}

SolveReport LinearSolver::solve_block(const TpetraMultiVector& B, TpetraMultiVector& X) {
  SolveReport worst;
  for (std::size_t j = 0; j < B.getNumVectors(); ++j) {
    const auto x = X.getVectorNonConst(j);
    const SolveReport report = solve(*B.getVector(j), *x);
    const double solve_seconds = worst.solve_seconds + report.solve_seconds;
    if (j == 0 || report.backward_error > worst.backward_error)
      worst = report;
    worst.iterations = std::max(worst.iterations, report.iterations);
    worst.solve_seconds = solve_seconds;
  }
  return worst;
}

std::unique_ptr<LinearSolver> create_linear_solver(const Teuchos::ParameterList& parameters) {
  const auto method = parameters.get<std::string>("Method");
  const double limit = parameters.get<double>("Backward error limit");
  if (method == "cholmod")
    return make_cholmod_solver(limit);
  if (method == "klu2")
    return make_klu2_solver(limit);
  KrylovSettings settings;
  settings.method = method;
  settings.preconditioner = parameters.get<std::string>("Preconditioner");
  settings.relative_tolerance = parameters.get<double>("Relative tolerance");
  settings.maximum_iterations = parameters.get<int>("Maximum iterations");
  settings.restart = parameters.get<int>("Restart");
  return make_krylov_solver(settings);
}

}  // namespace railfe
