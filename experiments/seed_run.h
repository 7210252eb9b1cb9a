#pragma once
// What an experiment produces (records/experiment_results.h) and the schema a protocol declares of
// it (records/schema.h), by the names the protocols use.

#include "cbbg/experiments/learnt_weights.h"
#include "cbbg/experiments/trial_runner.h"
#include "cbbg/records/experiment_results.h"

namespace cbbg::experiments {

using records::EvaluationRecord;
using records::ExperimentResults;
using records::NamedValue;
using records::SeedFigure;
using records::SeedRun;
using records::TrialRecord;

using records::check_schema;
using records::Column;
using records::ConsoleTable;
using records::Figure;
using records::FigureStatistics;
using records::FigureSummary;
using records::Missing;
using records::ResultsSchema;
using records::to_string;
using records::ValueType;

}  // namespace cbbg::experiments
