#pragma once
/// \file
/// What a deck parameter may hold. A ParameterRule rides on its Teuchos valid-list entry as the
/// entry's validator, so one Teuchos::ParameterList describes a module's parameters completely:
/// kind, default, range, choices, units, whether required, and a doc string.

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <Teuchos_ParameterEntryValidator.hpp>

namespace railfe {

/// The kinds of value a deck parameter can take (Teuchos XML type in brackets).
enum class ParameterKind {
  real,           ///< "double" (an "int" in the deck is accepted and converted)
  integer,        ///< "int"
  text,           ///< "string"
  flag,           ///< "bool"
  choice,         ///< "string" from a fixed list
  real_array,     ///< "Array(double)"
  integer_array,  ///< "Array(int)"
  text_array,     ///< "Array(string)"
  sublist,        ///< a ParameterList with fixed contents
  named_sublists  ///< a ParameterList whose children have user-chosen names and one layout
};

/// Bounds on a number (or on every entry of a numeric array). Unbounded by default.
struct Range {
  std::optional<double> lower;  ///< lower bound, if any
  std::optional<double> upper;  ///< upper bound, if any
  bool lower_inclusive = true;  ///< whether the lower bound itself is allowed
  bool upper_inclusive = true;  ///< whether the upper bound itself is allowed

  /// Values > 0.
  static Range positive();
  /// Values >= 0.
  static Range non_negative();
  /// Values >= \p low.
  static Range at_least(double low);
  /// Values in [low, high].
  static Range closed(double low, double high);
  /// Values in [low, high).
  static Range closed_open(double low, double high);
  /// Values in (low, high).
  static Range open(double low, double high);
  /// Values in (low, high].
  static Range open_closed(double low, double high);

  /// Whether \p value lies inside.
  bool contains(double value) const;
  /// Human-readable form: "> 0", "[-1, 0.5)", "any".
  std::string describe() const;
};

/// One allowed value of a choice parameter with its meaning.
struct Choice {
  std::string value;  ///< what the deck writes
  std::string doc;    ///< what it means
};

/// A parameter that means something only for some values of another parameter of the same list
/// (the controller: a choice, a flag, or a string array that must contain one of the values).
struct Condition {
  std::string controller;           ///< the parameter that decides
  std::vector<std::string> values;  ///< its values (for a flag "true"/"false") that give meaning
  /// "Geometry is 'semi-axes'", "Theories contains 'exact' or 'fastsim'", for messages and docs.
  std::string describe(bool array_controller) const;
};

/// The validator attached to every parameter railfe declares.
class ParameterRule : public Teuchos::ParameterEntryValidator {
 public:
  /// A rule of \p kind; \p required parameters have no default and must be given.
  ParameterRule(ParameterKind kind, bool required, std::string units = "", Range range = {},
                std::vector<Choice> choices = {}, int array_size = 0);

  /// The kind of value.
  ParameterKind kind() const { return kind_; }
  /// Whether the deck must give it.
  bool required() const { return required_; }
  /// SI units of the value ("" for dimensionless or non-numeric).
  const std::string& units() const { return units_; }
  /// Bounds for numbers.
  const Range& range() const { return range_; }
  /// Allowed values of a choice.
  const std::vector<Choice>& choices() const { return choices_; }
  /// Required length of an array (0: any length, at least one entry).
  int array_size() const { return array_size_; }
  /// For sublists: the owner validates them (the framework only checks they are sublists).
  bool delegated() const { return delegated_; }
  /// Marks a sublist as validated by its owner rather than by the level that declares it.
  void set_delegated(bool delegated) { delegated_ = delegated; }

  /// The condition under which the parameter means something (none: always).
  const std::optional<Condition>& condition() const { return condition_; }
  /// Sets the condition (ParameterSpec::only_when()).
  void set_condition(Condition condition) { condition_ = std::move(condition); }

  /// Checks \p entry; returns "" if it is acceptable, else the problem, phrased for a message.
  std::string check(const Teuchos::ParameterEntry& entry) const;
  /// The allowed values, phrased for a message ("> 0", "'cg', 'gmres'", "3 numbers").
  std::string describe_allowed() const;
  /// The kind as a short type name: "double", "int", "string", "bool", "Array(double)".
  std::string type_name() const;

  // Teuchos::ParameterEntryValidator interface, so Teuchos' own tools can use the rule too.
  const std::string getXMLTypeName() const override { return "railfe:" + type_name(); }
  void printDoc(const std::string& doc, std::ostream& out) const override;
  ValidStringsList validStringValues() const override;
  void validate(const Teuchos::ParameterEntry& entry, const std::string& name,
                const std::string& sublist_name) const override;

 private:
  ParameterKind kind_;
  bool required_;
  std::string units_;
  Range range_;
  std::vector<Choice> choices_;
  int array_size_;
  bool delegated_ = false;
  std::optional<Condition> condition_;
};

/// Returns the rule attached to \p entry, or nullptr if it has none.
const ParameterRule* rule_of(const Teuchos::ParameterEntry& entry);

}  // namespace railfe
