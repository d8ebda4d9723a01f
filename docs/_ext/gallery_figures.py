"""The gallery's image scraper: pyplot's figures and the package's own.

The package's figure functions (``spinimpact.viz.*``) return a ``matplotlib.figure.Figure``
made without pyplot, so that they never open a window; Sphinx-Gallery's Matplotlib scraper
only sees pyplot's figures. This scraper saves both: every figure pyplot knows, then every
``Figure`` the example's code holds in a variable, each once.
"""

from __future__ import annotations

import weakref

_SHOWN: weakref.WeakSet = weakref.WeakSet()


def scrape_figures(block, block_vars, gallery_conf, **kwargs) -> str:  # noqa: ANN001, ARG001
    import matplotlib.pyplot as plt
    from matplotlib.figure import Figure
    from sphinx_gallery.scrapers import figure_rst

    held = [v for v in block_vars["example_globals"].values() if isinstance(v, Figure)]
    paths = []
    for fig in [*(plt.figure(n) for n in plt.get_fignums()), *held]:
        if fig in _SHOWN:
            continue
        _SHOWN.add(fig)
        path = next(block_vars["image_path_iterator"])
        fig.savefig(path, facecolor=fig.get_facecolor(), edgecolor=fig.get_edgecolor())
        paths.append(path)
    plt.close("all")
    return figure_rst(paths, gallery_conf["src_dir"])
