// Unit tests of the bounds on a YAML input checked before its tree is built: the values counted
// as the tree would hold them (aliases as what they repeat), refused one past the limit, at the
// value that passes it; cycles refused; the built tree counted alike.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "hpcontact/core/error.hpp"
#include "hpcontact/io/problem_reader.hpp"
#include "hpcontact/io/yaml_limits.hpp"

#ifndef HPC_SOURCE_DIR
#define HPC_SOURCE_DIR "/work/main"
#endif

namespace hio = hpcontact::io;

namespace {

/// `n` zeros joined by commas: what a misread would take for a flow list of 2n tokens.
std::string zeros(std::size_t n) {
  std::string text = "0";
  for (std::size_t i = 1; i < n; ++i) text += ",0";
  return text;
}

/// A text's values as yaml-cpp builds them.
std::size_t values_of(const std::string& text) { return hio::count_yaml_values(YAML::Load(text)); }

/// A flow list of `n` values: the list and n - 1 zeros.
std::string flow_list(std::size_t n) {
  std::string text = "[";
  for (std::size_t i = 1; i < n; ++i) text += i == 1 ? "0" : ",0";
  return text + "]";
}

// The map, a: [1, 2], b: an anchored map of 3 values, d: its alias, e: an empty value.
const std::string small = "{a: [1, 2], b: &x {c: ~}, d: *x, e: }";
constexpr std::size_t small_values = 1 + 4 + 4 + (1 + 3) + 2;

/// A list of `n` values on the text's second line: a list of 10^4 values, 98 aliases of it, the
/// small map, then zeros (some 60 kB for a million values, read in a tenth of a second).
std::string near_the_limit(std::size_t n) {
  std::string text = "\n  [&z " + flow_list(10'000);
  for (int i = 0; i < 98; ++i) text += ", *z";
  const std::size_t before_zeros = 1 + 99 * 10'000 + small_values;
  return text + ", " + small + "," + flow_list(n - before_zeros + 1).substr(1);
}

}  // namespace

// A text of exactly kMaxYamlValues values shall be read; one value more shall be refused at that
// value's line and column, with the limit and what to do.
TEST(YamlLimits, RefusedOneValuePastTheLimitAtThatValue) {
  EXPECT_FALSE(hio::exceeded_yaml_bound(near_the_limit(hio::kMaxYamlValues), "problem file"));
  const std::string over = near_the_limit(hio::kMaxYamlValues + 1);
  const auto bound = hio::exceeded_yaml_bound(over, "problem file");
  ASSERT_TRUE(bound);
  EXPECT_EQ(bound->mark.line, 1);
  EXPECT_EQ(bound->mark.column, static_cast<int>(over.size()) - 3);  // the last 0 (line 1 starts at 1)
  EXPECT_NE(bound->what.find("the problem file has more than the 1000000 YAML values"),
            std::string::npos) << bound->what;
  EXPECT_NE(bound->what.find("give fewer elements"), std::string::npos) << bound->what;
}

// An alias shall count the values of what it repeats, so that a few bytes cannot stand for a
// tree of millions; the built tree shall be counted alike.
TEST(YamlLimits, AnAliasCountsAsWhatItRepeats) {
  EXPECT_EQ(hio::count_yaml_values(YAML::Load(small)), small_values);
  EXPECT_EQ(hio::count_yaml_values(YAML::Load(flow_list(7))), 7u);
  EXPECT_EQ(hio::count_yaml_values(YAML::Load(near_the_limit(hio::kMaxYamlValues))),
            hio::kMaxYamlValues);
  // 100 aliases of a list of 10^4 values: 10^6 values from 60 kB.
  std::string bomb = "[&a " + flow_list(10'000);
  for (int i = 0; i < 100; ++i) bomb += ", *a";
  bomb += "]";
  const auto bound = hio::exceeded_yaml_bound(bomb, "problem file");
  ASSERT_TRUE(bound);
  EXPECT_EQ(bound->mark.column, static_cast<int>(bomb.find("*a")) + 4 * 98);  // the 99th alias
}

// An alias inside the list or map it names (a cycle, which no tree can hold) shall be refused.
TEST(YamlLimits, ACycleIsRefused) {
  const auto bound = hio::exceeded_yaml_bound("a: &x [1, {b: *x}]", "problem file");
  ASSERT_TRUE(bound);
  EXPECT_EQ(bound->mark.column, 14);
  EXPECT_NE(bound->what.find("a cycle"), std::string::npos) << bound->what;
  EXPECT_FALSE(hio::exceeded_yaml_bound("a: &x [1]\nb: [*x, *x]", "problem file"));
}

// Syntax errors shall reach the caller as yaml-cpp reports them, so that the reader names them as
// before; text within the byte limit shall pass, one byte more shall not.
TEST(YamlLimits, SyntaxErrorsAndBytes) {
  EXPECT_THROW(hio::exceeded_yaml_bound("a: [1, 2", "problem file"), YAML::ParserException);
  EXPECT_FALSE(hio::exceeded_yaml_bytes(hio::kMaxYamlBytes, "problem file"));
  const auto too_large = hio::exceeded_yaml_bytes(hio::kMaxYamlBytes + 1, "problem file");
  ASSERT_TRUE(too_large);
  EXPECT_EQ(*too_large, "the problem file is larger than the 16 MB it may have (16 MB)");
}

// A flow list or map is read whole by yaml-cpp's scanner before its parser reports it, so its
// values are bounded from the text first: one past the limit shall be refused at its bracket,
// before yaml-cpp reads it, whether it stands where a key could or not.
TEST(YamlLimits, AFlowCollectionIsBoundedAtItsBracket) {
  for (const std::string& text : {"a: 1\nb:\n  - [[" + zeros(50) + "]]\n",
                                  "a: 1\nb:\n  - {x: [" + zeros(50) + "]}\n"}) {
    const auto bound = hio::exceeded_yaml_bound(text, "problem file", 30);
    ASSERT_TRUE(bound) << text;
    EXPECT_EQ(bound->mark.line, 2);
    EXPECT_EQ(bound->mark.column, 4);
    EXPECT_NE(bound->what.find("has a flow list or map ([...] or {...}) starting here with more "
                               "than the 30 YAML values the rest of the problem leaves it"),
              std::string::npos) << bound->what;
  }
}

// What only looks like a flow list shall not be taken for one: brackets and commas in quoted,
// block and plain scalars and in comments; a flow collection's own colons, comments, quotes and
// lines shall count as what they are. Each text is read at exactly its values, where a misread
// of its 60 zeros would refuse it.
TEST(YamlLimits, OnlyFlowCollectionsAreBoundedFromTheText) {
  const std::string z = zeros(60);
  for (const std::string& text : {
           "a: \"x: [" + z + "] \\\": [\"\nb: [1, 2]\n",
           "a: 'it''s: [" + z + "'\nb: {c: d}\n",
           "a: 1  # x: [" + z + "]\nb: [1, 2]\n",
           "a: |\n  x: [" + z + "\n\n  more: [\nb: [1, 2]\n",
           "- >-\n   {" + z + "\n- [1]\n",
           "a: x [" + z + "]\nb: y, {" + z + "\n",
           "a: [http://x.y/z:w, 'q: [" + z + "', \"r\"]\n",
           "a: [1, # [" + z + "\n    2,\n    {b: c, d: [e, f]}]\n",
           std::string("[a: 1, b, {c, d}, &x [e], *x, !!str f, ? g]\n"),
       }) {
    const std::size_t values = values_of(text);
    const auto bound = hio::exceeded_yaml_bound(text, "problem file", values);
    EXPECT_FALSE(bound) << text << "\n" << bound->what;
    EXPECT_TRUE(hio::exceeded_yaml_bound(text, "problem file", values - 1)) << text;
  }
}

// Every YAML file of the repository shall be read at exactly its own count of values: the
// reading of flow collections from the text never takes more for one than the tree holds.
TEST(YamlLimits, EveryYamlFileOfTheRepositoryIsReadAtItsValues) {
  int files = 0;
  for (const char* folder : {"examples", "tests"})
    for (const auto& entry :
         std::filesystem::recursive_directory_iterator(std::filesystem::path(HPC_SOURCE_DIR) / folder)) {
      if (entry.path().extension() != ".yaml") continue;
      std::ifstream in(entry.path());
      std::stringstream text;
      text << in.rdbuf();
      const std::size_t values = values_of(text.str());
      EXPECT_FALSE(hio::exceeded_yaml_bound(text.str(), "problem file", values)) << entry.path();
      EXPECT_TRUE(hio::exceeded_yaml_bound(text.str(), "problem file", values - 1)) << entry.path();
      ++files;
    }
  EXPECT_GT(files, 50);
}

// --set values shall be bounded together with the file: keys an override creates pass the limit
// as a value would. (The file's million values are mostly aliases of one list: its tree is small.)
TEST(YamlLimits, OverridesAreBoundedWithTheFile) {
  std::string text = "case: x\nbodies: []\nlists: [&z " + flow_list(10'000);
  for (int i = 0; i < 98; ++i) text += ", *z";
  text += "]\npad: ";
  const std::size_t values = values_of(text + "[]");  // up to here, the pad's list included
  text += flow_list(hio::kMaxYamlValues - 1 - values + 1) + "\n";
  ASSERT_EQ(values_of(text), hio::kMaxYamlValues - 1);
  try {  // a value for a value: within the limit, read (the schema refuses the key 'lists')
    hio::parse_problem(text, "case.yaml", {"case=y"});
    ADD_FAILURE() << "no error";
  } catch (const hpcontact::CommandLineError& e) {
    ADD_FAILURE() << e.what();
  } catch (const hpcontact::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("lists: unknown key"), std::string::npos) << e.what();
  }
  try {
    hio::parse_problem(text, "case.yaml", {"new.key=1"});  // new, its map, key and 1: four values
    ADD_FAILURE() << "not refused";
  } catch (const hpcontact::CommandLineError& e) {
    EXPECT_NE(std::string(e.what()).find("case.yaml: --set new.key=1: the problem has 1000003 YAML "
                                         "values with it, more than the 1000000"),
              std::string::npos) << e.what();
  }
}

namespace {

/// A one-element square with `loads` copies of one load, all but the first by alias.
std::string square_with_loads(std::size_t loads, const std::string& description = "a square") {
  std::string text = "case: square\ndescription: \"" + description + R"("
bodies:
  - name: block
    material: {E: 1000, nu: 0.25}
    nodes: {1: [0, 0], 2: [1, 0], 3: [1, 1], 4: [0, 1]}
    elements: {1: [1, 2, 3, 4]}
    edge_sets: {bottom: [[1, 2]], top: [[3, 4]]}
    constraints: [{edges: [bottom], ux: 0, uy: 0}]
    loads: [&l {edges: [top], pressure: 10})";
  for (std::size_t i = 1; i < loads; ++i) text += ", *l";
  return text + "]\n";
}

/// The InputError message of reading `text`, or "" if it is read.
std::string refusal(const std::string& text) {
  try {
    hio::parse_problem(text, "square.yaml");
  } catch (const hpcontact::InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

// The effective input (the problem with its defaults filled in) is written next to the results
// and read back to reproduce a run: a problem within the limits whose defaults would take it past
// them shall be refused (its bytes: test_limits.py).
TEST(YamlLimits, TheEffectiveInputCanBeReadBack) {
  // Values: each load gets its defaults, and each alias counts them again.
  const auto defaults = [](std::size_t loads) {
    return values_of(hio::parse_problem_full(square_with_loads(loads), "square.yaml").effective_yaml) -
           values_of(square_with_loads(loads));
  };
  const std::size_t per_load = defaults(2) - defaults(1);
  ASSERT_GT(per_load, 0u);
  const std::size_t load = values_of(square_with_loads(2)) - values_of(square_with_loads(1));
  const std::size_t loads = (hio::kMaxYamlValues - values_of(square_with_loads(1))) / load + 1;
  const std::string many = square_with_loads(loads);
  const std::size_t values = values_of(many);
  ASSERT_LE(values, hio::kMaxYamlValues);
  const std::string message = refusal(many);
  EXPECT_NE(message.find("square.yaml: the effective input (input.yaml, the problem with its "
                         "defaults filled in) has " +
                         std::to_string(values + defaults(1) + (loads - 1) * per_load) +
                         " YAML values, more than the 1000000 a problem file may have, so it "
                         "could not be read back"),
            std::string::npos)
      << message;
}
