#include "physics/wheelset_dynamics/vehicle_sweep.hpp"

#include <Teuchos_Array.hpp>

#include <chrono>
#include <iostream>
#include <sstream>

#include "framework/base/error.hpp"
#include "framework/output/csv_writer.hpp"
#include "framework/output/run_summary.hpp"
#include "physics/common/chart_script.hpp"

namespace railfe {

ParameterSpec vehicle_sweep_parameters() {
  ParameterSpec spec(
      "Cases to run instead of the step's single run: every combination of the lists given "
      "(a list left empty keeps the step's value), dealt out over the MPI ranks; one table "
      "<step>_sweep.csv and its chart at the end. Each case covers the step's track length "
      "(End time x Speed).");
  spec.real_array("Speeds", {}, "Running speeds.", "m/s", 0, Range::positive());
  spec.real_array("Spans", {}, "Span lengths of the Structure deviation.", "m", 0,
                  Range::positive());
  spec.real_array("Amplitudes", {}, "Amplitudes of the Structure deviation.", "m", 0,
                  Range::closed(-0.2, 0.2));
  return spec;
}

bool names_sweep_cases(const Teuchos::ParameterList& step) {
  if (!step.isSublist("Sweep"))
    return false;
  const auto& sweep = step.sublist("Sweep");
  for (const char* key : {"Speeds", "Spans", "Amplitudes"})
    if (sweep.isParameter(key) && !sweep.get<Teuchos::Array<double>>(key).empty())
      return true;
  return false;
}

std::vector<VehicleCase> sweep_cases(const Teuchos::ParameterList& step, const VehicleCase& base,
                                     const std::string& source, const std::string& path) {
  const auto& sweep = step.sublist("Sweep");
  auto list = [&](const char* key, double fallback) {
    const auto given = sweep.get<Teuchos::Array<double>>(key);
    return given.empty() ? std::vector<double>{fallback}
                         : std::vector<double>(given.begin(), given.end());
  };
  const auto given = [&](const char* key) {
    return !sweep.get<Teuchos::Array<double>>(key).empty();
  };
  if (!names_sweep_cases(step))
    return {};
  for (const char* key : {"Spans", "Amplitudes"})
    if (given(key) && base.deviation.shape == DeviationShape::none)
      throw_input_error(
          source, path + "/Sweep/" + key, "sweeps the Structure deviation, but its Shape is none",
          "a Structure deviation Shape of bending or translation, or no " + std::string(key));
  std::vector<VehicleCase> cases;
  const double length = base.end_time * base.speed;
  for (double span : list("Spans", base.deviation.span))
    for (double amplitude : list("Amplitudes", base.deviation.amplitude))
      for (double speed : list("Speeds", base.speed)) {
        VehicleCase c = base;
        c.speed = speed;
        c.end_time = length / speed;
        c.deviation.span = span;
        c.deviation.amplitude = amplitude;
        cases.push_back(c);
      }
  return cases;
}

namespace {

// The numbers each case gives the table, from its summary (key prefixes) and its outcome.
const std::vector<std::pair<const char*, const char*>> kFigures = {
    {"peak_Y_N", "peak lateral wheel force"},
    {"peak_Y_over_Q", "peak derailment quotient Y/Q"},
    {"peak_mean_Y_over_Q", "peak derailment quotient Y/Q, sliding mean"},
    {"peak_dQ_over_Q", "peak wheel unloading dQ/Q"},
    {"flange_impacts", "flange impacts"},
    {"peak_car_body_ay_m_per_s2", "peak lateral acceleration at "},
    {"rms_car_body_ay_m_per_s2", "RMS lateral acceleration at "},
    {"newton_iterations_per_step", "Newton iterations per step"},
    {"most_newton_iterations", "most Newton iterations in a step"},
};
// Per case: status (0 ran to its end, 1 Newton failed, 2 left the rails, 3 failed before
// stepping), stopped at, the figures, wall time, rank.
const std::size_t kColumns = 2 + 9 + 2;
const char* kStatus[] = {"completed", "Newton failed", "left the rails", "failed"};

// Every rank's strings \p local, in rank order, on every rank.
std::vector<std::string> all_gather(const Communicator& comm,
                                    const std::vector<std::string>& local) {
  std::vector<long long> flat;
  for (const std::string& text : local) {
    flat.push_back(static_cast<long long>(text.size()));
    flat.insert(flat.end(), text.begin(), text.end());
  }
  const std::vector<long long> all = comm.all_gather(flat);
  std::vector<std::string> texts;
  for (std::size_t i = 0; i < all.size();) {
    const auto size = static_cast<std::size_t>(all[i++]);
    std::string text;
    for (std::size_t k = 0; k < size; ++k)
      text.push_back(static_cast<char>(all[i++]));
    texts.push_back(text);
  }
  return texts;
}

}  // namespace

void run_sweep(StepContext& context, const std::vector<VehicleCase>& cases, const CaseRunner& run,
               const std::string& section) {
  const Communicator& comm = context.model.comm();
  const auto n = cases.size();
  const auto sweep_start = std::chrono::steady_clock::now();
  std::vector<double> table(n * kColumns, 0.0);
  std::vector<std::string> files, messages;
  for (std::size_t i = 0; i < n; ++i) {
    if (static_cast<int>(i % static_cast<std::size_t>(comm.n_ranks())) != comm.rank())
      continue;
    const VehicleCase& c = cases[i];
    const std::string name = context.step_name + "_case" + std::to_string(i + 1);
    const std::string path = context.path + ", case " + std::to_string(i + 1);
    RunSummary summary;
    StepContext case_context{context.model,  name,    path, context.parameters,
                             context.output, summary, true, context.progress_interval};
    const std::size_t registered = context.output.names().size();
    const auto case_start = std::chrono::steady_clock::now();
    CaseOutcome outcome;
    try {
      outcome = run(case_context, c);
    } catch (const RunError& error) {
      outcome = {"failed", 0, error.what()};
    }
    const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - case_start).count();
    for (std::size_t k = registered; k < context.output.names().size(); ++k)
      files.push_back(context.output.names()[k]);
    double* row = &table[i * kColumns];
    row[0] = outcome.stop.empty()                                       ? 0
             : outcome.stop == "Newton failed"                          ? 1
             : outcome.stop.find("left the rails") != std::string::npos ? 2
                                                                        : 3;
    row[1] = outcome.stop.empty() ? c.end_time : outcome.stopped_at;
    for (std::size_t f = 0; f < kFigures.size(); ++f)
      row[2 + f] = summary.number(kFigures[f].second);
    row[kColumns - 2] = wall;
    row[kColumns - 1] = comm.rank();
    if (!outcome.message.empty())
      messages.push_back(outcome.message);  // it names the step and the case
    if (!context.quiet) {
      std::ostringstream line;
      line << "[" << context.step_name << ": sweep] case " << i + 1 << " of " << n << " (V "
           << c.speed << " m/s, span " << c.deviation.span << " m, amplitude "
           << c.deviation.amplitude << " m) " << kStatus[static_cast<int>(row[0])];
      if (row[0] != 0)
        line << " at t = " << row[1] << " s";
      line << ", " << wall << " s on rank " << comm.rank() << "\n";
      std::cout << line.str() << std::flush;
    }
  }
  comm.sum_in_place(table);
  // Rank 0 renames every case's files at the end of the run: it learns the others' names.
  for (const std::string& file : all_gather(comm, files))
    context.output.staging_path(file);
  const std::vector<std::string> all_messages = all_gather(comm, messages);

