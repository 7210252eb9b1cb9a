#!/usr/bin/python3
"""Checks that what the documentation cites exists and that its code is the tested code.

Usage: check_docs.py --root REPO [--site HTML_DIR]

Reads README.md and docs/*.md under REPO and reports, one line each (file:line: what):
- a relative link whose file is missing, or whose #anchor is no heading of the target page
  (links into the generated API reference and diagrams, api/... and graphs/..., are
  checked against HTML_DIR when given);
- a repository path cited in a code span (`blocks/actor.h`, `examples/own_supervisor.cc:40`)
  that does not exist, or a line number past the file's end;
- a C++ or Python code block written into a page: the guide includes its snippets from the
  examples' files (a MyST literalinclude), which the tests compile and run, and such an
  include must name a file the tests build or run (under examples/, python/examples/,
  tests/ or python/tests/) and markers the file has;
- a README longer than 300 lines (it points into the guide for the rest);
- in the README, which GitHub shows without includes, a C++ or Python block not preceded by
  `<!-- snippet: FILE MARKER -->`, or not equal to the lines between FILE's `[docs MARKER]`
  and `[docs MARKER end]` comments.
With --site, every relative href and src of the site's guide pages must name a file of the
site. Exit status 0 when all is well, 1 when something is reported, 2 for a bad option.
"""

import argparse
import html.parser
import os
import re
import sys

LINK = re.compile(r"(?<!!)\[[^\]]*\]\(([^)\s]+)\)|!\[[^\]]*\]\(([^)\s]+)\)")
RAW_TARGET = re.compile(r"""(?:href|src)="([^"]+)\"""")
CODE_SPAN = re.compile(r"`([^`\n]+)`")
FENCE = re.compile(r"^(\s*)(`{3,})\s*(\{literalinclude\}\s*(\S+)|[\w+-]*)\s*$")
SNIPPET_MARK = re.compile(r"^<!--\s*snippet:\s*(\S+)\s+(\S+)\s*-->\s*$")
INCLUDE_OPTION = re.compile(r"^:([\w-]+):\s*\"?(.*?)\"?\s*$")
CODE_LANGUAGES = {"cpp", "c++", "cxx", "python", "py"}
README_LIMIT = 300
TESTED_SNIPPET_FOLDERS = ("examples/", "python/examples/", "tests/", "python/tests/")
GENERATED = ("api/", "graphs/")
# The first folders of the repository's own paths; a code span starting elsewhere
# (results/, DIR/, share/) names something a run or an install makes.
REPOSITORY_FOLDERS = (
    "apps", "bench", "blocks", "cmake", "codegen", "config", "configs", "diagrams", "docs",
    "environment", "examples", "experiments", "framework", "parameters", "plant", "python",
    "realtime", "records", "replay", "scripts", "store", "tests", ".ci",
)
PATH = re.compile(
    r"^((?:%s)/[\w./+-]*?)(?::(\d+)(?:-(\d+))?)?$" % "|".join(re.escape(f) for f in REPOSITORY_FOLDERS)
)


def slug(heading):
    """The anchor GitHub and MyST give a heading: lower case, punctuation dropped, spaces to -."""
    text = re.sub(r"`|\*|_(?=\W)|(?<=\W)_", "", heading.strip().lower())
    text = re.sub(r"[^\w\- ]", "", text)
    return text.replace(" ", "-")


def headings(text):
    anchors, in_fence = set(), False
    for line in text.splitlines():
        if line.lstrip().startswith("```"):
            in_fence = not in_fence
        elif not in_fence and re.match(r"^#{1,6} ", line):
            anchors.add(slug(line.lstrip("#")))
    return anchors


class Report:
    def __init__(self):
        self.problems = []

    def add(self, where, line, what):
        place = where if line is None else f"{where}:{line}"
        self.problems.append(f"{place}: {what}")


def check_link(report, root, page, line_number, target, site):
    if re.match(r"^[a-z]+:", target) or target.startswith("#") and not target[1:]:
        return
    path, _, anchor = target.partition("#")
    page_dir = os.path.dirname(page)
    if path.startswith(GENERATED) and os.path.basename(page_dir) == "docs":
        if site and not os.path.isfile(os.path.join(site, path)):
            report.add(rel(root, page), line_number, f"link to {path}: the site has no such page")
        return
    full = os.path.normpath(os.path.join(page_dir, path)) if path else page
    if not os.path.exists(full):
        report.add(rel(root, page), line_number, f"link to {target}: no file {rel(root, full)}")
        return
    if anchor and full.endswith(".md"):
        with open(full, encoding="utf-8") as f:
            if anchor not in headings(f.read()):
                report.add(rel(root, page), line_number,
                           f"link to {target}: {rel(root, full)} has no heading #{anchor}")


def check_code_span(report, root, page, line_number, span):
    match = PATH.match(span.strip())
    if not match or re.search(r"[*<>]|\.\.\.|/[A-Z]+(/|$)", span):
        return
    path, first, last = match.group(1), match.group(2), match.group(3)
    full = os.path.join(root, path)
    if not os.path.exists(full):
        report.add(rel(root, page), line_number, f"cites {path}: no such file or folder")
        return
    if first:
        with open(full, encoding="utf-8", errors="replace") as f:
            count = sum(1 for _ in f)
        if int(last or first) > count:
            report.add(rel(root, page), line_number, f"cites {span}: {path} has {count} lines")


