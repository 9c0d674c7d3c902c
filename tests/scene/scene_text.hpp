// tests/scene/scene_text.hpp -- what the scene tests share: the message a scene text is refused
// with, and an edit of a scene text that must find what it replaces.
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "hapstab/numeric/error.hpp"
#include "hapstab/scene/scene.hpp"

namespace scene_test {

/// The InputError message parsing `text` (as "s.toml") raises, or "" when it parsed.
inline std::string error_of(const std::string& text) {
  try {
    hapstab::scene::parse_scene(text, "s.toml");
  } catch (const hapstab::InputError& e) {
    return e.what();
  }
  return "";
}

/// `s` with its first `a` replaced by `b` (a test failure, and `s` unchanged, when there is none).
inline std::string replace(std::string s, const std::string& a, const std::string& b) {
  const auto p = s.find(a);
  EXPECT_NE(p, std::string::npos) << a;
  return p == std::string::npos ? s : s.replace(p, a.size(), b);
}

}  // namespace scene_test
