"""The jobs dock's board registration row: two reference holes, the drill jogged over each.

The operator chooses two holes of the loaded drill job (by their number in
drilling order), jogs the tool over each on the real board and presses
*Here*; *Register* then moves the whole job onto the board through
:func:`app.jobs.registration.register` and loads it like any other job, so
the runner's travel check refuses a board that lies off the bed.  *Clear*
gives the job back as the file says.  The geometry lives in the app layer;
this row only collects the points and says what was measured.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np
from PySide6.QtWidgets import QComboBox, QHBoxLayout, QLabel, QPushButton, QSpinBox, QWidget

from app.jobs.program import OpKind, Program
from app.jobs.registration import Point, RegistrationError, mirrored, register, registered
from app.station import Station


def reference_holes(program: Program) -> list[Point]:
    """Where each DRILL happens (X, Y of the MOVE just before it), in drilling order.

    From the program's arrays, not its operations one by one: a job without a
    drill (a 2-million-entry string-art file) costs nothing here, and a board
    of 50 000 holes is a few array operations on the GUI thread.
    """
    if OpKind.DRILL not in program.kinds():
        return []
    drills = program.indices_of(OpKind.DRILL)
    path = program.path(("X", "Y"))
    if not len(drills) or not len(path):
        return []
    # The last vertex of the operation just before each drill, when that one is a move.
    before = drills - 1
    at = np.searchsorted(path.ops, before, side="right") - 1
    valid = at >= 0
    at, before = at[valid], before[valid]
    moved = path.ops[at] == before
    coords = path.coords[at[moved]]
    known = ~np.isnan(coords).any(axis=1)
    return [(float(x), float(y)) for x, y in coords[known]]


class RegistrationBar(QWidget):
    """Collects two job holes and the measured machine points; hands back the moved job."""

    def __init__(
        self,
        station: Station,
        load: Callable[[Program], bool],
        say: Callable[[str], None],
    ) -> None:
        super().__init__()
        self.station = station
        self._load = load
        self._say = say
        #: The job as its file says (what registration transforms; Clear goes back to it).
        self.original: Program | None = None
        self._holes: list[Point] = []
        self.measured: list[Point | None] = [None, None]
        row = QHBoxLayout(self)
        row.setContentsMargins(0, 0, 0, 0)
        self.side_combo = QComboBox()
        self.side_combo.setObjectName("job_side")
        self.side_combo.setToolTip(
            "The bottom side of a double-sided board: the job mirrored about its own extent"
        )
        for label, about in (
            ("Top side", ""),
            ("Bottom, mirrored in X", "X"),
            ("Bottom, mirrored in Y", "Y"),
        ):
            self.side_combo.addItem(label, about)
        self.side_combo.activated.connect(self._side_changed)
        row.addWidget(self.side_combo)
        row.addWidget(QLabel("Register on holes"))
        self.hole_spins: list[QSpinBox] = []
        self.here_buttons: list[QPushButton] = []
        for k in range(2):
            spin = QSpinBox()
            spin.setObjectName(f"job_reference_{k + 1}")
            spin.setToolTip("A reference hole: its number in drilling order")
            spin.valueChanged.connect(lambda _v, k=k: self._forget(k))
            here = QPushButton("Here")
            here.setObjectName(f"job_reference_here_{k + 1}")
            here.setToolTip("The tool stands over this hole on the board: take its position")
            here.clicked.connect(lambda _c=False, k=k: self.take(k))
            row.addWidget(spin)
            row.addWidget(here)
            self.hole_spins.append(spin)
            self.here_buttons.append(here)
        self.register_button = QPushButton("Register")
        self.register_button.setObjectName("job_register")
        self.register_button.clicked.connect(self.apply)
        self.clear_button = QPushButton("Clear")
        self.clear_button.setObjectName("job_register_clear")
        self.clear_button.clicked.connect(self.clear)
        row.addWidget(self.register_button)
        row.addWidget(self.clear_button)
        row.addStretch(1)
        self.set_job(None)

    def set_job(self, program: Program | None) -> None:
        """A job as read from its file: its holes become the choices, measurements are dropped."""
        self.original = program
        self.side_combo.setCurrentIndex(0)
        self._choose_holes()

    @property
    def base(self) -> Program | None:
        """The job on the chosen side (mirrored for the bottom): what registration moves."""
        about = self.side_combo.currentData()
        if self.original is None or about not in ("X", "Y"):
            return self.original
        return mirrored(self.original, "X" if about == "X" else "Y")

    def _side_changed(self, *_args: object) -> None:
        try:
            base = self.base
        except RegistrationError as exc:
            self._say(f"cannot mirror: {exc}")
            self.side_combo.setCurrentIndex(0)
            return
        if base is not None:
            self._load(base)
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
            # Far apart registers best: the first hole and the one farthest from it.
            x0, y0 = self._holes[0]
            far = max(
                range(count),
                key=lambda i: (self._holes[i][0] - x0) ** 2 + (self._holes[i][1] - y0) ** 2,
            )
            self.hole_spins[0].setValue(1)
            self.hole_spins[1].setValue(far + 1)
        self.measured = [None, None]
        self.setVisible(count >= 2)
        self._update()

    def take(self, k: int) -> None:
        axes = self.station.model.axes
        self.measured[k] = (axes[0].position, axes[1].position)
        x, y = self.measured[k] or (0.0, 0.0)
        self._say(f"reference {k + 1} (hole {self.hole_spins[k].value()}) at X{x:.3f} Y{y:.3f}")
        self._update()

    def apply(self) -> None:
        first, second = self.measured
        base = self.base
        if base is None or first is None or second is None:
            return
        refs = [self._holes[spin.value() - 1] for spin in self.hole_spins]
        try:
            fit = register(refs, [first, second])
            moved = registered(base, fit)
        except RegistrationError as exc:
            self._say(f"registration refused: {exc}")
            return
        self._say(f"registered: {fit.describe()}")
        if warning := fit.warning():
            self._say(f"warning: {warning}")
        self._load(moved)

    def clear(self) -> None:
        """Back to the job as the file says on the chosen side, unregistered."""
        base = self.base
        if base is not None:
            self._load(base)
        self.measured = [None, None]
        self._update()

    def _forget(self, k: int) -> None:
        self.measured[k] = None
        self._update()

    def _update(self) -> None:
        self.register_button.setEnabled(None not in self.measured and self.original is not None)
