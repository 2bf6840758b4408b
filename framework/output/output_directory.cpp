#include "framework/output/output_directory.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "framework/base/error.hpp"
#include "framework/output/finite_check.hpp"

namespace railfe {

namespace fs = std::filesystem;

namespace {
const char* kManifest = ".railfe-outputs";
}

OutputDirectory::OutputDirectory(std::string path, const Communicator& comm)
    : path_(std::move(path)), comm_(comm) {
  std::string problem;
  if (comm_.is_root()) {
    std::error_code error;
    fs::create_directories(path_, error);
    if (error || !fs::is_directory(path_)) {
      problem = "cannot create output directory '" + path_ + "': " + error.message();
    } else {
      std::ifstream manifest(fs::path(path_) / kManifest);
      std::string name;
      while (std::getline(manifest, name)) {
        if (!name.empty() && name.find('/') == std::string::npos)
          fs::remove(fs::path(path_) / name, error);
      }
      fs::remove(fs::path(path_) / kManifest, error);
      fs::remove(fs::path(path_) / "FAILED.txt", error);
      std::ofstream probe(fs::path(path_) / ".railfe-write-test");
      if (!probe)
        problem = "output directory '" + path_ + "' is not writable";
      probe.close();
      fs::remove(fs::path(path_) / ".railfe-write-test", error);
    }
  }
  comm_.agree(problem, false);
}

std::string OutputDirectory::staging_path(const std::string& name) {
  const auto known = std::find(names_.begin(), names_.end(), name);
  if (known == names_.end()) {
    names_.push_back(name);
    owners_.push_back(current_step_);
  } else if (const std::string& owner = owners_[known - names_.begin()]; owner != current_step_) {
    throw RunError("step '" + current_step_ + "' would overwrite '" + name + "', written by " +
                   (owner.empty() ? std::string("the run itself") : "step '" + owner + "'") +
                   "; rename one of the steps so that their files differ");
  }
  return (fs::path(path_) / (name + ".part")).string();
}

std::string OutputDirectory::staged_path_of(const std::string& name) const {
  if (std::find(names_.begin(), names_.end(), name) == names_.end())
    throw RunError("no step of this run has written '" + name + "'");
  return (fs::path(path_) / (name + ".part")).string();
}

std::string OutputDirectory::final_path(const std::string& name) const {
  return (fs::path(path_) / name).string();
}

void OutputDirectory::finalize() {
  comm_.barrier();  // every rank has finished writing before files are renamed
  std::string problem;
  if (comm_.is_root()) {
    for (const auto& name : names_) {
      const fs::path staged = fs::path(path_) / (name + ".part");
      if (!fs::exists(staged))
        continue;
      const std::string where = find_non_finite(staged.string());
      if (!where.empty()) {
        problem = "a result is not finite (NaN or inf) in " + name + ", " + where +
                  ": the computation that produced it failed, so the run's results are kept "
                  "as .part files and must not be used";
        break;
      }
    }
  }
  comm_.agree(problem, false);
  if (comm_.is_root()) {
    std::ofstream manifest(fs::path(path_) / kManifest);
    for (const auto& name : names_) {
      std::error_code error;
      const fs::path staged = fs::path(path_) / (name + ".part");
      if (!fs::exists(staged))
        continue;
      fs::rename(staged, fs::path(path_) / name, error);
      if (error)
        problem = "cannot rename '" + staged.string() + "': " + error.message();
      manifest << name << "\n";
    }
  }
  comm_.agree(problem, false);
}

void OutputDirectory::mark_failed(const std::string& message) const {
  if (!comm_.is_root())
    return;
  std::ofstream failed(fs::path(path_) / "FAILED.txt");
  failed << "This run failed; files ending in .part are incomplete.\n" << message << "\n";
  // The next run removes exactly these files, and nothing else that may sit in the directory.
  std::ofstream manifest(fs::path(path_) / kManifest);
  for (const auto& name : names_)
    manifest << name << ".part\n";
}

}  // namespace railfe
