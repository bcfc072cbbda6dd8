#pragma once
// Helpers of the continuum deck tests: a deck text's InputError message, a text with one
// part replaced (the part must be there), and "the message has this part".
#include <gtest/gtest.h>

#include <string>

#include "mpmx/app/mpm/deck.hpp"
#include "mpmx/core/error.hpp"

namespace mpmx::test {

inline std::string mpm_deck_error(const std::string& text) {
  try {
    mpmx::app::read_mpm_deck_text(text, "t.toml");
  } catch (const mpmx::InputError& e) {
    return e.what();
  }
  return "(no error)";
}

inline std::string replace(std::string s, const std::string& from, const std::string& to) {
  const auto at = s.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return s.replace(at, from.size(), to);
}

}  // namespace mpmx::test

#define EXPECT_HAS(text, part) EXPECT_NE((text).find(part), std::string::npos) << (text)
