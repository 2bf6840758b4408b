#include "framework/deck/deck.hpp"

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include <Teuchos_ParameterList.hpp>
#include <Teuchos_StringInputSource.hpp>
#include <Teuchos_XMLObject.hpp>
#include <Teuchos_XMLParameterListReader.hpp>

#include "framework/base/error.hpp"
#include "framework/base/parallel.hpp"
#include "framework/deck/validation.hpp"

namespace railfe {

std::string Deck::resolve(const std::string& file_name) const {
  const std::filesystem::path file(file_name);
  if (file.is_absolute() || directory.empty()) return file.string();
  return (std::filesystem::path(directory) / file).lexically_normal().string();
}

namespace {

// Teuchos keeps the last of two same-named entries without a word; a deck that names a
// parameter twice is almost always a copy-paste slip, so it is refused.
void check_duplicates(const Teuchos::XMLObject& node, const std::string& source,
                      const std::string& path) {
  std::set<std::string> seen;
  for (int i = 0; i < node.numChildren(); ++i) {
    const Teuchos::XMLObject& child = node.getChild(i);
    const std::string& tag = child.getTag();
    if (tag != "Parameter" && tag != "ParameterList") {
      throw_input_error(source, path, "unexpected XML element <" + tag + ">",
                        "<Parameter> and <ParameterList>");
    }
    if (!child.hasAttribute("name")) {
      throw_input_error(source, path, "<" + tag + "> without a name attribute");
    }
    const std::string name = child.getAttribute("name");
    if (!seen.insert(name).second) {
      throw_input_error(source, join_path(path, name), "is given twice in the same list",
                        "each name once per list");
    }
    if (tag == "ParameterList") check_duplicates(child, source, join_path(path, name));
  }
}

}  // namespace

Deck parse_deck(const std::string& xml_text, const std::string& source,
                const std::string& directory) {
  Deck deck{source, directory, Teuchos::null};
  Teuchos::XMLObject root;
  try {
    Teuchos::StringInputSource input(xml_text);
    root = input.getObject();
  } catch (const std::exception& error) {
    throw_input_error(source, "", std::string("malformed XML: ") + error.what(),
                      "a Teuchos ParameterList XML document");
  }
  if (root.isEmpty() || root.getTag() != "ParameterList") {
    throw_input_error(source, "", "the root XML element must be <ParameterList>",
                      "a Teuchos ParameterList XML document");
  }
  check_duplicates(root, source, "");
  try {
    Teuchos::XMLParameterListReader reader;
    deck.parameters = Teuchos::rcp(new Teuchos::ParameterList(reader.toParameterList(root)));
  } catch (const std::exception& error) {
    // Teuchos reports bad values (type="double" value="abc", unknown types) here.
    std::string message = error.what();
    const auto newline = message.find_last_not_of("\n ");
    message = message.substr(0, newline + 1);
    throw_input_error(source, "", "malformed parameter: " + message,
                      "types double, int, bool, string, Array(double), Array(int), Array(string)");
  }
  return deck;
}

Deck read_deck(const std::string& path, const Communicator& comm) {
  std::string text;
  std::string problem;
  if (comm.is_root()) {
    std::ifstream file(path, std::ios::binary);
    if (!std::filesystem::exists(path)) {
      problem = format_input_message(path, "", "deck file not found");
    } else if (std::filesystem::is_directory(path)) {
      problem = format_input_message(path, "", "is a directory, not a deck file");
    } else if (!file) {
      problem = format_input_message(path, "", "deck file cannot be read (permissions?)");
    } else {
      std::ostringstream buffer;
      buffer << file.rdbuf();
      text = buffer.str();
    }
  }
  comm.agree(problem, true);
  comm.broadcast(text);
  const std::string directory = std::filesystem::path(path).parent_path().string();
  return parse_deck(text, path, directory);
}

}  // namespace railfe
