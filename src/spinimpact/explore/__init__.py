"""``spinimpact explore``: a local web page to explore one impact, every view at once.

The page (a Dash app: :func:`~spinimpact.explore.app.create_app`) reads its inputs as text
(:mod:`~spinimpact.explore.settings`), solves them with the library's public solvers and
draws the bounce, the impact process over the normal impulse, the regime map, the report's
tables and a ball's flight (:mod:`~spinimpact.explore.views`). :func:`serve` runs it on
this computer only (``127.0.0.1``) until Ctrl-C. It needs the ``explore`` extra:
``pip install 'spinimpact[explore]'``.
"""

from __future__ import annotations

__all__ = ["serve"]


def serve(host: str = "127.0.0.1", port: int = 8050, *, ready: object = None) -> None:
    """Serve the explorer at ``http://HOST:PORT/`` until interrupted (Ctrl-C or SIGTERM).

    Parameters
    ----------
    host : str
        The interface to listen on: ``127.0.0.1`` (this computer only) by default.
    port : int
        TCP port; ``0`` picks a free one.
    ready : callable, optional
        Called with the page's address once the server listens.

    Raises
    ------
    ImportError
        Without Dash: the message names ``pip install 'spinimpact[explore]'``.
    OSError
        When the port cannot be bound.
    """
    try:
        import dash  # noqa: F401
    except ImportError:
        raise ImportError(
            "spinimpact explore needs Dash, which is not installed: "
            "pip install 'spinimpact[explore]'"
        ) from None
    from werkzeug.serving import make_server

    from . import settings
    from .app import create_app, update

    app = create_app()
    for kind in ("paper", "sphere"):  # the first page opens without the imports' wait
        update(settings.defaults(kind))
    server = make_server(host, port, app.server, threaded=True)
    address = f"http://{host}:{server.server_port}/"
    if callable(ready):
        ready(address)
    try:
        server.serve_forever()
    finally:
        server.server_close()
