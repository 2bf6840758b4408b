#include "framework/deck/describe.hpp"

#include <sstream>
#include <vector>

#include <Teuchos_Array.hpp>

#include "framework/deck/parameter_spec.hpp"
#include "framework/deck/validation.hpp"

namespace railfe {

namespace {

std::string default_text(const Teuchos::ParameterEntry& entry, const ParameterRule& rule) {
  if (rule.required())
    return "required";
  if (entry.isList())
    return "";
  std::ostringstream out;
  auto join = [&out](const auto& values) {
    out << "{";
    for (decltype(values.size()) i = 0; i < values.size(); ++i)
      out << (i ? ", " : "") << values[i];
    out << "}";
  };
  if (entry.isType<std::string>()) {
    out << "'" << entry.getValue<std::string>(nullptr) << "'";
  } else if (entry.isType<Teuchos::Array<double>>()) {
    join(entry.getValue<Teuchos::Array<double>>(nullptr));
  } else if (entry.isType<Teuchos::Array<int>>()) {
    join(entry.getValue<Teuchos::Array<int>>(nullptr));
  } else if (entry.isType<Teuchos::Array<std::string>>()) {
    join(entry.getValue<Teuchos::Array<std::string>>(nullptr));
  } else if (entry.isType<bool>()) {
    out << (entry.getValue<bool>(nullptr) ? "true" : "false");
  } else {
    out << entry.getAny(false);
  }
  return out.str();
}

struct Row {
  std::string name, type, default_value, allowed, units, doc;
};

struct Section {
  std::string path, doc;
  std::vector<Row> rows;
  std::vector<std::string> choice_docs;
};

void collect(const Teuchos::ParameterList& valid, const std::string& path, const std::string& doc,
             std::vector<Section>& sections) {
  Section section{path, doc, {}, {}};
  std::vector<std::pair<std::string, const Teuchos::ParameterEntry*>> nested;
  for (auto it = valid.begin(); it != valid.end(); ++it) {
    const auto& entry = valid.entry(it);
    const std::string& name = valid.name(it);
    const ParameterRule* rule = rule_of(entry);
    if (name == kAnyName && entry.isList())
      nested.emplace_back(name, &entry);
    if (rule == nullptr)
      continue;
    std::string allowed;
    if (!entry.isList() && rule->kind() != ParameterKind::text)
      allowed = rule->describe_allowed();
    std::string type = rule->type_name();
    if (rule->kind() == ParameterKind::named_sublists)
      type = "ParameterList of named sublists";
    if (rule->kind() == ParameterKind::choice)
      type = "string (choice)";
    std::string doc = entry.docString();
    if (rule->condition()) {
      const bool array =
          valid.getEntry(rule->condition()->controller).isType<Teuchos::Array<std::string>>();
      doc += " Only when " + rule->condition()->describe(array) + ".";
    }
    section.rows.push_back({name, type, default_text(entry, *rule), allowed, rule->units(), doc});
    for (const auto& choice : rule->choices()) {
      section.choice_docs.push_back(name + " = '" + choice.value + "': " + choice.doc);
    }
    if (entry.isList())
      nested.emplace_back(name, &entry);
  }
  sections.push_back(section);
  for (const auto& [name, entry] : nested) {
    const auto& list = Teuchos::getValue<Teuchos::ParameterList>(*entry);
    const ParameterRule* rule = rule_of(*entry);
    if (rule == nullptr) {
      collect(list, join_path(path, name), entry->docString(), sections);
    } else if (rule->kind() == ParameterKind::named_sublists) {
      const auto& layout = list.sublist(kAnyName);
      collect(layout, join_path(join_path(path, name), kAnyName),
              entry->docString() + " Each sublist, under a name of your choice:", sections);
    } else {
      collect(list, join_path(path, name), entry->docString(), sections);
    }
  }
}

std::string escape_markdown(std::string text) {
  std::string result;
  for (char c : text) {
    if (c == '|')
      result += "\\|";
    else if (c == '<')
      result += "&lt;";
    else if (c == '>')
      result += "&gt;";
    else
      result += c;
  }
  return result;
}

}  // namespace

void describe_parameters(std::ostream& out, const Teuchos::ParameterList& valid,
                         const std::string& path, const std::string& title, DescribeFormat format) {
  std::vector<Section> sections;
  collect(valid, path, title, sections);
  for (const auto& section : sections) {
    const std::string heading = section.path.empty() ? "(top level)" : section.path;
    if (format == DescribeFormat::markdown) {
      out << "\n### " << escape_markdown(heading) << "\n\n";
      if (!section.doc.empty())
        out << escape_markdown(section.doc) << "\n\n";
      if (section.rows.empty())
        continue;
      out << "| Parameter | Type | Default | Allowed | Units | Description |\n";
      out << "|---|---|---|---|---|---|\n";
      for (const auto& row : section.rows) {
        out << "| " << escape_markdown(row.name) << " | " << escape_markdown(row.type) << " | "
            << escape_markdown(row.default_value) << " | " << escape_markdown(row.allowed) << " | "
            << row.units << " | " << escape_markdown(row.doc) << " |\n";
      }
      if (!section.choice_docs.empty()) {
        out << "\n";
        for (const auto& line : section.choice_docs)
          out << "- " << escape_markdown(line) << "\n";
      }
    } else {
      out << "\n[" << heading << "]";
      if (!section.doc.empty())
        out << "  " << section.doc;
      out << "\n";
      for (const auto& row : section.rows) {
        out << "  " << row.name << " (" << row.type;
        if (!row.units.empty())
          out << ", " << row.units;
        if (row.default_value == "required") {
          out << ", required";
        } else if (!row.default_value.empty()) {
          out << ", default " << row.default_value;
        }
        if (!row.allowed.empty() && row.type != "string (choice)")
          out << ", " << row.allowed;
        out << ")\n      " << row.doc << "\n";
      }
      for (const auto& line : section.choice_docs)
        out << "      - " << line << "\n";
    }
  }
}

}  // namespace railfe
