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

from PySide6.QtWidgets import QComboBox, QHBoxLayout, QPushButton, QSpinBox, QWidget

from app.jobs.program import OpKind, Program
from app.jobs.registration import Point, RegistrationError, mirrored, register, registered
from app.station import Station
from widgets.retranslate import Maker, Texts


def reference_holes(program: Program) -> list[Point]:
    """Where each DRILL happens (X, Y of the MOVE before it), in drilling order."""
    holes: list[Point] = []
    for index, where, _pen in program.positions():
        after = index + 1
        if after < len(program) and program[after].kind is OpKind.DRILL:
            if "X" in where and "Y" in where:
                holes.append((where["X"], where["Y"]))
    return holes


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
        t = self.texts = Texts(self)
        row = QHBoxLayout(self)
        row.setContentsMargins(0, 0, 0, 0)
        self.side_combo = QComboBox()
        self.side_combo.setObjectName("job_side")
        t.set(
            self.side_combo.setToolTip,
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
            self.side_combo.addItem("", about)
            t.item(self.side_combo, self.side_combo.count() - 1, label)
        self.side_combo.activated.connect(self._side_changed)
        row.addWidget(self.side_combo)
        row.addWidget(t.label(lambda: self.tr("Register on holes")))
        self.hole_spins: list[QSpinBox] = []
        self.here_buttons: list[QPushButton] = []
        for k in range(2):
            spin = QSpinBox()
            spin.setObjectName(f"job_reference_{k + 1}")
            t.set(
                spin.setToolTip, lambda: self.tr("A reference hole: its number in drilling order")
            )
            spin.valueChanged.connect(lambda _v, k=k: self._forget(k))
            here = t.button(
                lambda: self.tr("Here"),
                lambda: self.tr("The tool stands over this hole on the board: take its position"),
            )
            here.setObjectName(f"job_reference_here_{k + 1}")
            here.clicked.connect(lambda _c=False, k=k: self.take(k))
            row.addWidget(spin)
            row.addWidget(here)
            self.hole_spins.append(spin)
            self.here_buttons.append(here)
        self.register_button = t.button(lambda: self.tr("Register"))
        self.register_button.setObjectName("job_register")
        self.register_button.clicked.connect(self.apply)
        self.clear_button = t.button(lambda: self.tr("Clear"))
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
            self._say(self.tr("cannot mirror: {0}").format(exc))
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
        self._say(
            self.tr("reference {0} (hole {1}) at X{2} Y{3}").format(
                k + 1, self.hole_spins[k].value(), f"{x:.3f}", f"{y:.3f}"
            )
        )
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
            self._say(self.tr("registration refused: {0}").format(exc))
            return
        self._say(self.tr("registered: {0}").format(fit.describe()))
        if warning := fit.warning():
            self._say(self.tr("warning: {0}").format(warning))

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
