#include "framework/app/runner.hpp"

#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <memory>

#include "framework/app/deck_layout.hpp"
#include "framework/base/error.hpp"
#include "framework/base/resources.hpp"
#include "framework/mesh/mesh_parameters.hpp"

namespace railfe {

namespace {

std::string results_directory(const RunOptions& options, const Deck& deck) {
  if (!options.output.empty())
    return options.output;
  const auto configured = deck.parameters->sublist("Output").get<std::string>("Directory");
  if (!configured.empty())
    return deck.resolve(configured);
  return std::filesystem::path(deck.source).stem().string() + "_results";
}

// A results directory that cannot be written is the user's input: refused (exit 1) before the
// mesh is built, so no run ends after hours without its results.
void check_results_directory(const RunOptions& options, const Deck& deck, const std::string& path,
                             const Communicator& comm) {
  std::string problem;
  if (comm.is_root()) {
    namespace fs = std::filesystem;
    std::error_code error;
    fs::path existing = fs::absolute(path, error);
    while (!existing.empty() && !fs::exists(existing, error) && existing != existing.parent_path())
      existing = existing.parent_path();
    const bool target_exists = fs::exists(path, error);
    if (target_exists && !fs::is_directory(path, error)) {
      problem = "'" + path + "' is a file, not a directory";
    } else if (!fs::is_directory(existing, error)) {
      problem = "'" + existing.string() + "' is a file, so '" + path + "' cannot be created";
    } else {
      // Permission bits do not bind root, and a read-only file system ignores them: a probe
      // file is the only reliable test.
      const fs::path probe = existing / ".railfe-write-test";
      {
        std::ofstream file(probe);
        if (!file)
          problem = "'" + existing.string() + "' is not writable";
      }
      fs::remove(probe, error);
    }
  }
  const bool from_command_line = !options.output.empty();
  if (!problem.empty())
    problem = format_input_message(from_command_line ? "command line" : deck.source,
                                   from_command_line ? "--output" : "Output/Directory",
                                   "the results directory cannot be written: " + problem,
                                   "a writable directory, or a path where one can be created");
  comm.agree(problem, true);
}

std::string today() {
  char buffer[32];
  const std::time_t now = std::time(nullptr);
  std::strftime(buffer, sizeof buffer, "%Y-%m-%d %H:%M:%S", std::localtime(&now));
  return buffer;
}

struct PreparedStep {
  std::string name;
  std::string path;
  const Teuchos::ParameterList* parameters;
  std::unique_ptr<AnalysisStep> step;
};

void write_summary(const RunSummary& summary, OutputDirectory& output, const Communicator& comm,
                   bool quiet) {
  const std::string text_path = output.staging_path("summary.txt");
  const std::string json_path = output.staging_path("summary.json");
  if (!comm.is_root())
    return;
  std::ofstream(text_path) << summary.text();
  std::ofstream(json_path) << summary.json();
  if (!quiet)
    std::printf("\n%s", summary.text().c_str());
}

int run(const RunOptions& options, const ModuleRegistry& registry, const Communicator& comm,
        std::unique_ptr<OutputDirectory>& output) {
  Stopwatch total;
  RunSummary summary;
  Stopwatch phase;
  Deck deck = read_deck(options.deck, comm);
  validate_deck(deck, registry);
  const double read_seconds = phase.seconds();

  check_results_directory(options, deck, results_directory(options, deck), comm);

  phase.restart();
  // Geometry-only decks (contact geometry, contact patches) have no Mesh section; steps whose
  // module needs one are refused before anything runs.
  const bool has_mesh = deck.parameters->isSublist("Mesh");
  auto& step_lists = deck.parameters->sublist("Steps");
  for (auto it = step_lists.begin(); it != step_lists.end() && !has_mesh; ++it) {
    const std::string name = step_lists.name(it);
    const std::string module_name = step_lists.sublist(name).get<std::string>("Module");
    if (registry.find_module(module_name)->needs_mesh)
      throw_input_error(deck.source, "Steps/" + name,
                        "module '" + module_name + "' works on a mesh but the deck has no Mesh",
                        "a Mesh section");
  }
  Mesh mesh;
  PartitionMethod method = PartitionMethod::block;
  if (has_mesh) {
    const auto& mesh_section = deck.parameters->sublist("Mesh");
    // Every rank builds the mesh; a failure on some ranks only (a generator's helper program, a
    // file system) must stop them all.
    comm.run_collectively(
        [&] { mesh = build_mesh(mesh_section, deck, registry.mesh_generators()); });
    method = partition_method(mesh_section);
  } else {
    mesh.source = "none";
  }
  Model model(deck, std::move(mesh), comm, method);
  const double mesh_seconds = phase.seconds();

  const bool quiet = options.quiet;
  const double progress_interval =
      model.deck().parameters->sublist("Output").get<double>("Progress interval");
  std::vector<PreparedStep> steps;
  for (auto it = step_lists.begin(); it != step_lists.end(); ++it) {
    const std::string name = step_lists.name(it);
    const auto& parameters = step_lists.sublist(name);
    const auto* module = registry.find_module(parameters.get<std::string>("Module"));
    steps.push_back({name, "Steps/" + name, &parameters, module->create(parameters)});
  }

  for (auto& prepared : steps) {
    const CheckContext context{model, prepared.name, prepared.path};
    comm.run_collectively([&] { prepared.step->check(context); });
  }
  // Everything the deck can get wrong is known now; only then is the results directory touched.
  output = std::make_unique<OutputDirectory>(results_directory(options, model.deck()), comm);

  const auto& title = model.deck().parameters->get<std::string>("Title");
  summary.add("Run", "deck", options.deck);
  if (!title.empty())
    summary.add("Run", "title", title);
  summary.add("Run", "started", today());
  summary.add("Run", "MPI ranks", comm.n_ranks());
  summary.add("Run", "results", output->path());
  summary.add("Model", "mesh", model.mesh().source);
  summary.add("Model", "nodes", static_cast<double>(model.mesh().n_nodes()));
  summary.add("Model", "elements", static_cast<double>(model.mesh().n_elements()));
  for (const auto& block : model.mesh().blocks) {
    summary.add("Model", "block " + block.name,
                std::to_string(block.n_elements()) + " " + element_type_name(block.type));
  }
  summary.add("Model", "partitioner", model.partition().method_name());
  summary.add("Wall time", "read and validate deck", read_seconds, "s");
  summary.add("Wall time", "build, check and partition mesh", mesh_seconds, "s");

  for (auto& prepared : steps) {
    if (comm.is_root() && !quiet) {
      std::printf("railfe: step '%s' (%s)\n", prepared.name.c_str(),
                  prepared.parameters->get<std::string>("Module").c_str());
      std::fflush(stdout);
    }
    phase.restart();
    output->begin_step(prepared.name);
    StepContext context{model,   prepared.name, prepared.path, *prepared.parameters,
                        *output, summary,       quiet,         progress_interval};
    prepared.step->run(context);
    summary.add("Wall time", "step " + prepared.name, phase.seconds(), "s");
  }

  output->begin_step("");
  summary.add("Wall time", "total", total.seconds(), "s");
  const double peak = static_cast<double>(peak_resident_bytes());
  summary.add("Memory", "peak resident, largest rank", comm.max(peak) / 1048576.0, "MiB");
  summary.add("Memory", "peak resident, all ranks", comm.sum(peak) / 1048576.0, "MiB");
  write_summary(summary, *output, comm, quiet);
  output->finalize();
  return kSuccess;
}

}  // namespace

int run_deck(const RunOptions& options, const ModuleRegistry& registry, const Communicator& comm) {
  std::unique_ptr<OutputDirectory> output;
  auto report = [&](const char* kind, const std::string& message, int status) {
    if (output)
      output->mark_failed(message);
    if (comm.is_root())
      std::fprintf(stderr, "railfe: %s: %s\n", kind, message.c_str());
    return status;
  };
  try {
    return run(options, registry, comm, output);
  } catch (const InputError& error) {
    return report("error in input", error.what(), kBadInput);
  } catch (const RunError& error) {
    return report("run failed", error.what(), kRunFailed);
  }
}

}  // namespace railfe
