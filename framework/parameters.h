#pragma once
// How a params struct declares its parameters: once, in a describe() member that names each
// field's key, meaning and allowed values. Every reader, writer and checker of parameters is
// an archive that describe() visits:
//
//   struct CriticParams {
//     static constexpr const char* kSection = "critic";
//     double beta = 0.1;
//     template <class Archive> void describe(Archive& a) {
//       a.number("beta", beta, "critic learning rate", kPositive);
//     }
//   };
//
// The default is the field's own initialiser. The config layer turns the declarations into
// its keys (YAML, --set, --grid, `cbbg list`, messages); check_declared() checks a struct
// built in C++ against the same declarations. An archive offers:
//
//   number(key, double&, meaning, Bounds)
//   integer(key, long long&, meaning, Bounds)
//   choice(key, T&, meaning, Choices<T>)          an enum, by its words
//   text(key, std::string&, meaning, allowed words (none: any))
//   numbers(key, std::vector<double>& or std::array<double, N>&, meaning, Bounds of each)
//   names(key, std::vector<std::string>&, meaning, allowed words)
//   settings(key, std::vector<std::string>&, meaning)  "other.key=value" entries, each one
//                                                       a condition (transfer.conditions)
//   section(name, params)                         a nested struct, keys "name.key"

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "cbbg/framework/number_text.h"

namespace cbbg {

// The values a number may take: finite, and inside an interval whose ends may be open or
// absent (infinite).
struct Bounds {
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  bool min_open = false;
  bool max_open = false;

  bool contains(double value) const {
    if (!std::isfinite(value)) return false;
    const bool above = min_open ? value > min : value >= min;
    const bool below = max_open ? value < max : value <= max;
    return above && below;
  }
  // What a message says of a value outside: "must be finite and > 0", "must be in (0, 1]".
  std::string requirement() const {
    const bool has_min = std::isfinite(min);
    const bool has_max = std::isfinite(max);
    if (has_min && has_max) {
      return std::string("must be in ") + (min_open ? "(" : "[") + format_number(min) + ", " +
             format_number(max) + (max_open ? ")" : "]");
    }
    if (has_min)
      return std::string("must be finite and ") + (min_open ? "> " : ">= ") + format_number(min);
    if (has_max)
      return std::string("must be finite and ") + (max_open ? "< " : "<= ") + format_number(max);
    return "must be finite";
  }
};

inline constexpr Bounds kFinite{};
inline constexpr Bounds kPositive{0.0, std::numeric_limits<double>::infinity(), true, false};
inline constexpr Bounds kNonNegative{0.0, std::numeric_limits<double>::infinity(), false, false};
// [min, max], each end open when asked: interval(0, 1, kOpen, kClosed) is (0, 1]. (No
// designated initialisers: code built as C++17 for Simbody includes this too.)
inline constexpr bool kOpen = true;
inline constexpr bool kClosed = false;
constexpr Bounds interval(double min, double max, bool min_open = kClosed,
                          bool max_open = kClosed) {
  return {min, max, min_open, max_open};
}
constexpr Bounds at_least(double min) {
  return {min, std::numeric_limits<double>::infinity(), false, false};
}

// One word a choice key takes, and the value it stands for.
template <typename T>
struct Choice {
  const char* word;
  T value;
};
template <typename T>
using Choices = std::vector<Choice<T>>;

// Throws std::invalid_argument "<key> <requirement>; got <value>" unless `value` is inside
// `bounds`: every check of a declared number says it in these words.
inline void check_bounds(std::string_view key, double value, const Bounds& bounds) {
  if (!bounds.contains(value)) {
    throw std::invalid_argument(std::string(key) + " " + bounds.requirement() + "; got " +
                                format_number(value));
  }
}

// The archive of check_declared: throws std::invalid_argument at the first value outside its
// declaration, naming its key ("critic.gamma must be in (0, 1]; got 1.5").
class DeclarationCheck {
 public:
  explicit DeclarationCheck(std::string prefix) : prefix_(std::move(prefix)) {}

  void number(std::string_view key, const double& value, std::string_view, const Bounds& bounds) {
    check(std::string(key), value, bounds);
  }
  void integer(std::string_view key, const long long& value, std::string_view,
               const Bounds& bounds) {
    check(std::string(key), static_cast<double>(value), bounds);
  }
  template <typename List>
  void numbers(std::string_view key, const List& values, std::string_view, const Bounds& bounds) {
    for (std::size_t i = 0; i < values.size(); ++i) {
      check(std::string(key) + "[" + std::to_string(i) + "]", values[i], bounds);
    }
  }
  template <typename T>
  void choice(std::string_view key, const T& value, std::string_view, const Choices<T>& choices) {
    std::string words;
    for (const Choice<T>& choice : choices) {
      if (choice.value == value) return;
      words += (words.empty() ? "" : ", ") + std::string(choice.word);
    }
    throw std::invalid_argument(prefix_ + std::string(key) + " must be one of " + words);
  }
  void text(std::string_view key, const std::string& value, std::string_view,
            const std::vector<std::string>& words) {
    if (words.empty()) return;
    std::string listed;
    for (const std::string& word : words) {
      if (word == value) return;
      listed += (listed.empty() ? "" : ", ") + word;
    }
    throw std::invalid_argument(prefix_ + std::string(key) + " must be one of " + listed +
                                "; got '" + value + "'");
  }
  void names(std::string_view key, const std::vector<std::string>& values, std::string_view meaning,
             const std::vector<std::string>& words) {
    for (std::size_t i = 0; i < values.size(); ++i) {
      text(std::string(key) + "[" + std::to_string(i) + "]", values[i], meaning, words);
    }
  }
  // Any path is a path: whether it names a file is for its reader to find out.
  void file(std::string_view, const std::string&, std::string_view) {}
  // exp2's schedule and a list of settings are the config's to check.
  template <typename... Ignored>
  void annealing(Ignored&&...) {}
  template <typename... Ignored>
  void settings(Ignored&&...) {}
  template <typename Params>
  void section(std::string_view name, Params& params) {
    DeclarationCheck inner(prefix_ + std::string(name) + ".");
    params.describe(inner);
  }

 private:
  void check(const std::string& key, double value, const Bounds& bounds) const {
    check_bounds(prefix_ + key, value, bounds);
  }

  std::string prefix_;
};

// Checks `params` against its own declarations, its keys under `section` ("" for none).
template <typename Params>
void check_declared(const Params& params, std::string_view section) {
  Params copy = params;  // describe() is one member for reading and writing alike
  DeclarationCheck check(section.empty() ? std::string() : std::string(section) + ".");
  copy.describe(check);
}

}  // namespace cbbg
