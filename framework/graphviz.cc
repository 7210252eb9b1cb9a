#include "cbbg/framework/graphviz.h"

#include "cbbg/framework/number_text.h"
#include "cbbg/framework/owned_files.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <optional>
#include <stdexcept>
#include <string_view>
#include <utility>
#include <vector>

extern char** environ;

namespace cbbg {
namespace {

// ---------------------------------------------------------------------------------------------
// DOT text
//
// Node ids, all quoted block paths, never collide: a block's path has no '.', a diagram port
// node is "<diagram path>.in.<port>" or ".out.<port>", and a fixed value feeding an input is
// "<block path>.in.<port>.fixed". Cells inside a block's table are "in_<port>" and
// "out_<port>" (the prefix keeps a port named "n" or "e" from reading as a compass point).

// A fixed input shows at most this many values; longer vectors end with their length.
constexpr int kMaxFixedValuesShown = 6;

std::string dot_quoted(std::string_view id) {
  std::string text = "\"";
  for (const char c : id) {
    if (c == '"' || c == '\\') text += '\\';
    text += c;
  }
  return text + "\"";
}

std::string sized(const std::string& name, int size) {
  return name + " [" + std::to_string(size) + "]";
}

std::string value_text(const Vector& value) {
  if (value.size() == 1) return format_number(value[0]);
  std::string text = "[";
  const auto shown = std::min<Eigen::Index>(value.size(), kMaxFixedValuesShown);
  for (Eigen::Index i = 0; i < shown; ++i) text += (i == 0 ? "" : ", ") + format_number(value[i]);
  if (shown < value.size()) text += ", ... (" + std::to_string(value.size()) + " values)";
  return text + "]";
}

std::string port_node_id(const Block& diagram, const char* direction, const std::string& port) {
  return dot_quoted(diagram.path() + "." + direction + "." + port);
}

std::string fixed_node_id(const InputPort& port) {
  return dot_quoted(port.block().path() + ".in." + port.name() + ".fixed");
}

// Text for an HTML-like label: its markup characters escaped.
std::string html_text(const std::string& text) {
  std::string escaped;
  for (const char c : text) {
    if (c == '<') {
      escaped += "&lt;";
    } else if (c == '>') {
      escaped += "&gt;";
    } else if (c == '&') {
      escaped += "&amp;";
    } else {
      escaped += c;
    }
  }
  return escaped;
}

// A block drawn as one box: name and, under it, type on top, inputs left, outputs right (a
// block without inputs or without outputs has one column). A collapsed diagram's name sits on
// a grey band, so the reader knows there is more inside.
std::string box_label(const Block& block) {
  const int inputs = block.num_input_ports();
  const int outputs = block.num_output_ports();
  const int columns = std::max((inputs > 0 ? 1 : 0) + (outputs > 0 ? 1 : 0), 1);
  const std::string empty_cell = R"(<td border="0"></td>)";
  std::string label = R"(<<table border="0" cellborder="1" cellspacing="0" cellpadding="4">)";
  label += R"(<tr><td colspan=")" + std::to_string(columns) + R"(")" +
           (block.is_diagram() ? R"( bgcolor="lightgrey")" : "") + "><b>" + block.name() +
           R"(</b><br/><font point-size="10">)" + html_text(block.type_name()) +
           "</font></td></tr>";
  for (int row = 0; row < std::max(inputs, outputs); ++row) {
    label += "<tr>";
    if (row < inputs) {
      const InputPort& port = block.input_port(row);
      label += R"(<td port="in_)" + port.name() + R"(" align="left">)" +
               sized(port.name(), port.size()) + "</td>";
    } else if (inputs > 0) {
      label += empty_cell;
    }
    if (row < outputs) {
      const OutputPort& port = block.output_port(row);
      label += R"(<td port="out_)" + port.name() + R"(" align="right">)" +
               sized(port.name(), port.size()) + "</td>";
    } else if (outputs > 0) {
      label += empty_cell;
    }
    label += "</tr>";
  }
  return label + "</table>>";
}

class DotWriter {
 public:
  explicit DotWriter(const GraphvizOptions& options) : options_(options) {}

