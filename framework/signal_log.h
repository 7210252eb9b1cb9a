#pragma once
// SignalLog: records one output port at its own period, in memory and/or streamed to CSV.
// Logs belong to a Simulator, not to the diagram: nothing in a simulation can read them.

#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "cbbg/framework/port.h"
#include "cbbg/framework/types.h"

namespace cbbg {

class SignalLog {
 public:
  SignalLog(const OutputPort& port, double period, double offset);

  const OutputPort& port() const { return *port_; }
  double period() const { return period_; }
  double offset() const { return offset_; }
  int size() const { return port_->size(); }

  int num_samples() const { return static_cast<int>(times_.size()); }
  const std::vector<double>& times() const { return times_; }
  // Sample k, as recorded at times()[k].
  ConstVectorView sample(int k) const;
  // All samples as columns: size() rows, num_samples() columns.
  Eigen::Map<const Eigen::MatrixXd> values() const;

  // Column names for CSV; the default is the port name, with "[i]" where it has several.
  void set_column_names(std::vector<std::string> names);
  const std::vector<std::string>& column_names() const { return column_names_; }
  // Reserves memory so that recording up to `samples` samples never allocates.
  void reserve(int samples);
  // Writes every later sample to `path` as it is recorded (header first); with
  // keep_in_memory false, nothing grows in memory however long the run.
  void stream_to_csv(const std::filesystem::path& path, bool keep_in_memory = false);
  // Hands every later sample to `sink` as it is recorded: running statistics or a custom
  // format, in constant memory with keep_in_memory(false).
  using Sink = std::function<void(double time, const double* values)>;
  void set_sink(Sink sink) { sink_ = std::move(sink); }
  void keep_in_memory(bool keep) { keep_in_memory_ = keep; }
  void write_csv(std::ostream& out) const;
  void clear();

  // Called by the Simulator at the log's sample times.
  void record(double time, const double* values);

 private:
  const OutputPort* port_;
  double period_;
  double offset_;
  std::vector<std::string> column_names_;
  std::vector<double> times_;
  std::vector<double> values_;
  std::ofstream stream_;
  Sink sink_;
  bool keep_in_memory_ = true;
};

}  // namespace cbbg
