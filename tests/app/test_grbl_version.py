"""GRBL's version as its banner and ``$I`` say it (report.c), and which one is kept."""

from __future__ import annotations

import pytest

from app.machines.gcode.grbl_version import kept, same_version, version_in


@pytest.mark.parametrize(
    ("line", "version"),
    [
        ("Grbl 1.1h ['$' for help]", "1.1h"),
        ("Grbl 0.9j ['$' for help]\r", "0.9j"),
        ("[VER:1.1h.20190825:]", "1.1h.20190825"),
        ("[VER:1.1h.20190825:StepDeck emulator]", "1.1h.20190825"),
        ("[OPT:V,15,128]", None),
        ("[MSG:'$H'|'$X' to unlock]", None),
        ("$110=6000.000", None),
        ("Grbl is great", None),  # no banner: the words are not the version
        ("ok", None),
    ],
)
def test_the_version_is_read_from_the_banner_and_the_ver_line(
    line: str, version: str | None
) -> None:
    assert version_in(line) == version


def test_a_banner_keeps_the_build_date_of_its_own_version_only() -> None:
    assert kept(None, "1.1h") == "1.1h"
    assert kept("1.1h", "1.1h.20190825") == "1.1h.20190825"
    assert kept("1.1h.20190825", "1.1h") == "1.1h.20190825"  # a reset's banner
    assert kept("1.1h.20190825", "1.1f") == "1.1f"  # another board now
    assert same_version("1.1h", "1.1h.20190825") and same_version("1.1h.20190825", "1.1h")
    assert not same_version("1.1h.20190825", "1.1f.20170801")
    assert not same_version("1.1", "1.1h")
