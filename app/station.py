"""The station: one machine profile, its model, its link and the dialect session.

Widgets get a Station and talk to ``station.session`` for intents and to
``station.model`` for state; they never see a transport.  The built-in
emulator is created here, behind the loopback transport, so the rest of the
app is the same whether the device is real or emulated.

The station also owns reconnection: when the transport reports an error
(the port pulled, the BLE link dropped) it opens it again with back-off, on
its own clock, so the operator never has to, and the session re-reads the
device when it is back.  A device that merely falls silent while its port
stays open is not reopened: reopening a USB board's port restarts many of
them, and their position with it.  The session keeps asking it instead
(:meth:`MachineSession._lost_to_silence`) and says, once it answers, whether
its state is intact.

Closing a link on the operator's word (Disconnect, closing the window) first
stops every axis and waits — on the event loop, never blocking it — up to
:data:`STOP_CONFIRM_S` for the device to report its axes still, then closes:
a move must not run on with nobody left to stop it.  A machine without a stop
command (the drill) has its queue dropped and is closed at once; its running
procedure finishes, and the operator is told so.
"""

from __future__ import annotations

import dataclasses
import sys
from typing import TYPE_CHECKING, TypeVar, cast

from PySide6.QtCore import QCoreApplication, QObject, QTimer, Signal

from app.discovery import ble_uuids_for
from app.link import Link
from app.machine import LinkState, MachineModel
from app.machines.drill.conversion import DrillConversion
from app.machines.registry import DIALECTS, dialect_for
from app.machines.session import MachineSession
from app.machines.stage.echoes import StageEchoes
from app.machines.stage.session import StageSession
from app.profiles import MachineProfile
from protocol.clock import Clock, MonotonicClock
from protocol.drill.timing import DrillTiming
from protocol.emulator.device import EmulatedDevice
from protocol.stage.codec import EchoFrame
from protocol.transport.base import Transport
from protocol.transport.loopback import LoopbackTransport
from protocol.transport.serial_link import SerialTransport

if TYPE_CHECKING:
    from protocol.transport.ble import BleLoop, BleTransport

SessionT = TypeVar("SessionT", bound=MachineSession)
EmulatorT = TypeVar("EmulatorT", bound=EmulatedDevice)

RECONNECT_DELAYS = (0.5, 1.0, 2.0, 4.0)
POLL_MS = 100
#: The longest Disconnect or closing the window waits for the device to confirm the stop:
#: the stage brakes from its default 10 mm/s at 20 mm/s² in 0.5 s, and says so in its next
#: echo; a G-code board's hold takes about as long.
STOP_CONFIRM_S = 1.0
#: How often the wait looks at the device's reports (in real time).
STOP_CHECK_MS = 20


