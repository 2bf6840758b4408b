// Output: CSV precision, the run summary, Exodus files read back through the Exodus library,
// fields gathered from all ranks, and the rule that failed runs leave nothing that looks complete.
#include <gtest/gtest.h>

#include <exodusII.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <thread>

#include "framework/base/error.hpp"
#include "framework/mesh/box_generator.hpp"
#include "framework/mesh/mesh_readers.hpp"
#include "framework/output/csv_writer.hpp"
#include "framework/output/exodus_writer.hpp"
#include "framework/output/field_gather.hpp"
#include "framework/output/finite_check.hpp"
#include "framework/output/output_directory.hpp"
#include "framework/output/progress.hpp"
#include "framework/output/run_summary.hpp"

namespace railfe {
namespace {

namespace fs = std::filesystem;

std::string read(const fs::path& path) {
  std::ifstream file(path);
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

// One directory shared by all ranks of a test (rank 0 creates it).
fs::path shared_scratch(const std::string& name, const Communicator& comm) {
  const auto path = fs::temp_directory_path() / ("railfe_output_" + name);
  if (comm.is_root())
    fs::remove_all(path);
  comm.barrier();
  return path;
}

// shared_scratch(), created (by rank 0, before any rank goes on).
fs::path created_scratch(const std::string& name, const Communicator& comm) {
  const auto path = shared_scratch(name, comm);
  if (comm.is_root())
    fs::create_directories(path);
  comm.barrier();
  return path;
}

TEST(Csv, RoundTripsDoublesExactly) {
  const double value = 0.1 + 0.2;
  EXPECT_EQ(std::stod(CsvWriter::format(value)), value);
  const Communicator comm;
  const auto dir = created_scratch("csv", comm);
  {
    CsvWriter csv((dir / "h.csv").string(), {"time_s", "force_N"}, comm.is_root());
    csv.write_row(std::vector<double>{1e-7, -2.5});
  }
  comm.barrier();
  EXPECT_EQ(read(dir / "h.csv"), "time_s,force_N\n9.9999999999999995e-08,-2.5\n");
}

// Labels come from decks (a reference mode "umbrella (0,0)"): a comma or a quote in one must not
// shift the row's columns in a spreadsheet.
TEST(Csv, QuotesTextCellsThatHoldCommasOrQuotes) {
  EXPECT_EQ(CsvWriter::quoted("axial"), "axial");
  EXPECT_EQ(CsvWriter::quoted("umbrella (0,0)"), "\"umbrella (0,0)\"");
  EXPECT_EQ(CsvWriter::quoted("the \"(0,3)\" mode"), "\"the \"\"(0,3)\"\" mode\"");
  EXPECT_EQ(CsvWriter::quoted("two\nlines"), "\"two\nlines\"");
  EXPECT_EQ(CsvWriter::cells("\"the \"\"(0,3)\"\" mode\",1075,"),
            (std::vector<std::string>{"the \"(0,3)\" mode", "1075", ""}));
  const Communicator comm;
  const auto dir = created_scratch("csv_text", comm);
  {
    CsvWriter csv((dir / "t.csv").string(), {"reference", "reference_hz"}, comm.is_root());
    csv.write_row(std::vector<std::string>{"umbrella (0,0)", "183"});
  }
  comm.barrier();
  EXPECT_EQ(read(dir / "t.csv"), "reference,reference_hz\n\"umbrella (0,0)\",183\n");
}

// Work of known size gets a percentage and a time to go; iterations that stop when they
// converge get their count and the time each, never a time to go that assumes all of them.
TEST(Progress, IterationsUpToABoundGiveNoTimeToGo) {
  const Communicator comm;
  if (!comm.is_root())
    GTEST_SKIP() << "rank 0 prints";
  testing::internal::CaptureStdout();
  Progress work("assembly", 10, comm, false, 0.0);
  work.update(5);
  Progress iterations("contact iterations", 30, comm, false, 0.0, true);
  iterations.update(1);
  const std::string printed = testing::internal::GetCapturedStdout();
  EXPECT_NE(printed.find("[assembly]  50.0% done"), std::string::npos) << printed;
  EXPECT_NE(printed.find("to go"), std::string::npos) << printed;
  EXPECT_NE(printed.find("[contact iterations] 1 done (at most 30)"), std::string::npos) << printed;
  const std::string iteration_line = printed.substr(printed.find("[contact iterations]"));
  EXPECT_EQ(iteration_line.find("to go"), std::string::npos) << printed;
  EXPECT_EQ(iteration_line.find('%'), std::string::npos) << printed;
}

// A phase resumed at 80 % reckons its time to go from the work done since: after 0.6 s for 5 %
// more, about 1.8 s remain (15 % at the same rate), not the 0.1 s that counting the resumed 80 %
// as done in those 0.6 s would give.
TEST(Progress, ResumedPhaseCountsOnlyTheWorkSince) {
  const Communicator comm;
  if (!comm.is_root())
    GTEST_SKIP() << "rank 0 prints";
  testing::internal::CaptureStdout();
  Progress resumed("time", 100, comm, false, 0.0);
  resumed.start_at(80);
  resumed.update(80);
  std::this_thread::sleep_for(std::chrono::milliseconds(600));
  resumed.update(85);
  const std::string printed = testing::internal::GetCapturedStdout();
  const std::size_t line = printed.find("[time]  85.0% done, ");
  ASSERT_NE(line, std::string::npos) << printed;
  EXPECT_EQ(printed.substr(0, line).find("to go"), std::string::npos) << printed;
  double elapsed = 0, to_go = 0;
  ASSERT_EQ(std::sscanf(printed.c_str() + line, "[time]  85.0%% done, %lf s elapsed, about %lf",
                        &elapsed, &to_go),
            2)
      << printed;
  EXPECT_GE(elapsed, 0.6) << printed;
  EXPECT_NEAR(to_go, 3 * elapsed, 0.5 + 0.2 * elapsed) << printed;  // printed to the second
}

TEST(RunSummary, TextAndJson) {
  RunSummary summary;
  summary.add("Run", "deck", "a \"quoted\" name");
  summary.add("Solve", "iterations", 12);
  summary.add("Solve", "time", 0.5, "s");
  const std::string text = summary.text();
  EXPECT_NE(text.find("iterations  12"), std::string::npos) << text;
  EXPECT_NE(text.find("0.5 s"), std::string::npos) << text;
  const std::string json = summary.json();
  EXPECT_NE(json.find("\"deck\": \"a \\\"quoted\\\" name\""), std::string::npos) << json;
  EXPECT_NE(json.find("\"time [s]\": 0.5"), std::string::npos) << json;
  EXPECT_NE(json.find("\"iterations\": 12"), std::string::npos) << json;
}

TEST(OutputDirectory, FilesAppearOnlyWhenTheRunSucceeds) {
  const Communicator comm;
  const auto dir = shared_scratch("staging", comm);
  {
    OutputDirectory output(dir.string(), comm);
    const std::string staged = output.staging_path("result.csv");
    EXPECT_EQ(fs::path(staged).filename(), "result.csv.part");
    if (comm.is_root())
      std::ofstream(staged) << "x\n";
    comm.barrier();
    EXPECT_FALSE(fs::exists(dir / "result.csv"));
    output.finalize();
    EXPECT_TRUE(fs::exists(dir / "result.csv"));
    EXPECT_FALSE(fs::exists(staged));
  }
  comm.barrier();
  {
    // A second run that fails: the first run's file is gone, nothing complete is left.
    OutputDirectory output(dir.string(), comm);
    EXPECT_FALSE(fs::exists(dir / "result.csv"));
    const std::string staged = output.staging_path("other.csv");
    if (comm.is_root())
      std::ofstream(staged) << "partial\n";
    output.mark_failed("solver diverged");
    comm.barrier();
    EXPECT_TRUE(fs::exists(dir / "other.csv.part"));
    EXPECT_FALSE(fs::exists(dir / "other.csv"));
    EXPECT_NE(read(dir / "FAILED.txt").find("solver diverged"), std::string::npos);
  }
  comm.barrier();
  {
    // The next run clears the failure marker and the partial files.
    OutputDirectory output(dir.string(), comm);
    EXPECT_FALSE(fs::exists(dir / "FAILED.txt"));
    EXPECT_FALSE(fs::exists(dir / "other.csv.part"));
  }
}

// A successful run never leaves NaN or inf in a result: the file, row and column are named and
// the files keep their .part names.
TEST(OutputDirectory, NonFiniteResultsFailTheRun) {
  const Communicator comm;
  const auto dir = shared_scratch("non_finite", comm);
  OutputDirectory output(dir.string(), comm);
  const std::string good = output.staging_path("good.csv");
  const std::string bad = output.staging_path("forces.csv");
  if (comm.is_root()) {
    std::ofstream(good) << "theory,Fx_N\nlinear,1.5e3\n";
    std::ofstream(bad) << "theory,Fx_N,Fy_N\nlinear,1.5e3,2\npolach,3,-nan\n";
  }
  try {
    output.finalize();
    FAIL() << "finalize accepted a NaN";
  } catch (const RunError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("forces.csv, row 2, column 'Fy_N': -nan"), std::string::npos) << message;
  }
  comm.barrier();
  EXPECT_TRUE(fs::exists(bad));
  EXPECT_FALSE(fs::exists(dir / "forces.csv"));
  EXPECT_EQ(find_non_finite(good), "");
  if (comm.is_root()) {
    // A quoted label holding a comma is one cell: the NaN after it is named by its own column.
    const std::string labelled = (dir / "modes_validation.csv.part").string();
    std::ofstream(labelled) << "reference,computed_hz\n\"umbrella (0,0)\",nan\n";
    EXPECT_EQ(find_non_finite(labelled), "row 1, column 'computed_hz': nan");
    const std::string summary = (dir / "summary.json.part").string();
    std::ofstream(summary) << "{\"Solver\": {\"relative residual\": inf}}\n";
    EXPECT_EQ(find_non_finite(summary), "line 1: inf");
    // Words that merely contain the letters are no NaN.
    std::ofstream(summary) << "{\"status\": \"nano, infinite, not unique\"}\n";
    EXPECT_EQ(find_non_finite(summary), "");
  }
}

// One step's files never overwrite another's.
TEST(OutputDirectory, AStepCannotOverwriteAnotherStepsFile) {
  const Communicator comm;
  const auto dir = shared_scratch("owners", comm);
  OutputDirectory output(dir.string(), comm);
  output.begin_step("first");
  const std::string path = output.staging_path("patch_forces.csv");
  EXPECT_EQ(output.staging_path("patch_forces.csv"), path);  // the same step may ask again
  output.begin_step("second");
  try {
    output.staging_path("patch_forces.csv");
    FAIL() << "a second step was given the first step's file";
  } catch (const RunError& error) {
    EXPECT_NE(std::string(error.what())
                  .find("step 'second' would overwrite 'patch_forces.csv', "
                        "written by step 'first'"),
              std::string::npos)
        << error.what();
  }
}

// NaN in an Exodus field is found by variable and time step.
TEST(OutputDirectory, NonFiniteExodusFieldsAreFound) {
  const Communicator comm;
  const auto dir = shared_scratch("non_finite_exodus", comm);
  if (comm.is_root()) {
    fs::create_directories(dir);
    BoxSpec spec;
    spec.elements = {2, 1, 1};
    const Mesh mesh = generate_box(spec);
    const std::string path = (dir / "result.exo").string();
    {
      ExodusWriter writer(path, mesh, "test", {"ux"}, {"stress"}, true);
      std::vector<double> ux(mesh.n_nodes(), 1.0), stress(mesh.n_elements(), 2.0);
      writer.write_step(0.0, {ux}, {stress});
      EXPECT_EQ(find_non_finite(path), "");
      stress[1] = std::numeric_limits<double>::infinity();
      writer.write_step(1.0, {ux}, {stress});
      writer.close();
    }
    EXPECT_EQ(find_non_finite(path), "element variable 'stress' at time step 2: inf");
  }
}

TEST(ExodusWriter, FieldsGatheredFromAllRanksReadBack) {
  const Communicator comm;
  BoxSpec spec;
  spec.elements = {4, 3, 2};
  const Mesh mesh = generate_box(spec);
  const MeshPartition partition(mesh, comm, PartitionMethod::multijagged);
  // Nodal field: x + 10 y + 100 z of each owned node, three components (value, 2 value, 3 value).
  std::vector<double> owned;
  for (LocalIndex n = 0; n < partition.n_owned_nodes(); ++n) {
    const double* c = partition.coordinates(n);
    const double value = c[0] + 10 * c[1] + 100 * c[2];
    for (int k = 1; k <= 3; ++k)
      owned.push_back(k * value);
  }
  std::vector<double> element_values;
  for (const auto& block : partition.blocks()) {
    for (GlobalIndex e : block.elements)
      element_values.push_back(1000.0 + e);
  }
  const auto nodal = gather_node_field(partition, owned, 3);
  const auto element = gather_element_field(partition, element_values, 1);
  const auto dir = shared_scratch("exodus", comm);
  if (comm.is_root())
    fs::create_directories(dir);
  comm.barrier();
  const std::string path = (dir / "result.exo").string();
  {
    ExodusWriter writer(path, mesh, "test", {"displacement_x", "displacement_y", "displacement_z"},
                        {"marker"}, comm.is_root());
    writer.write_step(0.5, nodal, element);
    writer.write_step(1.0, nodal, element);
    writer.close();
  }
  comm.barrier();
  // Geometry and sets read back with railfe's reader...
  const Mesh back = read_exodus_mesh(path);
  EXPECT_EQ(back.coordinates, mesh.coordinates);
  EXPECT_EQ(back.blocks[0].connectivity, mesh.blocks[0].connectivity);
  EXPECT_EQ(back.node_set("zmax", "", "").nodes, mesh.node_set("zmax", "", "").nodes);
  EXPECT_EQ(back.side_set("xmin", "", "").sides.size(), mesh.side_set("xmin", "", "").sides.size());
  // ...and the fields with the Exodus library's own calls.
  int cpu = 8, io = 0;
  float version = 0;
  const int id = ex_open(path.c_str(), EX_READ, &cpu, &io, &version);
  ASSERT_GE(id, 0);
  EXPECT_EQ(ex_inquire_int(id, EX_INQ_TIME), 2);
  std::vector<double> y(mesh.n_nodes()), marker(mesh.n_elements());
  ASSERT_GE(ex_get_var(id, 2, EX_NODAL, 2, 1, mesh.n_nodes(), y.data()), 0);
  ASSERT_GE(ex_get_var(id, 2, EX_ELEM_BLOCK, 1, 1, mesh.n_elements(), marker.data()), 0);
  char name[64] = {0};
  ex_get_variable_name(id, EX_NODAL, 1, name);
  ex_close(id);
  EXPECT_STREQ(name, "displacement_x");
  for (GlobalIndex n = 0; n < mesh.n_nodes(); ++n) {
    const double value = mesh.coordinates[3 * n] + 10 * mesh.coordinates[3 * n + 1] +
                         100 * mesh.coordinates[3 * n + 2];
    EXPECT_DOUBLE_EQ(y[n], 2 * value);
  }
  for (GlobalIndex e = 0; e < mesh.n_elements(); ++e)
    EXPECT_DOUBLE_EQ(marker[e], 1000.0 + e);
}

}  // namespace
}  // namespace railfe
