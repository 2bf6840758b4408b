#include "framework/deck/deck.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <sstream>
#include <vector>

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
  if (file.is_absolute() || directory.empty())
    return file.string();
  return (std::filesystem::path(directory) / file).lexically_normal().string();
}

namespace {

// Only plain decimal numbers: strtod alone would also take "nan", "inf" and hexadecimal
// ("0x10" = 16), which Teuchos then reads differently (inside an array, "nan" becomes 0).
bool parses_as_number(const std::string& text, bool integer) {
  std::size_t i = 0;
  const std::size_t n = text.size();
  auto digits = [&] {
    const std::size_t start = i;
    while (i < n && std::isdigit(static_cast<unsigned char>(text[i])))
      ++i;
    return i - start;
  };
  while (i < n && std::isspace(static_cast<unsigned char>(text[i])))
    ++i;
  if (i < n && (text[i] == '+' || text[i] == '-'))
    ++i;
  std::size_t mantissa = digits();
  if (!integer && i < n && text[i] == '.') {
    ++i;
    mantissa += digits();
  }
  if (mantissa == 0)
    return false;
  if (!integer && i < n && (text[i] == 'e' || text[i] == 'E')) {
    ++i;
    if (i < n && (text[i] == '+' || text[i] == '-'))
      ++i;
    if (digits() == 0)
      return false;
  }
  while (i < n && std::isspace(static_cast<unsigned char>(text[i])))
    ++i;
  if (i != n)
    return false;
  // A decimal number too large for a double (1e999) would become inf.
  return integer ? true : std::isfinite(std::strtod(text.c_str(), nullptr));
}

// Teuchos turns type="double" value="abc" into 0 without a word: every number and flag is
// checked here first, so a typo in a value can never become a silent zero.
std::string value_problem(const std::string& type, const std::string& value) {
  const bool is_array = type.rfind("Array(", 0) == 0 && type.back() == ')';
  const std::string element = is_array ? type.substr(6, type.size() - 7) : type;
  const bool integer = element == "int" || element == "long long";
  const bool real = element == "double" || element == "float";
  const bool flag = element == "bool";
  if (is_array && element == "string") {
    const auto open = value.find('{'), close = value.rfind('}');
    if (open == std::string::npos || close == std::string::npos || close < open)
      return "array value '" + value + "' is not written as {a, b, c}";
    return "";
  }
  if (!integer && !real && !flag)
    return "";
  std::vector<std::string> items;
  if (is_array) {
    const auto open = value.find('{'), close = value.rfind('}');
    if (open == std::string::npos || close == std::string::npos || close < open) {
      return "array value '" + value + "' is not written as {a, b, c}";
    }
    const std::string inner = value.substr(open + 1, close - open - 1);
    std::size_t start = 0;
    while (start <= inner.size()) {
      const auto comma = inner.find(',', start);
      items.push_back(
          inner.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
      if (comma == std::string::npos)
        break;
      start = comma + 1;
    }
    if (items.size() == 1 && items[0].find_first_not_of(" \t") == std::string::npos)
      items.clear();
  } else {
    items.push_back(value);
  }
  for (auto item : items) {
    item.erase(0, item.find_first_not_of(" \t\n"));
    item.erase(item.find_last_not_of(" \t\n") + 1);
    if (flag) {
      std::string word;
      for (char c : item) {
        if (!std::isspace(static_cast<unsigned char>(c)))
          word += static_cast<char>(std::tolower(c));
      }
      if (word != "true" && word != "false" && word != "1" && word != "0") {
        return "'" + item + "' is not a bool";
      }
    } else if (!parses_as_number(item, integer)) {
      return "'" + item + "' is not " + (integer ? "an integer" : "a number");
    }
  }
  return "";
}

// The value types a deck may use (what railfe's parameters read).
const std::string kTypes[] = {"double",        "int",        "bool",         "string",
                              "Array(double)", "Array(int)", "Array(string)"};

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
    if (tag == "Parameter") {
      // Teuchos would stop with its own words ("Bad Parameter", "Can't find converter"), which
      // name neither the deck's parameter nor what is allowed.
      if (!child.hasAttribute("type") || !child.hasAttribute("value"))
        throw_input_error(source, join_path(path, name),
                          std::string("<Parameter> without a ") +
                              (child.hasAttribute("type") ? "value" : "type") + " attribute",
                          "<Parameter name=\"...\" type=\"...\" value=\"...\"/>");
      const std::string type = child.getAttribute("type");
      if (std::find(std::begin(kTypes), std::end(kTypes), type) == std::end(kTypes))
        throw_input_error(source, join_path(path, name), "unknown type '" + type + "'",
                          "double, int, bool, string, Array(double), Array(int), Array(string)");
    }
    if (tag == "Parameter" && child.hasAttribute("type") && child.hasAttribute("value")) {
      const std::string problem =
          value_problem(child.getAttribute("type"), child.getAttribute("value"));
      if (!problem.empty()) {
        throw_input_error(source, join_path(path, name), "malformed parameter: " + problem,
                          "a value of type " + child.getAttribute("type"));
      }
    }
    if (!seen.insert(name).second) {
      throw_input_error(source, join_path(path, name), "is given twice in the same list",
                        "each name once per list");
    }
    if (tag == "ParameterList")
      check_duplicates(child, source, join_path(path, name));
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
    throw_input_error(source, "", "malformed XML: " + essential_line(error.what()),
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
    // Teuchos reports unknown types and the like here.
    throw_input_error(source, "", "malformed parameter: " + essential_line(error.what()),
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
