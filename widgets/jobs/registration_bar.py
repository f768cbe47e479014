"""The jobs dock's board registration row: reference holes, the tool jogged over each.

The operator chooses the reference holes of the loaded drill job, by their
number in drilling order or by clicking them in the preview (*Pick*), jogs
the tool over each on the real board and presses *Here*; *Register* then
moves the whole job onto the board through
:func:`app.jobs.registration.register` and loads it like any other job, so
the runner's travel check refuses a board that lies off the bed.  A third
point (*3 points*) is averaged in and its disagreement shown.  *Clear* gives
the job back as the file says.  The geometry lives in the app layer; this row
only collects the points, says what was measured, and hands the dock the
:class:`~app.jobs.registration.Placement` the runner keeps with the checkpoint.
"""

from __future__ import annotations

from collections.abc import Callable

from PySide6.QtCore import Qt, Signal
from PySide6.QtWidgets import (
    QCheckBox,
    QComboBox,
    QHBoxLayout,
    QSpinBox,
    QToolButton,
    QVBoxLayout,
    QWidget,
)

from app.jobs.program import Program
from app.jobs.registration import (
    Placement,
    Point,
    RegistrationError,
    Side,
    hole_positions,
    mirrored,
    register,
)
from app.local_numbers import local_number
from app.station import Station
from widgets.retranslate import Maker, Texts
from widgets.style import compact

#: At most this many reference holes (three: least squares with a residual).
MAX_REFERENCES = 3


def reference_holes(program: Program) -> list[Point]:
    """Where each DRILL happens (X, Y of the MOVE before it), in drilling order."""
    return hole_positions(program)


