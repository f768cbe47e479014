"""``stepdeck install-desktop``: the menu entry, icon and MIME types, for this user only."""

from __future__ import annotations

import io
import sys
from pathlib import Path

import pytest
from PySide6.QtGui import QImage

from app.__main__ import main as stepdeck
from app.cli import install_desktop
from app.resources import ICON, MIME_TYPES


def _entry(path: Path) -> dict[str, str]:
    lines = path.read_text(encoding="utf-8").splitlines()
    assert lines[0] == "[Desktop Entry]"
    return dict(line.split("=", 1) for line in lines[1:] if line)


def test_installs_entry_icon_and_mime_types_under_xdg_data_home(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    home = tmp_path / "data"
    monkeypatch.setenv("XDG_DATA_HOME", str(home))
    monkeypatch.setenv("HOME", str(tmp_path / "home"))  # nothing may land there
    out = io.StringIO()
    assert install_desktop.main([], out=out, err=io.StringIO()) == 0
    entry = _entry(home / "applications" / "stepdeck.desktop")
    command, _, argument = entry["Exec"].partition(" ")
    assert argument == "%f"  # a file manager hands it the job file
    assert Path(command).is_absolute() and Path(command).is_file()  # runs without PATH
    assert Path(command).parent == Path(sys.executable).parent
    assert entry["Icon"] == "stepdeck" and entry["Name"] == "StepDeck"
    icons = home / "icons" / "hicolor"
    assert (icons / "scalable" / "apps" / "stepdeck.svg").read_bytes() == ICON.read_bytes()
    for size in install_desktop.PNG_SIZES:
        image = QImage(str(icons / f"{size}x{size}" / "apps" / "stepdeck.png"))
        assert (image.width(), image.height()) == (size, size)
        assert image.pixelColor(size // 2, size // 2).alpha() == 255  # drawn, not blank
    assert (home / "mime" / "packages" / "stepdeck.xml").read_bytes() == MIME_TYPES.read_bytes()
    assert str(home / "applications" / "stepdeck.desktop") in out.getvalue()
    assert not (tmp_path / "home").exists()

    assert install_desktop.main(["--remove"], out=out, err=io.StringIO()) == 0
    assert not [p for p in home.rglob("stepdeck*") if p.is_file()]


def test_the_station_command_runs_it(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("XDG_DATA_HOME", str(tmp_path))
    assert stepdeck(["install-desktop"]) == 0
    assert (tmp_path / "applications" / "stepdeck.desktop").is_file()


@pytest.mark.parametrize("value", ["", "relative/share"])
def test_an_unset_or_relative_xdg_data_home_means_local_share(value: str) -> None:
    # The base directory specification: a relative path there is invalid and ignored.
    home = install_desktop.data_home({"XDG_DATA_HOME": value})
    assert home == Path.home() / ".local" / "share"


@pytest.mark.parametrize(
    ("command", "exec_value"),
    [
        ("/opt/stepdeck/bin/stepdeck", "/opt/stepdeck/bin/stepdeck"),
        ("/home/a b/venv/bin/stepdeck", '"/home/a b/venv/bin/stepdeck"'),
        ("/srv/$x/100%/stepdeck", '"/srv/\\\\$x/100%%/stepdeck"'),
    ],
)
def test_the_command_is_quoted_as_the_desktop_entry_specification_asks(
    command: str, exec_value: str
) -> None:
    assert install_desktop.exec_argument(command) == exec_value


def test_a_wrong_option_is_a_usage_error() -> None:
    err = io.StringIO()
    assert install_desktop.main(["--everything"], out=io.StringIO(), err=err) == 1
    assert "unrecognized arguments" in err.getvalue()
