"""How job files are read on this machine: the jobs dock's options.

Drill files drilled or drawn (the original tool's two run modes), their
crosses and bit order, the Excellon step of files whose integer coordinates
carry no format; G-code files' pen lines translated and lines the machine
cannot run skipped.  Only the options this machine can use are shown.  Texts
keep the ``JobsDock`` translation context they had in the dock.
"""

from __future__ import annotations

from PySide6.QtCore import QCoreApplication, Signal
from PySide6.QtWidgets import QCheckBox, QComboBox, QGridLayout, QHBoxLayout, QWidget

from app.jobs.formats.string_art.reader import StringArtParams
from app.jobs.loaders import JobOptions
from app.station import Station
from widgets.retranslate import Texts


class JobOptionsBox(QWidget):
    """The reading options in two short columns; :attr:`changed` on any change."""

    #: An option changed (or the drill's timing, which the estimate reads): read the file again.
    changed = Signal()

    def __init__(self, station: Station, texts: Texts, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.station = station
        self.texts = texts
        self.setLayout(self._build_options())

    def _build_drill_options(self) -> QWidget:
        """How drill files are read: drill or draw (the original tool's two run modes), and
        the Excellon step for files whose integer coordinates carry no format (returned: the
        step's row)."""
        t = self.texts
        self.draw_check = QCheckBox()
        t.set(
            self.draw_check.setText,
            lambda: QCoreApplication.translate("JobsDock", "Draw holes with the pen"),
        )
        self.draw_check.setObjectName("job_draw")
        t.set(
            self.draw_check.setToolTip,
            lambda: QCoreApplication.translate(
                "JobsDock",
                "Drill files: instead of drilling, the pen goes down (K) at each bit's first"
                " hole, draws along the following holes, X then Y, and comes up (Z) after the"
                " last, as the original tool drew",
            ),
        )
        self.crosses_check = QCheckBox()
        t.set(
            self.crosses_check.setText,
            lambda: QCoreApplication.translate("JobsDock", "Crosses at the holes"),
        )
        self.crosses_check.setObjectName("job_draw_crosses")
        t.set(
            self.crosses_check.setToolTip,
            lambda: QCoreApplication.translate(
                "JobsDock",
                "Drawn drill files: a pen cross the size of each hole instead of one line"
                " along the holes",
            ),
        )
        self.crosses_check.setEnabled(False)
        self.draw_check.toggled.connect(self.crosses_check.setEnabled)
        self.smallest_check = QCheckBox()
        t.set(
            self.smallest_check.setText,
            lambda: QCoreApplication.translate("JobsDock", "Smallest bit first"),
        )
        self.smallest_check.setObjectName("job_smallest_first")
        t.set(
            self.smallest_check.setToolTip,
            lambda: QCoreApplication.translate(
                "JobsDock",
                "Drill files: the bit changes ordered from the smallest drill to the largest",
            ),
        )
        self.step_combo = QComboBox()
        self.step_combo.setObjectName("job_excellon_step")
        for denominator, inch in (("10000", 1e-4), ("1000", 1e-3), ("100000", 1e-5)):
            self.step_combo.addItem("", inch)
            t.item(
                self.step_combo,
                self.step_combo.count() - 1,
                lambda d=denominator: QCoreApplication.translate("JobsDock", "1/{0} inch").format(
                    d
                ),
            )
        t.set(
            self.step_combo.setToolTip,
            lambda: QCoreApplication.translate(
                "JobsDock", "Excellon step: the unit of bare integer coordinates"
            ),
        )
        step = QHBoxLayout()
        step.setSpacing(4)
        self.step_label = t.label(lambda: QCoreApplication.translate("JobsDock", "Excellon step"))
        step.addWidget(self.step_label)
        step.addWidget(self.step_combo)
        step.addStretch(1)
        self.draw_check.toggled.connect(self._changed)
        # The drill's timing constants changed (S2-06): the open file is estimated anew.
        self.station.drillTimingChanged.connect(self._changed)
        # The drill's conversion constants changed (S2-42): the open file is read anew.
        self.station.drillConversionChanged.connect(self._changed)
        self.crosses_check.toggled.connect(self._changed)
        self.smallest_check.toggled.connect(self._changed)
        self.step_combo.activated.connect(self._changed)
        step_widget = QWidget()
        step_widget.setLayout(step)
        step.setContentsMargins(0, 0, 0, 0)
        return step_widget

    def _build_gcode_options(self) -> None:
        """G-code files: other flavours' pen commands, and lines the machine cannot run."""
        t = self.texts
        self.translate_pen_check = QCheckBox()
        t.set(
            self.translate_pen_check.setText,
            lambda: QCoreApplication.translate("JobsDock", "Use this machine's pen commands"),
        )
        self.translate_pen_check.setObjectName("job_translate_pen")
        self.translate_pen_check.setChecked(True)
        t.set(
            self.translate_pen_check.setToolTip,
            lambda: QCoreApplication.translate(
                "JobsDock",
                "G-code: M300/M280 servo lines, Z pen heights, M3/M5 are sent as this machine's "
                "own pen-up / pen-down commands",
            ),
        )
        self.skip_check = QCheckBox()
        t.set(
            self.skip_check.setText,
            lambda: QCoreApplication.translate("JobsDock", "Skip lines it cannot run"),
        )
        self.skip_check.setObjectName("job_skip_unsupported")
        t.set(
            self.skip_check.setToolTip,
            lambda: QCoreApplication.translate(
                "JobsDock",
                "G-code: lines this machine cannot execute (e.g. M18) are listed and left out "
                "instead of refusing the job",
            ),
        )
        for check in (self.translate_pen_check, self.skip_check):
            check.toggled.connect(self._changed)

    def _build_options(self) -> QGridLayout:
        """The options this machine can use, in two short columns."""
        step_widget = self._build_drill_options()
        self._build_gcode_options()
        grid = QGridLayout()
        grid.setHorizontalSpacing(8)
        grid.setVerticalSpacing(2)
        grid.setContentsMargins(0, 0, 0, 0)
        gcode = self.station.dialect.takes_gcode_text
        pen = self.station.profile.capabilities.pen
        drill = self.station.profile.capabilities.drill
        # Drill files are drilled or drawn: where the machine has neither tool they are
        # refused whatever these say, so they are not offered; the pen option only where
        # there is a pen (the winder drills but has none).
        offered: list[tuple[QWidget, bool]] = [
            (self.draw_check, pen),
            (self.crosses_check, pen),
            (step_widget, pen or drill),
            (self.smallest_check, drill),
            (self.translate_pen_check, gcode and pen),
            (self.skip_check, gcode),
        ]
        # Two short columns rather than one long row: the dock must fit beside the window's
        # pages on a 1280 px screen, so no option may set a width of its own.  Only the
        # options this machine offers are placed, in order, so no gap is left where a
        # hidden one would have been.
        placed = [w for w, visible in offered if visible] + [w for w, v in offered if not v]
        for index, widget in enumerate(placed):
            grid.addWidget(widget, index // 2, index % 2)  # hidden ones last: they take no room
        for widget, visible in offered:
            if not visible:
                # Only hidden: shown while not yet in the dock, each flashed up as a window of
                # its own and took the keyboard from the main window (no more arrow jogs).
                widget.hide()
        grid.setColumnStretch(2, 1)  # spare width beside, so a click on a check's caption hits it
        return grid

    def option_values(self) -> dict[str, object]:
        """The operator's reading options, to keep across launches (the main window stores)."""
        return {
            "draw": self.draw_check.isChecked(),
            "draw_crosses": self.crosses_check.isChecked(),
            "smallest_first": self.smallest_check.isChecked(),
            "excellon_step_inch": float(self.step_combo.currentData()),
            "translate_pen": self.translate_pen_check.isChecked(),
            "skip_unsupported": self.skip_check.isChecked(),
        }

    def restore_options(self, values: dict[str, object]) -> None:
        """Set the reading options from ``values`` (unknown or malformed entries are ignored)."""
        checks = {
            "draw": self.draw_check,
            "draw_crosses": self.crosses_check,
            "smallest_first": self.smallest_check,
            "translate_pen": self.translate_pen_check,
            "skip_unsupported": self.skip_check,
        }
        for key, check in checks.items():
            value = values.get(key)
            if isinstance(value, bool):
                check.setChecked(value)
            elif isinstance(value, str) and value in ("true", "false"):  # INI files keep text
                check.setChecked(value == "true")
        step = values.get("excellon_step_inch")
        try:
            index = self.step_combo.findData(float(str(step)))
        except ValueError:
            index = -1
        if index >= 0:
            self.step_combo.setCurrentIndex(index)

    def job_options(self, board: StringArtParams | None, format: str | None) -> JobOptions:
        """The options as the loaders take them, with the board and format the operator gave."""
        profile = self.station.profile
        return JobOptions(
            # A choice kept from another machine's session never applies where it is hidden.
            draw=self.draw_check.isChecked() and profile.capabilities.pen,
            draw_crosses=self.crosses_check.isChecked(),
            smallest_first=self.smallest_check.isChecked(),
            excellon_step_inch=float(self.step_combo.currentData()),
            translate_pen=self.translate_pen_check.isChecked(),
            skip_unsupported=self.skip_check.isChecked(),
            gcode=profile.gcode,
            machine_title=profile.shown_title,
            one_bit=profile.drill_one_bit,
            excellon_scale=self.station.drill_conversion.excellon_scale,
            axis_scale=tuple(
                (axis.name, self.station.drill_conversion.axis_scale(index))
                for index, axis in enumerate(profile.axes)
            ),
            string_art=board,
            format=format,
        )

    def _changed(self, *_args: object) -> None:
        self.changed.emit()
