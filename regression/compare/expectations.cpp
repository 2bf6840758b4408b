#include "regression/compare/expectations.hpp"

#include <Teuchos_ParameterList.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>

#include "framework/base/error.hpp"
#include "framework/base/parallel.hpp"
#include "framework/deck/deck.hpp"
#include "framework/deck/expression.hpp"
#include "framework/deck/validation.hpp"
#include "regression/compare/result_files.hpp"

namespace railfe {

ParameterSpec expectation_parameters() {
  ParameterSpec check("One expected quantity.");
  check.choice("Kind", "reference",
               {{"reference",
                 "an analytic or external value, with the tolerance the method "
                 "promises"},
                {"regression",
                 "a value from an earlier run, with a tight tolerance, guarding "
                 "against unintended change"}},
               "What the expected value is.");
  check.text("Source", "", "Where the expected value comes from (formula, paper, program).");
  check.required_text("File", "Result file, relative to the results directory.");
  check.text("Column", "", "CSV: the column to read.");
  check.text("Row", "", "CSV: the row whose first cell is this text ('' = use Row index).");
  check.integer("Row index", -1, "CSV: row number from 0, or -1 for the last row.");
  check.text("Variable", "", "Exodus: the variable to read.");
  check.choice("Entity", "node", {{"node", "nodal variable"}, {"element", "element variable"}},
               "Exodus: where the variable lives.");
  check.choice("Statistic", "all",
               {{"all", "every value must match (CSV: the cell named by Row)"},
                {"max", "the largest value (CSV: over the whole Column)"},
                {"min", "the smallest value"},
                {"max_abs", "the largest magnitude"},
                {"mean", "the mean (of a history sampled at equal intervals: its time average)"},
                {"at", "the value at one node or element (Index)"}},
               "Exodus: which value(s) to compare.");
  check.text("Where column", "",
             "CSV, with Statistic max, min, max_abs or mean: take it only over the rows whose "
             "value in this column lies within Where range (e.g. the patch's slave nodes that "
             "stick: 'slipping' within {0, 0}).");
  check.real_array("Where range", {}, "CSV: the closed interval {low, high} of Where column.", "",
                   2);
  check.integer("Index", 1, "Exodus: 1-based node or element id for Statistic 'at'.",
                Range::at_least(1));
  check.text("Node set", "", "Exodus, nodal 'all': compare only the nodes of this set.");
  check.integer("Step", 0, "Exodus: output time from 1, or 0 for the last, -1 the one before...");
  check.real_array("Value", {}, "The expected value (one number).", "", 1);
  check.text("Text", "",
             "CSV, instead of Value: the exact text the cell must hold (labels such as a mode's "
             "family).");
  check.text("Expression", "",
             "Instead of Value: expected value as a function of x, y, z (node position or "
             "element centroid).");
  check.required_real("Relative tolerance", "Allowed |difference| / |expected|.", "",
                      Range::positive());
  check.real("Absolute floor", 0.0, "Allowed |difference| when the expected value is near zero.",
             "", Range::non_negative());
  ParameterSpec parallel("How closely runs on different numbers of ranks must agree.");
  parallel.real("Relative tolerance", 1e-8, "Normwise relative tolerance per quantity.", "",
                Range::positive());
  parallel.real("Absolute floor", 0.0,
                "Differences below this always pass (for quantities that are zero up to "
                "round-off, such as the sum of self-equilibrated reactions).",
                "", Range::non_negative());
  parallel.text_array("Ignore", {},
                      "CSV columns and Exodus variables left out: values the method leaves "
                      "arbitrary (e.g. how a free body's rigid-body eigenspace splits into modes); "
                      "say why in a comment.");
  ParameterSpec spec("Expected results of a regression case.");
  spec.required_text("Requirement", "The requirement this case protects.");
  spec.text("Documentation", "", "The docs page that derives the expected values.");
  spec.named_sublists("Checks", check, "The checks, each under a descriptive name.");
  spec.sublist("Parallel agreement", parallel,
               "Tolerance of the comparison between the 1-rank and 2-rank runs.");
  return spec;
}

namespace {

struct Quantity {
  std::vector<double> values;
  std::vector<std::array<double, 3>> points;
};

// The CSV cell a check names by Column and Row or Row index.
std::string csv_cell(const Teuchos::ParameterList& check, const std::string& path) {
  const CsvTable table = read_csv(path);
  const std::size_t column = table.column(check.get<std::string>("Column"));
  const std::string key = check.get<std::string>("Row");
  std::optional<std::size_t> row;
  if (!key.empty()) {
    for (std::size_t r = 0; r < table.rows.size(); ++r) {
      if (table.rows[r][0] == key)
        row = r;
    }
    if (!row)
      throw std::runtime_error("'" + path + "' has no row '" + key + "'");
  } else {
    const int index = check.get<int>("Row index");
    const long resolved = index >= 0 ? index : static_cast<long>(table.rows.size()) + index;
    if (resolved < 0 || resolved >= static_cast<long>(table.rows.size())) {
      throw std::runtime_error("'" + path + "' has no row " + std::to_string(index));
    }
    row = static_cast<std::size_t>(resolved);
  }
  return table.rows[*row][column];
}

// The rows a check's Where column and Where range select (every row without them).
struct RowFilter {
  bool active = false;
  std::size_t column = 0;
  double low = 0, high = 0;

