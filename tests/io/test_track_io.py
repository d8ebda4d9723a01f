"""Reading camera tracks from CSV files: grouping into tracks, and bad files named by line."""

from __future__ import annotations

import numpy as np
import pytest

from spinimpact.io.tracks import read_tracks


def _write(tmp_path, text, name="tracks.csv"):
    path = tmp_path / name
    path.write_text(text)
    return path


def _rows(n=8, set_="a", trajectory=1, t0=0.0):
    t = t0 + 0.005 * np.arange(n)
    return "".join(f"{set_},{trajectory},{ti:.4f},{ti:.4f},0.0,{1 - ti:.4f}\n" for ti in t)


def test_rows_are_grouped_into_named_tracks_in_file_order(tmp_path):
    path = _write(tmp_path, "# a comment\nset,trajectory,t,x,y,z\n" + _rows(set_="b")
                  + _rows(set_="a", trajectory=3))  # fmt: skip
    tracks = read_tracks(path)
    assert [t.name for t in tracks] == ["b 1 (tracks.csv)", "a 3 (tracks.csv)"]
    assert tracks[0].rows.tolist() == list(range(3, 11))  # lines in the file
    assert tracks[1].position.shape == (8, 3)


def test_a_file_without_groups_is_one_track_named_by_the_file(tmp_path):
    lines = _rows().splitlines(True)
    path = _write(tmp_path, "t,x,y,z\n" + "".join(line.split(",", 2)[2] for line in lines))
    (track,) = read_tracks(path)
    assert track.name == "tracks (tracks.csv)"


@pytest.mark.parametrize(
    ("text", "message"),
    [
        ("t,x,y\n0,0,0\n", "missing column\\(s\\) z"),
        ("t,x,y,z,speed\n", "unknown column\\(s\\) speed"),
        ("t,x,y,z\n" + "0,0,0,1\n" * 3 + "0.1,0,zero,1\n", "line 5: column y is not a number"),
        ("t,x,y,z\n" + "".join(f"{i / 100},0,0,{i}\n" for i in (0, 1, 2, 2, 4, 5, 6)),
         "row 5: time does not increase"),
        ("t,x,y,z\n" + "".join(f"{i / 100},0,0,1\n" for i in range(3)), "3 sample\\(s\\)"),
        ("t,x,y,z\n" + "".join(f"{i / 100},0,0,{'nan' if i == 4 else 1}\n" for i in range(8)),
         "row 6: time or position is NaN"),
        ("", "empty file"),
    ],
)  # fmt: skip
def test_bad_files_name_the_file_and_the_line(tmp_path, text, message):
    with pytest.raises(ValueError, match=message):
        read_tracks(_write(tmp_path, text))
