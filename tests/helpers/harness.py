"""A station wired to the emulator on a manual clock, driven step by step.

Tests move time with :meth:`StationHarness.run`: each control step advances
the clock, fires the session's periodic tick when a period has elapsed, runs
the emulator up to the present and lets Qt deliver what that produced.  No
sleeps, no real timers: the outcome depends only on the steps taken.
"""

from __future__ import annotations

from collections.abc import Callable

from PySide6.QtWidgets import QApplication

from app.machines.drill.session import DrillSession
from app.machines.gcode.session import GcodeSession
from app.machines.stage.session import StageSession
from app.machines.usb3.session import Usb3Session
from app.profiles import MachineProfile, load_profile
from app.station import Station
from protocol.clock import ManualClock
from protocol.emulator.drill_firmware import DrillFirmware
from protocol.emulator.gcode_firmware import GcodeFirmware
from protocol.emulator.stage_firmware import StageFirmware
from protocol.emulator.usb3_firmware import Usb3Firmware
from protocol.transport.loopback import LoopbackTransport

STEP_S = 0.005


class StationHarness:
    def __init__(self, profile: MachineProfile | None = None) -> None:
        self.clock = ManualClock()
        self.station = Station(profile or load_profile("xy-stage"), self.clock, realtime=False)
        self.written: list[bytes] = []
        self._next_tick = 0.0
        # Hook each new link before it opens, so the frames sent at connect are recorded too.
        self.station.sessionChanged.connect(self._record_link)

    def connect(self, *, wait_for_answer: bool = True) -> None:
        """Open the emulator link; by default also step until the device has answered.

        "Connected" means the device answered in its dialect, so motion stays
        locked until then; tests that look at that first moment pass False.
        """
        self.station.connect_emulator()
        session = self.station.session
        assert session is not None
        self._next_tick = self.clock.now() + session.period_ms / 1000
        if wait_for_answer:
            self.run_until(lambda: session.device_answered, timeout=5.0)

    def _record_link(self) -> None:
        if self.station.link is not None:
            self.station.link.dataSent.connect(self.written.append)

    @property
    def session(self) -> StageSession:
        session = self.station.stage_session
        assert session is not None, "not connected to a stage"
        return session

    @property
    def usb3_session(self) -> Usb3Session:
        session = self.station.usb3_session
        assert session is not None, "not connected to a usb3 unit"
        return session

    @property
    def drill_session(self) -> DrillSession:
        session = self.station.drill_session
        assert session is not None, "not connected to a drill"
        return session

    @property
    def gcode_session(self) -> GcodeSession:
        session = self.station.gcode_session
        assert session is not None, "not connected to a G-code machine"
        return session

    @property
    def gcode_emulator(self) -> GcodeFirmware:
        emulator = self.station.gcode_emulator
        assert emulator is not None, "no emulated G-code machine"
        return emulator

    @property
    def emulator(self) -> StageFirmware:
        emulator = self.station.stage_emulator
        assert emulator is not None, "no emulated stage"
        return emulator

    @property
    def usb3_emulator(self) -> Usb3Firmware:
        emulator = self.station.usb3_emulator
        assert emulator is not None, "no emulated usb3 unit"
        return emulator

    @property
    def drill_emulator(self) -> DrillFirmware:
        emulator = self.station.drill_emulator
        assert emulator is not None, "no emulated drill"
        return emulator

    @property
    def loopback(self) -> LoopbackTransport:
        transport = self.station.loopback
        assert transport is not None
        return transport

    def step(self, seconds: float = STEP_S) -> None:
        self.clock.advance(seconds)
        session = self.station.session
        if session is not None and self.clock.now() >= self._next_tick - 1e-9:
            self._next_tick += session.period_ms / 1000
            session.tick()
        self.station.poll()
        if self.station.loopback is not None:
            self.station.loopback.pump()
        QApplication.processEvents()

    def run(self, seconds: float) -> None:
        for _ in range(round(seconds / STEP_S)):
            self.step()

    def hold(self, seconds: float, every: float = 0.1) -> None:
        """Run while the operator holds a jog: the key's auto-repeat keeps the dead-man fed."""
        steps_between = max(1, round(every / STEP_S))
        for i in range(round(seconds / STEP_S)):
            self.step()
            session = self.station.session
            if session is not None and i % steps_between == 0:
                session.keep_jogging()

    def run_until(self, condition: Callable[[], bool], timeout: float = 30.0) -> float:
        """Step until ``condition`` holds; returns the emulated time it took."""
        start = self.clock.now()
        while not condition():
            if self.clock.now() - start > timeout:
                raise AssertionError(f"condition not met within {timeout} emulated seconds")
            self.step()
        return self.clock.now() - start

    def close(self) -> None:
        self.station.shutdown()
