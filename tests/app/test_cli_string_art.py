"""``stepdeck string-art``: a photo in: the pair and a PNG out, read back as the dock reads jobs."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from PIL import Image

from app.__main__ import main
from app.jobs.formats.string_art.export import export_sd_files
from app.jobs.formats.string_art.program import StringArtProgram
from app.jobs.formats.string_art.reader import read_string_art
from app.jobs.loaders import load_job
from app.profiles import load_profile
from tests.helpers.string_art_images import face


@pytest.fixture
def photo(tmp_path: Path) -> Path:
    path = tmp_path / "face.jpg"
    Image.fromarray(np.round(face(240) * 255).astype(np.uint8)).save(path, quality=92)
    return path


def test_the_pair_and_png_are_written_and_read_back_as_a_job(
    photo: Path, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    out = tmp_path / "sd card"
    code = main(
        [
            "string-art",
            str(photo),
            "--board",
            "6,90,12",
            "--lines",
            "500",
            "--out",
            str(out),
            "--resolution",
            "96",
            "--png-size",
            "160",
        ]
    )
    printed = capsys.readouterr().out
    assert code == 0
    assert sorted(p.name for p in out.iterdir()) == ["param.txt", "poradi.txt", "string-art.png"]
    param = b"tvar = 6\npocet_hrebiku = 90\npolomer_matrice = 12.0\n"
    assert (out / "param.txt").read_bytes() == param
    job = read_string_art(out / "param.txt")
    raw = (out / "poradi.txt").read_bytes()
    assert raw == (",".join(map(str, (len(job.sequence), *job.sequence))) + "\n").encode()
    # Byte-compatible: the station's own SD export of the re-read job writes the same bytes.
    export_sd_files(job, tmp_path / "again")
    assert (tmp_path / "again" / "poradi.txt").read_bytes() == raw
    winder = load_profile("string-art")
    program = load_job(out / "poradi.txt", [axis.name for axis in winder.axes])
    assert isinstance(program, StringArtProgram) and program.job == job
    with Image.open(out / "string-art.png") as png:
        assert png.size == (160, 160) and png.mode == "L"
        pixels = np.asarray(png)
    assert pixels.min() < 128 and pixels[0, 0] == 255  # thread drawn; the corner is bare board
    lines = len(job.sequence) - 1
    assert f"lines: {lines} of 500" in printed
    assert "MAE 0." in printed and "SSIM" in printed and "s to generate" in printed


def test_an_unreadable_image_writes_nothing(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    fake = tmp_path / "photo.png"
    fake.write_bytes(b"\x89PNG but not really")
    out = tmp_path / "out"
    assert main(["string-art", str(fake), "--board", "0,60,10", "--out", str(out)]) == 2
    assert "photo.png" in capsys.readouterr().err
    assert not out.exists()


@pytest.mark.parametrize(
    ("board", "words"),
    [("0,60", "TVAR,NAILS,RADIUS_CM"), ("2,60,10", "tvar = 2"), ("0,60,1", "radius")],
)
def test_a_board_the_winder_cannot_have_is_refused(
    photo: Path, tmp_path: Path, capsys: pytest.CaptureFixture[str], board: str, words: str
) -> None:
    with pytest.raises(SystemExit) as stop:
        main(["string-art", str(photo), "--board", board, "--out", str(tmp_path / "o")])
    assert stop.value.code == 2
    assert words in capsys.readouterr().err
    assert not (tmp_path / "o").exists()


def test_a_skip_too_large_for_the_board_is_refused(
    photo: Path, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    with pytest.raises(SystemExit):
        main(
            [
                *("string-art", str(photo), "--board", "0,20,10"),
                *("--skip", "12", "--out", str(tmp_path / "o")),
            ]
        )
    assert "minimum skip 12" in capsys.readouterr().err
