#include "framework/deck/validation.hpp"

#include <algorithm>
#include <vector>

#include <Teuchos_Array.hpp>

#include "framework/base/error.hpp"
#include "framework/deck/parameter_spec.hpp"

namespace railfe {

std::string join_path(const std::string& path, const std::string& name) {
  return path.empty() ? name : path + "/" + name;
}

namespace {

std::vector<std::string> names_of(const Teuchos::ParameterList& list) {
  std::vector<std::string> names;
  for (auto it = list.begin(); it != list.end(); ++it) {
    if (list.name(it) != kAnyName)
      names.push_back(list.name(it));
  }
  return names;
}

void report_unknown(const std::string& name, const Teuchos::ParameterList& valid,
                    const std::string& source, const std::string& path) {
  const auto known = names_of(valid);
  const std::string guess = closest_name(name, known);
  std::string problem = "unknown parameter or sublist '" + name + "'";
  if (!guess.empty())
    problem += " (did you mean '" + guess + "'?)";
  throw_input_error(source, join_path(path, name), problem, quoted_list(known, 40));
}

// Integers written for real parameters become doubles, so owners read one type.
void normalize_number_types(Teuchos::ParameterList& given, const std::string& name,
                            const ParameterRule& rule) {
  const auto& entry = given.getEntry(name);
  if (rule.kind() == ParameterKind::real && entry.isType<int>()) {
    given.set(name, static_cast<double>(entry.getValue<int>(nullptr)));
  } else if (rule.kind() == ParameterKind::real_array && entry.isType<Teuchos::Array<int>>()) {
    const auto& ints = entry.getValue<Teuchos::Array<int>>(nullptr);
    given.set(name, Teuchos::Array<double>(ints.begin(), ints.end()));
  }
}

bool has_required_entries(const Teuchos::ParameterList& valid) {
  for (auto it = valid.begin(); it != valid.end(); ++it) {
    const ParameterRule* rule = rule_of(valid.entry(it));
    if (rule != nullptr && rule->required())
      return true;
  }
  return false;
}

// The value of \p controller as words: the deck's if given, else the default.
std::vector<std::string> controller_words(const Teuchos::ParameterList& given,
                                          const Teuchos::ParameterList& valid,
                                          const std::string& controller) {
  const Teuchos::ParameterEntry& entry =
      given.isParameter(controller) ? given.getEntry(controller) : valid.getEntry(controller);
  if (entry.isType<bool>())
    return {entry.getValue<bool>(nullptr) ? "true" : "false"};
  if (entry.isType<std::string>())
    return {entry.getValue<std::string>(nullptr)};
  if (entry.isType<Teuchos::Array<std::string>>()) {
    const auto& words = entry.getValue<Teuchos::Array<std::string>>(nullptr);
    return {words.begin(), words.end()};
  }
  return {};
}

// Refuses a parameter the deck gives although its list's choices make it meaningless. Entries
// that validation itself filled in with defaults are marked as such and pass.
void check_condition(const Teuchos::ParameterList& given, const Teuchos::ParameterList& valid,
                     const std::string& name, const ParameterRule& rule, const std::string& source,
                     const std::string& path) {
  if (!rule.condition() || given.getEntry(name).isDefault())
    return;
  const Condition& condition = *rule.condition();
  const auto words = controller_words(given, valid, condition.controller);
  for (const auto& word : words) {
    if (std::find(condition.values.begin(), condition.values.end(), word) != condition.values.end())
      return;
  }
  const bool array = valid.getEntry(condition.controller).isType<Teuchos::Array<std::string>>();
  std::string actual;
  for (std::size_t i = 0; i < words.size(); ++i)
    actual += (i ? ", '" : "'") + words[i] + "'";
  const bool defaulted = !given.isParameter(condition.controller);
  throw_input_error(source, join_path(path, name),
                    "is used only when " + condition.describe(array) + ", but " +
                        condition.controller + (array ? " holds " : " is ") + actual +
                        (defaulted ? " (its default)" : "") + ", so the value would be ignored",
                    "remove '" + name + "', or set " + condition.controller);
}

}  // namespace

void validate_and_complete(Teuchos::ParameterList& given, const Teuchos::ParameterList& valid,
                           const std::string& source, const std::string& path) {
  for (const auto& name : names_of(given)) {
    const Teuchos::ParameterEntry* valid_entry = valid.getEntryPtr(name);
    if (valid_entry == nullptr && valid.isSublist(kAnyName)) {
      // A list of user-named sublists (such as Materials): every child follows one layout.
      if (!given.isSublist(name)) {
        throw_input_error(source, join_path(path, name), "is a parameter but must be a sublist",
                          "one sublist per named item");
      }
      validate_and_complete(given.sublist(name), valid.sublist(kAnyName), source,
                            join_path(path, name));
      continue;
    }
    if (valid_entry == nullptr)
      report_unknown(name, valid, source, path);
    const ParameterRule* rule = rule_of(*valid_entry);
    if (rule == nullptr) {
      throw std::logic_error("railfe: parameter '" + join_path(path, name) + "' has no rule");
    }
    const std::string problem = rule->check(given.getEntry(name));
    if (!problem.empty()) {
      throw_input_error(source, join_path(path, name), problem, rule->describe_allowed());
    }
    normalize_number_types(given, name, *rule);
    check_condition(given, valid, name, *rule, source, path);

    if (rule->kind() == ParameterKind::sublist && !rule->delegated()) {
      validate_and_complete(given.sublist(name),
                            Teuchos::getValue<Teuchos::ParameterList>(*valid_entry), source,
                            join_path(path, name));
    } else if (rule->kind() == ParameterKind::named_sublists) {
      const auto& layout =
          Teuchos::getValue<Teuchos::ParameterList>(*valid_entry).sublist(kAnyName);
      auto& children = given.sublist(name);
      for (const auto& child : names_of(children)) {
        const std::string child_path = join_path(join_path(path, name), child);
        if (!children.isSublist(child)) {
          throw_input_error(source, child_path, "is a parameter but must be a sublist",
                            "one sublist per named item");
        }
        validate_and_complete(children.sublist(child), layout, source, child_path);
      }
    }
  }

  for (auto it = valid.begin(); it != valid.end(); ++it) {
    const std::string& name = valid.name(it);
    if (name == kAnyName || given.isParameter(name))
      continue;
    const ParameterRule* rule = rule_of(valid.entry(it));
    if (rule == nullptr)
      continue;
    if (rule->required()) {
      const std::string what =
          rule->kind() == ParameterKind::sublist || rule->kind() == ParameterKind::named_sublists
              ? "missing required sublist"
              : "missing required parameter";
      throw_input_error(source, join_path(path, name),
                        what + " (" + valid.entry(it).docString() + ")", rule->describe_allowed());
    }
    if (rule->kind() == ParameterKind::sublist) {
      // An absent optional sublist gets its defaults unless it has required entries of its own:
      // then it is only needed when other parameters say so, and its owner checks that.
      const auto& layout = Teuchos::getValue<Teuchos::ParameterList>(valid.entry(it));
      if (!rule->delegated() && !has_required_entries(layout)) {
        validate_and_complete(given.sublist(name), layout, source, join_path(path, name));
      }
    } else if (rule->kind() == ParameterKind::named_sublists) {
      given.sublist(name);
    } else {
      Teuchos::ParameterEntry copy = valid.entry(it);
      copy.setValidator(Teuchos::null);
      copy.setAnyValue(copy.getAny(false), true);  // a default, not the deck's word
      given.setEntry(name, copy);
    }
  }
}

}  // namespace railfe
