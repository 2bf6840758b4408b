#pragma once
/// \file
/// An open Exodus II file that closes itself, with status checks that turn library errors into
/// railfe errors naming the file and the operation.

#include <string>
#include <vector>

namespace railfe {

/// How to open an Exodus file.
enum class ExodusMode { read, create };

/// RAII handle of an Exodus II database (libexodusii 6.02). All integer data go through the
/// 64-bit API, so files written with 32- or 64-bit ids read the same way.
class ExodusFile {
 public:
  /// Opens \p path for reading, or creates it (replacing any file there). Throws InputError when
  /// a file to read is missing or not Exodus, RunError when one cannot be created.
  ExodusFile(const std::string& path, ExodusMode mode);
  ~ExodusFile();
  ExodusFile(const ExodusFile&) = delete;
  ExodusFile& operator=(const ExodusFile&) = delete;

  /// The Exodus id for library calls.
  int id() const { return id_; }
  /// The path it was opened with.
  const std::string& path() const { return path_; }
  /// Throws (InputError when reading, RunError when writing) if \p status reports an error;
  /// \p what says which operation failed.
  void check(int status, const std::string& what) const;
  /// Names of the entities of \p entity_type (an ex_entity_type) in id order; "" where unnamed.
  std::vector<std::string> names(int entity_type, int count) const;
  /// Flushes and closes now (the destructor does nothing afterwards). Throws on failure.
  void close();

 private:
  std::string path_;
  ExodusMode mode_;
  int id_ = -1;
};

}  // namespace railfe