class RegistrationBar(QWidget):
    """Collects reference holes and measured machine points; hands back the moved job."""

    #: The operator wants to click reference ``k`` (0-based) in the preview; -1: stop picking.
    pickRequested = Signal(int)

    def __init__(
        self,
        station: Station,
        load: Callable[[Program, Placement], bool],
        say: Callable[[str], None],
    ) -> None:
        super().__init__()
        self.station = station
        self._load = load
        self._say = say
        #: The job as its file says (what registration transforms; Clear goes back to it).
        self.original: Program | None = None
        #: How the loaded job was put on the board (side, registration).
        self.placement = Placement()
        self._holes: list[Point] = []
        self.measured: list[Point | None] = [None] * MAX_REFERENCES
        # The job has two holes or more to register on; a job is under way.
        self._usable = False
        self._running = False
        t = self.texts = Texts(self)
        # Two rows: in one row the three references ran the jobs dock past a 1280 px screen.
        rows = QVBoxLayout(self)
        rows.setContentsMargins(0, 0, 0, 0)
        rows.setSpacing(2)
        row = QHBoxLayout()
        references = QHBoxLayout()
        references.setSpacing(8)
        rows.addLayout(row)
        rows.addLayout(references)
        # Short: the row must fit beside the Drill page on a 1280 px screen; the
        # tooltip says the rest.  On the first row: the references' row is the wider.
        row.addWidget(
            t.label(
                lambda: self.tr("Holes"),
                lambda: self.tr("Register on holes: two (or three) reference holes of the job"),
            )
        )
        self.side_combo = self._build_side_combo(t)
        row.addWidget(self.side_combo)
        self.hole_spins: list[QSpinBox] = []
        self.pick_buttons: list[QToolButton] = []
        self.here_buttons: list[QToolButton] = []
        for k in range(MAX_REFERENCES):
            references.addLayout(self._build_reference(t, k))
        self.three_check = QCheckBox()
        t.set(self.three_check.setText, lambda: self.tr("3 points"))
        self.three_check.setObjectName("job_reference_three")
        t.set(
            self.three_check.setToolTip,
            lambda: self.tr(
                "A third reference hole: averaged in, and how far the points disagree shown"
            ),
        )
        self.three_check.toggled.connect(self._count_changed)
        row.addWidget(self.three_check)
        row.addStretch(1)
        references.addStretch(1)
        self.register_button = t.button(lambda: self.tr("Register"))
        self.register_button.setObjectName("job_register")
        self.register_button.clicked.connect(self.apply)
        self.clear_button = t.button(lambda: self.tr("Clear"))
        self.clear_button.setObjectName("job_register_clear")
        self.clear_button.clicked.connect(self.clear)
        # As wide as their captions: the dock beside the pages has no width to spare.
        row.addWidget(compact(self.register_button))
        row.addWidget(compact(self.clear_button))
        self._count_changed()
        self.set_job(None)

    def _build_side_combo(self, t: Texts) -> QComboBox:
        """Which side of the board the job is for: the top, or the bottom mirrored."""
        combo = QComboBox()
        combo.setObjectName("job_side")
        t.set(
            combo.setToolTip,
            lambda: self.tr(
                "The bottom side of a double-sided board: the job mirrored about its own extent"
            ),
        )
        sides: tuple[tuple[Maker, str], ...] = (
            (lambda: self.tr("Top side"), ""),
            (lambda: self.tr("Bottom, mirrored in X"), "X"),
            (lambda: self.tr("Bottom, mirrored in Y"), "Y"),
        )
        for label, about in sides:
            combo.addItem("", about)
            t.item(combo, combo.count() - 1, label)
        combo.activated.connect(self._side_changed)
        return combo

    def _build_reference(self, t: Texts, k: int) -> QHBoxLayout:
        """Reference ``k``: its hole's number, Pick (in the preview) and Here (the tool's
        position)."""
        spin = QSpinBox()
        spin.setObjectName(f"job_reference_{k + 1}")
        t.set(spin.setToolTip, lambda: self.tr("A reference hole: its number in drilling order"))
        spin.valueChanged.connect(lambda _v, k=k: self._forget(k))
        pick = self._small_button(
            lambda: self.tr("Pick"), lambda: self.tr("Then click the hole in the preview")
        )
        pick.setObjectName(f"job_reference_pick_{k + 1}")
        pick.setCheckable(True)
        pick.toggled.connect(lambda on, k=k: self._pick(k, on))
        here = self._small_button(
            lambda: self.tr("Here"),
            lambda: self.tr("The tool stands over this hole on the board: take its position"),
        )
        here.setObjectName(f"job_reference_here_{k + 1}")
        here.clicked.connect(lambda _c=False, k=k: self.take(k))
        # A reference's number and its two buttons close together, the references apart:
        # at the style's spacing the row outgrew the dock beside the pages (Czech).
        group = QHBoxLayout()
        group.setSpacing(1)
        for widget in (spin, pick, here):
            group.addWidget(widget)
        self.hole_spins.append(spin)
        self.pick_buttons.append(pick)
        self.here_buttons.append(here)
        return group

    def _small_button(self, make: Maker, tip: Maker) -> QToolButton:
        """As wide as its text (a push button is 80 px at least): three references in a row."""
        button = QToolButton()
        button.setToolButtonStyle(Qt.ToolButtonStyle.ToolButtonTextOnly)
        self.texts.set(button.setText, make)
        self.texts.set(button.setToolTip, tip)
        return button

    @property
    def count(self) -> int:
        """Reference holes in use: two, or three with *3 points*."""
        return 3 if self.three_check.isChecked() else 2

    def set_job(self, program: Program | None, placement: Placement | None = None) -> None:
        """A job as read from its file, and how it was put on the board (kept or resumed).

        Its holes become the choices and the measurements are dropped; the
        side shown is the placement's.
        """
        self.original = program
        self.placement = placement or Placement()
        index = self.side_combo.findData(self.placement.side)
        self.side_combo.setCurrentIndex(max(index, 0))
        self._choose_holes()

    @property
    def side(self) -> Side:
        about = self.side_combo.currentData()
        return "X" if about == "X" else "Y" if about == "Y" else ""

    @property
    def base(self) -> Program | None:
        """The job on the chosen side (mirrored for the bottom): what registration moves."""
        side = self.side
        if self.original is None or not side:
            return self.original
        return mirrored(self.original, side)

    def _side_changed(self, *_args: object) -> None:
        try:
            base = self.base
        except RegistrationError as exc:
            self._say(self.tr("cannot mirror: {0}").format(exc))
            self.side_combo.setCurrentIndex(0)
            return
        if base is not None:
            self.placement = Placement(self.side)
            self._load(base, self.placement)
            self._choose_holes()

    def _choose_holes(self) -> None:
        base = self.base
        self._holes = reference_holes(base) if base is not None else []
        count = len(self._holes)
        for spin in self.hole_spins:
            spin.blockSignals(True)
            spin.setRange(1, max(count, 1))
            spin.blockSignals(False)
        if count:
            # Far apart registers best: the first hole, the one farthest from it, and the
            # one farthest from the line between them.
            x0, y0 = self._holes[0]
            far = max(
                range(count),
                key=lambda i: (self._holes[i][0] - x0) ** 2 + (self._holes[i][1] - y0) ** 2,
            )
            x1, y1 = self._holes[far]
            off_line = max(
                range(count),
                key=lambda i: abs(
                    (x1 - x0) * (self._holes[i][1] - y0) - (y1 - y0) * (self._holes[i][0] - x0)
                ),
            )
            for spin, value in zip(self.hole_spins, (1, far + 1, off_line + 1), strict=True):
                spin.blockSignals(True)
                spin.setValue(value)
                spin.blockSignals(False)
        self.measured = [None] * MAX_REFERENCES
        self._usable = count >= 2
        self._show()
        self._update()

    def set_job_running(self, running: bool) -> None:
        """While a job runs the row steps aside: registering replaces the loaded job, so it
        could not be used then, and the preview and the operator's prompt get its room."""
        self._running = running
        self._show()

    def _show(self) -> None:
        self.setVisible(self._usable and not self._running)

    def set_reference(self, k: int, hole: int) -> None:
        """Reference ``k`` (0-based) is hole ``hole`` (0-based, drilling order): a preview pick."""
        if not 0 <= k < MAX_REFERENCES or not 0 <= hole < len(self._holes):
            return
        self.pick_buttons[k].blockSignals(True)
        self.pick_buttons[k].setChecked(False)
        self.pick_buttons[k].blockSignals(False)
        self.hole_spins[k].setValue(hole + 1)  # a different hole forgets its measurement
        x, y = self._holes[hole]
        self._say(
            self.tr("reference {0} is hole {1} (X{2} Y{3} in the job)").format(
                k + 1, hole + 1, local_number(x, ".3f"), local_number(y, ".3f")
            )
        )

    def _pick(self, k: int, on: bool) -> None:
        if on:
            for other, button in enumerate(self.pick_buttons):
                if other != k and button.isChecked():
                    button.blockSignals(True)
                    button.setChecked(False)
                    button.blockSignals(False)
        self.pickRequested.emit(k if on else -1)

    def _count_changed(self, *_args: object) -> None:
        third = self.count == 3
        for widget in (self.hole_spins[2], self.pick_buttons[2], self.here_buttons[2]):
            widget.setVisible(third)
        self._update()

    def take(self, k: int) -> None:
        axes = self.station.model.axes
        self.measured[k] = (axes[0].position, axes[1].position)
        x, y = self.measured[k] or (0.0, 0.0)
        self._say(
            self.tr("reference {0} (hole {1}) at X{2} Y{3}").format(
                k + 1, self.hole_spins[k].value(), local_number(x, ".3f"), local_number(y, ".3f")
            )
        )
        self._update()

    def apply(self) -> None:
        count = self.count
        measured = self.measured[:count]
        base = self.base
        if base is None or any(point is None for point in measured):
            return
        refs = [self._holes[spin.value() - 1] for spin in self.hole_spins[:count]]
        points = [point for point in measured if point is not None]
        try:
            fit = register(refs, points)
            placement = Placement(self.side, fit)
            moved = placement.apply(self.original) if self.original is not None else base
        except RegistrationError as exc:
            self._say(self.tr("registration refused: {0}").format(exc))
            return
        self._say(self.tr("registered: {0}").format(fit.describe()))
        if count == 3:
            self._say(
                self.tr("the three points agree within {0} mm").format(
                    local_number(fit.residual_mm, ".3f")
                )
            )
        if warning := fit.warning():
            self._say(self.tr("warning: {0}").format(warning))
        if self._load(moved, placement):
            self.placement = placement

    def clear(self) -> None:
        """Back to the job as the file says on the chosen side, unregistered."""
        base = self.base
        if base is not None:
            self.placement = Placement(self.side)
            self._load(base, self.placement)
        self.measured = [None] * MAX_REFERENCES
        self._update()

    def _forget(self, k: int) -> None:
        self.measured[k] = None
        self._update()

    def _update(self) -> None:
        complete = None not in self.measured[: self.count]
        self.register_button.setEnabled(complete and self.original is not None)
