#include "framework/output/finite_check.hpp"

#include <exodusII.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include "framework/mesh/exodus_file.hpp"
#include "framework/output/csv_writer.hpp"

namespace railfe {

namespace {

bool is_non_finite_word(std::string word) {
  for (auto& c : word)
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (!word.empty() && (word[0] == '-' || word[0] == '+'))
    word.erase(0, 1);
  return word == "nan" || word == "inf" || word == "infinity" || word.rfind("nan(", 0) == 0;
}

bool is_separator(char c) {
  return std::isspace(static_cast<unsigned char>(c)) || c == ',' || c == ':' || c == '"' ||
         c == '{' || c == '}' || c == '[' || c == ']' || c == ';';
}

// A CSV line's cells (CsvWriter::cells: a quoted label may hold commas, so the column named is
// the cell's), each without spaces; another text file's words between separators.
std::vector<std::string> split(const std::string& line, bool csv) {
  std::vector<std::string> words;
  if (csv) {
    for (std::string cell : CsvWriter::cells(line)) {
      cell.erase(std::remove_if(cell.begin(), cell.end(), is_separator), cell.end());
      words.push_back(cell);
    }
    return words;
  }
  std::string word;
  for (std::size_t i = 0; i <= line.size(); ++i) {
    if (i < line.size() && !is_separator(line[i])) {
      word += line[i];
      continue;
    }
    if (!word.empty())
      words.push_back(word);
    word.clear();
  }
  return words;
}

// CSV keeps its header to name the column; other text files are located by line.
std::string scan_text(const std::string& path, bool csv) {
  std::ifstream file(path);
  std::string line;
  std::vector<std::string> header;
  for (long row = 0; std::getline(file, line); ++row) {
    const std::vector<std::string> words = split(line, csv);
    if (csv && row == 0) {
      header = words;
      continue;
    }
    for (std::size_t k = 0; k < words.size(); ++k) {
      if (!is_non_finite_word(words[k]))
        continue;
      if (!csv)
        return "line " + std::to_string(row + 1) + ": " + words[k];
      return "row " + std::to_string(row) + ", column '" +
             (k < header.size() ? header[k] : std::to_string(k + 1)) + "': " + words[k];
    }
  }
  return "";
}

std::string first_bad(const std::vector<double>& values) {
  for (double v : values)
    if (!std::isfinite(v)) {
      std::ostringstream text;
      text << v;
      return text.str();
    }
  return "";
}

std::string scan_exodus(const std::string& path) {
  ExodusFile file(path, ExodusMode::read);
  const int id = file.id();
  const int n_steps = static_cast<int>(ex_inquire_int(id, EX_INQ_TIME));
  const auto n_nodes = ex_inquire_int(id, EX_INQ_NODES);
  int n_nodal = 0, n_element = 0;
  ex_get_variable_param(id, EX_NODAL, &n_nodal);
  ex_get_variable_param(id, EX_ELEM_BLOCK, &n_element);
  const int n_blocks = static_cast<int>(ex_inquire_int(id, EX_INQ_ELEM_BLK));
  std::vector<ex_entity_id> block_ids(static_cast<std::size_t>(n_blocks));
  if (n_blocks > 0)
    ex_get_ids(id, EX_ELEM_BLOCK, block_ids.data());
  auto variable_name = [&](ex_entity_type type, int index) {
    std::vector<char> name(MAX_STR_LENGTH + 1, '\0');
    ex_get_variable_name(id, type, index, name.data());
    return std::string(name.data());
  };
  std::vector<double> values;
  for (int step = 1; step <= n_steps; ++step) {
    for (int v = 1; v <= n_nodal; ++v) {
      values.assign(static_cast<std::size_t>(n_nodes), 0.0);
      if (ex_get_var(id, step, EX_NODAL, v, 1, n_nodes, values.data()) < 0)
        continue;
      const std::string bad = first_bad(values);
      if (!bad.empty())
        return "nodal variable '" + variable_name(EX_NODAL, v) + "' at time step " +
               std::to_string(step) + ": " + bad;
    }
    for (int v = 1; v <= n_element; ++v) {
      for (const ex_entity_id block : block_ids) {
        ex_block info{};
        info.type = EX_ELEM_BLOCK;
        info.id = block;
        if (ex_get_block_param(id, &info) < 0 || info.num_entry <= 0)
          continue;
        values.assign(static_cast<std::size_t>(info.num_entry), 0.0);
        if (ex_get_var(id, step, EX_ELEM_BLOCK, v, block, info.num_entry, values.data()) < 0)
          continue;
        const std::string bad = first_bad(values);
        if (!bad.empty())
          return "element variable '" + variable_name(EX_ELEM_BLOCK, v) + "' at time step " +
                 std::to_string(step) + ": " + bad;
      }
    }
  }
  return "";
}

}  // namespace

std::string find_non_finite(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  if (extension == ".part")
    extension = std::filesystem::path(path).stem().extension().string();
  if (extension == ".csv")
    return scan_text(path, true);
  if (extension == ".json" || extension == ".txt")
    return scan_text(path, false);
  if (extension == ".exo")
    return scan_exodus(path);
  return "";
}

}  // namespace railfe
