"""The stage dialect's session: operator intents in, command frames out, echoes into the model.

The device is level-triggered (a jog lasts while JOG keeps arriving) and
answers every frame, so the session sends a frame every period *and* at
once whenever the operator's intent changes: a key press never waits for the
next tick.  One-shot commands (moves, writes, speed select) queue per axis and
take that axis's slot in the next frame; reads fill idle slots in the
background so an operator's command is never stuck behind them.
"""

from __future__ import annotations

from collections import deque
from collections.abc import Sequence

from PySide6.QtCore import QCoreApplication, QObject, QTimer

from app.link import Link
from app.machine import LinkState, MachineModel
from app.machines.stage.echoes import STATUS_TEXT as STATUS_TEXT  # re-exported for callers
from app.machines.stage.echoes import SUBSCRIBER_TELEMETRY as SUBSCRIBER_TELEMETRY
from app.machines.stage.echoes import StageEchoes
from app.machines.stage.frames import INFO_SUBSCRIBERS as INFO_SUBSCRIBERS  # re-exported
from app.machines.stage.frames import JOG_END_MARGIN_MM as JOG_END_MARGIN_MM
from app.machines.stage.frames import MAX_BURST as MAX_BURST
from app.machines.stage.frames import SUPERSEDING, StageFrames, to_um
from app.machines.stage.frames import SubscriberScheduler as SubscriberScheduler
from app.machines.stage.parameters import BY_TYPE, beyond_mechanics
from app.machines.stage.supervision import StageSupervisor
from protocol.clock import Clock
from protocol.stage.codec import (
    PARAMETERS,
    AxisStatus,
    CommandId,
    CommandPacket,
    EchoFrame,
    EchoType,
    Rejected,
    StageDecoder,
    encode_echo,
    write_command,
)

STALE_PERIODS = 3
LOST_AFTER_S = 2.0
JOG_RELEASE_REPEATS = 3
#: Echoes counted past a MOVE_ABS's frame before one is believed to answer a later frame.
#: Echoes come back in order, one per valid frame, so a lost frame or echo only makes the
#: count lag; the margin of one more covers a duplicated or stale echo.
MOVE_PROOF_ECHOES = 2


