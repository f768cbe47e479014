"""The G-code machine's page: its state, the pen, hold/resume/reset, and a console.

The console is what the plotter's old sender script was, done properly:
type a line, it is streamed like any other (refused here if the device
could never take it), the device's answer appears under it, and Up/Down walk
the lines sent before.  Job lines are not echoed here (a drawing has
hundreds of thousands); the developer pane's frame log shows everything.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from PySide6.QtWidgets import (
    QGridLayout,
    QHBoxLayout,
    QLabel,
    QMessageBox,
    QPlainTextEdit,
    QPushButton,
    QVBoxLayout,
    QWidget,
)

from app.machines.gcode.session import GcodeSession, SentLine, zeroes_by_hand
from app.station import Station
from widgets.history_entry import HistoryLineEdit
from widgets.link_text import axis_status_text
from widgets.number_field import NumberField, localized
from widgets.panels.gcode_overrides import OverrideBox
from widgets.panels.gcode_work_zero import WorkZeroBox
from widgets.panels.grbl_alarm_band import GrblAlarmBand
from widgets.retranslate import Maker, Texts

if TYPE_CHECKING:
    from app.jobs.run.runner import JobRunner
from widgets.style import monospace_font

CONSOLE_LINES = 2000


def _capitalised(text: str) -> str:
    """GRBL's state as it writes it ("Idle"), in the operator's language."""
    return text[:1].upper() + text[1:]


class GcodePanel(QWidget):
    def __init__(self, station: Station, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self._station = station
        self._watched: GcodeSession | None = None
        self._motion_enabled = True
        self._runner: JobRunner | None = None
        t = self.texts = Texts(self)

        machine = t.group(lambda: self.tr("Machine"))
        grid = QGridLayout(machine)
        self.state_label = QLabel("—")
        self.state_label.setObjectName("gcode_state")
        self.state_label.setFont(monospace_font())
        self.position_label = QLabel("—")
        self.position_label.setObjectName("gcode_position")
        self.position_label.setFont(monospace_font())
        grid.addWidget(t.label(lambda: self.tr("State")), 0, 0)
        grid.addWidget(self.state_label, 0, 1)
        grid.addWidget(t.label(lambda: self.tr("Position")), 1, 0)
        grid.addWidget(self.position_label, 1, 1, 1, 3)
        settings = station.profile.gcode
        up = settings.pen_up if settings else "M5"
        down = settings.pen_down if settings else "M3"
        self.home_button = self._button(
            lambda: self.tr("Home"), lambda: self.tr("Back to the origin ($H or G28)"), self.home
        )
        self.pen_up_button = self._button(
            lambda: self.tr("Pen up"),
            lambda: self.tr("Lift the pen ({0})").format(up),
            self.pen_up,
        )
        self.pen_down_button = self._button(
            lambda: self.tr("Pen down"),
            lambda: self.tr("Lower the pen ({0})").format(down),
            self.pen_down,
        )
        self.hold_button = self._button(
            lambda: self.tr("Hold !"), lambda: self.tr("Feed hold: decelerate and stop"), self.hold
        )
        self.resume_button = self._button(
            lambda: self.tr("Resume ~"), lambda: self.tr("Carry on after a hold or M0"), self.resume
        )
        self.reset_button = self._button(
            lambda: self.tr("Reset"),
            lambda: self.tr("Soft reset (Ctrl-X): stop and drop everything buffered"),
            self.soft_reset,
        )
        pen = station.profile.capabilities.pen
        if not pen:
            self.pen_up_button.hide()
            self.pen_down_button.hide()
        shown = [self.home_button]
        shown += [self.pen_up_button, self.pen_down_button] if pen else []
        shown += [self.hold_button, self.resume_button, self.reset_button]
        # Three to a row, so the page fits beside the jobs dock on a 1280 px screen.
        buttons = QGridLayout()
        for number, button in enumerate(shown):
            buttons.addWidget(button, number // 3, number % 3)
        grid.addLayout(buttons, 2, 0, 1, 4)

        self.hand_group = self._hand_zeroing(station)

        console = t.group(lambda: self.tr("Console"))
        box = QVBoxLayout(console)
        self.output = QPlainTextEdit()
        self.output.setObjectName("gcode_console")
        self.output.setReadOnly(True)
        self.output.setFont(monospace_font())
        self.output.setMaximumBlockCount(CONSOLE_LINES)
        self.entry = HistoryLineEdit()
        self.entry.setObjectName("gcode_entry")
        t.set(
            self.entry.setPlaceholderText,
            lambda: self.tr("G0 X10 Y10, $$, M3 …  (Up/Down: history)"),
        )
        self.entry.returnPressed.connect(self.send_line)
        self.send_button = t.button(lambda: self.tr("Send"))
        self.send_button.clicked.connect(self.send_line)
        self.clear_button = t.button(lambda: self.tr("Clear"), lambda: self.tr("Clear the console"))
        self.clear_button.clicked.connect(self.output.clear)
        line = QHBoxLayout()
        line.addWidget(self.entry, 1)
        line.addWidget(self.send_button)
        line.addWidget(self.clear_button)
        box.addWidget(self.output, 1)
        box.addLayout(line)

        layout = QVBoxLayout(self)
        layout.addWidget(machine)
        self._add_grbl_boxes(station, layout)
        #: A GRBL alarm or error explained, with what clears it (hidden without one).
        self.alarm_band = GrblAlarmBand(self)
        layout.addWidget(self.alarm_band)
        layout.addWidget(self.hand_group)
        layout.addWidget(console, 1)
        station.sessionChanged.connect(self._watch_session)
        self._watch_session()

    def _add_grbl_boxes(self, station: Station, layout: QVBoxLayout) -> None:
        """GRBL's work zero and overrides, under the machine's DRO (each hidden where the
        firmware has none)."""
        self.work_zero = WorkZeroBox(station)
        self.overrides = OverrideBox(station)
        layout.addWidget(self.work_zero)
        layout.addWidget(self.overrides)

    def _hand_zeroing(self, station: Station) -> QWidget:
        """The winder's manual zeroing (its white buttons, FIDELITY S0-24): release, zero here."""
        t = self.texts
        group = t.group(lambda: self.tr("Zero by hand"))
        settings = station.profile.gcode
        group.setVisible(settings is not None and zeroes_by_hand(settings))
        note = t.label(
            lambda: self.tr(
                "Release the motors, turn the base and move the needle by hand until nail 0 "
                "faces the needle and the needle stands at the board's edge, then Zero here: "
                "A 0, X the board radius, Z 0. Nothing moves."
            )
        )
        note.setWordWrap(True)
        x_axes = [a for a in station.profile.axes if a.name == "X"]
        travel = x_axes[0].travel if x_axes else 1000.0
        self.board_radius = NumberField(
            0.0, travel, decimals=1, unit="mm", value=min(120.0, travel), name="board_radius"
        )
        t.set(
            self.board_radius.set_description,
            lambda: self.tr("Board radius: X where the needle meets the board's edge"),
        )
        self.release_button = self._button(
            lambda: self.tr("Release motors"),
            lambda: self.tr(
                "Switch every driver off (M18) so the axes turn by hand; refused while a job "
                "is under way or the machine moves"
            ),
            self.release_motors,
        )
        self.zero_here_button = self._button(
            lambda: self.tr("Zero here"),
            lambda: self.tr(
                "The axes stand at the zero: A 0, X the board radius, Z 0 (G92); nothing moves"
            ),
            self.zero_here,
        )
        self.zero_here_button.setEnabled(False)
        grid = QGridLayout(group)
        grid.addWidget(note, 0, 0, 1, 3)
        grid.addWidget(t.label(lambda: self.tr("Board radius")), 1, 0)
        grid.addWidget(self.board_radius, 1, 1, 1, 2)
        grid.addWidget(self.release_button, 2, 1)
        grid.addWidget(self.zero_here_button, 2, 2)
        return group

    def _button(self, caption: Maker, tip: Maker, slot: object) -> QPushButton:
        button = self.texts.button(caption, tip)
        button.clicked.connect(slot)
        return button

    @property
    def session(self) -> GcodeSession | None:
        return self._station.session_as(GcodeSession)

    @property
    def history(self) -> tuple[str, ...]:
        return self.entry.history

    # --- what the buttons do -----------------------------------------------------------

    def send_line(self) -> bool:
        text = self.entry.take()
        if not text:
            return False
        session = self.session
        refusal = session.console.beyond_travel(text) if session is not None else None
        if session is not None and refusal is not None:
            answer = QMessageBox.warning(
                self,
                self.tr("Beyond the travel"),
                self.tr("{0}.\n\nSend it to the machine anyway?").format(refusal),
                QMessageBox.StandardButton.Yes | QMessageBox.StandardButton.Cancel,
                QMessageBox.StandardButton.Cancel,
            )
            if answer != QMessageBox.StandardButton.Yes:
                self.output.appendPlainText(
                    self.tr("! {0}: not sent (beyond the travel)").format(text)
                )
                return False
        sent = session is not None and session.send_line(text, "console", confirmed=True)
        if not sent:
            self.output.appendPlainText(self.tr("! {0}: not sent").format(text))
        return sent

    def home(self) -> None:
        if self.session is not None:
            self.session.home(0)

    def pen_up(self) -> None:
        if self.session is not None:
            self.session.pen(False)

    def pen_down(self) -> None:
        if self.session is not None:
            self.session.pen(True)

    def hold(self) -> None:
        if self.session is not None:
            self.session.feed_hold()

    def resume(self) -> None:
        if self.session is not None:
            self.session.cycle_start()

    def soft_reset(self) -> None:
        if self.session is not None:
            lost = self.session.soft_reset()
            self.output.appendPlainText(
                self.tr("! soft reset: %n unanswered line(s) dropped", "", len(lost))
            )

    def follow_jobs(self, runner: JobRunner) -> None:
        """The board radius follows the string-art job loaded (its ``polomer_matrice``)."""
        self._runner = runner
        runner.programChanged.connect(self._take_board_radius)
        self._take_board_radius()

    def _take_board_radius(self) -> None:
        # Imported here, not with the page: job formats (numpy) load on first use.
        from app.jobs.formats.string_art.program import StringArtProgram

        program = self._runner.program if self._runner is not None else None
        if isinstance(program, StringArtProgram):
            radius = program.job.params.radius_cm * 10.0
            if self.board_radius.minimum() <= radius <= self.board_radius.maximum():
                self.board_radius.setValue(radius)

    def release_motors(self) -> bool:
        """First step of zeroing by hand: the session judges it (gate) and sends ``M18``."""
        released = self.session is not None and self.session.zeroing.release_motors()
        self._sync_hand_zeroing()
        return released

    def zero_here(self) -> bool:
        """Second step: ``G92`` with X the board radius, once the motors are released."""
        radius = self.board_radius.value()
        if radius is None or self.session is None:
            return False
        zeroed = self.session.zeroing.zero_here(radius)
        self._sync_hand_zeroing()
        return zeroed

    def _sync_hand_zeroing(self, *_args: object) -> None:
        session = self.session
        released = session is not None and session.zeroing.released
        self.zero_here_button.setEnabled(self._motion_enabled and released)

    def set_motion_enabled(self, enabled: bool) -> None:
        self._motion_enabled = enabled
        for button in (
            self.home_button,
            self.pen_up_button,
            self.pen_down_button,
            self.release_button,
        ):
            button.setEnabled(enabled)
        self.work_zero.set_motion_enabled(enabled)
        self._sync_hand_zeroing()

    # --- the session's news ------------------------------------------------------------

    def _watch_session(self) -> None:
        session = self.session
        if session is self._watched:
            return
        self._watched = session
        self.alarm_band.watch(session)
        if session is not None:
            # Bound methods: Qt drops them with the panel (a lambda would outlive it).
            session.linesSent.connect(self._show_sent)
            session.linesSent.connect(self._sync_hand_zeroing)
            session.replyText.connect(self._show_reply)
            session.statusChanged.connect(self._show_status)

    def _show_sent(self, lines: list[SentLine]) -> None:
        for sent in lines:  # one write's lines at once: a job's are many, and never shown
            if sent.origin in ("console", "intent"):
                self.output.appendPlainText(f"> {sent.text}")

    def _show_reply(self, text: str) -> None:
        self.output.appendPlainText(f"< {text}")

    def _show_status(self, report: object) -> None:
        state = getattr(report, "state", "?")
        mpos = getattr(report, "wpos", ()) or getattr(report, "mpos", ())
        feed = getattr(report, "feed", 0.0)
        self.state_label.setText(
            self.tr("{0}   feed {1}").format(
                _capitalised(axis_status_text(str(state).lower())), localized(f"{feed:g}")
            )
        )
        names = [a.name for a in self._station.profile.axes]
        self.position_label.setText(
            localized("  ".join(f"{n} {v:9.3f}" for n, v in zip(names, mpos, strict=False)))
        )
