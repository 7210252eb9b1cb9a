"""The documentation's checks fail when they should: scripts/check_docs.py on a small tree
with one fault each, the site's Sphinx build (docs/site/conf.py, warnings as errors) on
pages with a broken link or a snippet marker its file lacks, and the API reference's Doxygen
build (docs/site/Doxyfile.in, warnings as errors) on a header comment it warns about; and
scripts/build_docs.sh refusing to replace a folder it did not make."""

import os
import shutil
import subprocess
import sys

import pytest

REPO = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
CHECKER = os.path.join(REPO, "scripts", "check_docs.py")
EXAMPLE = """int main() {
  // [docs hello]
  int answer = 42;
  return answer - 42;
  // [docs hello end]
}
"""
GOOD_README = """# Project

See [the guide](docs/guide.md#swapping-a-block) and `examples/hello.cc:3`.

<!-- snippet: examples/hello.cc hello -->
```cpp
int answer = 42;
return answer - 42;
```
"""
GOOD_GUIDE = """# Guide

## Swapping a block

```{literalinclude} ../examples/hello.cc
:language: cpp
:start-after: "[docs hello]"
:end-before: "[docs hello end]"
```

Back to [the top](guide.md#guide).
"""


def make_tree(tmp_path, readme=GOOD_README, guide=GOOD_GUIDE):
    (tmp_path / "docs").mkdir(parents=True)
    (tmp_path / "examples").mkdir()
    (tmp_path / "examples" / "hello.cc").write_text(EXAMPLE)
    (tmp_path / "README.md").write_text(readme)
    (tmp_path / "docs" / "guide.md").write_text(guide)
    return tmp_path


def check(root):
    return subprocess.run([sys.executable, CHECKER, "--root", str(root)],
                          capture_output=True, text=True)


def test_a_sound_tree_passes(tmp_path):
    result = check(make_tree(tmp_path))
    assert result.returncode == 0, result.stdout + result.stderr


@pytest.mark.parametrize("readme, guide, message", [
    (GOOD_README.replace("docs/guide.md#", "docs/gide.md#"), GOOD_GUIDE,
     "README.md:3: link to docs/gide.md#swapping-a-block: no file docs/gide.md"),
    (GOOD_README.replace("#swapping-a-block", "#swapping-blocks"), GOOD_GUIDE,
     "README.md:3: link to docs/guide.md#swapping-blocks: docs/guide.md has no heading"),
    (GOOD_README.replace("`examples/hello.cc:3`", "`examples/hello.cc:30`"), GOOD_GUIDE,
     "README.md:3: cites examples/hello.cc:30: examples/hello.cc has 6 lines"),
    (GOOD_README.replace("`examples/hello.cc:3`", "`examples/goodbye.cc`"), GOOD_GUIDE,
     "README.md:3: cites examples/goodbye.cc: no such file or folder"),
    (GOOD_README.replace("return answer - 42;", "return 0;"), GOOD_GUIDE,
     "README.md:6: snippet examples/hello.cc [docs hello]: the block differs"),
    (GOOD_README.replace("<!-- snippet: examples/hello.cc hello -->\n", ""), GOOD_GUIDE,
     "README.md:5: a cpp block without <!-- snippet: FILE MARKER --> above it"),
    (GOOD_README + "\n" + "line\n" * 300, GOOD_GUIDE,
     "README.md: 310 lines, more than the 300 a README may have"),
    (GOOD_README, GOOD_GUIDE + "\n```python\nprint('copied')\n```\n",
     "docs/guide.md:13: a python block written into the page"),
    (GOOD_README, GOOD_GUIDE.replace("[docs hello end]", "[docs hello stop]"),
     "docs/guide.md:5: includes examples/hello.cc: no line holds '[docs hello stop]'"),
    (GOOD_README, GOOD_GUIDE.replace("../examples/hello.cc", "../README.md"),
     "docs/guide.md:5: includes README.md: snippets come from examples/"),
    (GOOD_README, GOOD_GUIDE.replace("guide.md#guide", "gide.md#guide"),
     "docs/guide.md:11: link to gide.md#guide: no file docs/gide.md"),
])
def test_each_fault_is_reported_where_it_is(tmp_path, readme, guide, message):
    result = check(make_tree(tmp_path, readme, guide))
    assert result.returncode == 1
    assert message in result.stdout, result.stdout


