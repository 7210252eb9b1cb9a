#include "cbbg/blocks/feature_layout.h"

#include <algorithm>

#include "cbbg/framework/number_text.h"

namespace cbbg::blocks {

LayoutDifference first_difference(const FeatureLayout& first, const FeatureLayout& second) {
  for (std::size_t i = 0; i < std::max(first.size(), second.size()); ++i) {
    if (i >= first.size()) return {"no " + second[i].key, layout_text({second[i]})};
    if (i >= second.size()) return {layout_text({first[i]}), "no " + first[i].key};
    if (!(first[i] == second[i])) return {layout_text({first[i]}), layout_text({second[i]})};
  }
  return {};
}

std::string layout_text(const FeatureLayout& layout) {
  if (layout.empty()) return "no layout";
  std::string text;
  for (const LayoutEntry& entry : layout) {
    if (!text.empty()) text += " and ";
    text += entry.key + " ";
    if (entry.values.size() == 1) {
      text += format_number(entry.values.front());
      continue;
    }
    text += "[";
    for (std::size_t i = 0; i < entry.values.size(); ++i) {
      text += (i == 0 ? "" : ", ") + format_number(entry.values[i]);
    }
    text += "]";
  }
  return text;
}

}  // namespace cbbg::blocks
