"""Sphinx configuration of the documentation site: `make docs` builds it into docs/_build/html, offline.

Sphinx with the furo theme, Markdown pages through myst-parser, the command reference generated from the click
commands by sphinx-click and the Python reference from the docstrings by autodoc, so neither can drift from the code.
"""

import rodparadox

project = "sears-paradox"
author = "the sears-paradox authors"
copyright = "2026, the sears-paradox authors"
version = release = rodparadox.__version__

extensions = ["myst_parser", "sphinx_click", "sphinx.ext.autodoc"]
source_suffix = {".md": "markdown"}
root_doc = "index"
exclude_patterns = ["_build", "**/.ipynb_checkpoints"]

myst_heading_anchors = 3  # `[the reference](commands.md#reference)` links to a heading
myst_enable_extensions = ["colon_fence"]
smartquotes = False  # `--rod` stays two hyphens, as typed

autodoc_member_order = "bysource"
autodoc_typehints = "none"  # the signatures carry them; repeating each in the text adds nothing

html_theme = "furo"
html_title = f"sears-paradox {release}"
html_static_path = []
html_last_updated_fmt = None  # no dates: the same sources give the same pages


def _escape_bars(app, ctx, lines):
    """A help text's |U| is an absolute value, not a reStructuredText substitution: escape its bars."""
    lines[:] = [line.replace("|", "\\|") if "|" in line and not line.lstrip().startswith((":options:", ".. ")) else line
                for line in lines]


def _escape_docstring_bars(app, what, name, obj, options, lines):
    _escape_bars(app, None, lines)


def setup(app):
    app.connect("autodoc-process-docstring", _escape_docstring_bars)
    for part in ("description", "options", "arguments", "epilog"):
        app.connect(f"sphinx-click-process-{part}", _escape_bars)
