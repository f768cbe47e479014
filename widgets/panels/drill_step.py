"""VRTACKA's step-through on the Drill page (FIDELITY S2-41).

"Next line" reads the loaded job's file one line further and shows the line,
its coordinates in millimetres and in microsteps, and one button per drill
procedure that would run it (``X…``, ``Y…``, then ``V``, ``K`` or ``Z``).  The
operator sends them one by one, in any order, as the original let a class do
("nemusime dodrzovat poradi instrukci, jak by to udelala automatika").  Every
button goes through the drill session's motion gate: a position outside the
travel is refused and the reason shown here; nothing is sent while a job holds
the machine.  The preview rings the stop's hole (:attr:`holeMarked`).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

from PySide6.QtCore import Signal
from PySide6.QtGui import QShowEvent
from PySide6.QtWidgets import QGridLayout, QGroupBox, QHBoxLayout, QLabel, QPushButton, QWidget

from app.jobs.step_through import JobWalk, WalkStop
from app.machines.drill.conversion import mm_to_microsteps, profile_microsteps_per_mm
from app.machines.drill.session import MAX_POSITION, DrillSession
from app.station import Station
from protocol.drill.codec import Command
from widgets.number_field import localized
from widgets.retranslate import Texts
from widgets.style import compact, monospace_font

if TYPE_CHECKING:
    from app.jobs.program import Program
    from widgets.jobs.preview import JobPreview


#: The most characters of a file line shown (the whole line is in its tooltip).
LINE_SHOWN = 64


@dataclass(frozen=True)
class Procedure:
    """One letter button: a procedure, with its position in microsteps for X and Y.

    A position the wire cannot carry (a hole at negative Y) is still shown and
    judged: the gate says why it does not go.
    """

    letter: str
    axis: int | None = None
    value: int | None = None

    @property
    def text(self) -> str:
        """``X629``, ``V``: as the terminal and the original's buttons write it."""
        return self.letter + ("" if self.value is None else str(self.value))

    def command(self) -> Command | None:
        """The command to send, or None when the position is none the drill takes."""
        if self.value is not None and not 0 <= self.value <= MAX_POSITION:
            return None
        return Command(self.letter, self.value)