def marked_lines(path, marker):
    """The lines between `[docs MARKER]` and `[docs MARKER end]`, dedented; None if absent."""
    with open(path, encoding="utf-8") as f:
        lines = f.read().splitlines()
    starts = [i for i, l in enumerate(lines) if l.strip().endswith(f"[docs {marker}]")]
    ends = [i for i, l in enumerate(lines) if l.strip().endswith(f"[docs {marker} end]")]
    if len(starts) != 1 or len(ends) != 1 or ends[0] <= starts[0]:
        return None
    body = lines[starts[0] + 1 : ends[0]]
    indent = min((len(l) - len(l.lstrip()) for l in body if l.strip()), default=0)
    return [l[indent:] for l in body]


def check_include(report, root, page, line_number, target, options):
    full = os.path.normpath(os.path.join(os.path.dirname(page), target))
    where = rel(root, page)
    if not os.path.isfile(full):
        report.add(where, line_number, f"includes {target}: no such file")
        return
    if not rel(root, full).startswith(TESTED_SNIPPET_FOLDERS):
        report.add(where, line_number, f"includes {rel(root, full)}: snippets come from "
                   "examples/, python/examples/, tests/ or python/tests/, which the tests "
                   "build and run")
    with open(full, encoding="utf-8") as f:
        text = f.read()
    for option in ("start-after", "end-before"):
        if option in options and options[option] not in text:
            report.add(where, line_number,
                       f"includes {rel(root, full)}: no line holds {options[option]!r}")


def check_page(report, root, page, site, is_readme):
    with open(page, encoding="utf-8") as f:
        lines = f.read().splitlines()
    fence, block, snippet_mark, include = None, [], None, None
    for number, line in enumerate(lines, start=1):
        if fence is not None:
            if line.strip() == fence[1]:
                finish_block(report, root, page, fence, block, snippet_mark, include, is_readme)
                fence, block, snippet_mark, include = None, [], None, None
            else:
                block.append(line)
            continue
        match = FENCE.match(line)
        if match:
            previous = lines[number - 2] if number >= 2 else ""
            fence = (number, match.group(1) + match.group(2), match.group(3) or "")
            include = match.group(4)
            snippet_mark = SNIPPET_MARK.match(previous)
            continue
        for link in LINK.finditer(line):
            check_link(report, root, page, number, link.group(1) or link.group(2), site)
        for raw in RAW_TARGET.finditer(line):
            check_link(report, root, page, number, raw.group(1), site)
        for span in CODE_SPAN.finditer(line):
            check_code_span(report, root, page, number, span.group(1))
    if fence is not None:
        report.add(rel(root, page), fence[0], "code block never closed")


def finish_block(report, root, page, fence, block, snippet_mark, include, is_readme):
    number, _, info = fence
    language = info.strip().lower()
    where = rel(root, page)
    if include:
        options = dict(m.groups() for m in map(INCLUDE_OPTION.match, block) if m)
        check_include(report, root, page, number, include, options)
        return
    if language not in CODE_LANGUAGES:
        return
    if not is_readme:
        report.add(where, number, f"a {language} block written into the page: include it from "
                   "the example it comes from (a literalinclude with [docs NAME] markers)")
        return
    if not snippet_mark:
        report.add(where, number, f"a {language} block without <!-- snippet: FILE MARKER --> "
                   "above it")
        return
    source, marker = snippet_mark.groups()
    full = os.path.join(root, source)
    if not os.path.isfile(full) or not source.startswith(TESTED_SNIPPET_FOLDERS):
        report.add(where, number, f"snippet {source}: no such file under examples/, "
                   "python/examples/, tests/ or python/tests/")
        return
    expected = marked_lines(full, marker)
    if expected is None:
        report.add(where, number, f"snippet {source}: no [docs {marker}] ... [docs {marker} end]")
    elif expected != block:
        report.add(where, number, f"snippet {source} [docs {marker}]: the block differs from "
                   "the file's lines")


class Targets(html.parser.HTMLParser):
    def __init__(self):
        super().__init__()
        self.targets = []

    def handle_starttag(self, tag, attrs):
        for name, value in attrs:
            if name in ("href", "src") and value:
                self.targets.append((self.getpos()[0], value))


def check_site(report, site):
    for name in sorted(os.listdir(site)):
        if not name.endswith(".html"):
            continue
        parser = Targets()
        with open(os.path.join(site, name), encoding="utf-8") as f:
            parser.feed(f.read())
        for line, target in parser.targets:
            if re.match(r"^[a-z]+:|^#|^//", target):
                continue
            path = target.split("#")[0].split("?")[0]
            if path and not os.path.exists(os.path.normpath(os.path.join(site, path))):
                report.add(os.path.join(os.path.basename(site), name), line,
                           f"{target}: the site has no such file")


def rel(root, path):
    return os.path.relpath(path, root)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--root", required=True, help="the repository")
    parser.add_argument("--site", help="the built HTML site (build/docs/html)")
    args = parser.parse_args()
    docs = os.path.join(args.root, "docs")
    readme = os.path.join(args.root, "README.md")
    for path in (readme, docs) + ((args.site,) if args.site else ()):
        if not os.path.exists(path):
            print(f"check_docs.py: {path}: no such file or folder", file=sys.stderr)
            return 2
    report = Report()
    with open(readme, encoding="utf-8") as f:
        length = len(f.read().splitlines())
    if length > README_LIMIT:
        report.add("README.md", None, f"{length} lines, more than the {README_LIMIT} a README may have")
    check_page(report, args.root, readme, args.site, is_readme=True)
    for name in sorted(os.listdir(docs)):
        if name.endswith(".md"):
            check_page(report, args.root, os.path.join(docs, name), args.site, is_readme=False)
    if args.site:
        check_site(report, args.site)
    for problem in report.problems:
        print(problem)
    if report.problems:
        print(f"check_docs.py: {len(report.problems)} problem(s) in the documentation")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
