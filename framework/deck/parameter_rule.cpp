#include "framework/deck/parameter_rule.hpp"

#include <cmath>
#include <sstream>

#include <Teuchos_Array.hpp>
#include <Teuchos_ParameterEntry.hpp>
#include <Teuchos_ParameterList.hpp>
#include <Teuchos_StandardParameterEntryValidators.hpp>

namespace railfe {

Range Range::positive() {
  return Range{0.0, std::nullopt, false, true};
}
Range Range::non_negative() {
  return Range{0.0, std::nullopt, true, true};
}
Range Range::at_least(double low) {
  return Range{low, std::nullopt, true, true};
}
Range Range::closed(double low, double high) {
  return Range{low, high, true, true};
}
Range Range::closed_open(double low, double high) {
  return Range{low, high, true, false};
}
Range Range::open(double low, double high) {
  return Range{low, high, false, false};
}

Range Range::open_closed(double low, double high) {
  return Range{low, high, false, true};
}

bool Range::contains(double value) const {
  if (!std::isfinite(value))
    return false;
  if (lower && (lower_inclusive ? value < *lower : value <= *lower))
    return false;
  if (upper && (upper_inclusive ? value > *upper : value >= *upper))
    return false;
  return true;
}

namespace {
std::string number_text(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}
}  // namespace

std::string Range::describe() const {
  if (!lower && !upper)
    return "any finite number";
  if (lower && !upper)
    return (lower_inclusive ? ">= " : "> ") + number_text(*lower);
  if (!lower && upper)
    return (upper_inclusive ? "<= " : "< ") + number_text(*upper);
  return std::string(lower_inclusive ? "[" : "(") + number_text(*lower) + ", " +
         number_text(*upper) + (upper_inclusive ? "]" : ")");
}

std::string Condition::describe(bool array_controller) const {
  std::string text = controller + (array_controller ? " contains " : " is ");
  for (std::size_t i = 0; i < values.size(); ++i)
    text += (i == 0 ? "'" : i + 1 == values.size() ? " or '" : ", '") + values[i] + "'";
  return text;
}

ParameterRule::ParameterRule(ParameterKind kind, bool required, std::string units, Range range,
                             std::vector<Choice> choices, int array_size)
    : kind_(kind),
      required_(required),
      units_(std::move(units)),
      range_(range),
      choices_(std::move(choices)),
      array_size_(array_size) {}

std::string ParameterRule::type_name() const {
  switch (kind_) {
    case ParameterKind::real:
      return "double";
    case ParameterKind::integer:
      return "int";
    case ParameterKind::text:
      return "string";
    case ParameterKind::flag:
      return "bool";
    case ParameterKind::choice:
      return "string";
    case ParameterKind::real_array:
      return "Array(double)";
    case ParameterKind::integer_array:
      return "Array(int)";
    case ParameterKind::text_array:
      return "Array(string)";
    case ParameterKind::sublist:
      return "ParameterList";
    case ParameterKind::named_sublists:
      return "ParameterList";
  }
  return "?";
}

std::string ParameterRule::describe_allowed() const {
  switch (kind_) {
    case ParameterKind::choice: {
      std::string text;
      for (std::size_t i = 0; i < choices_.size(); ++i) {
        text += (i ? ", '" : "'") + choices_[i].value + "'";
      }
      return text;
    }
    case ParameterKind::real:
    case ParameterKind::integer:
      return range_.describe();
    case ParameterKind::real_array:
    case ParameterKind::integer_array: {
      const std::string count =
          array_size_ > 0 ? std::to_string(array_size_) + " numbers" : "one or more numbers";
      const bool bounded = range_.lower || range_.upper;
      return bounded ? count + ", each " + range_.describe() : count;
    }
    case ParameterKind::text_array:
      return "one or more strings";
    case ParameterKind::flag:
      return "true or false";
    default:
      return type_name();
  }
}

namespace {

template <typename T>
std::string check_array(const Teuchos::Array<T>& values, int required_size, const Range& range) {
  if (values.empty())
    return "is an empty array";
  if (required_size > 0 && static_cast<int>(values.size()) != required_size) {
    return "has " + std::to_string(values.size()) + " entries";
  }
  for (decltype(values.size()) i = 0; i < values.size(); ++i) {
    if (!range.contains(static_cast<double>(values[i]))) {
      return "entry " + std::to_string(i + 1) + " is " + number_text(values[i]);
    }
  }
  return "";
}

}  // namespace

std::string ParameterRule::check(const Teuchos::ParameterEntry& entry) const {
  const bool is_list = entry.isList();
  const bool want_list = kind_ == ParameterKind::sublist || kind_ == ParameterKind::named_sublists;
  if (is_list != want_list) {
    return want_list ? "is a parameter but must be a sublist (ParameterList)"
                     : "is a sublist but must be a parameter of type " + type_name();
  }
  switch (kind_) {
    case ParameterKind::real: {
      double value;
      if (entry.isType<double>()) {
        value = entry.getValue<double>(nullptr);
      } else if (entry.isType<int>()) {
        value = entry.getValue<int>(nullptr);
      } else {
        return "has type " + entry.getAny(false).typeName() + "; expected double";
      }
      if (!range_.contains(value))
        return "value " + number_text(value) + " is out of range";
      return "";
    }
    case ParameterKind::integer: {
      if (!entry.isType<int>())
        return "has type " + entry.getAny(false).typeName() + "; expected int";
      const int value = entry.getValue<int>(nullptr);
      if (!range_.contains(value))
        return "value " + std::to_string(value) + " is out of range";
      return "";
    }
    case ParameterKind::text:
      return entry.isType<std::string>()
                 ? ""
                 : "has type " + entry.getAny(false).typeName() + "; expected string";
    case ParameterKind::flag:
      return entry.isType<bool>()
                 ? ""
                 : "has type " + entry.getAny(false).typeName() + "; expected bool";
    case ParameterKind::choice: {
      if (!entry.isType<std::string>()) {
        return "has type " + entry.getAny(false).typeName() + "; expected string";
      }
      const auto value = entry.getValue<std::string>(nullptr);
      for (const auto& choice : choices_) {
        if (choice.value == value)
          return "";
      }
      return "value '" + value + "' is not one of the choices";
    }
    case ParameterKind::real_array:
      if (entry.isType<Teuchos::Array<double>>()) {
        const std::string problem =
            check_array(entry.getValue<Teuchos::Array<double>>(nullptr), array_size_, range_);
        return problem.empty() ? "" : problem;
      }
      if (entry.isType<Teuchos::Array<int>>()) {
        return check_array(entry.getValue<Teuchos::Array<int>>(nullptr), array_size_, range_);
      }
      return "has type " + entry.getAny(false).typeName() + "; expected Array(double)";
    case ParameterKind::integer_array:
      if (!entry.isType<Teuchos::Array<int>>()) {
        return "has type " + entry.getAny(false).typeName() + "; expected Array(int)";
      }
      return check_array(entry.getValue<Teuchos::Array<int>>(nullptr), array_size_, range_);
    case ParameterKind::text_array:
      if (!entry.isType<Teuchos::Array<std::string>>()) {
        return "has type " + entry.getAny(false).typeName() + "; expected Array(string)";
      }
      return entry.getValue<Teuchos::Array<std::string>>(nullptr).empty() ? "is an empty array"
                                                                          : "";
    case ParameterKind::sublist:
    case ParameterKind::named_sublists:
      return "";
  }
  return "";
}

void ParameterRule::printDoc(const std::string& doc, std::ostream& out) const {
  out << "# " << doc << "\n# type " << type_name() << ", allowed " << describe_allowed() << "\n";
}

Teuchos::ParameterEntryValidator::ValidStringsList ParameterRule::validStringValues() const {
  if (kind_ != ParameterKind::choice)
    return Teuchos::null;
  auto values = Teuchos::rcp(new Teuchos::Array<std::string>());
  for (const auto& choice : choices_)
    values->push_back(choice.value);
  return values;
}

void ParameterRule::validate(const Teuchos::ParameterEntry& entry, const std::string& name,
                             const std::string& sublist_name) const {
  const std::string problem = check(entry);
  TEUCHOS_TEST_FOR_EXCEPTION(
      !problem.empty(), Teuchos::Exceptions::InvalidParameterValue,
      sublist_name << "/" << name << ": " << problem << "; allowed: " << describe_allowed());
}

const ParameterRule* rule_of(const Teuchos::ParameterEntry& entry) {
  return dynamic_cast<const ParameterRule*>(entry.validator().get());
}

}  // namespace railfe