  std::string write(const Diagram& root) {
    text_ = "digraph " + dot_quoted(root.name()) + " {\n";
    text_ += "  comment=\"" + std::string(kDiagramGeneratorTag) + "\";\n";
    text_ += "  rankdir=LR;\n";
    text_ += "  node [fontname=\"Helvetica\", fontsize=11];\n";
    text_ += "  edge [fontname=\"Helvetica\", fontsize=9];\n";
    write_cluster(root, 0, 1);
    text_ += "}\n";
    return std::move(text_);
  }

 private:
  // Whether `block`, at nesting depth `depth`, is drawn as a cluster with its contents.
  bool expanded(const Block& block, int depth) const {
    return block.is_diagram() && (options_.max_depth < 0 || depth <= options_.max_depth);
  }

  bool hidden(const Block& block) const {
    const auto& hidden = options_.hidden_blocks;
    return std::find(hidden.begin(), hidden.end(), block.path()) != hidden.end();
  }

  // Where an edge leaving `port` starts: the output cell of a box, or the port node of an
  // expanded diagram. `depth` is the depth of the port's block.
  std::string source_of(const OutputPort& port, int depth) const {
    if (expanded(port.block(), depth)) return port_node_id(port.block(), "out", port.name());
    return dot_quoted(port.block().path()) + ":out_" + port.name();
  }

  std::string destination_of(const InputPort& port, int depth) const {
    if (expanded(port.block(), depth)) return port_node_id(port.block(), "in", port.name());
    return dot_quoted(port.block().path()) + ":in_" + port.name();
  }

  void line(int indent, const std::string& text) {
    text_.append(2 * static_cast<std::size_t>(indent), ' ');
    text_ += text;
    text_ += '\n';
  }

  void edge(int indent, const std::string& from, const std::string& to) {
    line(indent, from + " -> " + to + ";");
  }

  void write_cluster(const Diagram& diagram, int depth, int indent) {
    line(indent, "subgraph " + dot_quoted("cluster_" + diagram.path()) + " {");
    const int inner = indent + 1;
    line(inner, "label=" + dot_quoted(diagram.name()) + ";");
    for (int i = 0; i < diagram.num_input_ports(); ++i) {
      const InputPort& port = diagram.input_port(i);
      line(inner, port_node_id(diagram, "in", port.name()) +
                      " [shape=cds, label=" + dot_quoted(sized(port.name(), port.size())) + "];");
    }
    for (int i = 0; i < diagram.num_output_ports(); ++i) {
      const OutputPort& port = diagram.output_port(i);
      line(inner, port_node_id(diagram, "out", port.name()) +
                      " [shape=cds, label=" + dot_quoted(sized(port.name(), port.size())) + "];");
    }
    const int child_depth = depth + 1;
    for (const auto& child : diagram.blocks()) {
      if (hidden(*child)) continue;
      if (expanded(*child, child_depth)) {
        write_cluster(static_cast<const Diagram&>(*child), child_depth, inner);
      } else {
        line(inner,
             dot_quoted(child->path()) + " [shape=plaintext, label=" + box_label(*child) + "];");
      }
    }
    for (const auto& fixed : diagram.fixed_inputs()) {
      if (hidden(fixed.port->block())) continue;
      line(inner, fixed_node_id(*fixed.port) +
                      " [shape=plaintext, label=" + dot_quoted(value_text(fixed.value)) + "];");
    }

    for (const auto& exported : diagram.exported_inputs()) {
      const InputPort& port = diagram.input_port(exported.diagram_port);
      if (hidden(exported.inner->block())) continue;
      edge(inner, port_node_id(diagram, "in", port.name()),
           destination_of(*exported.inner, child_depth));
    }
    for (const auto& connection : diagram.connections()) {
      if (hidden(connection.source->block()) || hidden(connection.destination->block())) continue;
      edge(inner, source_of(*connection.source, child_depth),
           destination_of(*connection.destination, child_depth));
    }
    for (const auto& fixed : diagram.fixed_inputs()) {
      if (hidden(fixed.port->block())) continue;
      edge(inner, fixed_node_id(*fixed.port), destination_of(*fixed.port, child_depth));
    }
    for (int i = 0; i < diagram.num_output_ports(); ++i) {
      const OutputPort& inner_port = *diagram.exported_outputs()[static_cast<std::size_t>(i)];
      if (hidden(inner_port.block())) continue;
      edge(inner, source_of(inner_port, child_depth),
           port_node_id(diagram, "out", diagram.output_port(i).name()));
    }
    line(indent, "}");
  }

