// The TOML reader at scale (config/toml_reader.cpp): a long line of numbers
// is read (split after its commas, so the cost stays linear) and messages
// after it still name the file's own lines; a file of more values than the
// limit is refused naming the limit; an unknown key among many known ones
// is found and named.
#include <gtest/gtest.h>

#include <string>

#include "config/range.h"
#include "config/toml_reader.h"

namespace bdfcar {
namespace {

// "p" + std::to_string(i) written out: GCC 12 warns of a memcpy overlap in
// that concatenation (-Wrestrict, a false positive).
std::string named(const char* prefix, int i) {
  std::string s = prefix;
  s += std::to_string(i);
  return s;
}

std::string numbersLine(const std::string& key, int n) {
  std::string s = key + " = [";
  for (int i = 0; i < n; ++i) s += (i ? ", " : "") + std::to_string(i) + ".5";
  return s + "]\n";
}

TEST(TomlLimits, ALongLineOfNumbersIsReadWhole) {
  const int n = 200000;
  config::Table t = config::parseTomlText(numbersLine("a", n) + "b = 2.0\n", "long.toml");
  const std::vector<double> a = t.numbers("a", config::Dimension::None, config::Range{});
  ASSERT_EQ(a.size(), static_cast<std::size_t>(n));
  EXPECT_EQ(a.front(), 0.5);
  EXPECT_EQ(a[12345], 12345.5);
  EXPECT_EQ(a.back(), n - 1 + 0.5);
}

TEST(TomlLimits, MessagesAfterALongLineNameTheFilesLines) {
  const std::string text = "# line 1\n" + numbersLine("a", 5000) + "b = \"text\"\nc = [1.0, 2.0, \"three\"]\n";
  config::Table t = config::parseTomlText(text, "lines.toml");
  try {
    t.numbers("c", config::Dimension::None, config::Range{});
    ADD_FAILURE() << "a string among numbers accepted";
  } catch (const config::ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("lines.toml:4:"), std::string::npos) << e.what();
  }
  // A syntax error after the long line: its line, not the split text's.
  try {
    config::parseTomlText("# line 1\n" + numbersLine("a", 5000) + "b = \n", "syntax.toml");
    ADD_FAILURE() << "a key without a value accepted";
  } catch (const config::ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("syntax.toml:3:"), std::string::npos) << e.what();
  }
  // A bad element inside the long line: the long line's number.
  std::string bad = numbersLine("a", 3000);
  bad.replace(bad.find("1500.5"), 6, "\"oops\"");
  config::Table u = config::parseTomlText("x = 1\n" + bad, "inside.toml");
  try {
    u.numbers("a", config::Dimension::None, config::Range{});
    ADD_FAILURE() << "a string among numbers accepted";
  } catch (const config::ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("inside.toml:2:"), std::string::npos) << e.what();
  }
}

TEST(TomlLimits, StringsAndCommentsKeepTheirCommas) {
  std::string pad(600, 'x');
  const std::string text = "s = \"" + pad + ", a, b, c\"  # and, a, comment, " + pad + "\nl = ['x, y', \"" + pad +
                           "\", 'z']\n";
  config::Table t = config::parseTomlText(text, "strings.toml");
  EXPECT_EQ(t.string("s"), pad + ", a, b, c");
  const std::vector<std::string> l = t.scalarTexts("l");
  ASSERT_EQ(l.size(), 3u);
  EXPECT_EQ(l.front(), "'x, y'");
}

TEST(TomlLimits, TooManyValuesAreRefusedNamingTheLimit) {
  std::string text;
  for (int row = 0; row < 22; ++row) text += numbersLine(named("r", row), 100000);
  try {
    config::parseTomlText(text, "huge.toml");
    ADD_FAILURE() << "2.2 million values accepted";
  } catch (const config::ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("more than 2097152 values"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("huge.toml:21:"), std::string::npos) << e.what();
  }
}

TEST(TomlLimits, AnUnknownKeyAmongManyIsNamed) {
  std::string text = "[points]\n";
  for (int i = 0; i < 50000; ++i) text += named("p", i) + " = 1.0\n";
  text += "typo = 2.0\n";
  config::Table t = config::parseTomlText(text, "keys.toml");
  config::Table p = t.table("points");
  for (int i = 0; i < 50000; ++i) p.numberIn(named("p", i), config::Range{});
  try {
    p.finish();
    ADD_FAILURE() << "the unknown key passed";
  } catch (const config::ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("keys.toml:50002: unknown key 'points.typo'"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace bdfcar