class Station(QObject):
    sessionChanged = Signal()
    echoInjected = Signal(object)  # EchoFrame, for the frame log
    #: A link was closed on the operator's word (after the stop, when one was awaited).
    linkClosed = Signal()
    #: The drill's timing constants changed (:meth:`set_drill_timing`): estimates are stale.
    drillTimingChanged = Signal()
    #: The drill's conversion constants changed (:meth:`set_drill_conversion`): a loaded job
    #: is read again with them.
    drillConversionChanged = Signal()

    def __init__(
        self,
        profile: MachineProfile,
        clock: Clock | None = None,
        *,
        realtime: bool = True,
        parent: QObject | None = None,
    ) -> None:
        super().__init__(parent)
        self.dialect = dialect_for(profile)
        self.profile = profile
        self.clock: Clock = clock or MonotonicClock()
        self.realtime = realtime
        self.model = MachineModel(profile, self)
        self.link: Link | None = None
        self.session: MachineSession | None = None
        self.emulator: EmulatedDevice | None = None
        self.period_ms = profile.period_ms
        #: How a job's millimetres become the drill's microsteps (FIDELITY S2-42): the
        #: profile's until the teacher changes them.
        self.drill_conversion = DrillConversion.of_profile(profile.axes)
        self.reconnect_delays: tuple[float, ...] = RECONNECT_DELAYS
        self._attempt = 0
        self._reconnect_at: float | None = None
        self._closing = False
        self._ble_loop: BleLoop | None = None
        self._detached_echoes = StageEchoes(self.model, self.clock)
        self._poll = QTimer(self)
        self._poll.setInterval(POLL_MS)
        self._poll.timeout.connect(self.poll)
        #: Station-clock time by which the device must have confirmed the stop, while waiting.
        self._stop_deadline: float | None = None
        self._stop_check = QTimer(self)
        self._stop_check.setInterval(STOP_CHECK_MS)
        self._stop_check.timeout.connect(self._check_stop)

    @property
    def loopback(self) -> LoopbackTransport | None:
        transport = self.link.transport if self.link else None
        return transport if isinstance(transport, LoopbackTransport) else None

    def session_as(self, kind: type[SessionT]) -> SessionT | None:
        """The session when it is a ``kind`` (the stage's dynamics, the drill's terminal…).

        A panel that belongs to one dialect asks for that dialect's session by its
        class, so the station names no dialect and a new one adds nothing here.
        """
        return self.session if isinstance(self.session, kind) else None

    def emulator_as(self, kind: type[EmulatorT]) -> EmulatorT | None:
        """The built-in emulator when it is a ``kind`` (the developer pane's controls).

        The caller names the class, so it has imported its module: the station
        itself imports no emulator until one is made (:mod:`app.machines.registry`).
        """
        return self.emulator if isinstance(self.emulator, kind) else None

    if not TYPE_CHECKING:

        def __getattr__(self, name: str) -> object:
            """``<dialect>_session`` / ``<dialect>_emulator``: the tests' and scripts' short
            names, looked up in the registry (the session or emulator when this station
            speaks that dialect, else None).

            Hidden from the type checker: typed code says :meth:`session_as` or
            :meth:`emulator_as`, so a misspelt attribute stays an error there.
            """
            prefix, _, part = name.rpartition("_")
            entry = DIALECTS.get(prefix)
            if entry is not None and part == "session":
                return self.session_as(entry.session_type)
            if entry is not None and part == "emulator":
                # The station's emulator is always its own dialect's (connect_emulator).
                own = issubclass(self.dialect.session_type, entry.session_type)
                return self.emulator if own else None
            raise AttributeError(f"{type(self).__name__!r} object has no attribute {name!r}")

    @property
    def device_id(self) -> str | None:
        """What to remember as "the last used device": port path or BLE address."""
        transport = self.link.transport if self.link else None
        ble = sys.modules.get("protocol.transport.ble")  # imported with the first BLE link
        if ble is not None and isinstance(transport, ble.BleTransport):
            ble_transport = cast("BleTransport", transport)
            device = ble_transport.device
            return device.address if device else ble_transport.address
        if isinstance(transport, SerialTransport):
            return transport.port
        return None

    @property
    def transport_kind(self) -> str | None:
        """Which kind of link is open: "emulator", "serial" or "ble" (None: none, or another)."""
        transport = self.link.transport if self.link else None
        if transport is None:
            return None
        if isinstance(transport, LoopbackTransport):
            return "emulator"
        if isinstance(transport, SerialTransport):
            return "serial"
        ble = sys.modules.get("protocol.transport.ble")  # imported with the first BLE link
        if ble is not None and isinstance(transport, ble.BleTransport):
            return "ble"
        return None

    @property
    def reconnect_due(self) -> float | None:
        """Clock time of the next reconnection attempt, None when none is planned."""
        return self._reconnect_at

    def inject_echo(self, echo: EchoFrame) -> None:
        """Fold an echo into the model as if the device had sent it (developer pane).

        With a session it goes through the session (and counts as a sign of
        life); without a link it still reaches the model, so the panels can be
        exercised with nothing connected.
        """
        stage = self.session_as(StageSession)
        if stage is not None:
            stage.apply_echo(echo)
        else:
            self._detached_echoes.apply(echo)
        self.echoInjected.emit(echo)

    # --- choosing a link -----------------------------------------------------

    def connect_emulator(self) -> None:
        """Connect to a fresh in-process emulated device on this station's clock."""
        self.emulator = self.dialect.emulator(self.clock, self.profile)
        self.connect_transport(LoopbackTransport(self.emulator, self.clock, realtime=self.realtime))

    def connect_serial(self, port: str, baudrate: int | None = None) -> None:
        self.emulator = None
        self.connect_transport(SerialTransport(port, baudrate or self.profile.link.baud))

    def connect_ble(self, address: str | None) -> None:
        """Connect to the stage at ``address`` (the last used one), or the strongest found."""
        from protocol.transport.ble import BleTransport

        self.emulator = None
        self.connect_transport(
            BleTransport(
                address,
                ble_uuids_for(self.profile),
                name_prefix=self.profile.link.ble_name_prefix,
                loop=self.ble_loop(),
            )
        )

    def ble_loop(self) -> BleLoop:
        """The asyncio loop thread BLE runs on, started on first use and stopped at shutdown."""
        if self._ble_loop is None:
            from protocol.transport.ble import BleLoop

            self._ble_loop = BleLoop()
        return self._ble_loop

    def connect_transport(self, transport: Transport) -> None:
        self.close_link()
        self.link = Link(transport, self)
        self.session = self.dialect.session(
            self.model, self.link, self.clock, self.profile, self.period_ms, self.realtime
        )
        self.session.setParent(self)
        self.link.disconnected.connect(self._on_disconnected)
        self.link.connected.connect(self._on_connected)
        self.sessionChanged.emit()
        self.model.set_link_state(LinkState.CONNECTING, transport.describe())
        if self.realtime:
            self._poll.start()
        self.link.open()

    @property
    def stopping_to_close(self) -> bool:
        """A stop went out and the link closes once the device confirms it (or time is up)."""
        return self._stop_deadline is not None

    def stop_and_close(self) -> bool:
        """Disconnect: stop every axis, wait for the device to confirm it, then close.

        Returns True when the link closed at once (nothing moving, nothing to
        wait for, or a machine that cannot stop a move); False while the
        stop is awaited — :attr:`linkClosed` follows within
        :data:`STOP_CONFIRM_S` (plus one check), confirmed or not.
        """
        if self._stop_deadline is not None:
            return False
        session = self.session
        if not self._live():
            self.close_link()
            return True
        assert session is not None
        session.stop_all()
        if not self.profile.capabilities.stop_command or session.motion_stopped():
            self._close(send_stop=False)
            return True
        self._stop_deadline = self.clock.now() + STOP_CONFIRM_S
        self.model.message.emit(
            QCoreApplication.translate("Station", "Stopping every axis before closing the link…")
        )
        if self.realtime:
            self._stop_check.start()
        return False

    def _live(self) -> bool:
        """A link that is open to a device that has answered: a stop would reach it."""
        return (
            self.session is not None
            and self.link is not None
            and self.link.is_open
            and self.session.device_answered
        )

    def _check_stop(self) -> None:
        """While a stop is awaited: close once the device reports every axis still."""
        deadline = self._stop_deadline
        if deadline is None:
            self._stop_check.stop()
            return
        session = self.session
        if session is None or not self._live():
            self.model.message.emit(
                QCoreApplication.translate(
                    "Station", "The link went before the stop was confirmed; closed"
                )
            )
            self._close(send_stop=False)
        elif session.motion_stopped():
            self.model.message.emit(
                QCoreApplication.translate("Station", "Every axis stopped; link closed")
            )
            self._close(send_stop=False)
        elif self.clock.now() >= deadline:
            self.model.message.emit(
                QCoreApplication.translate(
                    "Station",
                    "The device did not confirm the stop within {0} s; "
                    "link closed anyway — check that the machine stands",
                ).format(f"{STOP_CONFIRM_S:g}")
            )
            self._close(send_stop=False)

    def close_link(self) -> None:
        """Close on the operator's word: no reconnection follows.

        Closing at once (another link chosen, the emulator switched off) still
        sends a stop first when an axis is moving; :meth:`stop_and_close`
        also waits for it to be confirmed.
        """
        self._close(send_stop=self._stop_deadline is None)

    def _close(self, *, send_stop: bool) -> None:
        self._stop_deadline = None
        self._stop_check.stop()
        self._reconnect_at = None
        self._attempt = 0
        self._poll.stop()
        if self.session is not None:
            if send_stop and self._live() and not self.session.motion_stopped():
                self.session.stop_all()
            self.session.shutdown()
        if self.link is not None:
            self._closing = True
            try:
                self.link.close()
            finally:
                self._closing = False
            self.link.deleteLater()
        had_session = self.session is not None
        if self.session is not None:
            self.session.deleteLater()
        self.link = None
        self.session = None
        self.model.set_link_state(LinkState.DISCONNECTED)
        if had_session:
            self.sessionChanged.emit()
            self.linkClosed.emit()

    def set_drill_timing(self, timing: DrillTiming) -> None:
        """The drill's timing constants from now on (FIDELITY S2-06: the teacher changes them).

        The estimate and the session's timeouts read them from the profile; an
        emulated drill runs them from its next procedure on.
        """
        self.profile = dataclasses.replace(self.profile, drill_timing=timing)
        self.model.profile = self.profile
        # Imported here: only a station whose timing is changed needs the drill's emulator.
        from protocol.emulator.drill_firmware import DrillFirmware

        drill = self.emulator_as(DrillFirmware)
        if drill is not None:
            drill.set_timing(timing)
        self.drillTimingChanged.emit()

    def set_drill_conversion(self, conversion: DrillConversion) -> bool:
        """The conversion constants from now on, unless a job is under way (then False).

        A job under way was checked against the travel and timed with the
        constants it was loaded with: changed under it, its remaining holes
        would go where nothing checked them.
        """
        busy = self.model.jog_lock_reason
        if busy is not None:
            self.model.message.emit(
                QCoreApplication.translate(
                    "Station", "Conversion constants not changed: {0}"
                ).format(busy)
            )
            return False
        if conversion != self.drill_conversion:
            self.drill_conversion = conversion
            self.drillConversionChanged.emit()
        return True

    def set_period_ms(self, period_ms: int) -> None:
        self.period_ms = period_ms
        if self.session is not None:
            self.session.set_period_ms(period_ms)

    def shutdown(self) -> None:
        """Stop motion, close the link and end the BLE thread, at once (the application ends).

        The window waits for the stop first (:meth:`stop_and_close`); this is the last word.
        """
        stop_now = self._stop_deadline is None and self._live()
        if stop_now:
            assert self.session is not None
            self.session.stop_all()
        self._close(send_stop=False)
        if self._ble_loop is not None:
            self._ble_loop.stop()
            self._ble_loop = None

    # --- losing and regaining the link ---------------------------------------

    def poll(self) -> None:
        """Start a due reconnection attempt (a timer in real time, the test clock otherwise).

        Also looks at an awaited stop, so that on a test clock the wait advances with it.
        """
        if self._stop_deadline is not None:
            self._check_stop()
        if self._reconnect_at is None or self.link is None:
            return
        if self.clock.now() < self._reconnect_at:
            return
        self._reconnect_at = None
        self.model.set_link_state(
            LinkState.LOST,
            QCoreApplication.translate("Station", "reconnecting to {0}…").format(
                self.link.describe()
            ),
        )
        self.link.open()

    def _on_connected(self) -> None:
        self._attempt = 0
        self._reconnect_at = None

    def _on_disconnected(self, reason: object) -> None:
        if self._closing or reason is None:
            return
        self._schedule_reconnect(str(reason))

    def _schedule_reconnect(self, reason: str) -> None:
        delay = self.reconnect_delays[min(self._attempt, len(self.reconnect_delays) - 1)]
        self._attempt += 1
        self._reconnect_at = self.clock.now() + delay
        retrying = QCoreApplication.translate("Station", "{0} — retrying in {1} s")
        self.model.set_link_state(LinkState.LOST, retrying.format(reason, f"{delay:g}"))