  const GraphvizOptions& options_;
  std::string text_;
};

// ---------------------------------------------------------------------------------------------
// Rendering

class FileDescriptor {
 public:
  explicit FileDescriptor(int fd) : fd_(fd) {}
  ~FileDescriptor() {
    if (fd_ >= 0) ::close(fd_);
  }
  FileDescriptor(const FileDescriptor&) = delete;
  FileDescriptor& operator=(const FileDescriptor&) = delete;
  int get() const { return fd_; }

 private:
  int fd_;
};

// "<what>: <the description of errno>".
std::string errno_message(const std::string& what) { return what + ": " + std::strerror(errno); }

// A uniquely named file beside the output; renamed onto it once complete, removed otherwise.
class PendingFile {
 public:
  explicit PendingFile(const std::filesystem::path& output) : output_(output) {
    const std::filesystem::path directory =
        output.has_parent_path() ? output.parent_path() : std::filesystem::path(".");
    // ".cbbg-tmp-" marks it as cbbg's temporary, which a later command may clean up.
    std::string pattern =
        (directory / ("." + output.filename().string() + ".cbbg-tmp-XXXXXX")).string();
    fd_ = ::mkostemp(pattern.data(), O_CLOEXEC);
    if (fd_ < 0) throw std::runtime_error(errno_message("cannot write '" + output.string() + "'"));
    path_ = pattern;
    // mkostemp makes the file private to its owner; an image or DOT file is for sharing.
    ::fchmod(fd_, S_IRUSR | S_IWUSR | S_IRGRP | S_IROTH);
  }
  ~PendingFile() {
    if (fd_ >= 0) ::close(fd_);
    if (!committed_) ::unlink(path_.c_str());
  }
  PendingFile(const PendingFile&) = delete;
  PendingFile& operator=(const PendingFile&) = delete;

  const std::string& path() const { return path_; }
  int fd() const { return fd_; }

  void commit() {
    const int fd = std::exchange(fd_, -1);
    if (::close(fd) != 0 || ::rename(path_.c_str(), output_.c_str()) != 0) {
      throw std::runtime_error(errno_message("cannot write '" + output_.string() + "'"));
    }
    committed_ = true;
  }

