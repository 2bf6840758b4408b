#pragma once
/// \file
/// What a "vehicle dynamics" step writes while it runs and sums up at the end: the histories of
/// the wheelsets, the wheels and the measuring points; contact events; flange impacts (each
/// flange contact from touch to release, with its peak forces); the running-safety indices
/// (derailment quotient Y/Q, wheel unloading ΔQ/Q) per wheel and the comfort figures (peak and
/// RMS lateral acceleration) per measuring point.

#include <Eigen/Dense>

#include <array>
#include <string>
#include <vector>

#include "framework/app/module.hpp"
#include "framework/output/csv_writer.hpp"
#include "physics/wheelset_dynamics/vehicle_system.hpp"

namespace railfe {

/// The step's outputs (see the file comment).
class VehicleRecorder {
 public:
  /// Opens the CSV files of step \p context (written on the ranks where \p writes) for
  /// \p system's wheelsets and the measuring points \p point_names whose motions
  /// \p point_motion gives from the model's unknowns; \p static_loads are the wheels' Q at
  /// rest, [wheelset][side].
  VehicleRecorder(StepContext& context, VehicleSystem& system, std::vector<std::string> point_names,
                  std::vector<Eigen::MatrixXd> point_motion,
                  std::vector<std::array<double, 2>> static_loads, bool writes);
  /// Also reports each wheel's Y/Q as a sliding mean over the last \p samples calls of
  /// record(), spanning \p length metres of track (UIC 518 takes 2 m); 1 sample: none.
  void set_sliding_mean(int samples, double length);
  /// Takes the converged state at \p time (\p iterations Newton iterations; \p u, \p v, \p a
  /// the vehicle's unknowns): events, impacts and peaks every step, a history row when
  /// \p write_row.
  void record(double time, int iterations, const double* u, const double* v, const double* a,
              const std::vector<std::array<ContactState, n_wheelset_contacts>>& states,
              bool write_row);
  /// Closes open impacts at \p time, writes the impacts and the safety table, adds the figures
  /// to the summary under \p section.
  void finish(double time, RunSummary& summary, const std::string& section);

 private:
  struct Impact {
    int wheelset = 0, side = 0;
    double start = 0, end = 0, peak_flange = 0, peak_Y = 0, peak_Y_over_Q = 0;
  };
  struct WheelPeaks {
    double Y_over_Q = 0, unloading = 0, Y = 0, mean_Y_over_Q = 0;
    std::vector<double> recent;  // the last Y/Q values, a ring of window_ entries
    double sum = 0;              // their sum
  };

  VehicleSystem& system_;
  bool writes_;
  std::vector<std::string> point_names_;
  std::vector<Eigen::MatrixXd> point_motion_;
  std::vector<std::array<double, 2>> static_loads_;
  CsvWriter wheelsets_, wheels_, points_, events_;
  std::string impacts_path_, safety_path_, comfort_path_;
  std::vector<std::array<bool, n_wheelset_contacts>> active_;
  std::vector<std::array<int, 2>> open_impact_;  // index into impacts_, or -1
  std::vector<Impact> impacts_;
  std::vector<std::array<WheelPeaks, 2>> peaks_;
  std::vector<double> peak_ay_, sum_ay2_;
  std::size_t samples_ = 0, n_events_ = 0;
  int window_ = 1;            // samples in the sliding mean of Y/Q
  double window_length_ = 0;  // the track length it spans (m), for the report
};

}  // namespace railfe
