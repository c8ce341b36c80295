"""Sphinx configuration of halfplane's documentation site, built by ``./scripts/docs`` into
target/docs-site: the Markdown pages of docs/ (myst-parser), the Python API from the package's
docstrings (autodoc, autosummary), the command-line reference from ``halfplane <command> --help``
(the local extension _ext/halfplane_cli.py) and the example gallery under docs/gallery, whose
scripts run during the build (sphinx-gallery). Warnings are errors (``-W --keep-going``) and
every cross-reference must resolve (``nitpicky``)."""

from __future__ import annotations

import os
import re
import sys
from pathlib import Path
from typing import Any

from docutils import nodes

HERE = Path(__file__).resolve().parent
#: docs/ itself (scripts/docs builds from a copy of it in target/, and says where it came from).
DOCS = Path(os.environ.get("HALFPLANE_DOCS_SOURCE", HERE))
sys.path.insert(0, str(HERE / "_ext"))

import halfplane  # the installed package the site documents

project = "halfplane"
author = "the halfplane developers"
copyright = "the halfplane developers; MIT OR Apache-2.0"
release = version = halfplane.__version__

extensions = [
    "myst_parser",
    "sphinx.ext.autodoc",
    "sphinx.ext.autosummary",
    "sphinx_gallery.gen_gallery",
    "halfplane_cli",
]

source_suffix = {".rst": "restructuredtext", ".md": "markdown"}
root_doc = "index"
# The figures the pages show are the committed PNGs beside them; generated gallery sources
# (auto_gallery) are written at build time.
exclude_patterns = ["_build", "gallery/README.md", "**/*.ipynb", "auto_gallery/*.ipynb"]

# Internal links are checked: every reference must resolve, and a Markdown link to a page that
# does not exist is a warning (so an error).
nitpicky = True
myst_heading_anchors = 3
# Types of other libraries named in signatures: the build has no network for their inventories.
nitpick_ignore_regex = [
    (r"py:.*", r"(pandas|pd|numpy|np|npt|matplotlib|os|typing|typing_extensions|collections\.abc)\..*"),
    (r"py:class", r"(Axes|Figure|Floats|FloatArray|PathLike|ArrayLike|NDArray|DataFrame|ndarray)"),
    (r"py:class", r"halfplane\._halfplane\.Case"),
    (r"py:class", r"optional"),
    # The type variable of the generic records (Edges[T], PerPoint[T]).
    (r"py:class", r"T"),
]

def _repository_files() -> list[str]:
    """Links of the pages to files of the repository outside docs/ (source files, examples):
    GitHub shows them, the site has no page for them. Each must exist (a link to a missing file
    is still an error); the site shows its text without a link."""
    found = []
    for page in DOCS.glob("*.md"):
        for target in re.findall(r"\]\((\.\./[^)\s]+)\)|^\[[^\]]+\]: (\.\./\S+)", page.read_text(), re.MULTILINE):
            path = next(t for t in target if t)
            if (DOCS / path.split("#")[0]).exists():
                found.append(path)
    return found


REPOSITORY_FILES = _repository_files()
nitpick_ignore = [("myst", target) for target in REPOSITORY_FILES]

autodoc_default_options = {"members": True, "member-order": "bysource"}
autodoc_typehints = "description"
autodoc_typehints_format = "short"
autodoc_preserve_defaults = True
autosummary_generate = False

sphinx_gallery_conf = {
    "examples_dirs": "gallery",
    "gallery_dirs": "auto_gallery",
    "filename_pattern": r"/plot_",
    "within_subsection_order": "FileNameSortKey",
    "abort_on_example_error": True,
    "download_all_examples": False,
    "remove_config_comments": True,
    "image_scrapers": ("matplotlib",),
    # Show what the examples print, not the repr of the Axes a figure function returns.
    "capture_repr": (),
}

html_theme = "furo"
html_title = f"halfplane {release}"
html_static_path: list[str] = []
html_show_sourcelink = False


def _unlink_repository_files(app: Any, doctree: nodes.document, docname: str) -> None:
    """The links of :data:`REPOSITORY_FILES` as their text: the site has no page for them."""
    for ref in list(doctree.findall(nodes.reference)):
        if ref.get("refid") in REPOSITORY_FILES:
            ref.replace_self(nodes.inline("", "", *ref.children))


#: ``|x|`` in the docstrings is an absolute value, never an reST substitution.
_BARS = re.compile(r"(``.*?``)|\|")


def _absolute_values(app: Any, what: str, name: str, obj: Any, options: Any, lines: list[str]) -> None:
    lines[:] = [_BARS.sub(lambda m: m.group(1) or "\\|", line) for line in lines]


def setup(app: Any) -> None:
    app.connect("autodoc-process-docstring", _absolute_values)
    app.connect("doctree-resolved", _unlink_repository_files)
