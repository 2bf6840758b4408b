#pragma once
/// \file
/// Reading a deck: the XML file is read once, on rank 0, and its text broadcast; every rank
/// parses the same text into a Teuchos::ParameterList.

#include <string>

#include <Teuchos_RCP.hpp>

namespace Teuchos {
class ParameterList;
}

namespace railfe {

class Communicator;

/// A parsed deck and where it came from.
struct Deck {
  std::string source;     ///< the path as the user gave it (used in every message)
  std::string directory;  ///< directory of the deck; relative file names in it start here
  Teuchos::RCP<Teuchos::ParameterList> parameters;  ///< the whole deck

  /// Resolves \p file_name written in the deck: absolute paths stay, relative ones are taken
  /// from the deck's directory.
  std::string resolve(const std::string& file_name) const;
};

/// Reads \p path on rank 0 and parses it on every rank. Throws InputError on every rank (with the
/// same message) if the file is missing or unreadable, or the XML is malformed.
Deck read_deck(const std::string& path, const Communicator& comm);

/// Parses deck text. \p source names it in messages, \p directory resolves relative paths.
/// Throws InputError for malformed XML and for duplicated names in one list.
Deck parse_deck(const std::string& xml_text, const std::string& source,
                const std::string& directory);

}  // namespace railfe
