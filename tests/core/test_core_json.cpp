// core/json: the string escaper and the number-or-null format of every hand-written JSON file.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>

#include "core/json.hpp"

namespace ejecta {
namespace {

TEST(CoreJson, NonFiniteNumbersAreNull) {
  EXPECT_EQ(jsonNumber(std::numeric_limits<double>::quiet_NaN(), 10), "null");
  EXPECT_EQ(jsonNumber(std::numeric_limits<double>::infinity(), 10), "null");
  EXPECT_EQ(jsonNumber(-std::numeric_limits<double>::infinity(), 12), "null");
}

TEST(CoreJson, FiniteNumbersArePrintfG) {
  // The formats thermal.json (12 digits), viewfactors.json (10) and the apps (10) wrote before.
  EXPECT_EQ(jsonNumber(1.5, 10), "1.5");
  EXPECT_EQ(jsonNumber(1.0 / 3.0, 10), "0.3333333333");
  EXPECT_EQ(jsonNumber(1.0 / 3.0, 12), "0.333333333333");
  EXPECT_EQ(jsonNumber(2.5e9, 12), "2500000000");
  EXPECT_EQ(jsonNumber(-1.25e-30, 10), "-1.25e-30");
  EXPECT_EQ(jsonNumber(0.0, 10), "0");
  // Out-of-range digit counts are clamped: 17 tell every double apart.
  EXPECT_EQ(jsonNumber(0.1, 40), jsonNumber(0.1, 17));
  EXPECT_EQ(jsonNumber(0.1, 0), "0.1");
  EXPECT_EQ(nlohmann::json::parse(jsonNumber(0.1, 17)).get<double>(), 0.1);
}

TEST(CoreJson, ControlCharactersAreEscaped) {
  EXPECT_EQ(jsonString("a\nb"), "\"a\\nb\"");
  EXPECT_EQ(jsonString("tab\there"), "\"tab\\there\"");
  EXPECT_EQ(jsonString(std::string("\x01\x1f", 2)), "\"\\u0001\\u001f\"");
  EXPECT_EQ(jsonString(std::string(1, '\0')), "\"\\u0000\"");
  // Every control character round-trips through a JSON reader.
  for (int c = 0; c < 0x20; ++c) {
    std::string text = "x";  // built stepwise: GCC 12 gives a false -Wrestrict on "x" + string
    text += static_cast<char>(c);
    text += 'y';
    const std::string literal = jsonString(text);
    for (char ch : literal) EXPECT_GE(static_cast<unsigned char>(ch), 0x20) << c;
    EXPECT_EQ(nlohmann::json::parse(literal).get<std::string>(), text) << c;
  }
}

TEST(CoreJson, PlainStringsAreWrittenAsBefore) {
  // What the hand-written escapers wrote for names and paths without control characters.
  EXPECT_EQ(jsonString("side0"), "\"side0\"");
  EXPECT_EQ(jsonString(""), "\"\"");
  EXPECT_EQ(jsonString("say \"hi\" \\ bye"), "\"say \\\"hi\\\" \\\\ bye\"");
  EXPECT_EQ(jsonString("/runs/a b/x.vdb"), "\"/runs/a b/x.vdb\"");
  EXPECT_EQ(jsonString("\xC2\xB5m"), "\"\xC2\xB5m\"");  // UTF-8 passes through
}

TEST(CoreJson, InvalidUtf8BecomesTheReplacementCharacter) {
  const std::string literal = jsonString("a\xFFz");
  EXPECT_EQ(literal, "\"a\xEF\xBF\xBDz\"");
  EXPECT_NO_THROW(nlohmann::json::parse(literal));
}

}  // namespace
}  // namespace ejecta