  std::vector<std::string> columns{"case",        "speed_m_per_s", "speed_km_per_h",    "span_m",
                                   "amplitude_m", "status",        "end_or_stop_time_s"};
  for (const auto& figure : kFigures)
    columns.push_back(figure.first);
  columns.push_back("wall_time_s");
  columns.push_back("rank");
  const std::string table_path = context.output.staging_path(context.step_name + "_sweep.csv");
  int stopped = 0;
  {
    CsvWriter file(table_path, columns, comm.is_root());
    for (std::size_t i = 0; i < n; ++i) {
      const double* row = &table[i * kColumns];
      std::vector<std::string> cells{std::to_string(i + 1),
                                     CsvWriter::format(cases[i].speed),
                                     CsvWriter::format(cases[i].speed * 3.6),
                                     CsvWriter::format(cases[i].deviation.span),
                                     CsvWriter::format(cases[i].deviation.amplitude),
                                     kStatus[static_cast<int>(row[0])]};
      for (std::size_t k = 1; k < kColumns; ++k)
        cells.push_back(CsvWriter::format(row[k]));
      file.write_row(cells);
      stopped += row[0] != 0;
    }
  }
  if (comm.is_root())
    for (const std::string& message : all_messages)
      std::cerr << "warning: " << message << "\n";
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - sweep_start).count();
  double case_time = 0;
  for (std::size_t i = 0; i < n; ++i)
    case_time += table[i * kColumns + kColumns - 2];
  context.summary.add(section, "sweep cases", static_cast<double>(n));
  context.summary.add(section, "sweep cases that stopped before their end", stopped);
  context.summary.add(section, "sweep ranks", comm.n_ranks());
  context.summary.add(section, "sweep wall time", wall, "s");
  context.summary.add(section, "sweep wall time of the cases, summed", case_time, "s");
  if (context.parameters.get<bool>("Chart"))
    draw_chart(context, section, "vehicle_sweep_chart.py",
               {table_path, context.output.staging_path(context.step_name + "_sweep.png"),
                context.step_name});
}

}  // namespace railfe