class StageSession(StageFrames):
    """frameSent carries CommandFrames; frameReceived EchoFrames or Rejected lines."""

    def __init__(
        self,
        model: MachineModel,
        link: Link,
        clock: Clock,
        *,
        period_ms: int | None = None,
        autotick: bool = True,
        parent: QObject | None = None,
    ) -> None:
        super().__init__(model, link, clock, parent)
        self.decoder = StageDecoder(self.axis_count)
        self._period_ms = period_ms or model.profile.period_ms
        self.subscribers = SubscriberScheduler(self._period_ms / 1000)
        self._release_repeats = [0] * self.axis_count
        #: Axes whose held jog was turned into a move to the travel end (+1/-1, 0: none).
        self._jog_limited = [0] * self.axis_count
        self._urgent: list[deque[CommandPacket]] = [deque() for _ in range(self.axis_count)]
        self._background: list[deque[CommandPacket]] = [deque() for _ in range(self.axis_count)]
        self._read_in_last_frame = [False] * self.axis_count
        self.echoes = StageEchoes(model, clock)
        #: Every echoed position is judged against the moves sent (stopped when off them).
        self.supervisor = StageSupervisor(model, self.gate)
        self._shift_held = False
        self._device_fast: bool | None = None
        self._last_echo: float | None = None
        #: Frames sent and echoes received since the link opened (see _check_moves).
        self._frames_sent = 0
        self._echoes_received = 0
        #: Per axis: the last MOVE_ABS sent and the frame count it went out with, until an
        #: echo of a later frame shows whether the stage received it.
        self._unproven: list[tuple[int, CommandPacket] | None] = [None] * self.axis_count
        self._timer = QTimer(self)
        self._timer.setInterval(self._period_ms)
        self._timer.timeout.connect(self.tick)
        self._autotick = autotick
        self.discounts_stalls = autotick  # a real-time timer ticks: its lateness is ours
        link.connected.connect(self._on_connected)
        link.disconnected.connect(self._on_disconnected)
        link.dataReceived.connect(self._on_data)

    # --- settings ------------------------------------------------------------

    @property
    def period_ms(self) -> int:
        return self._period_ms

    def set_period_ms(self, period_ms: int) -> None:
        self._period_ms = max(20, min(1000, int(period_ms)))
        self._timer.setInterval(self._period_ms)
        self.subscribers.period_s = self._period_ms / 1000

    def set_plotted_subscriber(self, subscriber: int | None) -> None:
        self.subscribers.plotted = subscriber

    @property
    def rejected(self) -> int:
        return self.decoder.rejected

    # --- operator intents ----------------------------------------------------

    def set_jog(self, directions: Sequence[int]) -> None:
        """The jog directions of all axes as the operator holds them right now."""
        wanted = self._jog_wanted(directions)
        if wanted == self._jog:
            return
        for axis, (old, new) in enumerate(zip(self._jog, wanted, strict=True)):
            if self._jog_limited[axis] and new != self._jog_limited[axis]:
                # The jog became a move to the travel end: a release must stop that move.
                self._jog_limited[axis] = 0
                if not new:
                    self._urgent[axis].append(CommandPacket(CommandId.STOP))
                    continue
            if old and not new:
                self._release_repeats[axis] = JOG_RELEASE_REPEATS
            elif new:
                self._release_repeats[axis] = 0
        self._jog = wanted
        self._jog_started()
        self._send_now()

    def set_shift(self, held: bool) -> None:
        """Shift held jogs at the other speed; the switch goes out at once."""
        if held != self._shift_held:
            self._shift_held = held
            self._sync_speed()
            self._send_now()

    def select_speed(self, fast: bool) -> None:
        self._fast_selected = fast
        self._sync_speed()
        self._send_now()

    def stop_all(self) -> None:
        """Stop everything: drop queued motion and jogs, STOP every axis at once."""
        self._jog = [0] * self.axis_count
        self._jog_limited = [0] * self.axis_count
        self._release_repeats = [0] * self.axis_count
        for queue in self._urgent:
            queue.clear()
        for queue in self._urgent:
            queue.append(CommandPacket(CommandId.STOP))
        self._send_now()

    def move_absolute(self, axis: int, position_mm: float) -> bool:
        if self.gate.refuse(self.gate.refuse_target(axis, position_mm)):
            return False
        return self._motion(axis, CommandPacket(CommandId.MOVE_ABS, to_um(position_mm)))

    def move_relative(self, axis: int, delta_mm: float) -> bool:
        if self.gate.refuse(self.gate.refuse_relative(axis, delta_mm)):
            return False
        return self._motion(axis, CommandPacket(CommandId.MOVE_REL, to_um(delta_mm)))

    def home(self, axis: int) -> bool:
        return self._motion(axis, CommandPacket(CommandId.HOME))

    def set_position(self, axis: int, position_mm: float) -> None:
        self._urgent[axis].append(CommandPacket(CommandId.SET_POS, to_um(position_mm)))
        self._send_now()

    def set_sleep(self, sleep: bool) -> None:
        if sleep:
            self._jog = [0] * self.axis_count
        for queue in self._urgent:
            queue.append(CommandPacket(CommandId.SLEEP, 1 if sleep else 0))
        self._send_now()

    def write_parameter(self, axis: int, parameter: EchoType, value: int) -> bool:
        """Write one stored parameter; a travel beyond the mechanics is refused here.

        Values outside the device's own ranges go out: the device refuses them
        and says which value it kept.
        """
        known = BY_TYPE.get(int(parameter))
        if known is not None:
            reason = beyond_mechanics(known, value, self.model.profile.axes[axis])
            if reason is not None:
                self.model.message.emit(
                    QCoreApplication.translate("StageSession", "Not written: {0} {1}").format(
                        self.model.axes[axis].name, reason
                    )
                )
                return False
        self.echoes.expect_write(axis, parameter, value)
        self._urgent[axis].append(CommandPacket(write_command(parameter), value))
        self._send_now()
        return True

    def read_parameter(self, axis: int, parameter: EchoType) -> None:
        self._background[axis].append(CommandPacket(CommandId.READ, parameter))

    def read_all_parameters(self) -> None:
        for axis in range(self.axis_count):
            for parameter in PARAMETERS:
                self.read_parameter(axis, parameter)

    # --- the wire ------------------------------------------------------------

    def tick(self) -> None:
        """One period: health check, then the periodic frame."""
        self._check_answer()
        self._check_health()
        self._check_deadman()
        if self.link.is_open:
            self._send_frame()

    # --- link events ---------------------------------------------------------

    def _on_connected(self) -> None:
        self.decoder.reset()
        self._frames_sent = self._echoes_received = 0
        self._unproven = [None] * self.axis_count
        self._last_echo = self.clock.now()
        self._device_fast = None
        self._jog = [0] * self.axis_count
        self._jog_limited = [0] * self.axis_count
        self.supervisor.release()
        self.await_device()
        self._sync_speed()
        self.read_all_parameters()
        if self._autotick:
            self._timer.start()
        self._send_now()

    def _on_disconnected(self, reason: object) -> None:
        self._timer.stop()
        self._jog = [0] * self.axis_count
        self._jog_limited = [0] * self.axis_count
        self.echoes.forget_writes()
        self._unproven = [None] * self.axis_count
        for queue in (*self._urgent, *self._background):
            queue.clear()
        if reason is None:
            self.model.set_link_state(LinkState.DISCONNECTED)
        else:
            self.model.set_link_state(LinkState.LOST, str(reason))
            self.model.message.emit(
                QCoreApplication.translate("Session", "Link lost: {0}").format(reason)
            )

    def _check_health(self) -> None:
        now = self.clock.now()
        stall = self._station_stall(now)
        if self._last_echo is None or self.model.link_state not in (
            LinkState.CONNECTED,
            LinkState.STALE,
        ):
            return
        # Time the station itself was not running is nobody's silence (a busy computer).
        self._last_echo = min(now, self._last_echo + stall)
        silent = now - self._last_echo
        if silent > LOST_AFTER_S:
            self._jog = [0] * self.axis_count  # the device's watchdog has stopped it already
        # Every frame is echoed within 20 ms: three silent periods are amber, 2 s red.
        self._watch_silence(silent, STALE_PERIODS * self._period_ms / 1000, LOST_AFTER_S)

    def _on_data(self, data: bytes) -> None:
        self.heard_unrecognised(data)  # kept until the device answers: whose words?
        for result in self.decoder.feed(data):
            if isinstance(result, Rejected):
                self.frameReceived.emit(result, result.raw)
            elif isinstance(result, EchoFrame):
                # The codec is canonical, so re-encoding gives back the bytes received.
                self.frameReceived.emit(result, encode_echo(result))
                self._echoes_received += 1
                self.apply_echo(result)
                self._check_moves(result)
            else:
                # A command frame arriving here is an echo of our own bytes (a looped
                # cable, a misbehaving bridge): noise on this side, counted as such.
                self.decoder.rejected += 1

    # --- echoes into the model -----------------------------------------------

    def apply_echo(self, echo: EchoFrame) -> None:
        """Fold one echo into the model; any echo proves the link is alive."""
        self._last_echo = self.clock.now()
        self.device_replied()  # green again, after a silence too: its frames kept asking
        fault = self.supervisor.judge(echo)
        self.echoes.apply(echo)
        if fault is not None:
            self.stop_for_fault(fault)

    def _check_moves(self, echo: EchoFrame) -> None:
        """Send again a MOVE_ABS the stage never received (its frame lost or mangled).

        The stage drops a frame whose checksum fails and answers nothing, so a
        lost move is seen only in what it reports afterwards: an echo that
        answers a later frame (it tells the state after every frame before it)
        showing the axis standing still, off the target, with no stop or end
        switch to explain it.  Only then was the move never run, and only then
        does it go out again: a move that may have run is never repeated.
        """
        for axis, unproven in enumerate(self._unproven):
            if unproven is None or axis >= len(echo.packets):
                continue
            sent_as, packet = unproven
            report = echo.packets[axis]
            if self._echoes_received < sent_as + MOVE_PROOF_ECHOES:
                continue  # this echo may answer the move's own frame or one before it
            if report.type != EchoType.POSITION:
                continue  # a parameter answer in the position's place: the next one tells
            self._unproven[axis] = None
            if report.status not in (AxisStatus.IDLE, AxisStatus.TARGET_REACHED):
                continue  # it runs, or a stop, a switch or a block explains where it stands
            if abs(report.data - packet.data) <= self._arrival_toleranceto_um(axis):
                continue  # it stands on the target: run, or nothing to run
            if any(
                p.command in SUPERSEDING or p.command == CommandId.MOVE_ABS
                for p in self._urgent[axis]
            ):
                continue  # newer motion for this axis is on its way
            self._urgent[axis].appendleft(packet)
            self._send_now()

    def _arrival_toleranceto_um(self, axis: int) -> float:
        """Half a microstep plus the µm the wire rounds to: as the job judges arrival."""
        profile = self.model.profile.axes[axis]

        def known(parameter: EchoType, fallback: float) -> float:
            value = self.model.parameter(axis, parameter).value
            return float(value) if value else fallback

        lead_um = known(EchoType.LEAD, profile.lead * 1000)
        per_rev = known(EchoType.STEPS_PER_REV, profile.steps_per_rev) * known(
            EchoType.MICROSTEPS, profile.microsteps
        )
        return lead_um / per_rev / 2 + 1.0

    def _silence_began(self) -> str:
        """Given up as silent: a job's resume re-examines its move, so none is judged here."""
        self._unproven = [None] * self.axis_count
        return ""

    def _back_after_silence(self) -> None:
        """A stage switched on again runs slow and may hold other parameters: as at connect."""
        self._device_fast = None
        self._sync_speed()
        self.read_all_parameters()
        self._send_now()

    def _recovery_verdict(self) -> object:
        """Its echoes are back, but nothing in them tells a stage switched off and on (it
        restores its count at power-on) from one that ran on: a job waits for the operator."""
        return QCoreApplication.translate(
            "StageSession", "nothing it reports shows whether it was switched off meanwhile"
        )

    def shutdown(self) -> None:
        self._timer.stop()
