#pragma once
/// \file
/// How an implicit step advances its distributed state (u, v, a over the owned DOFs): directly by
/// HHT-α on the Tpetra system, or through the direct method's constrained solve on rank 0
/// (constrained_stepper.hpp). The step's loop, outputs and energy balance are the same for both.

#include <cstddef>

#include "framework/time/hht_integrator.hpp"

namespace railfe {

/// Advances the owned state of an implicit step.
class ImplicitStepper {
 public:
  virtual ~ImplicitStepper() = default;
  /// Writes the acceleration that satisfies the equations at \p time to \p a (collective).
  virtual void initialize(double time, double* u, double* v, double* a) = 0;
  /// Advances from \p time by \p dt; returns the sub-steps taken (collective). Throws RunError
  /// (StepNotConverged where Newton failed) on every rank.
  virtual int advance(double time, double dt, double* u, double* v, double* a) = 0;
  /// Newton counters (those of rank 0 where only rank 0 integrates).
  virtual NewtonStatistics statistics() const = 0;
  /// Cut-backs so far.
  virtual std::size_t n_cut_backs() const = 0;
};

/// HHT-α on a distributed SecondOrderSystem.
class DistributedStepper : public ImplicitStepper {
 public:
  /// Steps \p integrator (not owned).
  explicit DistributedStepper(HhtIntegrator& integrator) : integrator_(integrator) {}
  void initialize(double time, double* u, double* v, double* a) override {
    integrator_.initialize(time, u, v, a);
  }
  int advance(double time, double dt, double* u, double* v, double* a) override {
    return integrator_.advance(time, dt, u, v, a);
  }
  NewtonStatistics statistics() const override { return integrator_.newton_statistics(); }
  std::size_t n_cut_backs() const override { return integrator_.n_cut_backs(); }

 private:
  HhtIntegrator& integrator_;
};

}  // namespace railfe
