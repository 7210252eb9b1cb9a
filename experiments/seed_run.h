#pragma once
// What an experiment produces (results/records.h) and the schema a protocol declares of it
// (results/schema.h), by the names the protocols use.

#include "cbbg/experiments/learnt_weights.h"
#include "cbbg/experiments/trial_runner.h"
#include "cbbg/results/records.h"

namespace cbbg::experiments {

using results::EvaluationRecord;
using results::ExperimentResults;
using results::NamedValue;
using results::SeedFigure;
using results::SeedRun;
using results::TrialRecord;

using results::check_schema;
using results::Column;
using results::ConsoleTable;
using results::Figure;
using results::FigureStatistics;
using results::FigureSummary;
using results::Missing;
using results::ResultsSchema;
using results::to_string;
using results::ValueType;

}  // namespace cbbg::experiments
