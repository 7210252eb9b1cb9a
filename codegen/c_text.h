#pragma once
// The text both exporters write (c_export.cc, c_learner_export.cc): names, head comments,
// constants, and a block's body with its $NAME and @part names resolved.

#include <functional>
#include <string>
#include <vector>

#include "cbbg/codegen/c_calculation.h"

namespace cbbg {
class Block;
}

namespace cbbg::codegen::text {

bool is_identifier_character(char c, bool first);
// Whether `word` is a C99 keyword (no member or field may be named so).
bool is_c_keyword(const std::string& word);
std::string upper(std::string text);

// "/* FILE: written by cbbg export; do not edit." and the provenance lines.
std::string head_comment(const std::string& file, const std::vector<std::string>& provenance);

// The macros a body calls <math.h> through: CBBG_EXP, CBBG_EXP2, CBBG_SQRT, CBBG_LOG, CBBG_COS
// and CBBG_FABS (a macro the code never calls brings no dependency).
std::string math_macros(Scalar scalar);

// `constant` as `static const real PREFIXNAME...;`, an array or one number.
std::string constant_definition(const CConstant& constant, const std::string& prefix,
                                Scalar scalar);

// What a body's names become.
struct BodyNames {
  std::string constant_prefix;  // $NAME -> constant_prefix + NAME
  // @part (next: false) and @@part (next: true) -> C; throws std::logic_error for one the
  // export does not allow there.
  std::function<std::string(const std::string& part, bool next)> part;
};

// `body` with every $NAME and @part resolved. A constant or part `block` does not have, or a
// constant the body never names (C warns of it), is the block's mistake: std::logic_error.
std::string resolve(const std::string& body, const std::vector<CConstant>& constants,
                    const BodyNames& names, const Block& block);

}  // namespace cbbg::codegen::text
