#pragma once
// What gives learnt weights their meaning: the parameters of the blocks between the measured
// state and the features (a normaliser's scales, an RBF grid, a user's tiling). Such a block
// describes its own layout; a closed loop gathers them (diagrams::ClosedLoop::layout), and
// weights files record it and are loaded only into a loop of the same layout.

#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace cbbg::blocks {

// One named list of numbers: "rbf.centres" -> [-3, ..., 3]. Keys are one word, the block's
// kind, a dot and the parameter ("normaliser.scale_theta").
struct LayoutEntry {
  std::string key;
  std::vector<double> values;
  bool operator==(const LayoutEntry&) const = default;
};
using FeatureLayout = std::vector<LayoutEntry>;

// The layout of a params struct: every number it declares (framework/parameters.h), keyed
// "<Params::kSection>.<key>" in declaration order, so the keys are the config's own.
template <typename Params>
FeatureLayout declared_layout(const Params& params);

// Implemented by a block (besides Block) whose parameters shape the features.
class DescribesLayout {
 public:
  virtual ~DescribesLayout() = default;
  // Its entries, in a fixed order.
  virtual FeatureLayout layout() const = 0;
  // One line a weights file may carry as a comment to help a reader (which feature a weight
  // belongs to); "" for none.
  virtual std::string layout_note() const { return ""; }
};

// "rbf.centres [-1, 0, 1] and rbf.width 0.5": a layout in messages; "no layout" when empty.
std::string layout_text(const FeatureLayout& layout);

// Where two layouts first differ, in words: {"rbf.width 0.5", "rbf.width 0.7"}, or
// {"tiles.tilings 4", "no tiles.tilings"}; two empty texts when they are the same.
struct LayoutDifference {
  std::string first;
  std::string second;
  bool empty() const { return first.empty() && second.empty(); }
};
LayoutDifference first_difference(const FeatureLayout& first, const FeatureLayout& second);

namespace detail {

// The archive of declared_layout: numbers become entries; words and names are not layout.
class LayoutCollector {
 public:
  LayoutCollector(std::string prefix, FeatureLayout& layout)
      : prefix_(std::move(prefix)), layout_(layout) {}

  template <typename Bounds>
  void number(std::string_view key, const double& value, std::string_view, const Bounds&) {
    layout_.push_back({prefix_ + std::string(key), {value}});
  }
  template <typename Bounds>
  void integer(std::string_view key, const long long& value, std::string_view, const Bounds&) {
    layout_.push_back({prefix_ + std::string(key), {static_cast<double>(value)}});
  }
  template <typename List, typename Bounds>
  void numbers(std::string_view key, const List& values, std::string_view, const Bounds&) {
    layout_.push_back({prefix_ + std::string(key), {values.begin(), values.end()}});
  }
  template <typename... Ignored>
  void text(Ignored&&...) {}
  template <typename... Ignored>
  void choice(Ignored&&...) {}
  template <typename... Ignored>
  void names(Ignored&&...) {}
  template <typename... Ignored>
  void file(Ignored&&...) {}
  template <typename... Ignored>
  void annealing(Ignored&&...) {}
  template <typename... Ignored>
  void settings(Ignored&&...) {}
  template <typename Params>
  void section(std::string_view name, Params& params) {
    LayoutCollector inner(prefix_ + std::string(name) + ".", layout_);
    params.describe(inner);
  }

 private:
  std::string prefix_;
  FeatureLayout& layout_;
};

}  // namespace detail

template <typename Params>
FeatureLayout declared_layout(const Params& params) {
  FeatureLayout layout;
  Params copy = params;  // describe() is one member for reading and writing alike
  detail::LayoutCollector collector(std::string(Params::kSection) + ".", layout);
  copy.describe(collector);
  return layout;
}

}  // namespace cbbg::blocks
