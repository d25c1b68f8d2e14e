// Editing test input text: one occurrence of a fragment replaced, checked to be there once.
#pragma once

#include <gtest/gtest.h>

#include <string>

namespace hpcontact::test {

/// `text` with the one occurrence of `from` replaced by `to`.
inline std::string with(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << "test text lacks '" << from << "'";
  EXPECT_EQ(text.find(from, at + 1), std::string::npos) << "'" << from << "' is not unique";
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

}  // namespace hpcontact::test
