#!/usr/bin/python3
"""Doxygen's input filter (Doxyfile INPUT_FILTER): keeps a header comment's equations as the
header lays them out.

A block's `///` comment writes its equations as lines indented by two or more spaces after
the marker (`///   y = C x + D u`); Doxygen's Markdown would flow them into the paragraph.
Each run of such lines, unless it continues a list item (`///  1. ...`, `/// - ...`), is
wrapped in \\verbatim ... \\endverbatim, the two commands added at the end of the line
before the run and of its last line, so every line keeps its number (the reference links
to `file.h` line N). Usage: doxygen_comment_filter.py FILE.h > filtered text.
"""

import re
import sys

COMMENT = re.compile(r"^(\s*///)(.*)$")
INDENTED = re.compile(r"^ {3,}\S")  # the marker's one space, then two or more
LIST_ITEM = re.compile(r"^\s*(\d+\.|[-*])\s")


def filtered(lines):
    out = list(lines)
    index = 0
    while index < len(lines):
        match = COMMENT.match(lines[index])
        if not (match and INDENTED.match(match.group(2))) or index == 0:
            index += 1
            continue
        previous = COMMENT.match(lines[index - 1])
        end = index
        while end + 1 < len(lines):
            following = COMMENT.match(lines[end + 1])
            if not (following and INDENTED.match(following.group(2))):
                break
            end += 1
        if previous and not LIST_ITEM.match(previous.group(2)):
            out[index - 1] = out[index - 1] + " \\verbatim"
            out[end] = out[end] + " \\endverbatim"
        index = end + 1
    return as_block_comments(lines, out)


def as_block_comments(lines, out):
    """Each run of `///` lines as one /** ... */ comment of the same lines: Doxygen keeps the
    `///` markers inside a verbatim block, but not a block comment's indentation."""
    index = 0
    while index < len(lines):
        if not COMMENT.match(lines[index]):
            index += 1
            continue
        end = index
        while end + 1 < len(lines) and COMMENT.match(lines[end + 1]):
            end += 1
        for line in range(index, end + 1):
            marker = COMMENT.match(out[line]).group(1)
            opening = "/**" if line == index else "   "
            out[line] = marker[: -3] + opening + out[line][len(marker):]
        out[end] += " */"
        index = end + 1
    return out


def main():
    with open(sys.argv[1], encoding="utf-8") as f:
        text = f.read()
    sys.stdout.write("\n".join(filtered(text.split("\n"))))


if __name__ == "__main__":
    main()
