#include "framework/mesh/exodus_file.hpp"

#include <exodusII.h>

#include <algorithm>
#include <filesystem>

#include "framework/base/error.hpp"

namespace railfe {

ExodusFile::ExodusFile(const std::string& path, ExodusMode mode) : path_(path), mode_(mode) {
  int cpu_word_size = sizeof(double);
  int io_word_size = sizeof(double);
  float version = 0;
  ex_opts(0);  // errors come back as status codes; railfe words the message
  if (mode == ExodusMode::read) {
    if (!std::filesystem::exists(path))
      throw_input_error(path, "", "mesh file not found");
    id_ = ex_open(path.c_str(), EX_READ, &cpu_word_size, &io_word_size, &version);
    if (id_ < 0) {
      throw_input_error(path, "", "cannot be read as an Exodus II file (corrupt or not Exodus)");
    }
  } else {
    id_ = ex_create(path.c_str(), EX_CLOBBER | EX_LARGE_MODEL, &cpu_word_size, &io_word_size);
    if (id_ < 0)
      throw RunError("cannot create Exodus file '" + path + "'");
  }
  ex_set_int64_status(id_, EX_ALL_INT64_API);
}

ExodusFile::~ExodusFile() {
  if (id_ >= 0)
    ex_close(id_);
}

void ExodusFile::close() {
  if (id_ < 0)
    return;
  const int status = ex_close(id_);
  id_ = -1;
  if (status < 0)
    throw RunError("closing Exodus file '" + path_ + "' failed");
}

void ExodusFile::check(int status, const std::string& what) const {
  if (status >= 0)
    return;
  const std::string message =
      "Exodus error while " + what + " (status " + std::to_string(status) + ")";
  if (mode_ == ExodusMode::read)
    throw_input_error(path_, "", message);
  throw RunError(path_ + ": " + message);
}

std::vector<std::string> ExodusFile::names(int entity_type, int count) const {
  std::vector<std::string> result(count);
  if (count == 0)
    return result;
  const int length =
      std::max<int>(32, static_cast<int>(ex_inquire_int(id_, EX_INQ_DB_MAX_USED_NAME_LENGTH)));
  ex_set_max_name_length(id_, length);
  std::vector<std::vector<char>> buffers(count, std::vector<char>(length + 1, '\0'));
  std::vector<char*> pointers(count);
  for (int i = 0; i < count; ++i)
    pointers[i] = buffers[i].data();
  check(ex_get_names(id_, static_cast<ex_entity_type>(entity_type), pointers.data()),
        "reading entity names");
  for (int i = 0; i < count; ++i)
    result[i] = buffers[i].data();
  return result;
}

}  // namespace railfe
