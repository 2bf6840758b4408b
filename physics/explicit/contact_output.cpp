#include "physics/explicit/contact_output.hpp"

#include <sstream>

#include "framework/base/error.hpp"
#include "framework/output/csv_writer.hpp"
#include "framework/output/output_directory.hpp"
#include "framework/output/run_summary.hpp"
#include "physics/common/contact_pairs.hpp"
#include "physics/common/contact_tables.hpp"
#include "physics/explicit/explicit_settings.hpp"
#include "physics/explicit/explicit_solver.hpp"

namespace railfe {

namespace {

/// Appends \p rows' numbers to \p values, row after row.
void append_numbers(std::vector<double>& values, const std::vector<std::vector<double>>& rows) {
  for (const auto& row : rows)
    values.insert(values.end(), row.begin(), row.end());
}

/// Reads \p count numbers from \p values at \p k (advanced past them) as rows of \p width.
std::vector<std::vector<double>> read_rows(const std::vector<double>& values, std::size_t& k,
                                           std::size_t count, std::size_t width) {
  if (count % width != 0 || k + count > values.size())
    throw RunError(
        "the checkpoint's contact output does not fit this deck's contact pairs (was it "
        "written by a run of another deck?)");
  std::vector<std::vector<double>> rows;
  for (const std::size_t end = k + count; k < end; k += width)
    rows.emplace_back(values.begin() + static_cast<std::ptrdiff_t>(k),
                      values.begin() + static_cast<std::ptrdiff_t>(k + width));
  return rows;
}

}  // namespace

ContactRecorder::ContactRecorder(const ExplicitSettings& settings, const ExplicitSolver& solver,
                                 OutputDirectory& output, const std::string& step_name, bool root)
    : settings_(settings), solver_(solver), output_(output), step_name_(step_name), root_(root) {
  for (const ContactPairSpec& pair : settings.contact_pairs) {
    histories_.push_back(std::make_unique<CsvWriter>(
        output.staging_path(step_name + "_contact_" + pair.name + ".csv"),
        contact_history_columns(), root_));
  }
  rows_.resize(settings.contact_pairs.size());
  // Registered now so that no other step can claim the names, written when their time comes.
  for (std::size_t p = 0; p < settings.contact_pairs.size(); ++p)
    for (std::size_t k = 0; k < settings.contact_pairs[p].patch_times.size(); ++k) {
      output.staging_path(patch_name(p, k, ".csv"));
      if (settings.contact_pairs[p].patch_charts)
        output.staging_path(patch_name(p, k, ".png"));
    }
  next_patch_.assign(settings.contact_pairs.size(), 0);
  patch_rows_.resize(settings.contact_pairs.size());
  flexibility_.resize(settings.contact_pairs.size());
}

ContactRecorder::~ContactRecorder() = default;

void ContactRecorder::record(bool force_row) {
  const ContactPairs& contact = solver_.contact();
  const long long step = solver_.n_steps();
  const bool due = (force_row || step % settings_.history_interval == 0) && step != last_step_;
  for (std::size_t p = 0; p < contact.pairs().size(); ++p) {
    const PenaltyContactPair& pair = contact.pairs()[p];
    const auto& patch_times = settings_.contact_pairs[p].patch_times;
    // A patch is written at the first step that reaches its time.
    while (next_patch_[p] < patch_times.size() &&
           solver_.time() >= patch_times[next_patch_[p]] * (1 - 1e-12)) {
      write_patch(p, next_patch_[p]);
      ++next_patch_[p];
    }
    if (!due)
      continue;
    if (pair.settings().friction.kind != FrictionLaw::Kind::none &&
        pair.totals().normal_force > flexibility_[p].normal_force) {
      const auto& [shear_modulus, poisson] = contact.master_elastic(p);
      const PenaltyFlexibility now = penalty_flexibility(pair, shear_modulus, poisson);
      if (now.patch > 0)
        flexibility_[p] = now;
    }
    const std::vector<double> row = contact_history_row(solver_.time(), pair);
    histories_[p]->write_row(row);
    if (root_)
      rows_[p].push_back(row);
  }
  if (due) {
    last_step_ = step;
    for (auto& history : histories_)
      history->flush();
  }
}

std::string ContactRecorder::patch_name(std::size_t p, std::size_t index,
                                        const char* extension) const {
  return step_name_ + "_contact_" + settings_.contact_pairs[p].name + "_patch_" +
         std::to_string(index + 1) + extension;
}

void ContactRecorder::write_patch(std::size_t p, std::size_t index) {
  const ContactPairs& contact = solver_.contact();
  auto rows = contact_patch_rows(solver_.time(), contact.pairs()[p], contact);
  write_patch_file(p, index, rows);
  if (root_) {
    patch_rows_[p].resize(index + 1);
    patch_rows_[p][index] = std::move(rows);
  }
}

void ContactRecorder::write_patch_file(std::size_t p, std::size_t index, const Rows& rows) const {
  CsvWriter file(output_.staging_path(patch_name(p, index, ".csv")), contact_patch_columns(),
                 root_);
  for (const auto& row : rows)
    file.write_row(row);
}

std::vector<std::array<std::string, 2>> ContactRecorder::patch_charts() const {
  std::vector<std::array<std::string, 2>> charts;
  for (std::size_t p = 0; p < next_patch_.size(); ++p)
    if (settings_.contact_pairs[p].patch_charts)
      for (std::size_t k = 0; k < next_patch_[p]; ++k)
        charts.push_back({output_.staging_path(patch_name(p, k, ".csv")),
                          output_.staging_path(patch_name(p, k, ".png"))});
  return charts;
}

std::vector<std::string> ContactRecorder::summarise(RunSummary& summary,
                                                    const std::string& section) const {
  std::vector<std::string> warnings;
  const ContactPairs& contact = solver_.contact();
  for (std::size_t p = 0; p < contact.pairs().size(); ++p) {
    const std::string& name = contact.pairs()[p].settings().name;
    if (!contact.ever_touched(p))
      warnings.push_back("contact pair '" + name +
                         "' never touched: its surfaces did not come within reach (check the "
                         "sets and the parts' placement)");
    const PenaltyFlexibility& flexibility = flexibility_[p];
    if (!(flexibility.patch > 0))
      continue;
    const std::string key = "contact " + name + ": penalty tangential flexibility / patch's";
    summary.add(section, key, flexibility.ratio());
    std::ostringstream axes;
    axes.precision(3);
    axes << 1e3 * flexibility.rolling_semi_axis << ", " << 1e3 * flexibility.lateral_semi_axis
         << " mm";
    summary.add(section, "contact " + name + ": patch semi-axes a, b at the largest normal force",
                axes.str());
    if (flexibility.ratio() > kFlexibilityWarning) {
      std::ostringstream warning;
      warning.precision(2);
      warning << "contact pair '" << name << "': the penalty layer's tangential flexibility is "
              << flexibility.ratio() << " x the patch's own (Kalker's 8a/(3 C11 G), a = "
              << 1e3 * flexibility.rolling_semi_axis
              << " mm at the largest normal force): where the patch sticks the creep force is "
                 "low by about "
              << 100 * flexibility.ratio() / (1 + flexibility.ratio())
              << " %; raise the Penalty factor (its step falls as 1/sqrt(f): least with "
                 "Penalty stiffness 'bulk modulus, softer side') or refine the contact surfaces";
      warnings.push_back(warning.str());
    }
  }
  return warnings;
}

std::vector<double> ContactRecorder::state() const {
  std::vector<double> values;
  for (std::size_t p = 0; p < rows_.size(); ++p) {
    values.push_back(static_cast<double>(next_patch_[p]));
    values.push_back(static_cast<double>(rows_[p].size()));
    append_numbers(values, rows_[p]);
  }
  // The patch files, as a count of files, then each file's count of numbers and its numbers.
  const std::size_t width = contact_patch_columns().size();
  for (const auto& patches : patch_rows_) {
    values.push_back(static_cast<double>(patches.size()));
    for (const auto& patch : patches) {
      values.push_back(static_cast<double>(patch.size() * width));
      append_numbers(values, patch);
    }
  }
  // The flexibility at the largest normal force so far, so that a resumed run reports the one
  // an uninterrupted run would.
  for (const PenaltyFlexibility& f : flexibility_)
    values.insert(values.end(),
                  {f.normal_force, f.rolling_semi_axis, f.lateral_semi_axis, f.penalty, f.patch});
  return values;
}

void ContactRecorder::restore(const std::vector<double>& values) {
  std::size_t k = 0;
  const std::size_t width = contact_history_columns().size();
  for (std::size_t p = 0; p < rows_.size(); ++p) {
    next_patch_[p] = static_cast<std::size_t>(values.at(k++));
    const auto count = static_cast<std::size_t>(values.at(k++));
    rows_[p] = read_rows(values, k, count * width, width);
    for (const auto& row : rows_[p])
      histories_[p]->write_row(row);
  }
  const std::size_t patch_width = contact_patch_columns().size();
  for (std::size_t p = 0; p < patch_rows_.size(); ++p) {
    patch_rows_[p].resize(static_cast<std::size_t>(values.at(k++)));
    for (std::size_t index = 0; index < patch_rows_[p].size(); ++index) {
      const auto count = static_cast<std::size_t>(values.at(k++));
      patch_rows_[p][index] = read_rows(values, k, count, patch_width);
      write_patch_file(p, index, patch_rows_[p][index]);
    }
  }
  for (PenaltyFlexibility& f : flexibility_)
    for (double* field :
         {&f.normal_force, &f.rolling_semi_axis, &f.lateral_semi_axis, &f.penalty, &f.patch})
      *field = values.at(k++);
}

}  // namespace railfe
