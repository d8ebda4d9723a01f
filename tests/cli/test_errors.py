"""The error vocabulary as the shell sees it: a wrong type, a bad value or a missing
optional package is one line on stderr and exit status 2, with no traceback.

A missing package is simulated honestly by hiding it: ``sys.modules[name] = None``
makes every ``import name`` raise ``ImportError``, as it would without the package.
"""

import signal
import subprocess
import sys

import pytest

import spinimpact
from spinimpact import Body
from spinimpact._validation import require
from spinimpact.cli import main


@pytest.fixture(autouse=True)
def _keep_sigterm():
    """``main`` installs a SIGTERM handler; give pytest its own back."""
    previous = signal.getsignal(signal.SIGTERM)
    yield
    signal.signal(signal.SIGTERM, previous)


def run_main(capsys, *args):
    """Run the command in this process; (exit status, stdout, stderr)."""
    with pytest.raises(SystemExit) as exit_:
        main([str(a) for a in args])
    out = capsys.readouterr()
    return exit_.value.code, out.out, out.err


def assert_one_line(status, stdout, stderr, needle):
    assert status == 2
    assert stdout == ""
    lines = stderr.strip().splitlines()
    assert len(lines) == 1, stderr
    assert lines[0].startswith("spinimpact: error: ")
    assert needle in lines[0]
    assert "Traceback" not in stderr


def test_missing_dask_is_one_line_exit_2(capsys, monkeypatch):
    monkeypatch.setitem(sys.modules, "distributed", None)
    result = run_main(
        capsys, "sweep", "--vx", "1", "--omega", "0", "--dask", "tcp://127.0.0.1:8786"
    )
    assert_one_line(*result, "--dask needs the optional extra: pip install 'spinimpact[dask]'")


@pytest.mark.parametrize("command", ["batch", "sweep"])
def test_missing_pyarrow_for_parquet_is_one_line_exit_2(capsys, monkeypatch, tmp_path, command):
    monkeypatch.setitem(sys.modules, "pyarrow", None)
    output = tmp_path / "out.parquet"
    if command == "batch":
        source = tmp_path / "in.csv"
        source.write_text("vx,vy,omega\n1,-1,0\n")
        args = ["batch", source, "--output", output]
    else:
        args = ["sweep", "--vx", "1", "--omega", "0", "--output", output]
    assert_one_line(*run_main(capsys, *args), "pip install 'spinimpact[parquet]'")
    assert not list(tmp_path.glob("out*"))  # nothing written, not even a temporary file


def test_import_error_from_require_is_one_line_exit_2(capsys, monkeypatch):
    """Any command reaching for an absent extra through ``require`` fails cleanly."""
    import spinimpact.cli.solve as solve_module

    monkeypatch.setitem(sys.modules, "numba", None)

    def needs_numba(options):
        require("numba", "the fast kernels")

    monkeypatch.setattr(solve_module, "solve_options", needs_numba)
    needle = "the fast kernels needs numba, which is not installed: pip install 'spinimpact[fast]'"
    assert_one_line(*run_main(capsys, "solve", "--json"), needle)


def test_type_error_is_one_line_exit_2(capsys, monkeypatch):
    """A value of the wrong type reaching the library (here a string for vx) is a
    TypeError; the shell reports it like a bad value."""
    import spinimpact.cli.solve as solve_module

    def wrong_type(options):
        return spinimpact.solve(
            Body.ring(mass=1.0, radius=0.1), "fast", -1.0, 0.0, mu=0.2, kappa=0.5
        )

    monkeypatch.setattr(solve_module, "solve_options", wrong_type)
    assert_one_line(*run_main(capsys, "solve", "--json"), "vx must be a real number")


def test_bugs_keep_their_traceback(capsys, monkeypatch):
    """Only the error vocabulary is translated: anything else is a bug and says so."""
    import spinimpact.cli.solve as solve_module

    def broken(options):
        raise KeyError("a bug")

    monkeypatch.setattr(solve_module, "solve_options", broken)
    with pytest.raises(KeyError):
        main(["solve", "--json"])


@pytest.mark.slow
def test_missing_package_in_a_fresh_process():
    """The installed command, end to end: dask hidden from a fresh interpreter."""
    code = (
        "import sys; sys.modules['distributed'] = None; from spinimpact.cli import main; "
        "main(['sweep', '--vx', '1', '--omega', '0', '--dask', 'tcp://127.0.0.1:8786'])"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=60)
    assert_one_line(out.returncode, out.stdout, out.stderr, "pip install 'spinimpact[dask]'")


@pytest.mark.parametrize("args", [["--help"], ["solve", "--json"], ["solve", "--help"]])
@pytest.mark.slow
def test_light_commands_import_neither_matplotlib_nor_rich(args):
    code = (
        "import sys; from spinimpact.cli import main; main(sys.argv[1:]); "
        "print(sorted(m for m in ('matplotlib', 'rich', 'pyarrow', 'scipy.integrate') "
        "if m in sys.modules), file=sys.stderr)"
    )
    out = subprocess.run(
        [sys.executable, "-c", code, *args], capture_output=True, text=True, timeout=60
    )
    assert out.returncode == 0, out.stderr
    assert out.stderr.strip() == "[]"


def test_simulate_plot_suffix_names_the_plot_option(capsys, tmp_path):
    status, out, err = run_main(capsys, "simulate", "--plot", str(tmp_path / "x.xyz"))
    assert_one_line(status, out, err, "--plot must end in .png, .svg or .pdf")


def test_an_extra_that_is_installed_but_fails_to_load_is_not_called_missing(monkeypatch):
    # Under ulimit -v a compiled library can fail to map: that is not "not installed".
    import importlib

    def fail(name, *args, **kwargs):
        raise ImportError("libarrow.so: failed to map segment from shared object")

    monkeypatch.setattr(importlib, "import_module", fail)
    with pytest.raises(ImportError, match="failed to map segment") as caught:
        require("pyarrow", "Parquet files")
    assert "not installed" not in str(caught.value)
