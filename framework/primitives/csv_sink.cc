#include "cbbg/framework/primitives/csv_sink.h"

#include <array>
#include <stdexcept>
#include <system_error>
#include <utility>

#include "cbbg/framework/block_context.h"
#include "cbbg/framework/number_text.h"
#include "cbbg/framework/owned_files.h"
#include "cbbg/framework/primitives/argument_checks.h"

namespace cbbg {
namespace fs = std::filesystem;

namespace {

bool csv_safe(const std::string& column) {
  return !column.empty() && column.find_first_of(",\"\r\n") == std::string::npos;
}

}  // namespace

CsvSink::CsvSink(std::string name, fs::path path, const std::vector<Input>& inputs, double period,
                 double offset)
    : Block(std::move(name)),
      label_(primitive_checks::label("CsvSink", this->name())),
      path_(std::move(path)) {
  if (inputs.empty()) {
    throw std::invalid_argument(label_ + ": no inputs; give at least one");
  }
  for (const Input& input : inputs) {
    if (input.size < 1) {
      throw std::invalid_argument(label_ + ": input '" + input.name + "' has size " +
                                  std::to_string(input.size) + "; it must be at least 1");
    }
    if (!input.columns.empty() && static_cast<int>(input.columns.size()) != input.size) {
      throw std::invalid_argument(label_ + ": input '" + input.name + "' has " +
                                  std::to_string(input.columns.size()) + " column names for size " +
                                  std::to_string(input.size) + "; give one per element, or none");
    }
    for (const std::string& column : input.columns) {
      if (!csv_safe(column)) {
        throw std::invalid_argument(label_ + ": column name '" + column + "' of input '" +
                                    input.name +
                                    "' must be non-empty, without comma, quote or line break");
      }
    }
  }
  primitive_checks::check_period(label_, period, offset);
  if (path_.empty()) {
    throw std::invalid_argument(label_ + ": the path is empty; give a file's path");
  }
  const fs::path directory = path_.parent_path();
  std::error_code error;
  if (!directory.empty() && !fs::is_directory(directory, error)) {
    throw std::invalid_argument(label_ + ": cannot write '" + path_.string() +
                                "': its directory does not exist");
  }
  check_writable();

  for (const Input& input : inputs) {
    inputs_.push_back(&declare_input_port(input.name, input.size));
    for (int i = 0; i < input.size; ++i) {
      columns_.push_back(!input.columns.empty() ? input.columns[static_cast<std::size_t>(i)]
                         : input.size == 1      ? input.name
                                                : input.name + "[" + std::to_string(i) + "]");
    }
  }
  declare_initialization_update<&CsvSink::open_file>();
  declare_periodic_update<&CsvSink::write_sample>(period, offset);
}

EventStatus CsvSink::open_file(BlockContext&, VectorRef) const {
  if (!stream_.is_open()) open();
  return EventStatus::succeeded();
}

EventStatus CsvSink::write_sample(BlockContext& context, VectorRef) const {
  write_row(context.time(), context);
  return EventStatus::succeeded();
}

void CsvSink::check_writable() const {
  if (const std::string kind = non_regular_kind(path_); !kind.empty()) {
    throw std::invalid_argument(label_ + ": cannot write '" + path_.string() + "': it is " + kind +
                                "; give a regular file's path");
  }
  std::error_code error;
  if (fs::exists(fs::symlink_status(path_, error)) && !carries_tag(path_, kCsvSinkTag)) {
    throw std::invalid_argument(label_ + ": '" + path_.string() +
                                "' exists and cbbg did not write it; cbbg never replaces a file "
                                "of yours: give a new path");
  }
}

void CsvSink::open() const {
  check_writable();  // again: something may have appeared there since the constructor
  stream_.open(path_, std::ios::out | std::ios::trunc);
  if (!stream_) {
    throw std::runtime_error(label_ + ": cannot open '" + path_.string() + "' for writing");
  }
  stream_ << kCsvSinkTag << "\nt";
  for (const std::string& column : columns_) stream_ << ',' << column;
  stream_ << '\n';
  rows_ = 0;
}

void CsvSink::write_row(double time, const BlockContext& context) const {
  if (!stream_.is_open()) return;  // only an update outside a simulation could get here
  // Formatted into a stack buffer: a row never allocates.
  std::array<char, 32> buffer{};
  const auto put = [&](double value) {
    stream_.write(buffer.data(), write_number(buffer.data(), buffer.data() + buffer.size(), value) -
                                     buffer.data());
  };
  put(time);
  for (const InputPort* input : inputs_) {
    const ConstVectorView values = context.input(*input);
    for (Eigen::Index i = 0; i < values.size(); ++i) {
      stream_.put(',');
      put(values[i]);
    }
  }
  stream_.put('\n');
  ++rows_;
  if (!stream_) {
    throw std::runtime_error(label_ + ": cannot write to '" + path_.string() + "'");
  }
}

void CsvSink::flush() {
  if (stream_.is_open() && !stream_.flush()) {
    throw std::runtime_error(label_ + ": cannot write to '" + path_.string() + "'");
  }
}

}  // namespace cbbg
