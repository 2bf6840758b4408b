#include "framework/base/error.hpp"

#include <algorithm>
#include <cctype>

namespace railfe {

std::string format_input_message(const std::string& source, const std::string& path,
                                 const std::string& problem, const std::string& allowed) {
  std::string message;
  if (!source.empty())
    message += source + ": ";
  if (!path.empty())
    message += "'" + path + "': ";
  message += problem;
  if (!allowed.empty())
    message += "; allowed: " + allowed;
  return message;
}

void throw_input_error(const std::string& source, const std::string& path,
                       const std::string& problem, const std::string& allowed) {
  throw InputError(format_input_message(source, path, problem, allowed));
}

namespace {

std::string lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> previous(b.size() + 1), current(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j)
    previous[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    current[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t substitution = previous[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
      current[j] = std::min({previous[j] + 1, current[j - 1] + 1, substitution});
    }
    std::swap(previous, current);
  }
  return previous[b.size()];
}

}  // namespace

std::string closest_name(const std::string& name, const std::vector<std::string>& candidates) {
  const std::string key = lower(name);
  std::string best;
  std::size_t best_distance = std::string::npos;
  for (const auto& candidate : candidates) {
    const std::size_t distance = edit_distance(key, lower(candidate));
    if (distance < best_distance) {
      best_distance = distance;
      best = candidate;
    }
  }
  // A third of the name's length (at least 2 edits) still reads as a typo; more is a different
  // word.
  const std::size_t limit = std::max<std::size_t>(2, key.size() / 3);
  return best_distance <= limit ? best : std::string();
}

std::string essential_line(const std::string& message) {
  std::string best;
  std::size_t start = 0;
  while (start < message.size()) {
    const std::size_t end = message.find('\n', start);
    const std::string line =
        message.substr(start, end == std::string::npos ? std::string::npos : end - start);
    if (line.find_first_not_of(" \t\r") != std::string::npos)
      best = line;
    if (end == std::string::npos)
      break;
    start = end + 1;
  }
  return best;
}

std::string quoted_list(const std::vector<std::string>& names, std::size_t max_shown) {
  if (names.empty())
    return "(none)";
  std::string text;
  const std::size_t shown = std::min(names.size(), max_shown);
  for (std::size_t i = 0; i < shown; ++i) {
    if (i > 0)
      text += ", ";
    text += "'" + names[i] + "'";
  }
  if (shown < names.size())
    text += " and " + std::to_string(names.size() - shown) + " more";
  return text;
}

}  // namespace railfe
