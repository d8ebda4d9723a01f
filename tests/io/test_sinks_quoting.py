"""The CSV writer's quick test of whether any text cell may need quotes."""

from __future__ import annotations

import pytest

from spinimpact.io._sinks import _structural_bytes

pa = pytest.importorskip("pyarrow")


@pytest.mark.parametrize("odd", [",", '"', "\r", "\n"])
def test_a_structural_character_is_found_only_within_the_slice(odd):
    cells = ["1.5", "-2", f"a{odd}b", "3e-3", "x", "7"]
    whole = pa.array(cells, pa.large_string())
    assert _structural_bytes(whole)
    assert not _structural_bytes(whole.slice(0, 2))  # before it
    assert not _structural_bytes(whole.slice(3))  # after it
    assert _structural_bytes(whole.slice(2, 1))
    assert _structural_bytes(pa.array(cells, pa.string()).slice(1, 3).cast(pa.large_string()))


def test_plain_text_empty_and_null_cells_need_no_quotes():
    assert not _structural_bytes(pa.array(["1", "", None, "abc"], pa.large_string()))
    assert not _structural_bytes(pa.array([], pa.large_string()))
    assert not _structural_bytes(pa.array([None, None], pa.large_string()))