def test_a_broken_link_of_the_built_site_is_reported(tmp_path):
    root = make_tree(tmp_path / "tree")
    site = tmp_path / "site"
    site.mkdir()
    (site / "index.html").write_text('<a href="guide.html#x">guide</a><img src="graphs/a.svg">')
    (site / "guide.html").write_text("<p>guide</p>")
    result = subprocess.run([sys.executable, CHECKER, "--root", str(root), "--site", str(site)],
                            capture_output=True, text=True)
    assert result.returncode == 1
    assert "site/index.html:1: graphs/a.svg: the site has no such file" in result.stdout


SPHINX = shutil.which("sphinx-build")


@pytest.mark.skipif(SPHINX is None, reason="Sphinx is not installed")
@pytest.mark.parametrize("fault, message", [
    ("", None),
    ("See [nowhere](nowhere.md).\n", "reference target not found: nowhere.md"),
    ("See [a missing reference page](api/missing.html).\n",
     "reference target not found: api/missing.html"),
    ("```{literalinclude} ../examples/hello.cc\n:start-after: \"[docs gone]\"\n```\n",
     "start-after pattern not found"),
])
def test_the_site_build_fails_on_a_warning(tmp_path, fault, message):
    root = make_tree(tmp_path)
    (root / "docs" / "index.md").write_text(
        "# Home\n\n" + fault + "\n```{toctree}\nguide\n```\n")
    extra = tmp_path / "extra"
    (extra / "api").mkdir(parents=True)
    (extra / "api" / "index.html").write_text("<p>reference</p>")
    result = subprocess.run(
        [SPHINX, "-W", "--keep-going", "-q", "-b", "html", "-c", os.path.join(REPO, "docs", "site"),
         str(root / "docs"), str(tmp_path / "html")],
        capture_output=True, text=True, env={**os.environ, "CBBG_DOCS_EXTRA": str(extra)})
    if message is None:
        assert result.returncode == 0, result.stderr
    else:
        assert result.returncode != 0
        assert message in result.stderr, result.stderr


DOXYGEN = shutil.which("doxygen")


@pytest.mark.skipif(DOXYGEN is None, reason="Doxygen is not installed")
@pytest.mark.parametrize("comment, message", [
    ("/// A block with a port table.", None),
    ("/// A block whose comment holds <input name>.", "Unsupported xml/html tag <input> found"),
])
def test_the_reference_build_fails_on_a_warning(tmp_path, comment, message):
    (tmp_path / "block.h").write_text(f"#pragma once\n{comment}\nclass Block {{}};\n")
    with open(os.path.join(REPO, "docs", "site", "Doxyfile.in"), encoding="utf-8") as f:
        doxyfile = f.read()
    for name, value in {"@PROJECT_VERSION@": "0", "@CBBG_DOCS_EXTRA@": str(tmp_path / "out"),
                        "@PROJECT_SOURCE_DIR@": REPO,
                        "@CBBG_DOXYGEN_INPUT@": str(tmp_path / "block.h")}.items():
        doxyfile = doxyfile.replace(name, value)
    result = subprocess.run([DOXYGEN, "-"], input=doxyfile, capture_output=True, text=True)
    if message is None:
        assert result.returncode == 0, result.stderr
    else:
        assert result.returncode != 0
        assert f"block.h:2: error: {message}" in result.stderr, result.stderr


@pytest.mark.parametrize("folder", ["--out", "--extra"])
def test_the_site_build_never_replaces_a_folder_it_did_not_make(tmp_path, folder):
    mine = tmp_path / "mine"
    mine.mkdir()
    (mine / "notes.txt").write_text("a user's notes")
    paths = {"--out": str(tmp_path / "html"), "--extra": str(tmp_path / "extra"), folder: str(mine)}
    command = ["bash", os.path.join(REPO, "scripts", "build_docs.sh"), "--source", "docs",
               "--doxyfile", "Doxyfile", "--cbbg", "cbbg", "--sphinx", "sphinx-build"]
    for option, path in paths.items():
        command += [option, path]
    result = subprocess.run(command, capture_output=True, text=True)
    assert result.returncode == 2
    assert f"{mine} exists and is not" in result.stderr
    assert (mine / "notes.txt").read_text() == "a user's notes"
    assert sorted(os.listdir(tmp_path)) == ["mine"]
