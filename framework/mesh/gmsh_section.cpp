#include "framework/mesh/gmsh_section.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "framework/base/error.hpp"
#include "framework/mesh/mesh_readers.hpp"

namespace railfe {

namespace {

namespace fs = std::filesystem;

// Removes the directory however the meshing ends.
class TemporaryDirectory {
 public:
  TemporaryDirectory() {
    std::string pattern = (fs::temp_directory_path() / "railfe_gmsh_XXXXXX").string();
    if (mkdtemp(pattern.data()) == nullptr)
      throw RunError("railfe: cannot create a temporary directory in " + pattern);
    path_ = pattern;
  }
  ~TemporaryDirectory() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
  }
  TemporaryDirectory(const TemporaryDirectory&) = delete;
  TemporaryDirectory& operator=(const TemporaryDirectory&) = delete;
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

// gmsh's "Error : ..." lines (it may exit with status 0 after some of them).
std::string error_lines(const fs::path& log) {
  std::ifstream in(log);
  std::string line, errors;
  while (std::getline(in, line)) {
    if (line.rfind("Error", 0) == 0)
      errors += (errors.empty() ? "" : " | ") + line;
  }
  return errors;
}

}  // namespace

std::string find_gmsh() {
  const char* path = std::getenv("PATH");
  std::istringstream directories(path != nullptr ? path : "");
  std::string directory;
  while (std::getline(directories, directory, ':')) {
    const fs::path candidate = fs::path(directory.empty() ? "." : directory) / "gmsh";
    if (access(candidate.c_str(), X_OK) == 0 && !fs::is_directory(candidate))
      return candidate.string();
  }
  return "";
}

SectionMesh mesh_section_with_gmsh(const std::string& geo_script, const std::string& source) {
  const std::string gmsh = find_gmsh();
  if (gmsh.empty()) {
    throw RunError(source +
                   ": the gmsh program is not on PATH; meshing this cross-section needs Gmsh 4 "
                   "(Debian package gmsh, installed by cmake/install-dependencies.sh)");
  }
  const TemporaryDirectory directory;
  const fs::path geo = directory.path() / "section.geo", msh = directory.path() / "section.msh",
                 log = directory.path() / "gmsh.log";
  std::ofstream(geo) << geo_script;
  const std::string command = "'" + gmsh + "' '" + geo.string() + "' -2 -format msh41 -o '" +
                              msh.string() + "' > '" + log.string() + "' 2>&1";
  const int status = std::system(command.c_str());
  if (status == -1)
    throw RunError(source + ": could not start " + gmsh);
  const std::string errors = error_lines(log);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || !errors.empty() || !fs::exists(msh)) {
    std::string problem = "gmsh could not mesh the cross-section";
    if (WIFSIGNALED(status))
      problem += " (gmsh crashed with signal " + std::to_string(WTERMSIG(status)) + ")";
    if (!errors.empty())
      problem += ": " + errors;
    throw_input_error(source, "", problem, "dimensions that give a valid cross-section");
  }
  try {
    SectionMesh section = read_gmsh_section(msh.string());
    section.source = source;
    return section;
  } catch (const InputError& error) {
    throw_input_error(source, "", std::string("gmsh's mesh of the cross-section: ") + error.what());
  }
}

}  // namespace railfe
