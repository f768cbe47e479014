"""What the operator reads when things go wrong, in Czech and Slovak: nothing left in English.

The walk over every widget (test_i18n_every_widget) sees the window as a job
runs; this drives the paths that end in a message instead: a move refused at
the travel's end, a motion fault (a corrupted move the supervision stops), a
GRBL alarm, and a lost link.  Every message the station sends the operator
(status bar and jobs dock), the status bar at the end, and the developer
pane's decoded frames are read, and a word of English or a decimal point in
them fails the test, as in the walk.
"""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import pytest
from PySide6.QtWidgets import QApplication
from pytestqt.qtbot import QtBot

from app import i18n
from app.profiles import available_profiles, load_profile
from protocol.stage.codec import CommandId
from protocol.transport.loopback import Direction
from protocol.usb3.codec import StepSize
from tests.helpers.harness import StationHarness
from tests.widgets.test_i18n_every_widget import WORD, decimal_points, english_words
from widgets.main_window import MainWindow


@pytest.fixture(autouse=True)
def english_after(qapp: object, i18n_cache: Path) -> Iterator[None]:
    """The language this test installs does not follow the tests that come after it."""
    yield
    i18n.install("en", i18n_cache)


def _corrupt_usb3_moves(direction: Direction, data: bytes) -> bytes:
    """A noisy cable: a usb3 move of 3200 counts arrives as one of a million more."""
    if direction is Direction.TO_DEVICE:
        return data.replace(b"X000000000003200;", b"X000001000003200;")
    return data


@pytest.mark.parametrize("language", ["cs", "sk"])
@pytest.mark.parametrize("profile", available_profiles())
def test_refusals_faults_alarms_and_a_lost_link_are_told_in_the_language(
    qtbot: QtBot, i18n_cache: Path, tmp_path: Path, profile: str, language: str
) -> None:
    i18n.install(language, i18n_cache)
    harness = StationHarness(load_profile(profile))
    station = harness.station
    said: list[tuple[str, str]] = []
    moment = ["connect"]
    station.model.message.connect(lambda text: said.append((moment[0], text)))
    names = set(WORD.findall(f"{tmp_path} {available_profiles()}"))
    names |= {command.name for command in CommandId}  # the stage's wire commands, as named
    try:
        window = MainWindow(station, checkpoint_dir=tmp_path / "checkpoints")
        qtbot.addWidget(window)
        window.show()
        window.developer_pane.show()
        harness.connect()
        harness.run(1.5)
        session = station.session
        assert session is not None

        moment[0] = "a move past the travel"
        linear = next(i for i, a in enumerate(station.profile.axes) if a.kind != "rotary")
        travel = station.profile.axes[linear].travel
        said_before = len(said)
        assert not session.move_absolute(linear, travel + 50.0)
        harness.run(0.5)
        assert len(said) > said_before, "the refusal was not told"

        if profile == "usb3":
            moment[0] = "a motion fault"
            usb3 = harness.usb3_session
            usb3.set_step_size(0, StepSize.FULL)
            harness.run(0.3)
            harness.loopback.set_manipulator(_corrupt_usb3_moves)
            assert usb3.move_relative(0, 0.5)
            harness.run(3.0)
            harness.loopback.set_manipulator(None)
            assert any(m == moment[0] for m, _ in said), "no fault was told"
            moment[0] = "less than one step"
            assert not usb3.move_relative(0, 1e-6)
        if station.profile.dialect == "gcode":
            moment[0] = "an alarm"
            harness.gcode_emulator.trigger_alarm(1)
            harness.run(1.0)
            assert any(m == moment[0] for m, _ in said), "the alarm was not told"

        moment[0] = "a lost link"
        harness.loopback.sever("cable pulled")
        harness.run(2.0)
        assert any(m == moment[0] for m, _ in said), "the lost link was not told"
        QApplication.processEvents()
        said.append(("status bar at the end", window.statusBar().currentMessage()))
        for entry in window.frame_log.entries:
            said.append(("developer pane, decoded", entry.decoded))
    finally:
        harness.close()
    found: dict[str, str] = {}
    for where, text in said:
        checked = text.replace("cable pulled", " ")  # the reason is the test's own
        words = english_words(checked, language, names)
        points = decimal_points(checked)
        if words or points:
            found.setdefault(f"{text!r} {words} {points}", where)
    listed = "\n".join(f"{text}  ({where})" for text, where in sorted(found.items()))
    assert not found, f"{len(found)} texts still in English ({language}, {profile}):\n{listed}"
