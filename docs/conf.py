# Sphinx configuration of the wearscale manual: the Markdown pages of docs/
# (MyST) and the C++ API reference (Breathe over Doxygen's XML).
#
# Built by `cmake --build build --target docs` (cmake/WearscaleDocs.cmake),
# which runs Doxygen first and passes the XML directory as
# `-D breathe_projects.wearscale=<dir>`; the ctest `docs.build` builds it
# with -W (warnings are errors).
import os
import sys

project = "wearscale"
author = "The wearscale developers"
copyright = "wearscale developers"
release = os.environ.get("WEARSCALE_VERSION", "")

extensions = ["myst_parser", "breathe", "sphinx.ext.autodoc"]
source_suffix = {".md": "markdown"}
root_doc = "index"
exclude_patterns = ["_build", "figures/*.md"]

# Headings become anchors the way GitHub makes them, so links such as
# bem.md#distributed-grids-mpi work both on GitHub and in the site.
myst_heading_anchors = 4
myst_enable_extensions = ["dollarmath"]

breathe_projects = {"wearscale": os.environ.get("WEARSCALE_DOXYGEN_XML", "")}
breathe_default_project = "wearscale"
breathe_default_members = ("members",)

# Pages link to the results logs where GitHub shows them, ../bench/results/;
# in the site those logs are the pages results/<area> (docs/results/*.md
# include them), so the links are pointed there before parsing.
def _results_links(app, docname, source):
    prefix = "../" * docname.count("/")
    source[0] = source[0].replace("](../bench/results/", "](" + prefix + "results/")


def setup(app):
    app.connect("source-read", _results_links)
    app.connect("source-read", _python_api_page)
    app.connect("autodoc-process-docstring", _plain_docstrings)


# The Python API (python_api.md) comes from the built module's docstrings:
# WEARSCALE_PYTHON_DIR is the build tree's python/ (cmake/WearscaleDocs.cmake
# sets it when the module is built). Without it the page says so.
PYTHON_MODULES = ["wearscale", "wearscale.contact", "wearscale.surface", "wearscale.wear",
                  "wearscale.dem", "wearscale.materials", "wearscale.io"]
_python_dir = os.environ.get("WEARSCALE_PYTHON_DIR", "")
_python_api = None
if _python_dir:
    sys.path.insert(0, _python_dir)
    try:
        import wearscale  # noqa: F401

        _python_api = "\n".join(f".. automodule:: {m}" for m in PYTHON_MODULES)
    except ImportError as error:
        _python_missing = f"it does not import here ({error})"
else:
    _python_missing = "the module was not built in this tree (configure with WEARSCALE_PYTHON=ON)"
if _python_api is None:
    _python_api = f"The reference is generated from the module's docstrings; {_python_missing}."
else:
    _python_api = "```{eval-rst}\n" + _python_api + "\n```"
autodoc_default_options = {"members": True, "undoc-members": True}
autodoc_typehints = "signature"


def _python_api_page(app, docname, source):
    if docname == "python_api":
        source[0] = source[0].replace("<!-- python-api -->", _python_api)


def _plain_docstrings(app, what, name, obj, options, lines):
    # The docstrings are plain text (formulas such as <|h - <h>|>), not
    # reStructuredText: a bar would open a substitution reference.
    lines[:] = [line.replace("|", "\\|") for line in lines]


html_theme = "alabaster"
html_title = "wearscale manual"
html_static_path = []
