# Sphinx configuration of the wearscale manual: the Markdown pages of docs/
# (MyST) and the C++ API reference (Breathe over Doxygen's XML).
#
# Built by `cmake --build build --target docs` (cmake/WearscaleDocs.cmake),
# which runs Doxygen first and passes the XML directory as
# `-D breathe_projects.wearscale=<dir>`; the ctest `docs.build` builds it
# with -W (warnings are errors).
import os

project = "wearscale"
author = "The wearscale developers"
copyright = "wearscale developers"
release = os.environ.get("WEARSCALE_VERSION", "")

extensions = ["myst_parser", "breathe"]
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


html_theme = "alabaster"
html_title = "wearscale manual"
html_static_path = []
