"""The three-axis unit's page, as its own C# tool had it: move by millimetres per axis.

Per axis a signed distance, the step size and the thread (what the unit
needs to turn millimetres into steps), and Send; "Send all" moves every axis
by its distance in one command, as the tool's one Send did, and "Zero all"
zeroes all positions.  Because the unit moves in whole steps, the page shows the
distance that will really be moved next to the one typed.
"""

from __future__ import annotations

from PySide6.QtCore import Qt
from PySide6.QtWidgets import (
    QComboBox,
    QGridLayout,
    QHBoxLayout,
    QLabel,
    QPushButton,
    QWidget,
)

from app.machines.usb3.session import Usb3Session
from app.station import Station
from protocol.usb3.codec import StepSize, Thread
from widgets.number_field import FieldGate, NumberField, distance_box, localized
from widgets.retranslate import Texts, bold
from widgets.style import monospace_font


class Usb3Panel(QWidget):
    def __init__(self, station: Station, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self._station = station
        self._watched: Usb3Session | None = None
        self.distances: list[NumberField] = []
        self.note = QLabel()
        self.gate = FieldGate(self.note, self)
        self.reachable: list[QLabel] = []
        self.step_combos: list[QComboBox] = []
        self.thread_combos: list[QComboBox] = []
        self.send_buttons: list[QPushButton] = []
        t = self.texts = Texts(self)

        grid = QGridLayout(self)
        grid.setHorizontalSpacing(10)
        grid.setVerticalSpacing(8)
        titles = (
            lambda: bold(self.tr("Move by")),
            lambda: bold(self.tr("Will move")),
            lambda: bold(self.tr("Step")),
            lambda: bold(self.tr("Thread")),
        )
        for column, title in enumerate(titles, start=1):
            header = t.label(title)
            header.setWordWrap(True)  # two short lines rather than a column too wide
            grid.addWidget(header, 0, column, Qt.AlignmentFlag.AlignBottom)
        for index, axis in enumerate(station.profile.axes):
            row = index + 1
            distance = distance_box(
                f"distance_{axis.name}",
                axis.unit,
                -axis.travel,
                axis.travel,
                "",
            )
            t.set(
                distance.set_description,
                lambda a=axis: self.tr("Signed distance to move {0} (fractions allowed)").format(
                    a.name
                ),
            )
            distance.textChanged.connect(lambda _t="", i=index: self._show_reachable(i))
            reachable = QLabel()
            reachable.setFont(monospace_font())
            t.set(
                reachable.setToolTip,
                lambda: self.tr("The unit moves in whole steps: this is what it will really move"),
            )
            steps = self._step_combo(index)
            threads = self._thread_combo(index)
            send = t.button(lambda a=axis: self.tr("Send {0}").format(a.name))
            send.clicked.connect(lambda _=False, i=index: self.send(i))
            for column, widget in enumerate(
                (QLabel(axis.name), distance, reachable, steps, threads, send)
            ):
                grid.addWidget(widget, row, column)
            self.distances.append(distance)
            self.reachable.append(reachable)
            self.step_combos.append(steps)
            self.thread_combos.append(threads)
            self.send_buttons.append(send)
            self.gate.watch(distance, lambda a=axis: self.tr("{0} distance").format(a.name))
            self.gate.bind(send, distance)
        self.zero_button = t.button(
            lambda: self.tr("Zero all"),
            lambda: self.tr("Set every axis' position to 0 where it stands (C;)"),
        )
        self.zero_button.clicked.connect(self.zero_all)
        # The unit's own tool had one Send for the three axes (FIDELITY S4-22): they start
        # together; the per-axis Sends stay for moving one alone.
        self.send_all_button = t.button(
            lambda: self.tr("Send all"),
            lambda: self.tr("Move every axis by its distance, all starting together"),
        )
        self.send_all_button.clicked.connect(self.send_all)
        self.gate.bind(self.send_all_button, *self.distances)
        # Side by side under the last columns, in a row of their own: in the grid's cells
        # they widened the columns, and the page outgrew a 1280 px screen beside the dock.
        both = QHBoxLayout()
        both.setSpacing(10)
        both.addStretch(1)
        both.addWidget(self.send_all_button)
        both.addWidget(self.zero_button)
        grid.addLayout(both, len(self.distances) + 1, 2, 1, 4)
        grid.addWidget(self.note, len(self.distances) + 2, 0, 1, 6)
        grid.setColumnStretch(6, 1)
        grid.setRowStretch(len(self.distances) + 3, 1)
        station.sessionChanged.connect(self._watch_session)
        self._watch_session()
        t.also(self._show_settings)

    def _step_combo(self, index: int) -> QComboBox:
        steps = QComboBox()
        for size in StepSize:
            steps.addItem(size.label, size)
        self.texts.item(steps, 0, lambda: self.tr("full", "full step"))
        steps.activated.connect(lambda _i=0, i=index: self._step_chosen(i))
        return steps

    def _thread_combo(self, index: int) -> QComboBox:
        threads = QComboBox()
        for number, thread in enumerate(Thread):
            threads.addItem("", thread)
            # The pitch in the language's form (0,7 mm), again after a language switch.
            self.texts.item(
                threads,
                number,
                lambda th=thread: localized(f"{th.name} ({th.pitch_mm:g} mm)"),
            )
        threads.activated.connect(lambda _i=0, i=index: self._thread_chosen(i))
        return threads

    @property
    def session(self) -> Usb3Session | None:
        return self._station.session_as(Usb3Session)

    def send(self, axis: int) -> bool:
        """Move ``axis`` by its distance; False when refused (bad distance, locked)."""
        distance = self.distances[axis].value()
        if distance is None:
            self.gate.refusal(self.distances[axis])
            return False
        session = self.session
        return session is not None and session.move_relative(axis, distance)

    def send_all(self) -> bool:
        """Every axis by its distance in one command; False when refused (nothing moves)."""
        if self.gate.refusal(*self.distances) is not None:
            return False
        distances = [field.value() or 0.0 for field in self.distances]
        session = self.session
        return session is not None and session.move_relative_axes(distances)

    def zero_all(self) -> None:
        if self.session is not None:
            self.session.zero_all()

    def set_motion_enabled(self, enabled: bool) -> None:
        self.gate.set_enabled(enabled)

    def _step_chosen(self, axis: int) -> None:
        if self.session is not None:
            self.session.set_step_size(axis, StepSize(self.step_combos[axis].currentData()))

    def _thread_chosen(self, axis: int) -> None:
        if self.session is not None:
            self.session.set_thread(axis, Thread(self.thread_combos[axis].currentData()))

    def _watch_session(self) -> None:
        session = self.session
        if session is self._watched:
            return
        self._watched = session
        if session is not None:
            # The unit's own menu can change these; the panel follows what it reports.
            session.settingsChanged.connect(self._show_settings)
        self._show_settings()

    def _show_settings(self) -> None:
        session = self.session
        for axis in range(len(self.distances)):
            if session is not None:
                self.step_combos[axis].setCurrentIndex(int(session.step_sizes[axis]))
                self.thread_combos[axis].setCurrentIndex(int(session.threads[axis]))
            self._show_reachable(axis)

    def _show_reachable(self, axis: int) -> None:
        session = self.session
        if session is None:
            self.reachable[axis].setText("—")
            return
        distance = self.distances[axis].value()
        if distance is None:
            self.reachable[axis].setText("—")
            return
        mm = session.reachable(axis, distance)
        speed = session.speed_mm_s(axis)
        self.reachable[axis].setText(localized(f"{mm:+.4f} mm"))
        self.reachable[axis].setToolTip(
            self.tr("The unit moves in whole steps; top speed at this step size {0} mm/s").format(
                localized(f"{speed:.3f}")
            )
        )
