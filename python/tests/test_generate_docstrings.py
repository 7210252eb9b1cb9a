"""python/generate_docstrings.py on headers of its own: the constants it writes, and its refusal
of a listed class without a comment (the build stops rather than ship an empty docstring)."""

import pathlib
import subprocess
import sys

GENERATOR = pathlib.Path(__file__).resolve().parents[1] / "generate_docstrings.py"

DOCUMENTED = """\
#pragma once

namespace demo {

// Config keys demo.*.
struct DemoParams {
  double gain = 1.0;
};

/// Demo: a documented block.
///
/// | port | dir | size | meaning |
/// |------|-----|------|---------|
/// | y    | out | 1    | gain    |
///
///   y = gain   (indented, as written)
class Demo final : public Block {
 public:
  Demo();
};

}  // namespace demo
"""

UNDOCUMENTED = """\
#pragma once

namespace demo {

// A comment about something else, a blank line above the class.

class Bare final : public Block {
 public:
  Bare();
};

}  // namespace demo
"""


def generate(tmp_path, *pairs):
    output = tmp_path / "out" / "docstrings.h"
    completed = subprocess.run(
        [sys.executable, str(GENERATOR), "--source-dir", str(tmp_path), "--output", str(output),
         *pairs],
        capture_output=True, text=True, check=False)
    return completed, output


def test_writes_one_constant_per_class_with_the_comment_unmarked(tmp_path):
    (tmp_path / "demo").mkdir()
    (tmp_path / "demo" / "demo.h").write_text(DOCUMENTED, encoding="utf-8")
    completed, output = generate(tmp_path, "Demo=demo/demo.h", "DemoParams=demo/demo.h")
    assert completed.returncode == 0, completed.stderr
    text = output.read_text(encoding="utf-8")
    assert ('inline constexpr const char* kDemoDoc = R"cbbgdoc(Demo: a documented block.\n'
            "\n"
            "| port | dir | size | meaning |\n"
            "|------|-----|------|---------|\n"
            "| y    | out | 1    | gain    |\n"
            "\n"
            '  y = gain   (indented, as written))cbbgdoc";\n') in text
    assert ('inline constexpr const char* kDemoParamsDoc = R"cbbgdoc(Config keys demo.*.)cbbgdoc";'
            in text)
    assert "namespace cbbg::python {" in text


def test_refuses_a_class_without_a_comment_naming_header_and_class(tmp_path):
    (tmp_path / "demo").mkdir()
    (tmp_path / "demo" / "demo.h").write_text(DOCUMENTED, encoding="utf-8")
    (tmp_path / "demo" / "bare.h").write_text(UNDOCUMENTED, encoding="utf-8")
    completed, output = generate(tmp_path, "Demo=demo/demo.h", "Bare=demo/bare.h")
    assert completed.returncode == 1
    lines = completed.stderr.splitlines()
    assert len(lines) == 1, completed.stderr
    assert "demo/bare.h" in lines[0] and "class Bare has no comment above it" in lines[0]
    assert not output.exists()  # nothing half-written for the build to compile


def test_refuses_a_class_its_header_does_not_define(tmp_path):
    (tmp_path / "demo").mkdir()
    (tmp_path / "demo" / "demo.h").write_text(DOCUMENTED + "class Forward;\n", encoding="utf-8")
    completed, _ = generate(tmp_path, "Forward=demo/demo.h")
    assert completed.returncode == 1
    assert completed.stderr.strip() == (
        "generate_docstrings.py: demo/demo.h: no definition of class Forward")
