"""The jog state machine (app/jog_state.py) without a widget: keys are plain numbers mapped to
an axis and a direction, and the mouse's state is told, as the window's event plumbing does.
"""

from __future__ import annotations

import pytest

from app.jog_state import JogState
from tests.helpers.harness import StationHarness

RIGHT, LEFT, UP, RAISE = 1, 2, 3, 4
KEYS = {RIGHT: (0, +1), LEFT: (0, -1), UP: (1, +1), RAISE: (2, +1)}


@pytest.fixture
def harness(harness: StationHarness) -> StationHarness:
    """The shared harness (the XY stage on a test clock), connected."""
    harness.connect()
    harness.run(1.5)
    return harness


@pytest.fixture
def jog(harness: StationHarness) -> JogState:
    return JogState(harness.station, KEYS)


def test_any_key_numbers_jog_the_axes_they_are_mapped_to(
    harness: StationHarness, jog: JogState
) -> None:
    vectors: list[tuple[int, ...]] = []
    jog.vectorChanged.connect(vectors.append)
    assert jog.key_press(RIGHT) and jog.key_press(UP)
    assert harness.session.jog_vector == (1, 1)
    assert jog.key_release(RIGHT)
    assert harness.session.jog_vector == (0, 1) == jog.vector
    assert not jog.key_press(99)  # not a jog key: the caller handles it
    assert not jog.is_jog_key(RAISE)  # a Z key on a machine without Z
    assert vectors == [(1, 0), (1, 1), (0, 1)]


def test_opposite_keys_cancel_and_a_button_adds_without_cancelling_a_key(
    harness: StationHarness, jog: JogState
) -> None:
    jog.key_press(RIGHT)
    jog.key_press(LEFT)
    assert harness.session.jog_vector == (0, 0)
    assert jog.button_press("up", (0, 1))
    jog.key_release(LEFT)
    jog.button_release("up")
    assert harness.session.jog_vector == (1, 0)  # the key still held goes on


def test_a_key_release_that_never_comes_is_let_go_when_the_session_ends_the_jog(
    harness: StationHarness, jog: JogState
) -> None:
    ended: list[str] = []
    keys: list[tuple[int, ...]] = []
    harness.session.jogEnded.connect(ended.append)
    jog.keysChanged.connect(keys.append)
    jog.key_press(RIGHT)  # and neither a repeat nor the release ever comes
    harness.run_until(lambda: bool(ended), timeout=5)
    assert jog.vector == (0, 0) and not jog.is_held(RIGHT)
    assert keys[-1] == (0, 0)  # the key's on-screen button no longer shows pressed
    assert jog.key_press(RIGHT)  # the next press is a new jog, not a key "already held"
    assert harness.session.jog_vector == (1, 0)


def test_repeats_keep_a_held_key_jogging(harness: StationHarness, jog: JogState) -> None:
    ended: list[str] = []
    harness.session.jogEnded.connect(ended.append)
    jog.key_press(UP)
    for _ in range(30):
        harness.run(0.1)
        assert jog.key_repeat(UP)
    assert not ended and harness.session.jog_vector == (0, 1)
    assert not jog.key_repeat(RIGHT)  # a repeat of a key not held is not ours


def test_the_mouse_told_held_keeps_a_button_jogging_and_let_go_ends_it(
    harness: StationHarness, jog: JogState
) -> None:
    ended: list[str] = []
    harness.session.jogEnded.connect(ended.append)
    jog.button_press("right", (1, 0))
    for _ in range(15):
        harness.run(0.2)
        assert jog.poll_buttons(mouse_held=True)
    assert not ended and harness.session.jog_vector == (1, 0)
    # The button's release is lost (the pointer left the window): the mouse says let go.
    harness.run_until(lambda: bool(ended) or not jog.poll_buttons(mouse_held=False), timeout=5)
    assert ended and jog.vector == (0, 0)
    assert not jog.poll_buttons(mouse_held=True)  # nothing held: stop looking


def test_a_tap_in_step_mode_moves_one_step_and_repeats_add_none(
    harness: StationHarness, jog: JogState
) -> None:
    jog.set_key_step(1.0)
    before = len(harness.written)
    assert jog.key_press(RIGHT)
    sent = len(harness.written)
    assert sent > before and harness.session.jog_vector == (0, 0)  # a step, not a held jog
    assert jog.key_repeat(RIGHT) and jog.key_press(RIGHT)
    assert len(harness.written) == sent  # held down: still the one step
    assert jog.is_held(RIGHT)
    assert jog.key_release(RIGHT) and not jog.is_held(RIGHT)


def test_locked_input_holds_nothing_and_says_why(harness: StationHarness, jog: JogState) -> None:
    said: list[str] = []
    harness.station.model.message.connect(said.append)
    jog.key_press(RIGHT)
    jog.set_enabled(False, "a job is running")
    assert harness.session.jog_vector == (0, 0)
    assert jog.key_press(UP)  # a jog key, refused: not somebody else's key
    assert not jog.button_press("up", (0, 1))
    assert harness.session.jog_vector == (0, 0)
    assert said.count("Jog refused: a job is running") == 2
    jog.set_enabled(True)
    jog.key_press(UP)
    assert harness.session.jog_vector == (0, 1)


def test_stop_is_announced_before_the_session_stops(harness: StationHarness, jog: JogState) -> None:
    order: list[str] = []
    jog.stopRequested.connect(lambda: order.append(f"requested {harness.session.jog_vector}"))
    jog.key_press(RIGHT)
    jog.stop_all()
    assert order == ["requested (1, 0)"]
    assert harness.session.jog_vector == (0, 0) and not jog.is_held(RIGHT)
