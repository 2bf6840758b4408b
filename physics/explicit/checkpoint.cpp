#include "physics/explicit/checkpoint.hpp"

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "framework/base/error.hpp"

namespace railfe {

namespace {

// The last character is the format: 2 since the contact recorder carries its patch files, 3
// since the solver's state carries the stable step's calibration, 4 since the contact recorder
// carries the penalty flexibility at the largest normal force.
constexpr char kMagic[8] = {'R', 'A', 'I', 'L', 'F', 'E', 'C', '4'};

}  // namespace

void write_checkpoint(const std::string& path, int n_ranks, const CheckpointSections& sections) {
  const std::string temporary = path + ".tmp";
  {
    std::ofstream file(temporary, std::ios::binary | std::ios::trunc);
    if (!file)
      throw RunError("cannot write the checkpoint '" + temporary + "'");
    const std::int64_t header[2] = {n_ranks, static_cast<std::int64_t>(sections.size())};
    file.write(kMagic, sizeof kMagic);
    file.write(reinterpret_cast<const char*>(header), sizeof header);
    for (const auto& section : sections) {
      const std::int64_t size = static_cast<std::int64_t>(section.size());
      file.write(reinterpret_cast<const char*>(&size), sizeof size);
      file.write(reinterpret_cast<const char*>(section.data()),
                 static_cast<std::streamsize>(section.size() * sizeof(double)));
    }
    file.write(kMagic, sizeof kMagic);
    if (!file)
      throw RunError("cannot write the checkpoint '" + temporary + "' (disk full?)");
  }
  std::error_code error;
  std::filesystem::rename(temporary, path, error);
  if (error)
    throw RunError("cannot rename the checkpoint '" + temporary + "': " + error.message());
}

CheckpointSections read_checkpoint(const std::string& path, int n_ranks) {
  std::ifstream file(path, std::ios::binary);
  if (!file)
    throw RunError("cannot open the checkpoint '" + path + "'");
  char magic[8];
  std::int64_t header[2] = {0, 0};
  file.read(magic, sizeof magic);
  file.read(reinterpret_cast<char*>(header), sizeof header);
  if (!file || std::memcmp(magic, kMagic, sizeof magic - 1) != 0)
    throw RunError("'" + path + "' is not a railfe checkpoint");
  if (magic[7] != kMagic[7])
    throw RunError("the checkpoint '" + path + "' is in format " + std::string(1, magic[7]) +
                   ", written by another version of railfe; this one reads format " +
                   std::string(1, kMagic[7]) +
                   ": remove it (or set Checkpoint/Restart false) and run from the start");
  if (header[0] != n_ranks)
    throw RunError("the checkpoint '" + path + "' was written by a run on " +
                   std::to_string(header[0]) + " ranks; resume it on that many (this run has " +
                   std::to_string(n_ranks) + ")");
  CheckpointSections sections(static_cast<std::size_t>(header[1]));
  for (auto& section : sections) {
    std::int64_t size = 0;
    file.read(reinterpret_cast<char*>(&size), sizeof size);
    if (!file || size < 0)
      throw RunError("the checkpoint '" + path + "' is damaged");
    section.resize(static_cast<std::size_t>(size));
    file.read(reinterpret_cast<char*>(section.data()),
              static_cast<std::streamsize>(section.size() * sizeof(double)));
  }
  file.read(magic, sizeof magic);
  if (!file || std::memcmp(magic, kMagic, sizeof magic) != 0)
    throw RunError("the checkpoint '" + path + "' is truncated");
  return sections;
}

bool checkpoint_exists(const std::string& path, const Communicator& comm) {
  const long long found = std::filesystem::exists(path) ? 1 : 0;
  return comm.sum(found) == comm.n_ranks();
}

}  // namespace railfe
