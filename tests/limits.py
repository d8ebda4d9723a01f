"""Commands run under resource limits (as ``ulimit`` sets them), without ``preexec_fn``.

``subprocess``'s ``preexec_fn`` runs Python in the child between fork and exec, so Python
first calls the fork hooks of every library the test process has loaded. JAX's hook (JAX
is loaded by the array-API tests, earlier in the same process whenever they run first)
warns that a fork of its threads may deadlock, and that warning, an error in this suite,
failed the test: whether such a test passed depended on which tests ran before it. Here a
small interpreter sets the limits on itself and replaces itself with the command (exec),
which runs under exactly those limits, with no fork hook called in the test process.
"""

from __future__ import annotations

import sys

_LAUNCHER = """\
import os, resource, signal, sys
for spec in filter(None, sys.argv[1].split(",")):
    name, value = spec.split("=")
    resource.setrlimit(getattr(resource, name), (int(value), int(value)))
for name in filter(None, sys.argv[2].split(",")):
    signal.signal(getattr(signal, name), signal.SIG_IGN)
os.execvp(sys.argv[3], sys.argv[3:])
"""


def under_limits(command, *, ignore=(), **limits: int) -> list[str]:
    """The argument list that runs ``command`` under ``limits`` (``RLIMIT_AS=2**30``, the
    soft and hard limit alike), with the signals named in ``ignore`` (``"SIGXFSZ"``)
    ignored, as the command inherits them across exec."""
    spec = ",".join(f"{name}={int(value)}" for name, value in limits.items())
    launcher = [sys.executable, "-I", "-S", "-c", _LAUNCHER, spec, ",".join(ignore)]
    return [*launcher, *map(str, command)]