 private:
  std::filesystem::path output_;
  std::string path_;
  int fd_ = -1;
  bool committed_ = false;
};

void write_all(int fd, std::string_view text, const std::filesystem::path& output) {
  while (!text.empty()) {
    const ssize_t written = ::write(fd, text.data(), text.size());
    if (written < 0 && errno == EINTR) continue;
    if (written < 0)
      throw std::runtime_error(errno_message("cannot write '" + output.string() + "'"));
    text.remove_prefix(static_cast<std::size_t>(written));
  }
}

std::string read_all(int fd) {
  std::string text;
  char buffer[4096];
  for (;;) {
    const ssize_t got = ::read(fd, buffer, sizeof(buffer));
    if (got < 0 && errno == EINTR) continue;
    if (got <= 0) return text;
    text.append(buffer, static_cast<std::size_t>(got));
  }
}

// An anonymous temporary file (already unlinked), for dot's stdin and what it prints.
FileDescriptor anonymous_file(const std::filesystem::path& output) {
  std::string pattern = (std::filesystem::temp_directory_path() / "cbbg-dot-XXXXXX").string();
  const int fd = ::mkostemp(pattern.data(), O_CLOEXEC);
  if (fd < 0) {
    throw std::runtime_error(
        errno_message("cannot render '" + output.string() + "': no temporary file"));
  }
  ::unlink(pattern.c_str());
  return FileDescriptor(fd);
}

// The first executable file named `program` in the directories of PATH, as execvp finds it.
std::optional<std::filesystem::path> find_on_path(const std::string& program) {
  const char* path = std::getenv("PATH");
  if (path == nullptr) return std::nullopt;
  std::string_view directories(path);
  for (;;) {
    const std::size_t colon = directories.find(':');
    const std::string_view directory = directories.substr(0, colon);
    // An empty entry means the current directory.
    const std::filesystem::path candidate =
        std::filesystem::path(directory.empty() ? "." : std::string(directory)) / program;
    std::error_code error;
    if (std::filesystem::is_regular_file(candidate, error) &&
        ::access(candidate.c_str(), X_OK) == 0) {
      return candidate;
    }
    if (colon == std::string_view::npos) return std::nullopt;
    directories.remove_prefix(colon + 1);
  }
}

std::string trimmed(std::string text) {
  const auto is_space = [](unsigned char c) { return std::isspace(c) != 0; };
  while (!text.empty() && is_space(static_cast<unsigned char>(text.back()))) text.pop_back();
  const auto first = std::find_if_not(text.begin(), text.end(), is_space);
  return std::string(first, text.end());
}

// Runs `dot -T<format> -o <file>` with the DOT text on stdin; throws unless it succeeds.
// A drawing replaces only a drawing of cbbg's: never a file of the user's, never a FIFO.
void check_replaceable(const std::filesystem::path& output) {
  if (const std::string kind = non_regular_kind(output); !kind.empty()) {
    throw std::invalid_argument("cannot render '" + output.string() + "': it is " + kind +
                                "; give a regular file's path");
  }
  std::error_code error;
  if (std::filesystem::exists(std::filesystem::symlink_status(output, error)) &&
      !carries_tag(output, kDiagramGeneratorTag)) {
    throw std::invalid_argument("cannot render '" + output.string() +
                                "': it exists and cbbg did not write it; cbbg never replaces "
                                "a file of yours");
  }
}

// `dot` with the generator tag as the graph's comment (dot copies it into an SVG), added
// after the opening brace when a text written elsewhere lacks it.
std::string tagged(const std::string& dot) {
  const auto brace = dot.find('{');
  if (dot.find(kDiagramGeneratorTag) != std::string::npos || brace == std::string::npos) {
    return dot;
  }
  std::string text = dot;
  // On the brace's line, so dot's messages keep the line numbers of the text as given.
  text.insert(brace + 1, " comment=\"" + std::string(kDiagramGeneratorTag) + "\";");
  return text;
}

std::uint32_t png_crc(std::string_view bytes) {
  std::uint32_t crc = 0xffffffffU;
  for (const char c : bytes) {
    crc ^= static_cast<unsigned char>(c);
    for (int bit = 0; bit < 8; ++bit) crc = (crc >> 1) ^ (0xedb88320U & (0U - (crc & 1U)));
  }
  return crc ^ 0xffffffffU;
}

std::string big_endian(std::uint32_t value) {
  return {static_cast<char>(value >> 24), static_cast<char>(value >> 16),
          static_cast<char>(value >> 8), static_cast<char>(value)};
}

// Graphviz cannot label a PNG: a tEXt chunk ("Software", the tag) goes in after IHDR.
void tag_png(const std::string& path, const std::filesystem::path& output) {
  std::string png;
  {
    std::ifstream in(path, std::ios::binary);
    png.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  constexpr std::size_t kAfterHeader = 8 + 4 + 4 + 13 + 4;  // signature, IHDR chunk
  if (png.size() < kAfterHeader || png.compare(12, 4, "IHDR") != 0) {
    throw std::runtime_error("cannot render '" + output.string() + "': dot wrote no PNG");
  }
  const std::string body = std::string("tEXtSoftware") + '\0' + kDiagramGeneratorTag;
  const std::string chunk =
      big_endian(static_cast<std::uint32_t>(body.size() - 4)) + body + big_endian(png_crc(body));
  png.insert(kAfterHeader, chunk);
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << png;
  if (!out.flush())
    throw std::runtime_error(errno_message("cannot write '" + output.string() + "'"));
}

void run_dot(const std::filesystem::path& dot_program, const std::string& format,
             const std::string& dot, const std::string& file, const std::filesystem::path& output) {
  FileDescriptor input = anonymous_file(output);
  write_all(input.get(), dot, output);
  ::lseek(input.get(), 0, SEEK_SET);
  FileDescriptor messages = anonymous_file(output);

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, input.get(), STDIN_FILENO);
  posix_spawn_file_actions_adddup2(&actions, messages.get(), STDOUT_FILENO);
  posix_spawn_file_actions_adddup2(&actions, messages.get(), STDERR_FILENO);
  std::vector<std::string> arguments = {"dot", "-T" + format, "-o", file};
  std::vector<char*> argv;
  for (std::string& argument : arguments) argv.push_back(argument.data());
  argv.push_back(nullptr);
  pid_t child = 0;
  const int spawn_error =
      ::posix_spawn(&child, dot_program.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  const std::string prefix = "cannot render '" + output.string() + "': ";
  if (spawn_error != 0) {
    throw std::runtime_error(prefix + "could not run '" + dot_program.string() +
                             "': " + std::strerror(spawn_error));
  }

  int status = 0;
  while (::waitpid(child, &status, 0) < 0) {
    if (errno != EINTR) throw std::runtime_error(errno_message(prefix + "waiting for 'dot'"));
  }
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return;
  ::lseek(messages.get(), 0, SEEK_SET);
  const std::string printed = trimmed(read_all(messages.get()));
  const std::string how = WIFEXITED(status)
                              ? "exited with status " + std::to_string(WEXITSTATUS(status))
                              : "was killed by signal " + std::to_string(WTERMSIG(status));
  throw std::runtime_error(prefix + "'" + dot_program.string() + "' " + how +
                           (printed.empty() ? "" : ": " + printed));
}

}  // namespace

std::string to_dot(const Diagram& diagram, const GraphvizOptions& options) {
  return DotWriter(options).write(diagram);
}

void render_dot(const std::string& dot, const std::filesystem::path& output) {
  std::string extension = output.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension != ".dot" && extension != ".svg" && extension != ".png") {
    throw std::invalid_argument("cannot render '" + output.string() + "': " +
                                (extension.empty()
                                     ? std::string("it has no extension")
                                     : "unknown extension '" + output.extension().string() + "'") +
                                "; the allowed extensions are .dot, .svg and .png");
  }
  check_replaceable(output);
  const std::string text = tagged(dot);
  if (extension == ".dot") {
    PendingFile file(output);
    write_all(file.fd(), text, output);
    file.commit();
    return;
  }
  const std::optional<std::filesystem::path> dot_program = find_on_path("dot");
  if (!dot_program) {
    throw std::runtime_error("cannot render '" + output.string() +
                             "': the Graphviz program 'dot' was not found on PATH; install the "
                             "Debian package 'graphviz' or write a .dot file");
  }
  PendingFile file(output);
  run_dot(*dot_program, extension.substr(1), text, file.path(), output);
  if (extension == ".png") tag_png(file.path(), output);
  file.commit();
}

}  // namespace cbbg
