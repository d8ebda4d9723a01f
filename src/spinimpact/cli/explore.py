"""``spinimpact explore``: the explorer's web page on this computer (``spinimpact.explore``).

The server listens on ``127.0.0.1`` unless ``--host`` says otherwise, prints the page's
address, and runs until Ctrl-C (exit status 130, as every command stopped by SIGINT).
"""

from __future__ import annotations

import click

__all__ = ["explore_command"]


class _Port(click.ParamType):
    """A TCP port: a whole number in [0, 65535] (0: any free port)."""

    name = "port"

    def convert(self, value, param, ctx):  # type: ignore[no-untyped-def]
        try:
            port = int(str(value), 10)
        except ValueError:
            port = -1
        if not 0 <= port <= 65535:
            self.fail(f"must be a whole number in [0, 65535], got {value!r}", param, ctx)
        return port


@click.command("explore")
@click.option(
    "--host",
    default="127.0.0.1",
    show_default=True,
    help="Network interface the explorer listens on (127.0.0.1: this computer only); "
    "0.0.0.0 opens the page to the network.",
)
@click.option(
    "--port",
    type=_Port(),
    default=8050,
    show_default=True,
    help="TCP port of the explorer (0: any free port).",
)
@click.option(
    "--open/--no-open",
    "open_browser",
    default=False,
    help="Open the explorer's page in the default web browser.",
)
def explore_command(host: str, port: int, open_browser: bool) -> None:
    """Explore one impact in a web page: the bounce, the impact process over the normal
    impulse, the regime map, the report's numbers and a ball's flight, all following the
    inputs; the page's address reproduces it, and it downloads as CSV or JSON with the
    command line that computes it. Needs pip install 'spinimpact[explore]'.

    Stop it with Ctrl-C.
    """
    from ..explore import serve

    def ready(address: str) -> None:
        click.echo(f"spinimpact explorer at {address} (Ctrl-C stops it)", err=True)
        if open_browser:
            import webbrowser

            webbrowser.open(address)

    try:
        serve(host, port, ready=ready)
    except OSError as exc:
        raise click.UsageError(f"--host {host} --port {port}: {exc.strerror or exc}") from None
