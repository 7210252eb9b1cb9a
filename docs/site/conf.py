"""Sphinx configuration of cbbg's documentation site: the user guide (docs/*.md, MyST
Markdown) with the API reference (Doxygen HTML) and the presets' diagrams beside it.

Built by the CMake target `docs` (scripts/docs.sh), which first writes the reference and the
diagrams into the folder named by CBBG_DOCS_EXTRA and then runs
    sphinx-build -W -c docs/site docs <build>/docs/html
Every warning fails the build. A guide page links into the reference as `api/<page>.html`
and to a diagram as `graphs/<preset>.svg`: such a link resolves only when that file exists.
"""

import os

from docutils import nodes

project = "cbbg"
author = "the cbbg authors"
copyright = "the cbbg authors"
version = release = os.environ.get("CBBG_VERSION", "")

extensions = ["myst_parser"]
source_suffix = {".md": "markdown"}
root_doc = "index"
exclude_patterns = ["site", "figures"]
myst_heading_anchors = 4

html_theme = "sphinx_rtd_theme"
html_title = "cbbg documentation"
html_show_sourcelink = False
html_static_path = ["_static"]
html_css_files = ["cbbg.css"]

EXTRA = os.environ.get("CBBG_DOCS_EXTRA", "")
if not EXTRA or not os.path.isdir(EXTRA):
    raise RuntimeError(
        "CBBG_DOCS_EXTRA must name the folder holding the API reference (api/) and the "
        "diagrams (graphs/): build the site with `cmake --build build --target docs` "
        "(or scripts/docs.sh)"
    )
html_extra_path = [EXTRA]
GENERATED = ("api/", "graphs/")


def resolve_generated_link(app, env, node, contnode):
    """A link to a page of the reference or a diagram resolves to that file when it exists;
    otherwise Sphinx reports it as a missing target (a warning, so a failed build)."""
    target = node.get("reftarget", "")
    if node.get("reftype") not in ("myst", "any") or not target.startswith(GENERATED):
        return None
    if not os.path.isfile(os.path.join(EXTRA, target.split("#")[0])):
        return None
    depth = node.get("refdoc", "").count("/")
    reference = nodes.reference("", "", internal=False, refuri="../" * depth + target)
    reference.append(contnode)
    return reference


def setup(app):
    app.connect("missing-reference", resolve_generated_link)
