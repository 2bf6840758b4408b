#pragma once
/// \file
/// ParameterSpec: how a module declares its valid parameters. Each call adds one entry with a
/// ParameterRule and a doc string to a Teuchos valid list; the result is what validation,
/// `railfe --describe` and the generated deck reference read.

#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>

#include "framework/deck/parameter_rule.hpp"

namespace railfe {

/// Key under which a named_sublists entry stores the layout every user-named child follows.
inline constexpr const char* kAnyName = "<name>";

/// Builder of a valid-parameter list. Copying a spec shares the underlying list.
class ParameterSpec {
 public:
  /// An empty spec for a list whose purpose is \p doc.
  explicit ParameterSpec(std::string doc = "");

  /// An optional real number with a default.
  ParameterSpec& real(const std::string& name, double default_value, const std::string& doc,
                      const std::string& units = "", Range range = {});
  /// A real number the deck must give.
  ParameterSpec& required_real(const std::string& name, const std::string& doc,
                               const std::string& units = "", Range range = {});
  /// An optional integer with a default.
  ParameterSpec& integer(const std::string& name, int default_value, const std::string& doc,
                         Range range = {});
  /// An optional string with a default.
  ParameterSpec& text(const std::string& name, const std::string& default_value,
                      const std::string& doc);
  /// A string the deck must give.
  ParameterSpec& required_text(const std::string& name, const std::string& doc);
  /// An optional true/false switch.
  ParameterSpec& flag(const std::string& name, bool default_value, const std::string& doc);
  /// One of a fixed set of strings, with a default.
  ParameterSpec& choice(const std::string& name, const std::string& default_value,
                        std::vector<Choice> choices, const std::string& doc);
  /// One of a fixed set of strings that the deck must give.
  ParameterSpec& required_choice(const std::string& name, std::vector<Choice> choices,
                                 const std::string& doc);
  /// An optional array of reals (\p size entries, or any length if 0).
  ParameterSpec& real_array(const std::string& name, const std::vector<double>& default_value,
                            const std::string& doc, const std::string& units = "", int size = 0,
                            Range range = {});
  /// An array of reals the deck must give.
  ParameterSpec& required_real_array(const std::string& name, const std::string& doc,
                                     const std::string& units = "", int size = 0, Range range = {});
  /// An optional array of integers.
  ParameterSpec& integer_array(const std::string& name, const std::vector<int>& default_value,
                               const std::string& doc, int size = 0, Range range = {});
  /// An array of strings the deck must give.
  ParameterSpec& required_text_array(const std::string& name, const std::string& doc);
  /// An optional array of strings.
  ParameterSpec& text_array(const std::string& name, const std::vector<std::string>& default_value,
                            const std::string& doc);
  /// A sublist with fixed contents, validated by this spec.
  ParameterSpec& sublist(const std::string& name, const ParameterSpec& contents,
                         const std::string& doc, bool required = false);
  /// A sublist whose children carry user-chosen names, each laid out as \p each
  /// (materials, boundary conditions, probes...).
  ParameterSpec& named_sublists(const std::string& name, const ParameterSpec& each,
                                const std::string& doc);
  /// A sublist validated by another owner (the level declaring it only checks it is a list).
  /// \p contents documents it for --describe.
  ParameterSpec& delegated_sublist(const std::string& name, const ParameterSpec& contents,
                                   const std::string& doc, bool required = false);

  /// Declares that the parameters \p names (declared before) mean something only when the
  /// parameter \p controller of this list (a choice, a flag, or a string array) has one of
  /// \p values (a flag: "true" or "false"; an array: contains one of them). A deck that gives
  /// one of them otherwise is refused, naming both, so no given value is ignored in silence.
  ParameterSpec& only_when(const std::string& controller, const std::vector<std::string>& values,
                           const std::vector<std::string>& names);

  /// The valid list being built.
  Teuchos::RCP<Teuchos::ParameterList> list() const { return list_; }
  /// What the list is for.
  const std::string& doc() const { return doc_; }

 private:
  void add(const std::string& name, const Teuchos::ParameterEntry& value, const std::string& doc,
           Teuchos::RCP<ParameterRule> rule);

  std::string doc_;
  Teuchos::RCP<Teuchos::ParameterList> list_;
};

}  // namespace railfe
