#include "framework/deck/parameter_spec.hpp"

#include <stdexcept>

#include <Teuchos_Array.hpp>

namespace railfe {

ParameterSpec::ParameterSpec(std::string doc)
    : doc_(std::move(doc)), list_(Teuchos::rcp(new Teuchos::ParameterList())) {}

void ParameterSpec::add(const std::string& name, const Teuchos::ParameterEntry& value,
                        const std::string& doc, Teuchos::RCP<ParameterRule> rule) {
  list_->setEntry(name, value);
  auto entry = list_->getEntryRCP(name);
  entry->setDocString(doc);
  entry->setValidator(rule);
}

namespace {

template <typename T>
Teuchos::ParameterEntry entry_of(const T& value) {
  return Teuchos::ParameterEntry(value);
}

template <typename T>
Teuchos::ParameterEntry array_entry(const std::vector<T>& values) {
  return Teuchos::ParameterEntry(Teuchos::Array<T>(values.begin(), values.end()));
}

Teuchos::RCP<ParameterRule> rule(ParameterKind kind, bool required, const std::string& units = "",
                                 Range range = {}, std::vector<Choice> choices = {}, int size = 0) {
  return Teuchos::rcp(new ParameterRule(kind, required, units, range, std::move(choices), size));
}

}  // namespace

ParameterSpec& ParameterSpec::real(const std::string& name, double default_value,
                                   const std::string& doc, const std::string& units, Range range) {
  add(name, entry_of(default_value), doc, rule(ParameterKind::real, false, units, range));
  return *this;
}

ParameterSpec& ParameterSpec::required_real(const std::string& name, const std::string& doc,
                                            const std::string& units, Range range) {
  add(name, entry_of(0.0), doc, rule(ParameterKind::real, true, units, range));
  return *this;
}

ParameterSpec& ParameterSpec::integer(const std::string& name, int default_value,
                                      const std::string& doc, Range range) {
  add(name, entry_of(default_value), doc, rule(ParameterKind::integer, false, "", range));
  return *this;
}

ParameterSpec& ParameterSpec::text(const std::string& name, const std::string& default_value,
                                   const std::string& doc) {
  add(name, entry_of(default_value), doc, rule(ParameterKind::text, false));
  return *this;
}

ParameterSpec& ParameterSpec::required_text(const std::string& name, const std::string& doc) {
  add(name, entry_of(std::string()), doc, rule(ParameterKind::text, true));
  return *this;
}

ParameterSpec& ParameterSpec::flag(const std::string& name, bool default_value,
                                   const std::string& doc) {
  add(name, entry_of(default_value), doc, rule(ParameterKind::flag, false));
  return *this;
}

ParameterSpec& ParameterSpec::choice(const std::string& name, const std::string& default_value,
                                     std::vector<Choice> choices, const std::string& doc) {
  add(name, entry_of(default_value), doc,
      rule(ParameterKind::choice, false, "", {}, std::move(choices)));
  return *this;
}

ParameterSpec& ParameterSpec::required_choice(const std::string& name, std::vector<Choice> choices,
                                              const std::string& doc) {
  add(name, entry_of(std::string()), doc,
      rule(ParameterKind::choice, true, "", {}, std::move(choices)));
  return *this;
}

ParameterSpec& ParameterSpec::real_array(const std::string& name,
                                         const std::vector<double>& default_value,
                                         const std::string& doc, const std::string& units, int size,
                                         Range range) {
  add(name, array_entry(default_value), doc,
      rule(ParameterKind::real_array, false, units, range, {}, size));
  return *this;
}

ParameterSpec& ParameterSpec::required_real_array(const std::string& name, const std::string& doc,
                                                  const std::string& units, int size, Range range) {
  add(name, array_entry(std::vector<double>{}), doc,
      rule(ParameterKind::real_array, true, units, range, {}, size));
  return *this;
}

ParameterSpec& ParameterSpec::integer_array(const std::string& name,
                                            const std::vector<int>& default_value,
                                            const std::string& doc, int size, Range range) {
  add(name, array_entry(default_value), doc,
      rule(ParameterKind::integer_array, false, "", range, {}, size));
  return *this;
}

ParameterSpec& ParameterSpec::required_text_array(const std::string& name, const std::string& doc) {
  add(name, array_entry(std::vector<std::string>{}), doc, rule(ParameterKind::text_array, true));
  return *this;
}

ParameterSpec& ParameterSpec::text_array(const std::string& name,
                                         const std::vector<std::string>& default_value,
                                         const std::string& doc) {
  add(name, array_entry(default_value), doc, rule(ParameterKind::text_array, false));
  return *this;
}

ParameterSpec& ParameterSpec::sublist(const std::string& name, const ParameterSpec& contents,
                                      const std::string& doc, bool required) {
  add(name, Teuchos::ParameterEntry(*contents.list()), doc, rule(ParameterKind::sublist, required));
  return *this;
}

ParameterSpec& ParameterSpec::named_sublists(const std::string& name, const ParameterSpec& each,
                                             const std::string& doc) {
  Teuchos::ParameterList holder;
  holder.set(kAnyName, *each.list(), each.doc());
  add(name, Teuchos::ParameterEntry(holder), doc, rule(ParameterKind::named_sublists, false));
  return *this;
}

ParameterSpec& ParameterSpec::delegated_sublist(const std::string& name,
                                                const ParameterSpec& contents,
                                                const std::string& doc, bool required) {
  auto sublist_rule = rule(ParameterKind::sublist, required);
  sublist_rule->set_delegated(true);
  add(name, Teuchos::ParameterEntry(*contents.list()), doc, sublist_rule);
  return *this;
}

ParameterSpec& ParameterSpec::only_when(const std::string& controller,
                                        const std::vector<std::string>& values,
                                        const std::vector<std::string>& names) {
  if (list_->getEntryPtr(controller) == nullptr)
    throw std::logic_error("railfe: only_when: no controller '" + controller + "'");
  for (const auto& name : names) {
    const Teuchos::ParameterEntry* entry = list_->getEntryPtr(name);
    auto* rule =
        entry == nullptr
            ? nullptr
            : dynamic_cast<ParameterRule*>(
                  Teuchos::rcp_const_cast<Teuchos::ParameterEntryValidator>(entry->validator())
                      .get());
    if (rule == nullptr)
      throw std::logic_error("railfe: only_when: no parameter '" + name + "'");
    rule->set_condition({controller, values});
  }
  return *this;
}

}  // namespace railfe
