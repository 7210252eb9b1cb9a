#pragma once

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "cbbg/framework/block.h"

namespace cbbg {

// The first line of every file a CsvSink writes: what marks the file as cbbg's, so that a
// later sink may replace it (owned_files.h). CSV readers skip it as a comment (pandas'
// read_csv(comment='#'), numpy's loadtxt and genfromtxt by default).
inline constexpr const char* kCsvSinkTag = "# written by cbbg CsvSink";

/// CsvSink: writes its inputs to a CSV file every `period` h from `offset` t_0, a row per
/// sample t_k = t_0 + k h:
///
///     # written by cbbg CsvSink
///     t,<columns of the first input>,<columns of the next>,...
///     t_k,u_1(t_k),...,u_N(t_k)
///
/// | port         | dir | size     | meaning                                 |
/// |--------------|-----|----------|-----------------------------------------|
/// | (each input) | in  | its size | one per declared input, in column order |
///
/// A row holds the values every update at t_k reads (simulator.h step 2), the same a
/// SignalLog of the signal would record at t_k; numbers are written as number_text.h writes
/// them (the shortest text that reads back as the same double). Columns are named as given,
/// or after the input: its name, or name[i] where it has several elements.
///
/// Why a block and not a SignalLog: a log records one output port and belongs to a
/// Simulator, set up in code after the diagram is built; a sink is part of the diagram, wired
/// like any block to several signals at once, with one file and one time column for them all.
///
/// The file: the constructor checks its path, before any work; the first
/// Simulator::initialize of a simulation of the diagram creates the file (or replaces one a
/// CsvSink wrote) and writes the tag and the header; every later run of the diagram appends
/// its rows to the same file (t starts again at each run), until the block is destroyed,
/// which closes it. flush() makes the rows written so far readable meanwhile.
///
/// The rule of owned_files.h: a path is written only when nothing is there or the file there
/// carries kCsvSinkTag; a file of the user's, a directory, FIFO, socket or device is refused
/// (std::invalid_argument naming the path), at construction and again when the file is
/// opened, and never opened.
///
/// Limits: the open file lives in the block, not in a Context: simulate the diagram in one
/// context at a time (simulations of it in parallel would mix their rows in one file), and
/// give each sink its own path. Writing a row never allocates (the stream's buffer is made
/// when the file opens); a write the stream reports failed throws std::runtime_error.
class CsvSink final : public Block {
 public:
  struct Input {
    std::string name;  // the input port's name
    int size = 1;
    // One per element; empty: the input's name, or name[i] where it has several.
    std::vector<std::string> columns = {};
  };

  // Throws std::invalid_argument naming the block and the argument unless there is at least
  // one input, each of size >= 1 with none or `size` column names (non-empty, without comma,
  // quote or line break), the period is positive and finite, the offset finite and >= 0, and
  // `path` may be written (see above) in a directory that exists.
  CsvSink(std::string name, std::filesystem::path path, const std::vector<Input>& inputs,
          double period, double offset = 0.0);

  const std::filesystem::path& file_path() const { return path_; }
  // The columns after "t", in order.
  const std::vector<std::string>& column_names() const { return columns_; }
  // Rows written since the file was opened.
  long long num_rows() const { return rows_; }
  // Hands the rows written so far to the file; throws std::runtime_error when that fails.
  void flush();

 private:
  // Initialization update: opens the file, the first time, with the tag and the header.
  EventStatus open_file(BlockContext& context, VectorRef next_state) const;
  // Periodic update: writes the row of t_k.
  EventStatus write_sample(BlockContext& context, VectorRef next_state) const;
  // Throws unless the path may be written now (owned_files.h).
  void check_writable() const;
  void open() const;
  void write_row(double time, const BlockContext& context) const;

  std::string label_;
  std::filesystem::path path_;
  std::vector<const InputPort*> inputs_;
  std::vector<std::string> columns_;
  // The open file and its count of rows live in the block (see Limits above), so the updates,
  // const as every calculation, change them.
  mutable std::ofstream stream_;
  mutable long long rows_ = 0;
};

}  // namespace cbbg
