// Deck reading and validation: every class of bad input gets one clear message naming the deck,
// the parameter path, the problem and what is allowed.
#include <gtest/gtest.h>

#include <sstream>

#include <Teuchos_Array.hpp>

#include "framework/base/error.hpp"
#include "framework/deck/deck.hpp"
#include "framework/deck/describe.hpp"
#include "framework/deck/parameter_spec.hpp"
#include "framework/deck/validation.hpp"
#include "framework/testing/input_error.hpp"

namespace railfe {
namespace {

ParameterSpec test_spec() {
  ParameterSpec item("A load.");
  item.required_text("Node set", "Where it acts.");
  item.real("Magnitude", 1.0, "How much.", "N");
  ParameterSpec solver("Solver settings.");
  solver.flag("Verbose", false, "Talk.");
  solver.integer("Maximum iterations", 100, "Limit.", Range::at_least(1));
  ParameterSpec spec("A test list.");
  spec.required_real("Young's modulus", "E.", "Pa", Range::positive());
  spec.real("Poisson's ratio", 0.3, "nu.", "", Range::open(-1.0, 0.5));
  spec.choice("Method", "cg", {{"cg", "conjugate gradients"}, {"gmres", "GMRES"}}, "Method.");
  spec.real_array("Origin", {0, 0, 0}, "Corner.", "m", 3);
  spec.sublist("Solver", solver, "Solver.");
  spec.named_sublists("Loads", item, "Loads.");
  return spec;
}

// Parses XML (the body of a <ParameterList name="deck">), validates it and returns the message of
// the InputError thrown, or "" if none.
std::string problem_with(const std::string& body) {
  try {
    Deck deck =
        parse_deck("<ParameterList name=\"deck\">" + body + "</ParameterList>", "test.xml", "");
    validate_and_complete(*deck.parameters, *test_spec().list(), deck.source, "");
  } catch (const InputError& error) {
    return error.what();
  }
  return "";
}

const std::string kValid =
    R"xml(<Parameter name="Young's modulus" type="double" value="2.1e11"/>)xml";

TEST(Deck, ValidDeckGetsDefaults) {
  Deck deck = parse_deck("<ParameterList>" + kValid + "</ParameterList>", "test.xml", "");
  validate_and_complete(*deck.parameters, *test_spec().list(), deck.source, "");
  const auto& list = *deck.parameters;
  EXPECT_DOUBLE_EQ(list.get<double>("Young's modulus"), 2.1e11);
  EXPECT_DOUBLE_EQ(list.get<double>("Poisson's ratio"), 0.3);
  EXPECT_EQ(list.get<std::string>("Method"), "cg");
  EXPECT_EQ(list.get<Teuchos::Array<double>>("Origin").size(), 3u);
  EXPECT_EQ(list.sublist("Solver").get<int>("Maximum iterations"), 100);
  EXPECT_FALSE(list.sublist("Solver").get<bool>("Verbose"));
}

TEST(Deck, IntegerForRealIsConverted) {
  Deck deck =
      parse_deck(R"xml(<ParameterList><Parameter name="Young's modulus" type="int" value="7"/>
                            <Parameter name="Origin" type="Array(int)" value="{1,2,3}"/>
                            </ParameterList>)xml",
                 "test.xml", "");
  validate_and_complete(*deck.parameters, *test_spec().list(), deck.source, "");
  EXPECT_DOUBLE_EQ(deck.parameters->get<double>("Young's modulus"), 7.0);
  EXPECT_DOUBLE_EQ(deck.parameters->get<Teuchos::Array<double>>("Origin")[2], 3.0);
}

TEST(Deck, MisspelledNameIsRefusedWithSuggestion) {
  const auto message =
      problem_with(kValid + R"xml(<Parameter name="Poisons ratio" type="double" value="0.3"/>)xml");
  EXPECT_NE(message.find("test.xml"), std::string::npos) << message;
  EXPECT_NE(message.find("'Poisons ratio'"), std::string::npos) << message;
  EXPECT_NE(message.find("did you mean 'Poisson's ratio'"), std::string::npos) << message;
  EXPECT_NE(message.find("allowed:"), std::string::npos) << message;
}

TEST(Deck, UnknownNameWithoutNeighbourListsWhatIsAllowed) {
  const auto message =
      problem_with(kValid + R"xml(<Parameter name="Colour" type="string" value="red"/>)xml");
  EXPECT_NE(message.find("unknown parameter"), std::string::npos) << message;
  EXPECT_EQ(message.find("did you mean"), std::string::npos) << message;
  EXPECT_NE(message.find("'Method'"), std::string::npos) << message;
}

TEST(Deck, WrongTypeIsRefused) {
  const auto message = problem_with(
      kValid +
      R"xml(<ParameterList name="Solver"><Parameter name="Maximum iterations" type="string" value="ten"/></ParameterList>)xml");
  EXPECT_NE(message.find("'Solver/Maximum iterations'"), std::string::npos) << message;
  EXPECT_NE(message.find("expected int"), std::string::npos) << message;
}

TEST(Deck, OutOfRangeValuesAreRefused) {
  auto message =
      problem_with(R"xml(<Parameter name="Young's modulus" type="double" value="-2e11"/>)xml");
  EXPECT_NE(message.find("'Young's modulus'"), std::string::npos) << message;
  EXPECT_NE(message.find("out of range"), std::string::npos) << message;
  EXPECT_NE(message.find("allowed: > 0"), std::string::npos) << message;
  message = problem_with(kValid +
                         R"xml(<Parameter name="Poisson's ratio" type="double" value="0.5"/>)xml");
  EXPECT_NE(message.find("allowed: (-1, 0.5)"), std::string::npos) << message;
  message = problem_with(R"xml(<Parameter name="Young's modulus" type="double" value="0"/>)xml");
  EXPECT_NE(message.find("out of range"), std::string::npos) << message;
}

TEST(Deck, MissingRequiredValueIsNamed) {
  const auto message = problem_with("");
  EXPECT_NE(message.find("'Young's modulus'"), std::string::npos) << message;
  EXPECT_NE(message.find("missing required parameter"), std::string::npos) << message;
}

TEST(Deck, ChoicesAndArraySizesAreEnforced) {
  auto message =
      problem_with(kValid + R"xml(<Parameter name="Method" type="string" value="bicg"/>)xml");
  EXPECT_NE(message.find("not one of the choices"), std::string::npos) << message;
  EXPECT_NE(message.find("'cg', 'gmres'"), std::string::npos) << message;
  message = problem_with(kValid +
                         R"xml(<Parameter name="Origin" type="Array(double)" value="{1,2}"/>)xml");
  EXPECT_NE(message.find("has 2 entries"), std::string::npos) << message;
  EXPECT_NE(message.find("3 numbers"), std::string::npos) << message;
}

TEST(Deck, NamedSublistsAreValidatedWithTheirPath) {
  auto message = problem_with(kValid + R"xml(<ParameterList name="Loads"><ParameterList name="tip">
                  <Parameter name="Magnitude" type="double" value="5"/></ParameterList></ParameterList>)xml");
  EXPECT_NE(message.find("'Loads/tip/Node set'"), std::string::npos) << message;
  message = problem_with(
      kValid +
      R"xml(<ParameterList name="Loads"><Parameter name="tip" type="int" value="1"/></ParameterList>)xml");
  EXPECT_NE(message.find("must be a sublist"), std::string::npos) << message;
}

TEST(Deck, MalformedXmlIsReported) {
  auto message = problem_with(R"xml(<Parameter name="Young's modulus" type="double" value="1")xml");
  EXPECT_NE(message.find("malformed XML"), std::string::npos) << message;
  message = problem_with(R"xml(<Parameter name="Young's modulus" type="double" value="abc"/>)xml");
  EXPECT_NE(message.find("malformed parameter: 'abc' is not a number"), std::string::npos)
      << message;
  message = problem_with(
      kValid + R"xml(<Parameter name="Origin" type="Array(double)" value="{1,x,3}"/>)xml");
  EXPECT_NE(message.find("'x' is not a number"), std::string::npos) << message;
  message = problem_with(
      kValid +
      R"xml(<ParameterList name="Solver"><Parameter name="Verbose" type="bool" value="yes"/></ParameterList>)xml");
  EXPECT_NE(message.find("'yes' is not a bool"), std::string::npos) << message;
  message = problem_with(kValid + kValid);
  EXPECT_NE(message.find("given twice"), std::string::npos) << message;
}

// Teuchos reads "nan" inside an array as 0 and strtod takes "0x10" as 16: neither may pass.
TEST(Deck, NonFiniteAndHexadecimalNumbersAreRefused) {
  for (const std::string bad :
       {"nan", "NaN", "inf", "-inf", "infinity", "0x10", "1e999", "1e", ".", "1.2.3"}) {
    auto message = problem_with(
        kValid + R"xml(<Parameter name="Origin" type="Array(double)" value="{1e6, )xml" + bad +
        R"xml(, 0}"/>)xml");
    EXPECT_NE(message.find("'" + bad + "' is not a number"), std::string::npos) << message;
    message = problem_with(R"xml(<Parameter name="Young's modulus" type="double" value=")xml" +
                           bad + R"xml("/>)xml");
    EXPECT_NE(message.find("is not a number"), std::string::npos) << bad << ": " << message;
  }
  auto message = problem_with(
      kValid +
      R"xml(<ParameterList name="Solver"><Parameter name="Maximum iterations" type="int" value="0x10"/></ParameterList>)xml");
  EXPECT_NE(message.find("'0x10' is not an integer"), std::string::npos) << message;
  for (const std::string good : {"1", "2.5", "+3.", ".5", "1e-3", "2.1E+11", " 7 "}) {
    EXPECT_EQ(problem_with(R"xml(<Parameter name="Young's modulus" type="double" value=")xml" +
                           good + R"xml("/>)xml"),
              "")
        << good;
  }
}

// A parameter the deck's choices make meaningless is refused, not dropped in silence.
TEST(Deck, ParameterIgnoredByTheChosenOptionIsRefused) {
  ParameterSpec spec("Patch.");
  spec.choice("Geometry", "curvatures", {{"curvatures", "A, B"}, {"semi-axes", "a, b"}}, "How.");
  spec.real("A", 1.0, "Curvature.", "1/m");
  spec.real("a", 7e-3, "Semi-axis.", "m");
  spec.flag("Chart", true, "Draw.");
  spec.text("Chart title", "", "Title.");
  spec.text_array("Theories", {"linear"}, "Theories.");
  spec.integer("Exact grid", 40, "Grid.");
  spec.only_when("Geometry", {"curvatures"}, {"A"});
  spec.only_when("Geometry", {"semi-axes"}, {"a"});
  spec.only_when("Chart", {"true"}, {"Chart title"});
  spec.only_when("Theories", {"exact"}, {"Exact grid"});
  auto problem = [&](const std::string& body) {
    return input_error_of([&] {
      Deck deck =
          parse_deck("<ParameterList name=\"deck\">" + body + "</ParameterList>", "d.xml", "");
      validate_and_complete(*deck.parameters, *spec.list(), deck.source, "Steps/patch");
      // Validating a completed list again changes nothing: defaults are no deck words.
      validate_and_complete(*deck.parameters, *spec.list(), deck.source, "Steps/patch");
    });
  };
  auto message = problem(R"xml(<Parameter name="a" type="double" value="0.01"/>)xml");
  EXPECT_NE(message.find("Steps/patch/a"), std::string::npos) << message;
  EXPECT_NE(message.find("is used only when Geometry is 'semi-axes', but Geometry is "
                         "'curvatures' (its default)"),
            std::string::npos)
      << message;
  EXPECT_EQ(problem(R"xml(<Parameter name="Geometry" type="string" value="semi-axes"/>
                          <Parameter name="a" type="double" value="0.01"/>)xml"),
            "");
  message = problem(R"xml(<Parameter name="Chart" type="bool" value="false"/>
                          <Parameter name="Chart title" type="string" value="x"/>)xml");
  EXPECT_NE(message.find("used only when Chart is 'true'"), std::string::npos) << message;
  message = problem(R"xml(<Parameter name="Exact grid" type="int" value="20"/>)xml");
  EXPECT_NE(message.find("used only when Theories contains 'exact', but Theories holds 'linear'"),
            std::string::npos)
      << message;
  EXPECT_EQ(problem(R"xml(<Parameter name="Theories" type="Array(string)" value="{linear, exact}"/>
                          <Parameter name="Exact grid" type="int" value="20"/>)xml"),
            "");
}

// Teuchos' own words ("Bad Parameter", "Can't find converter", "not a valid array
// represntation") name no parameter: railfe catches these first.
TEST(Deck, MalformedEntriesNameTheirParameter) {
  auto message = problem_with(
      kValid + R"xml(<ParameterList name="Solver"><Parameter name="Verbose"/></ParameterList>)xml");
  EXPECT_NE(message.find("'Solver/Verbose': <Parameter> without a type attribute"),
            std::string::npos)
      << message;
  message = problem_with(kValid + R"xml(<Parameter name="Method" type="foo" value="cg"/>)xml");
  EXPECT_NE(message.find("'Method': unknown type 'foo'; allowed: double, int"), std::string::npos)
      << message;
  message = problem_with(kValid + R"xml(<ParameterList name="Loads"><ParameterList name="l">
      <Parameter name="Node set" type="Array(string)" value="top"/></ParameterList></ParameterList>)xml");
  EXPECT_NE(message.find("'Loads/l/Node set': malformed parameter: array value 'top' is not "
                         "written as {a, b, c}"),
            std::string::npos)
      << message;
}

TEST(Deck, RelativePathsStartAtTheDeck) {
  Deck deck{"decks/a.xml", "decks", Teuchos::null};
  EXPECT_EQ(deck.resolve("mesh.exo"), "decks/mesh.exo");
  EXPECT_EQ(deck.resolve("/abs/mesh.exo"), "/abs/mesh.exo");
}

TEST(Deck, DescribeListsEveryParameter) {
  std::ostringstream text, markdown;
  describe_parameters(text, *test_spec().list(), "", "Test", DescribeFormat::text);
  describe_parameters(markdown, *test_spec().list(), "", "Test", DescribeFormat::markdown);
  for (const char* name :
       {"Young's modulus", "Poisson's ratio", "Maximum iterations", "Node set"}) {
    EXPECT_NE(text.str().find(name), std::string::npos) << name;
    EXPECT_NE(markdown.str().find(name), std::string::npos) << name;
  }
  EXPECT_NE(text.str().find("required"), std::string::npos);
  EXPECT_NE(text.str().find("Pa"), std::string::npos);
  EXPECT_NE(markdown.str().find("| Parameter | Type |"), std::string::npos);
  EXPECT_NE(markdown.str().find("Loads/&lt;name&gt;"), std::string::npos);
}

TEST(Deck, ClosestNameFindsTyposOnly) {
  EXPECT_EQ(closest_name("Desnity", {"Density", "Blocks"}), "Density");
  EXPECT_EQ(closest_name("youngs modulus", {"Young's modulus", "Density"}), "Young's modulus");
  EXPECT_EQ(closest_name("Temperature", {"Density", "Blocks"}), "");
}

}  // namespace
}  // namespace railfe
