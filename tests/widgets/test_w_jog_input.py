"""The jog input: held keys and buttons merged into one vector, sent at once, let go together."""

from __future__ import annotations

import pytest
from PySide6.QtCore import Qt

from tests.helpers.harness import StationHarness
from widgets.jog_input import JogInput

RIGHT, LEFT, UP, DOWN = Qt.Key.Key_Right, Qt.Key.Key_Left, Qt.Key.Key_Up, Qt.Key.Key_Down


@pytest.fixture
def harness(harness: StationHarness) -> StationHarness:
    """The shared harness, connected."""
    harness.connect()
    harness.run(1.5)
    return harness


@pytest.fixture
def jog(harness: StationHarness) -> JogInput:
    return JogInput(harness.station)


def test_keys_make_axes_and_diagonals(harness: StationHarness, jog: JogInput) -> None:
    jog.key_press(RIGHT)
    assert harness.session.jog_vector == (1, 0)
    jog.key_press(DOWN)
    assert harness.session.jog_vector == (1, -1)
    jog.key_release(RIGHT)
    assert harness.session.jog_vector == (0, -1)
    jog.key_press(LEFT)
    assert harness.session.jog_vector == (-1, -1)
    jog.key_release(LEFT)
    jog.key_release(DOWN)
    assert harness.session.jog_vector == (0, 0)


def test_every_change_goes_out_at_once(harness: StationHarness, jog: JogInput) -> None:
    before = len(harness.written)
    jog.key_press(UP)
    assert len(harness.written) == before + 1
    jog.key_press(UP)  # already held: nothing new to say
    assert len(harness.written) == before + 1
    jog.key_release(UP)
    assert len(harness.written) == before + 2


def test_buttons_and_keys_do_not_cancel_each_other(harness: StationHarness, jog: JogInput) -> None:
    jog.button_press("y+", (0, 1))
    jog.key_press(UP)
    jog.button_release("y+")
    assert harness.session.jog_vector == (0, 1)
    jog.button_press("x+", (1, 0))
    jog.key_release(UP)
    assert harness.session.jog_vector == (1, 0)
    jog.button_release("x+")
    assert harness.session.jog_vector == (0, 0)


def test_release_all_lets_go_of_everything(harness: StationHarness, jog: JogInput) -> None:
    jog.key_press(RIGHT)
    jog.button_press("y+", (0, 1))
    jog.set_shift(True)
    harness.run(0.5)
    jog.release_all()
    assert harness.session.jog_vector == (0, 0)
    assert not jog.is_held(RIGHT)
    harness.run(0.3)
    assert harness.emulator.snapshot().fast[0]  # Shift forgotten too
    jog.key_release(RIGHT)  # the late key-up changes nothing
    jog.button_release("y+")
    assert harness.session.jog_vector == (0, 0)


def test_shift_selects_the_other_speed(harness: StationHarness, jog: JogInput) -> None:
    assert harness.emulator.snapshot().fast[0]
    jog.set_shift(True)
    harness.run(0.1)
    assert not harness.emulator.snapshot().fast[0]
    jog.set_shift(False)
    harness.run(0.1)
    assert harness.emulator.snapshot().fast[0]


def test_disabled_input_holds_nothing(harness: StationHarness, jog: JogInput) -> None:
    jog.key_press(RIGHT)
    jog.set_enabled(False)
    assert harness.session.jog_vector == (0, 0)
    assert jog.key_press(LEFT)  # still a jog key, so the window swallows it
    jog.button_press("x+", (1, 0))
    assert harness.session.jog_vector == (0, 0)
    jog.set_enabled(True)
    assert harness.session.jog_vector == (0, 0)


def test_z_keys_are_not_jog_keys_on_an_xy_stage(jog: JogInput) -> None:
    assert not jog.is_jog_key(Qt.Key.Key_PageUp)
    assert not jog.key_press(Qt.Key.Key_PageUp)
    assert jog.is_jog_key(RIGHT)


def test_stop_all_forgets_held_keys(harness: StationHarness, jog: JogInput) -> None:
    jog.key_press(RIGHT)
    harness.run(0.5)
    jog.stop_all()
    harness.run_until(lambda: not harness.station.model.any_moving, timeout=2)
    assert harness.station.model.axes[0].status_text == "stopped"
    assert jog.vector == (0, 0)