class DrillStepBox(QGroupBox):
    """Next line / Previous line over the loaded job, and its procedures as buttons."""

    #: The stop's position (x, y) in the job's millimetres, or None: the preview rings it.
    holeMarked = Signal(object)

    def __init__(self, station: Station, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.setObjectName("drill_step")
        self._station = station
        self.walk = JobWalk(())
        self._program: Program | None = None
        self._problem = ""
        self._line_count = 0
        self._motion_enabled = True
        self._laid_out = True
        self._keep_index = -1
        self.procedures: list[Procedure] = []
        self.procedure_buttons: list[QPushButton] = []
        t = self.texts = Texts(self)
        t.set(self.setTitle, lambda: self.tr("Step through the job (teaching)"))
        self.previous_button = t.button(
            lambda: self.tr("Previous line"), lambda: self.tr("Back one line of the job's file")
        )
        self.previous_button.setObjectName("step_previous")
        self.previous_button.clicked.connect(self.previous_line)
        self.next_button = t.button(
            lambda: self.tr("Next line"),
            lambda: self.tr("Read the next line of the job's file (Načti řádek)"),
        )
        self.next_button.setObjectName("step_next")
        self.next_button.clicked.connect(self.next_line)
        self.where = QLabel()
        self.where.setWordWrap(True)  # a refusal of the file names it and its line
        self.where.setObjectName("step_where")
        self.line_text = QLabel()
        self.line_text.setObjectName("step_line")
        self.line_text.setFont(monospace_font())
        self.coordinates = QLabel()
        self.coordinates.setObjectName("step_coordinates")
        self.coordinates.setFont(monospace_font())
        self.note = QLabel()
        self.note.setObjectName("step_note")
        self.note.setWordWrap(True)
        self._procedures = QHBoxLayout()
        self._procedures.setSpacing(4)
        grid = QGridLayout(self)
        walk_row = QHBoxLayout()
        walk_row.addWidget(compact(self.previous_button))
        walk_row.addWidget(compact(self.next_button))
        walk_row.addWidget(self.where, 1)
        grid.addLayout(walk_row, 0, 0, 1, 2)
        grid.addWidget(self.line_text, 1, 0, 1, 2)
        grid.addWidget(self.coordinates, 2, 0, 1, 2)
        grid.addLayout(self._procedures, 3, 0)
        grid.addWidget(self.note, 4, 0, 1, 2)
        grid.setColumnStretch(1, 1)
        t.also(self._show)
        self._show()

    # --- the job -----------------------------------------------------------------

    def set_program(self, program: Program | None) -> None:
        """Walk ``program``'s file from its start (None: nothing to walk).

        The walk is laid out when the box is shown (at once if it is): a board of
        50 000 holes takes a third of a second, which nobody who never opens the
        step-through should wait for at every load.
        """
        if program is self._program:
            return
        # The same file read again (other constants, another placement): the walk stays on
        # its line, which then shows what the new reading makes of it.
        before = self._program.source if self._program is not None else None
        same_file = program is not None and before is not None and program.source == before
        self._keep_index = self.walk.index if same_file else -1
        self._program = program
        self._laid_out = False
        self.walk = JobWalk(())
        if self.isVisible():
            self._lay_out()
        else:
            self._show()

    def showEvent(self, event: QShowEvent) -> None:
        if not self._laid_out:
            self._lay_out()
        super().showEvent(event)

    def _lay_out(self) -> None:
        """Read the program's file and make its stops."""
        program = self._program
        self._laid_out = True
        self._problem = ""
        stops: list[WalkStop] = []
        self._line_count = 0
        if program is not None and program.source is not None:
            # Imported here: a job's reading (numpy) loads with the first job, not the page.
            from app.jobs.program import JobFileError
            from app.jobs.reading import read_job_text
            from app.jobs.step_through import walk_stops

            try:
                lines = read_job_text(program.source, latin1_fallback=True).splitlines()
                self._line_count = len(lines)
                axes = tuple(a.name for a in self._station.profile.axes[:2])
                stops = walk_stops(program, lines, (axes[0], axes[1]))
            except (JobFileError, OSError) as exc:
                self._problem = str(exc)
        self.walk = JobWalk(stops)
        if self._keep_index < len(self.walk.stops):
            self.walk.index = self._keep_index
        self._show()

    def follow(self, preview: JobPreview) -> None:
        """Walk the job ``preview`` draws (a refused one too) and ring each stop on it."""
        preview.programShown.connect(self.set_program)
        self.holeMarked.connect(preview.mark_step)
        self.set_program(preview.program)

    def next_line(self) -> WalkStop | None:
        stop = self.walk.next()
        self._show()
        return stop

    def previous_line(self) -> WalkStop | None:
        stop = self.walk.previous()
        self._show()
        return stop

    # --- conversions ---------------------------------------------------------------

    def microsteps(self, axis: int, mm: float) -> int:
        """``mm`` on ``axis`` in the drill's microsteps, rounded as the session rounds."""
        return mm_to_microsteps(mm, profile_microsteps_per_mm(self._station.profile.axes[axis]))

    def procedures_for(self, stop: WalkStop) -> list[Procedure]:
        """The procedures that run ``stop``: its moves (X, Y) and then what it does there."""
        found: list[Procedure] = []
        if stop.position is not None:
            for axis, mm in enumerate(stop.position):
                name = self._station.profile.axes[axis].name
                found.append(Procedure(name, axis, self.microsteps(axis, mm)))
        found += [Procedure(letter) for letter in stop.procedures]
        return found

    # --- sending -------------------------------------------------------------------

    def send_procedure(self, index: int) -> bool:
        """Send the stop's ``index``-th procedure through the session and its motion gate."""
        if not 0 <= index < len(self.procedures):
            return False
        procedure = self.procedures[index]
        text = procedure.text
        session = self._station.session_as(DrillSession)
        if session is None:
            self.note.setText(self.tr("{0} not sent: not connected").format(text))
            return False
        held = self._station.model.jog_lock_reason
        if held is not None:
            self.note.setText(self.tr("{0} not sent: {1}").format(text, held))
            return False
        if procedure.axis is not None and procedure.value is not None:
            reason = session.position_refusal(procedure.axis, procedure.value)
        else:
            reason = session.why_refused(Command(procedure.letter))
        command = procedure.command()
        if reason is None and command is not None and session.send_command(command):
            self.note.setText(self.tr("{0} sent").format(text))
            return True
        self.note.setText(self.tr("{0} not sent: {1}").format(text, reason or "—"))
        return False

    def set_motion_enabled(self, enabled: bool) -> None:
        self._motion_enabled = enabled
        for button in self.procedure_buttons:
            button.setEnabled(enabled)

    # --- showing ---------------------------------------------------------------------

    def _show(self) -> None:
        stop = self.walk.current
        count = len(self.walk.stops)
        self.previous_button.setEnabled(count > 0 and not self.walk.at_start)
        self.next_button.setEnabled(count > 0 and not self.walk.at_end)
        if self._program is None:
            self.where.setText(self.tr("No job loaded: open an Excellon file in the Jobs dock"))
        elif self._problem:
            self.where.setText(self._problem)
        elif stop is None:
            self.where.setText(
                self.tr("{0} lines: Next line reads the first").format(self._line_count)
            )
        elif stop.parts > 1:
            self.where.setText(
                self.tr("line {0} of {1}, position {2} of {3}").format(
                    stop.line, self._line_count, stop.part, stop.parts
                )
            )
        else:
            self.where.setText(self.tr("line {0} of {1}").format(stop.line, self._line_count))
        shown = f"{stop.line}: {stop.text}" if stop is not None else ""
        # A long line (a comment, a hostile file) must not widen the page past the screen.
        self.line_text.setText(shown if len(shown) <= LINE_SHOWN else shown[: LINE_SHOWN - 1] + "…")
        self.line_text.setToolTip(shown)
        self.coordinates.setText(self._coordinates(stop))
        self._show_procedures(stop)
        self.holeMarked.emit(stop.position if stop is not None else None)

    def _coordinates(self, stop: WalkStop | None) -> str:
        if stop is None:
            return ""
        if stop.position is None:
            return self.tr("no coordinates on this line")
        parts = []
        conversion = self._station.drill_conversion
        for axis, mm in enumerate(stop.position):
            name = self._station.profile.axes[axis].name
            # The job's millimetre, before the teacher's microsteps a mm stretched it onto
            # the machine (S2-42): what the file means, and what the drill is sent for it.
            job_mm = mm / conversion.axis_scale(axis)
            parts.append(
                self.tr("{0} {1} mm = {2} µsteps").format(
                    name, localized(f"{job_mm:.3f}"), self.microsteps(axis, mm)
                )
            )
        return "   ".join(parts)

    def _show_procedures(self, stop: WalkStop | None) -> None:
        for button in self.procedure_buttons:
            self._procedures.removeWidget(button)
            button.deleteLater()
        self.procedure_buttons = []
        self.procedures = self.procedures_for(stop) if stop is not None else []
        enabled = self._motion_enabled
        for index, procedure in enumerate(self.procedures):
            button = QPushButton(procedure.text)
            button.setObjectName(f"step_procedure_{index}")
            button.setToolTip(self.tr("Send {0} to the drill").format(procedure.text))
            button.clicked.connect(lambda _=False, i=index: self.send_procedure(i))
            button.setEnabled(enabled)
            self._procedures.addWidget(compact(button))
            self.procedure_buttons.append(button)
        self.note.setText("")
