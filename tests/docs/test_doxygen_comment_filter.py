"""The API reference's input filter keeps a header's equations laid out, keeps every line
where it was, and leaves list items and code alone."""

import os
import subprocess
import sys

FILTER = os.path.join(os.path.dirname(__file__), "..", "..", "docs", "site",
                      "doxygen_comment_filter.py")
HEADER = """#pragma once
/// Gain: y = k u.
///
/// The law:
///   y = k u
///   (elementwise)
/// In order:
///  1. read u;
///  2. write y, which holds
///     until the next sample.
class Gain {
  int k;  ///< the gain
};
"""


def filtered(tmp_path, text):
    header = tmp_path / "gain.h"
    header.write_text(text)
    return subprocess.run([sys.executable, FILTER, str(header)], capture_output=True,
                          text=True, check=True).stdout


def test_an_equation_run_becomes_verbatim_and_lines_keep_their_numbers(tmp_path):
    lines = filtered(tmp_path, HEADER).split("\n")
    assert len(lines) == len(HEADER.split("\n"))
    assert lines[1] == "/** Gain: y = k u."
    assert lines[3] == "    The law: \\verbatim"
    assert lines[4] == "      y = k u"
    assert lines[5] == "      (elementwise) \\endverbatim"


def test_a_list_items_continuation_is_not_verbatim(tmp_path):
    lines = filtered(tmp_path, HEADER).split("\n")
    assert lines[8] == "     2. write y, which holds"
    assert lines[9] == "        until the next sample. */"
    assert "verbatim" not in "".join(lines[6:10])


def test_code_and_member_comments_are_left_as_they_are(tmp_path):
    lines = filtered(tmp_path, HEADER).split("\n")
    assert lines[10:] == HEADER.split("\n")[10:]
