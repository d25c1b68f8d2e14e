// Unit tests of the study-file reader: the runs a sweep, a zip and explicit rows expand to, in
// order, with their labels and overrides, and errors that name the file, place and cause.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "hpcontact/core/error.hpp"
#include "hpcontact/io/study_reader.hpp"

namespace hio = hpcontact::io;
using hpcontact::InputError;

namespace {

// Cases are relative to the study file's folder: a study "in" examples/lame/.
const std::string label = HPC_SOURCE_DIR "/examples/lame/study.yaml";

std::vector<std::string> labels(const hio::StudySpec& s) {
  std::vector<std::string> out;
  for (const auto& r : s.runs) out.push_back(r.label);
  return out;
}

std::string error_of(const std::string& text) {
  try {
    hio::parse_study(text, label);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

}  // namespace

TEST(StudyReader, SweepIsTheCartesianProductLastKeyFastest) {
  const auto s = hio::parse_study(
      "study: s\ncase: thick-cylinder.yaml\nset: [discretization.condense=true]\n"
      "sweep:\n  discretization.degree: [2, 3]\n  bodies[0].material.nu: [0.2, 0.3, 0.4]\n", label);
  ASSERT_EQ(s.runs.size(), 6u);
  EXPECT_EQ(labels(s)[0], "degree=2, nu=0.2");
  EXPECT_EQ(labels(s)[1], "degree=2, nu=0.3");
  EXPECT_EQ(labels(s)[5], "degree=3, nu=0.4");
  const std::vector<std::string> sets = {"discretization.condense=true", "discretization.degree=3",
                                         "bodies[0].material.nu=0.4"};
  EXPECT_EQ(s.runs[5].sets, sets);
}

TEST(StudyReader, ZipVariesItsKeysTogetherAsOneAxisAfterTheSweep) {
  const auto s = hio::parse_study(
      "study: s\ncase: thick-cylinder.yaml\nsweep: {discretization.degree: [4, 6]}\n"
      "zip:\n  bodies[0].loads[0].pressure: [100, 200, 300]\n  exact.inner_pressure: [100, 200, 300]\n",
      label);
  ASSERT_EQ(s.runs.size(), 6u);  // 2 degrees x 3 linked rows, not 2 x 3 x 3
  EXPECT_EQ(labels(s)[0], "degree=4, pressure=100, inner_pressure=100");
  EXPECT_EQ(labels(s)[4], "degree=6, pressure=200, inner_pressure=200");
  const std::vector<std::string> sets = {"discretization.degree=6", "bodies[0].loads[0].pressure=200",
                                         "exact.inner_pressure=200"};
  EXPECT_EQ(s.runs[4].sets, sets);
}

TEST(StudyReader, ZipAloneAndExplicitRowsAfterIt) {
  const auto s = hio::parse_study(
      "study: s\ncase: thick-cylinder.yaml\n"
      "zip: {'bodies[0].loads[0].pressure': [1, 2], exact.inner_pressure: [1, 2]}\n"
      "runs: [{label: plain}]\n", label);
  ASSERT_EQ(s.runs.size(), 3u);
  EXPECT_EQ(labels(s)[1], "pressure=2, inner_pressure=2");
  EXPECT_EQ(labels(s)[2], "plain");
  EXPECT_TRUE(s.runs[2].sets.empty());
}

TEST(StudyReader, KeysThatEndAlikeAreNamedInFull) {
  const auto s = hio::parse_study(
      "study: s\ncase: thick-cylinder.yaml\n"
      "zip:\n  bodies[0].loads[0].pressure: [1, 2]\n  contact[0].pressure: [3, 4]\n", label);
  EXPECT_EQ(labels(s)[0], "bodies[0].loads[0].pressure=1, contact[0].pressure=3");
}

TEST(StudyReader, ZipErrorsNameTheKeyAndTheCause) {
  const std::string lengths = error_of(
      "study: s\ncase: thick-cylinder.yaml\n"
      "zip:\n  bodies[0].loads[0].pressure: [1, 2, 3]\n  exact.inner_pressure: [1, 2]\n");
  EXPECT_NE(lengths.find("study.yaml:5:"), std::string::npos) << lengths;
  EXPECT_NE(lengths.find("zip.exact.inner_pressure: must have as many values as "
                         "zip.bodies[0].loads[0].pressure (3; got 2)"),
            std::string::npos)
      << lengths;
  const std::string twice = error_of(
      "study: s\ncase: thick-cylinder.yaml\nsweep: {discretization.degree: [2, 3]}\n"
      "zip: {discretization.degree: [4, 5], exact.inner_pressure: [1, 2]}\n");
  EXPECT_NE(twice.find("zip.discretization.degree: is in sweep too"), std::string::npos) << twice;
  const std::string empty = error_of("study: s\ncase: thick-cylinder.yaml\nzip: {a.b: []}\n");
  EXPECT_NE(empty.find("zip.a.b: must be a non-empty list"), std::string::npos) << empty;
  const std::string no_case = error_of("study: s\nzip: {a.b: [1]}\n");
  EXPECT_NE(no_case.find("zip: needs the study's case"), std::string::npos) << no_case;
}
