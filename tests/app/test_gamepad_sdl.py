"""The gamepad through SDL itself, on SDL's virtual game controller (no hardware, no display):
the stick pushed jogs the emulated GRBL plotter, released or unplugged stops it, the dead
zone moves nothing, and a running job refuses it.

SDL's joystick subsystem needs no video driver; the virtual controller has SDL's standard
layout (left stick = axes 0 and 1, right stick's vertical = axis 3, shoulders = buttons 9
and 10).
"""

from __future__ import annotations

import os
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest
from pytestqt.qtbot import QtBot

from app.gamepad.poller import GamepadJog, PadState
from app.gamepad.sdl import SdlPadSource, load_sdl
from app.jobs.run.runner import JobRunner, JobState
from app.jog_state import JogState
from app.profiles import load_profile
from tests.app.test_job_runner_gcode import square_program
from tests.helpers.harness import StationHarness

# Headless: no window system for SDL, and only the virtual device (no HID scan of the host).
os.environ.setdefault("SDL_VIDEODRIVER", "dummy")
os.environ.setdefault("SDL_JOYSTICK_HIDAPI", "0")

FULL = 32767
LEFT_X, LEFT_Y = 0, 1
LEFT_SHOULDER = 9


class VirtualPad:
    """SDL's virtual game controller, attached for one test."""

    def __init__(self, sdl: Any) -> None:
        self.sdl = sdl
        self.index = sdl.SDL_JoystickAttachVirtual(sdl.SDL_JOYSTICK_TYPE_GAMECONTROLLER, 6, 15, 0)
        assert self.index >= 0, sdl.SDL_GetError()
        self.name = sdl.SDL_JoystickNameForIndex(self.index).decode()
        # The virtual device's values are set through a joystick opened on it.
        self.handle = sdl.SDL_JoystickOpen(self.index)
        assert self.handle
        self.attached = True

    def axis(self, axis: int, value: int) -> None:
        assert self.sdl.SDL_JoystickSetVirtualAxis(self.handle, axis, value) == 0

    def button(self, button: int, down: bool) -> None:
        assert self.sdl.SDL_JoystickSetVirtualButton(self.handle, button, int(down)) == 0

    def detach(self) -> None:
        if self.attached:
            self.attached = False
            self.sdl.SDL_JoystickClose(self.handle)
            index = next(
                i for i in range(self.sdl.SDL_NumJoysticks()) if self.sdl.SDL_JoystickIsVirtual(i)
            )
            assert self.sdl.SDL_JoystickDetachVirtual(index) == 0


@pytest.fixture
def pad() -> Iterator[VirtualPad]:
    virtual = VirtualPad(load_sdl())
    yield virtual
    virtual.detach()


@pytest.fixture
def grbl(qtbot: QtBot) -> Iterator[StationHarness]:
    harness = StationHarness(load_profile("grbl-plotter"))
    harness.connect()
    harness.run(1.0)
    yield harness
    harness.close()


@pytest.fixture
def poller(grbl: StationHarness, pad: VirtualPad) -> Iterator[GamepadJog]:
    jog = JogState(grbl.station, {})
    built = GamepadJog(grbl.station, jog, source_factory=SdlPadSource, poll_ms=None)
    built.set_device(pad.name)
    built.set_enabled(True)
    assert built.state is PadState.CONNECTED
    yield built
    built.shutdown()


def hold(harness: StationHarness, poller: GamepadJog, seconds: float) -> None:
    for _ in range(round(seconds / 0.04)):
        harness.run(0.04)
        poller.poll()


def jog_lines(harness: StationHarness, since: int) -> list[bytes]:
    return [w for w in harness.written[since:] if w.startswith(b"$J=")]


def test_the_stick_jogs_on_the_wire_and_its_release_stops(
    grbl: StationHarness, pad: VirtualPad, poller: GamepadJog
) -> None:
    before = len(grbl.written)
    pad.button(LEFT_SHOULDER, True)
    pad.axis(LEFT_X, FULL)
    poller.poll()
    assert grbl.gcode_session.jog_vector == (1, 0)
    lines = jog_lines(grbl, before)
    assert lines and b"X" in lines[0] and b"-" not in lines[0]
    hold(grbl, poller, 1.5)
    assert grbl.gcode_session.jog_vector == (1, 0)  # held past the dead-man's second
    moved = grbl.station.model.axes[0].position
    assert moved > 10
    released = len(grbl.written)
    pad.axis(LEFT_X, 0)
    poller.poll()
    assert grbl.gcode_session.jog_vector == (0, 0)
    assert b"\x85" in b"".join(grbl.written[released:])
    grbl.run_until(lambda: grbl.gcode_emulator.state == "Idle", timeout=5)
    stopped = grbl.gcode_emulator.position()["X"]
    hold(grbl, poller, 0.5)
    assert grbl.gcode_emulator.position()["X"] == stopped
    assert not jog_lines(grbl, released + 1)


def test_pushed_away_jogs_y_positive_and_without_enable_nothing(
    grbl: StationHarness, pad: VirtualPad, poller: GamepadJog
) -> None:
    pad.axis(LEFT_Y, -FULL)  # SDL's up is negative
    hold(grbl, poller, 0.2)
    assert grbl.gcode_session.jog_vector == (0, 0)  # no enable button
    pad.button(LEFT_SHOULDER, True)
    poller.poll()
    assert grbl.gcode_session.jog_vector == (0, 1)


def test_unplugged_mid_jog_stops_at_once(
    grbl: StationHarness, pad: VirtualPad, poller: GamepadJog
) -> None:
    pad.button(LEFT_SHOULDER, True)
    pad.axis(LEFT_X, -FULL)
    poller.poll()
    hold(grbl, poller, 0.5)
    assert grbl.gcode_session.jog_vector == (-1, 0)
    before = len(grbl.written)
    pad.detach()
    poller.poll()
    assert grbl.gcode_session.jog_vector == (0, 0)
    assert b"\x85" in b"".join(grbl.written[before:])
    assert poller.state is PadState.SEARCHING


def test_a_push_inside_the_dead_zone_sends_nothing(
    grbl: StationHarness, pad: VirtualPad, poller: GamepadJog
) -> None:
    before = len(grbl.written)
    pad.button(LEFT_SHOULDER, True)
    pad.axis(LEFT_X, FULL // 5)  # 0.2 of full: a worn stick at rest
    pad.axis(LEFT_Y, -FULL // 5)
    hold(grbl, poller, 1.0)
    assert grbl.gcode_session.jog_vector == (0, 0)
    assert not jog_lines(grbl, before)


def test_a_running_job_refuses_the_stick(
    grbl: StationHarness, pad: VirtualPad, poller: GamepadJog, tmp_path: Path
) -> None:
    said: list[str] = []
    grbl.station.model.message.connect(said.append)
    runner = JobRunner(grbl.station, tmp_path / "checkpoints")
    assert runner.load(square_program()) == []
    runner.start()
    grbl.run(0.5)
    assert runner.state is JobState.RUNNING
    before = len(grbl.written)
    pad.button(LEFT_SHOULDER, True)
    pad.axis(LEFT_X, FULL)
    hold(grbl, poller, 0.5)
    assert not jog_lines(grbl, before)
    assert b"\x85" not in b"".join(grbl.written[before:])
    assert len([m for m in said if m.startswith("Jog refused")]) == 1
    runner.abort()
    runner.deleteLater()
