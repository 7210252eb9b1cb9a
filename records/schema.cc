#include "cbbg/records/schema.h"

#include "cbbg/blocks/learner.h"

#include <algorithm>
#include <set>
#include <stdexcept>

namespace cbbg::records {
namespace {

const std::vector<std::string>& plot_names() {
  static const std::vector<std::string> names{"pitch",     "failures",   "skill",
                                              "annealing", "evaluation", "figures"};
  return names;
}

}  // namespace

const char* to_string(ValueType type) {
  switch (type) {
    case ValueType::kInteger:
      return "integer";
    case ValueType::kNumber:
      return "number";
    case ValueType::kFlag:
      return "flag";
  }
  return "number";
}

const char* to_string(FigureSummary summary) {
  switch (summary) {
    case FigureSummary::kSum:
      return "sum";
    case FigureSummary::kList:
      return "list";
    case FigureSummary::kNone:
      return "none";
  }
  return "sum";
}

const char* to_string(Missing missing) {
  return missing == Missing::kBeyondMaxTrials ? "beyond_max_trials" : "not_counted";
}

const std::vector<Figure>& run_figures() {
  static const std::vector<Figure> figures{
      {.name = "failures_before_success",
       .type = ValueType::kInteger,
       .meaning = "failed or diverged trials before the first success; all of them if none "
                  "succeeded",
       .summary = FigureSummary::kList,
       .statistics = {"", "median", "min", "max"}},
      {.name = "succeeded",
       .type = ValueType::kFlag,
       .meaning = "whether a trial succeeded",
       .summary = FigureSummary::kList,
       .statistics = {"num_succeeded", "", "", ""}}};
  return figures;
}

const Figure* ResultsSchema::figure(const std::string& name) const {
  for (const Figure& f : figures) {
    if (f.name == name) return &f;
  }
  return nullptr;
}

std::string ResultsSchema::headline_name() const {
  return headline.empty() ? "failures_before_success" : headline;
}

void check_schema(const ResultsSchema& schema, const std::string& protocol) {
  const std::string where = "protocol '" + protocol + "': ";
  std::set<std::string> columns;
  for (const Column& column : schema.trial_columns) {
    if (!blocks::is_part_name(column.name)) {  // the same words as a learnt part's
      throw std::invalid_argument(where + "trial column '" + column.name +
                                  "' is not a word of letters, digits and '_'");
    }
    if (!columns.insert(column.name).second) {
      throw std::invalid_argument(where + "two trial columns named '" + column.name + "'");
    }
  }
  std::set<std::string> figures;
  for (const Figure& figure : schema.figures) {
    if (figure.name.empty() || figure.name.find_first_of("\r\n") != std::string::npos) {
      throw std::invalid_argument(where + "a figure's name must be a line of text");
    }
    if (std::any_of(run_figures().begin(), run_figures().end(),
                    [&](const Figure& own) { return own.name == figure.name; })) {
      throw std::invalid_argument(where + "'" + figure.name +
                                  "' is every run's own figure; give the protocol's another name");
    }
    if (!figures.insert(figure.name).second) {
      throw std::invalid_argument(where + "two figures named '" + figure.name + "'");
    }
  }
  if (!schema.headline.empty() && schema.figure(schema.headline) == nullptr) {
    throw std::invalid_argument(where + "the headline '" + schema.headline +
                                "' is none of its figures");
  }
  for (const std::string& plot : schema.plots) {
    if (std::find(plot_names().begin(), plot_names().end(), plot) == plot_names().end()) {
      throw std::invalid_argument(where + "no drawing is named '" + plot +
                                  "' (pitch, failures, skill, annealing, evaluation, figures)");
    }
  }
}

}  // namespace cbbg::records