  bool accepts(const std::vector<std::string>& row) const {
    if (!active)
      return true;
    double value = 0;
    if (!parse_number(row[column], value))
      throw std::runtime_error("Where column cell '" + row[column] + "' is not a number");
    return value >= low && value <= high;
  }
};

RowFilter row_filter(const Teuchos::ParameterList& check, const CsvTable& table) {
  RowFilter filter;
  const std::string name = check.get<std::string>("Where column");
  const auto& range = check.get<Teuchos::Array<double>>("Where range");
  if (name.empty() != range.empty())
    throw std::runtime_error("give both Where column and Where range, or neither");
  if (name.empty())
    return filter;
  filter.active = true;
  filter.column = table.column(name);
  filter.low = range[0];
  filter.high = range[1];
  return filter;
}

// The one value a Statistic (max, min, max_abs, mean) makes of \p quantity.
Quantity reduce(const Quantity& quantity, const std::string& statistic) {
  if (statistic == "mean") {
    double sum = 0;
    for (double value : quantity.values)
      sum += value;
    return Quantity{{sum / static_cast<double>(quantity.values.size())}, {quantity.points[0]}};
  }
  auto pick = std::max_element(quantity.values.begin(), quantity.values.end());
  if (statistic == "min")
    pick = std::min_element(quantity.values.begin(), quantity.values.end());
  if (statistic == "max_abs") {
    pick = std::max_element(quantity.values.begin(), quantity.values.end(),
                            [](double a, double b) { return std::abs(a) < std::abs(b); });
  }
  const std::size_t k = pick - quantity.values.begin();
  const double value = statistic == "max_abs" ? std::abs(*pick) : *pick;
  return Quantity{{value}, {quantity.points[k]}};
}

Quantity read_quantity(const Teuchos::ParameterList& check, const std::string& directory) {
  const std::string path =
      (std::filesystem::path(directory) / check.get<std::string>("File")).string();
  Quantity quantity;
  const std::string statistic = check.get<std::string>("Statistic");
  if (!check.get<std::string>("Column").empty() && statistic != "all" && statistic != "at") {
    // A whole CSV column (a history): its extreme.
    const CsvTable table = read_csv(path);
    const std::size_t column = table.column(check.get<std::string>("Column"));
    const RowFilter filter = row_filter(check, table);
    for (const auto& row : table.rows) {
      if (!filter.accepts(row))
        continue;
      double value = 0;
      if (!parse_number(row[column], value))
        throw std::runtime_error("cell '" + row[column] + "' is not a number");
      quantity.values.push_back(value);
      quantity.points.push_back({0, 0, 0});
    }
    if (quantity.values.empty())
      throw std::runtime_error(filter.active ? "no row lies within Where range"
                                             : "the column is empty");
    return reduce(quantity, statistic);
  }
  if (!check.get<std::string>("Where column").empty())
    throw std::runtime_error(
        "Where column needs a CSV Column and Statistic max, min, max_abs or mean");
  if (!check.get<std::string>("Column").empty()) {
    const std::string cell = csv_cell(check, path);
    double value = 0;
    if (!parse_number(cell, value))
      throw std::runtime_error("cell '" + cell + "' is not a number");
    quantity.values.push_back(value);
    quantity.points.push_back({0, 0, 0});
    return quantity;
  }
  const std::string variable = check.get<std::string>("Variable");
  if (variable.empty())
    throw std::runtime_error("give Column (CSV) or Variable (Exodus)");
  const bool nodal = check.get<std::string>("Entity") == "node";
  ExodusField field = read_exodus_field(path, variable, nodal, check.get<int>("Step"));
  if (statistic == "at") {
    const std::size_t index = static_cast<std::size_t>(check.get<int>("Index")) - 1;
    if (index >= field.values.size())
      throw std::runtime_error("index beyond the field");
    quantity.values = {field.values[index]};
    quantity.points = {field.points[index]};
    return quantity;
  }
  const std::string node_set = check.get<std::string>("Node set");
  if (!node_set.empty()) {
    for (long long node : read_exodus_node_set(path, node_set)) {
      quantity.values.push_back(field.values[node]);
      quantity.points.push_back(field.points[node]);
    }
  } else {
    quantity.values = std::move(field.values);
    quantity.points = std::move(field.points);
  }
  if (quantity.values.empty())
    throw std::runtime_error("the field is empty");
  return statistic == "all" ? quantity : reduce(quantity, statistic);
}

CheckOutcome evaluate(const std::string& name, const Teuchos::ParameterList& check,
                      const std::string& directory, const std::string& source,
                      const std::string& path) {
  CheckOutcome outcome;
  outcome.name = name;
  outcome.kind = check.get<std::string>("Kind");
  const auto& value = check.get<Teuchos::Array<double>>("Value");
  const std::string text = check.get<std::string>("Expression");
  const std::string expected_text = check.get<std::string>("Text");
  if (int(!value.empty()) + int(!text.empty()) + int(!expected_text.empty()) != 1) {
    throw_input_error(source, path, "give exactly one of Value, Expression and Text");
  }
  if (outcome.kind == "reference" && check.get<std::string>("Source").empty()) {
    throw_input_error(source, path + "/Source",
                      "a reference check must say where its value "
                      "comes from");
  }
  if (!expected_text.empty()) {
    if (check.get<std::string>("Column").empty())
      throw_input_error(source, path + "/Text", "needs a CSV Column to read");
    try {
      const std::string file =
          (std::filesystem::path(directory) / check.get<std::string>("File")).string();
      const std::string cell = csv_cell(check, file);
      outcome.passed = cell == expected_text;
      if (!outcome.passed)
        outcome.problem = "the cell holds '" + cell + "', expected '" + expected_text + "'";
    } catch (const std::exception& error) {
      outcome.problem = error.what();
    }
    return outcome;
  }
  std::optional<Expression> expression;
  if (!text.empty())
    expression.emplace(text, source, path + "/Expression");
  const double relative = check.get<double>("Relative tolerance");
  const double floor = check.get<double>("Absolute floor");
  try {
    const Quantity quantity = read_quantity(check, directory);
    double worst_ratio = -1;  // difference / allowed: the entity closest to failing
    for (std::size_t k = 0; k < quantity.values.size(); ++k) {
      const auto& p = quantity.points[k];
      const double expected = expression ? (*expression)(p[0], p[1], p[2]) : value[0];
      const double difference = std::abs(quantity.values[k] - expected);
      const double allowed = std::max(relative * std::abs(expected), floor);
      const double ratio = !std::isfinite(difference) ? 1e300
                           : allowed > 0              ? difference / allowed
                                                      : (difference > 0 ? 1e300 : 0.0);
      if (ratio > worst_ratio) {
        worst_ratio = ratio;
        outcome.computed = quantity.values[k];
        outcome.expected = expected;
        outcome.difference = difference;
        outcome.allowed = allowed;
      }
    }
    outcome.passed = worst_ratio <= 1;
  } catch (const std::exception& error) {
    outcome.problem = error.what();
  }
  return outcome;
}

}  // namespace

std::vector<CheckOutcome> evaluate_expectations(const std::string& expected_file,
                                                const std::string& results_directory,
                                                std::string* requirement) {
  Deck deck = read_deck(expected_file, Communicator(MPI_COMM_SELF));
  validate_and_complete(*deck.parameters, *expectation_parameters().list(), deck.source, "");
  if (requirement)
    *requirement = deck.parameters->get<std::string>("Requirement");
  const auto& checks = deck.parameters->sublist("Checks");
  if (checks.numParams() == 0)
    throw_input_error(deck.source, "Checks", "has no checks");
  std::vector<CheckOutcome> outcomes;
  for (auto it = checks.begin(); it != checks.end(); ++it) {
    const std::string name = checks.name(it);
    outcomes.push_back(
        evaluate(name, checks.sublist(name), results_directory, deck.source, "Checks/" + name));
  }
  return outcomes;
}

DiffTolerance parallel_tolerance(const std::string& expected_file) {
  Deck deck = read_deck(expected_file, Communicator(MPI_COMM_SELF));
  validate_and_complete(*deck.parameters, *expectation_parameters().list(), deck.source, "");
  const auto& parallel = deck.parameters->sublist("Parallel agreement");
  const auto& ignored = parallel.get<Teuchos::Array<std::string>>("Ignore");
  return {parallel.get<double>("Relative tolerance"), parallel.get<double>("Absolute floor"),
          std::vector<std::string>(ignored.begin(), ignored.end())};
}

bool report_outcomes(std::ostream& out, const std::vector<CheckOutcome>& outcomes) {
  bool all = true;
  char line[512];
  std::snprintf(line, sizeof line, "%-6s %-10s %-52s %14s %14s %11s %11s\n", "result", "kind",
                "check", "computed", "expected", "difference", "allowed");
  out << line;
  for (const auto& o : outcomes) {
    all = all && o.passed;
    if (!o.problem.empty()) {
      out << "ERROR  " << o.kind << "  " << o.name << ": " << o.problem << "\n";
      continue;
    }
    std::snprintf(line, sizeof line, "%-6s %-10s %-52s %14.7g %14.7g %11.3e %11.3e\n",
                  o.passed ? "pass" : "FAIL", o.kind.c_str(), o.name.substr(0, 52).c_str(),
                  o.computed, o.expected, o.difference, o.allowed);
    out << line;
  }
  return all;
}

}  // namespace railfe
