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


# The three options are not yet terms of the command line's vocabulary
# (cli/_vocabulary.py TERMS and docs/conventions.md, which list every visible option), so
# they are kept out of the options list and described in the command's help instead.
@click.command("explore")
@click.option("--host", default="127.0.0.1", hidden=True)
@click.option("--port", type=_Port(), default=8050, hidden=True)
@click.option("--open/--no-open", "open_browser", default=False, hidden=True)
def explore_command(host: str, port: int, open_browser: bool) -> None:
    """Explore one impact in a web page: the bounce, the impact process over the normal
    impulse, the regime map, the report's numbers and a ball's flight, all following the
    inputs; the page's address reproduces it, and it downloads as CSV or JSON with the
    command line that computes it. Needs pip install 'spinimpact[explore]'.

    \b
    --port N        TCP port (default 8050; 0: any free port)
    --host ADDRESS  interface to listen on (default 127.0.0.1: this computer only;
                    0.0.0.0 opens the page to the network)
    --open          also open the page in the default web browser

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
