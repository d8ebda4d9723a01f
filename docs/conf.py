"""Sphinx configuration of the spinimpact site (``make docs`` builds it into build/docs).

Everything the pages need is installed by the ``[docs]`` extra: nothing is fetched from
the web at build or view time (no intersphinx inventories, MathJax from the
``sphinx-mathjax-offline`` package, the theme's fonts and icons from its own files).
"""

from __future__ import annotations

import os
import sys
from pathlib import Path

import spinimpact

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(Path(__file__).parent))  # the site's own extensions (_ext)

project = "spinimpact"
author = "the spinimpact developers"
copyright = "2026, the spinimpact developers"  # noqa: A001 - Sphinx's name
release = spinimpact.__version__
version = release

extensions = [
    "sphinx.ext.autodoc",
    "sphinx.ext.autosummary",
    "sphinx.ext.mathjax",
    "sphinx-mathjax-offline",
    "numpydoc",
    "myst_parser",
    "sphinx_gallery.gen_gallery",
    "_ext.cli_reference",
    "_ext.internals",
]

source_suffix = {".rst": "restructuredtext", ".md": "markdown"}
root_doc = "index"
exclude_patterns = ["_build", "scripts", "Thumbs.db", ".DS_Store"]
templates_path = ["_templates"]
html_static_path = ["_static"]

# -- the theme -------------------------------------------------------------------------
# pydata-sphinx-theme: the theme of NumPy, SciPy, Matplotlib and pvlib, whose readers are
# ours; its version switcher, icon links and analytics stay off (nothing external).
html_theme = "pydata_sphinx_theme"
html_title = f"spinimpact {release}"
html_theme_options = {
    "navigation_with_keys": False,
    "show_toc_level": 2,
    "navbar_align": "left",
    "header_links_before_dropdown": 4,
    "secondary_sidebar_items": ["page-toc"],
    "footer_start": ["copyright"],
    "footer_end": ["sphinx-version"],
}
html_show_sourcelink = False
# The light/dark switch starts from the reader's system setting (without it the theme logs
# an error on a reader's first visit).
html_context = {"default_mode": "auto"}
# The landing and start pages stand alone: no section navigation beside them.
html_sidebars = {"index": [], "start/*": []}

# -- MyST: the Markdown pages ----------------------------------------------------------
myst_enable_extensions = ["dollarmath", "amsmath", "deflist", "colon_fence"]
myst_heading_anchors = 3

# -- API reference -----------------------------------------------------------------------
autosummary_generate = True
autodoc_typehints = "none"
numpydoc_show_class_members = False
numpydoc_class_members_toctree = False
numpydoc_xref_param_type = False
numpydoc_validation_checks: set[str] = set()

# References to NumPy, SciPy, Matplotlib and the standard library stay plain text (no
# inventories are fetched): the nitpicky check ignores them by name.
nitpicky = True
# numpydoc turns a docstring's References section into citations and warns when the text
# does not cite one; the module docstrings list the works they rest on without citing each.
suppress_warnings = ["ref.citation"]
nitpick_ignore_regex = [
    (r"py:.*", r"(numpy|np|scipy|matplotlib|pyarrow|dask|distributed|numba|jax|click)\..*"),
    (r"py:.*", r"(array_like|array-like|ndarray|optional|callable|scalar|default.*)"),
    (r"py:class", r"(int|float|str|bool|dict|list|tuple|bytes|object|None|type|slice)"),
    (r"py:class", r"(pathlib\.Path|os\.PathLike.*|collections\.abc\..*|typing\..*)"),
    (r"py:.*", r"(atexit|signal|tracemalloc|warnings|threading|concurrent)(\..*)?"),
]

# -- the gallery -----------------------------------------------------------------------
sphinx_gallery_conf = {
    "examples_dirs": str(ROOT / "examples"),
    "gallery_dirs": "gallery",
    "filename_pattern": r"/plot_",
    "backreferences_dir": "gen_modules/backreferences",
    "doc_module": ("spinimpact",),
    "reference_url": {"spinimpact": None},
    "download_all_examples": False,
    "remove_config_comments": True,
    "within_subsection_order": "FileNameSortKey",
    "matplotlib_animations": False,
    "image_scrapers": ("_ext.gallery_figures.scrape_figures",),
    "show_memory": False,
    "min_reported_time": 1e9,
    # The execution-times pages load a table library from a CDN; the site fetches nothing.
    "write_computation_times": False,
}
os.environ.setdefault("MPLBACKEND", "Agg")
