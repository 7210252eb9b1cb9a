#include "cbbg/framework/signal_log.h"

#include "cbbg/framework/number_text.h"

#include <array>
#include <charconv>
#include <cmath>
#include <stdexcept>

namespace cbbg {
SignalLog::SignalLog(const OutputPort& port, double period, double offset)
    : port_(&port), period_(period), offset_(offset) {
  if (!std::isfinite(period) || period <= 0.0) {
    throw std::invalid_argument("log of '" + port.path() +
                                "': the period must be positive and finite; got " +
                                std::to_string(period));
  }
  if (!std::isfinite(offset) || offset < 0.0) {
    throw std::invalid_argument("log of '" + port.path() +
                                "': the offset must be finite and >= 0; got " +
                                std::to_string(offset));
  }
  for (int i = 0; i < port.size(); ++i) {
    column_names_.push_back(port.size() == 1 ? port.name()
                                             : port.name() + "[" + std::to_string(i) + "]");
  }
}

ConstVectorView SignalLog::sample(int k) const {
  if (k < 0 || k >= num_samples() || !keep_in_memory_) {
    throw std::out_of_range("log of '" + port_->path() + "' has no sample " + std::to_string(k) +
                            " in memory (it holds " + std::to_string(num_samples()) + ")");
  }
  return ConstVectorView(values_.data() + static_cast<size_t>(k) * static_cast<size_t>(size()),
                         size());
}

Eigen::Map<const Eigen::MatrixXd> SignalLog::values() const {
  return Eigen::Map<const Eigen::MatrixXd>(values_.data(), size(), num_samples());
}

void SignalLog::set_column_names(std::vector<std::string> names) {
  if (static_cast<int>(names.size()) != size()) {
    throw std::invalid_argument("log of '" + port_->path() + "': " + std::to_string(names.size()) +
                                " column names for a port of size " + std::to_string(size()));
  }
  column_names_ = std::move(names);
}

void SignalLog::reserve(int samples) {
  times_.reserve(static_cast<size_t>(samples));
  values_.reserve(static_cast<size_t>(samples) * static_cast<size_t>(size()));
}

void SignalLog::stream_to_csv(const std::filesystem::path& path, bool keep_in_memory) {
  stream_.open(path, std::ios::out | std::ios::trunc);
  if (!stream_) {
    throw std::runtime_error("log of '" + port_->path() + "': cannot open '" + path.string() +
                             "' for writing");
  }
  keep_in_memory_ = keep_in_memory;
  stream_ << "t";
  for (const auto& name : column_names_) stream_ << ',' << name;
  stream_ << '\n';
}

void SignalLog::write_csv(std::ostream& out) const {
  out << "t";
  for (const auto& name : column_names_) out << ',' << name;
  out << '\n';
  std::string line;
  for (int k = 0; k < num_samples(); ++k) {
    line.clear();
    append_number(line, times_[static_cast<size_t>(k)]);
    for (int i = 0; i < size(); ++i) {
      line += ',';
      append_number(line, values_[static_cast<size_t>(k * size() + i)]);
    }
    line += '\n';
    out << line;
  }
}

void SignalLog::clear() {
  times_.clear();
  values_.clear();
}

void SignalLog::record(double time, const double* values) {
  if (keep_in_memory_) {
    times_.push_back(time);
    values_.insert(values_.end(), values, values + size());
  }
  if (stream_.is_open()) {
    // Formatted into a stack buffer: streaming never allocates.
    std::array<char, 32> buffer{};
    stream_.write(buffer.data(),
                  write_number(buffer.data(), buffer.data() + buffer.size(), time) - buffer.data());
    for (int i = 0; i < size(); ++i) {
      stream_.put(',');
      stream_.write(
          buffer.data(),
          write_number(buffer.data(), buffer.data() + buffer.size(), values[i]) - buffer.data());
    }
    stream_.put('\n');
  }
  if (sink_) sink_(time, values);
}

}  // namespace cbbg
