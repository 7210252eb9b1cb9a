#pragma once
// JSON documents of a results directory (summary.json, schema.json) as text, laid out for a
// reader: an object with containers inside, down to two levels, one key per line; an array of
// objects one per line; everything else on one line. Numbers in the shortest text that reads
// back the same (framework/number_text.h), integers as integers, non-finite numbers as null.

#include <string>

#include <nlohmann/json.hpp>

namespace cbbg::store {

using Json = nlohmann::ordered_json;

// `document` as text, ending with a line break.
std::string json_text(const Json& document);

// Parses `text`; throws std::runtime_error naming `source` and where it stops being JSON.
Json parse_json(const std::string& text, const std::string& source);

}  // namespace cbbg::store
