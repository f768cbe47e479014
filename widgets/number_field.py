"""A number field that keeps what the operator typed and says when it is out of range.

A spin box refuses the keystroke that would leave its range, so typing 80
into a 0…50 field leaves 8 — and a Go then moves to 8.  It also clamps a
value set from code.  Both turn the operator's number into another one.
This field never does: the text stays exactly as typed, a value outside the
range (or with more decimals than the field takes) is framed red with the
reason and the range in its tooltip, and :meth:`NumberField.value` is None
until the text is an acceptable number, so an action cannot use it by
accident.  Only characters that can never be part of a number are refused
as typed.

Up and Down step by the single step (PageUp/PageDown by ten), within the
range, as a spin box does; the unit is drawn inside the field, right-aligned.

Numbers are shown with the decimal separator of the language in use (a comma
in Czech and Slovak), and both a point and a comma are accepted when typed,
whatever the language: an operator used to either is never refused.
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable

from PySide6.QtCore import QCoreApplication, QEvent, QLocale, QObject, Qt, QTimer, Signal
from PySide6.QtGui import QColor, QKeyEvent, QPainter, QPaintEvent, QValidator
from PySide6.QtWidgets import QLabel, QLineEdit, QPushButton, QWidget

from widgets.style import MINUS, monospace_font
from widgets.units import shown_unit

#: A number being typed: optional sign, digits, one decimal point or comma, digits.
_PARTIAL = re.compile(r"[+\-\u2212]?\d*(?:[.,]\d*)?")
_INVALID_STYLE = "QLineEdit { border: 2px solid #d03030; background: #fff0f0; color: #1d1d1d; }"
_UNIT_COLOUR = QColor("#707070")
#: The note under a page's fields that says which one is wrong.
NOTE_STYLE = "color: #d03030;"


class _NumberShape(QValidator):
    """Refuses only keystrokes that can never make a number; range is judged elsewhere."""

    def validate(self, text: str, pos: int) -> object:
        if _PARTIAL.fullmatch(text.strip()):
            return QValidator.State.Acceptable, text, pos
        return QValidator.State.Invalid, text, pos


def decimal_point() -> str:
    """The decimal separator of the language in use ("," in Czech and Slovak)."""
    return "," if QLocale().decimalPoint() == "," else "."


def localized(text: str) -> str:
    """A number formatted by Python (``f"{x:.3f}"``) with the language's decimal separator."""
    point = decimal_point()
    return text if point == "." else text.replace(".", point)


def format_number(value: float, decimals: int) -> str:
    """How a value is filled in: its fixed decimals, an ASCII minus the operator can retype."""
    return localized(f"{value:.{decimals}f}")


def _short(value: float, decimals: int) -> str:
    """A limit as the tooltip names it: no trailing zeros, the typographic minus."""
    text = f"{value:.{decimals}f}"
    if "." in text:
        text = text.rstrip("0").rstrip(".")
    return localized(text).replace("-", MINUS)


class NumberField(QLineEdit):
    """A number in ``[low, high]`` with at most ``decimals`` decimals, and a unit."""

    #: An acceptable value was committed: Enter, focus out or an Up/Down step.
    committed = Signal(float)
    #: The field turned acceptable or not acceptable (its buttons follow this).
    validityChanged = Signal(bool)

    def __init__(
        self,
        low: float,
        high: float,
        *,
        decimals: int = 3,
        unit: str = "",
        step: float = 1.0,
        name: str = "",
        tooltip: str = "",
        value: float | None = None,
        parent: QWidget | None = None,
    ) -> None:
        super().__init__(parent)
        if name:
            self.setObjectName(name)
        self._low = low
        self._high = high
        self._decimals = decimals
        self._unit = unit
        #: What follows the unit, derived from the value (e.g. a current scale's amperes).
        self._note = ""
        self._step = step
        self._base_tooltip = tooltip
        self._problem: str | None = None
        self._acceptable = True
        self.setValidator(_NumberShape(self))
        self.setFont(monospace_font())
        self.setAlignment(Qt.AlignmentFlag.AlignRight | Qt.AlignmentFlag.AlignVCenter)
        self.setMinimumWidth(130)
        self._reserve_unit_space()
        self.textChanged.connect(self._judge)
        self.editingFinished.connect(self._commit)
        # Like a spin box: zero, or the range's end nearest to it.
        self.setValue(min(high, max(low, 0.0)) if value is None else value)

    # --- the spin-box-like surface the panels use ----------------------------------

    def minimum(self) -> float:
        return self._low

    def maximum(self) -> float:
        return self._high

    def decimals(self) -> int:
        return self._decimals

    def unit(self) -> str:
        return self._unit

    def note(self) -> str:
        return self._note

    def set_note(self, text: str) -> None:
        """Words drawn after the unit, such as what the typed value means on the machine."""
        if text == self._note:
            return
        self._note = text
        self._reserve_unit_space()
        self.update()

    def _suffix(self) -> str:
        return " ".join(part for part in (shown_unit(self._unit), self._note) if part)

    def set_description(self, text: str) -> None:
        """What the field is for, the first line of its tooltip (the range follows)."""
        self._base_tooltip = text
        self._judge()

    def changeEvent(self, event: QEvent) -> None:
        if event.type() == QEvent.Type.LanguageChange:
            self._judge()  # the reason and the range, in the new language
        super().changeEvent(event)

    def setRange(self, low: float, high: float) -> None:
        """A new range is judged against the text as it stands; the text is not touched."""
        self._low, self._high = low, high
        self._judge()

    def setValue(self, value: float) -> None:
        """Show ``value`` as it is — out of range it is shown, and framed invalid."""
        self.setText(format_number(value, self._decimals))
        self._judge()  # also when the caller blocked signals to fill the field quietly

    def number(self) -> float | None:
        """The number the text spells, in range or not; None when it spells none."""
        text = self.text().strip().replace(MINUS, "-").replace(",", ".")
        try:
            number = float(text)
        except ValueError:
            return None
        return number if math.isfinite(number) else None

    def value(self) -> float | None:
        """The number when it is acceptable (in range, not too precise), else None."""
        return self.number() if self._acceptable else None

    def is_acceptable(self) -> bool:
        return self._acceptable

    def problem(self) -> str | None:
        """Why the text is not acceptable, for the operator; None when it is."""
        return self._problem

    def range_text(self) -> str:
        unit = f" {shown_unit(self._unit)}" if self._unit else ""
        low, high = _short(self._low, self._decimals), _short(self._high, self._decimals)
        return f"{low}…{high}{unit}"

    # --- judging ---------------------------------------------------------------

    def _judge(self, _text: str = "") -> None:
        problem = self._find_problem()
        acceptable = problem is None
        self._problem = problem
        self.setStyleSheet("" if acceptable else _INVALID_STYLE)
        tip = self._base_tooltip
        limits = QCoreApplication.translate("NumberField", "Allowed: {0}").format(self.range_text())
        tip = f"{tip}\n{limits}" if tip else limits
        self.setToolTip(tip if acceptable else f"{problem}\n{tip}")
        if acceptable != self._acceptable:
            self._acceptable = acceptable
            self.validityChanged.emit(acceptable)

    def _find_problem(self) -> str | None:
        number = self.number()
        if number is None:
            return (
                QCoreApplication.translate("NumberField", "Not a number")
                if self.text().strip()
                else QCoreApplication.translate("NumberField", "Empty: type a number")
            )
        if not self._low <= number <= self._high:
            return QCoreApplication.translate("NumberField", "{0} is outside {1}").format(
                self.text().strip(), self.range_text()
            )
        fraction = self.text().strip().replace(",", ".").partition(".")[2]
        if len(fraction.rstrip("0")) > self._decimals:
            if self._decimals > 0:
                return self.tr("At most %n decimal(s)", "", self._decimals)
            return QCoreApplication.translate("NumberField", "Whole numbers only")
        return None

    def _commit(self) -> None:
        value = self.value()
        if value is not None:
            self.committed.emit(value)

    # --- keys and looks ----------------------------------------------------------

    def keyPressEvent(self, event: QKeyEvent) -> None:
        steps = {
            Qt.Key.Key_Up: 1,
            Qt.Key.Key_Down: -1,
            Qt.Key.Key_PageUp: 10,
            Qt.Key.Key_PageDown: -10,
        }.get(Qt.Key(event.key()))
        if steps is None or self.isReadOnly():
            super().keyPressEvent(event)
            return
        self.step_by(steps)
        event.accept()

    def step_by(self, steps: int) -> None:
        """Up/Down: step from the number shown, and stay within the range."""
        start = self.number()
        if start is None:
            start = self._low
        target = min(self._high, max(self._low, start + steps * self._step))
        self.setValue(target)
        self._commit()

    def _reserve_unit_space(self) -> None:
        suffix = self._suffix()
        width = self.fontMetrics().horizontalAdvance(f" {suffix}") + 6 if suffix else 0
        self.setTextMargins(0, 0, width, 0)

    def paintEvent(self, event: QPaintEvent) -> None:
        super().paintEvent(event)
        suffix = self._suffix()
        if not suffix:
            return
        painter = QPainter(self)
        painter.setPen(_UNIT_COLOUR)
        painter.setFont(self.font())
        area = self.rect().adjusted(0, 0, -6, 0)
        align = Qt.AlignmentFlag.AlignRight | Qt.AlignmentFlag.AlignVCenter
        painter.drawText(area, align, suffix)
        painter.end()


def distance_box(name: str, unit: str, low: float, high: float, tooltip: str) -> NumberField:
    """A distance field as every motion panel shows it: three decimals, the axis unit."""
    return NumberField(low, high, decimals=3, unit=unit, name=name, tooltip=tooltip)


class FieldGate(QObject):
    """Action buttons that need acceptable fields, and a note that says what is wrong.

    A button is enabled only while the motion lock allows it and every field
    it reads is acceptable; the note under the fields names each field that
    is not, and why, so the operator sees the reason where they typed.  Labels may be
    given as functions, so that they follow a language switch.
    """

    def __init__(self, note: QLabel, parent: QObject | None = None) -> None:
        super().__init__(parent)
        self.note = note
        note.setWordWrap(True)
        note.setStyleSheet(NOTE_STYLE)
        note.hide()
        self._bound: list[tuple[QPushButton, tuple[NumberField, ...], str]] = []
        self._fields: dict[NumberField, str | Callable[..., str]] = {}
        self._enabled = True
        self._written: dict[QPushButton, str] = {}

    def _label(self, field: NumberField) -> str:
        label = self._fields.get(field, field.objectName())
        return label if isinstance(label, str) else label()

    def event(self, event: QEvent) -> bool:
        if event.type() == QEvent.Type.LanguageChange:
            # After the whole tree has its new texts: the buttons' tooltips are then the
            # new plain ones again, and the fields have judged themselves anew.
            QTimer.singleShot(0, self, self._retranslate)
        return super().event(event)

    def _retranslate(self) -> None:
        bound = []
        for button, fields, tip in self._bound:
            shown = button.toolTip()
            # Unchanged since the gate wrote it: nobody made the plain tooltip again.
            bound.append((button, fields, tip if shown == self._written.get(button) else shown))
        self._bound = bound
        self._refresh()

    def watch(self, field: NumberField, label: str | Callable[..., str]) -> None:
        """Name ``field`` in the note as ``label`` when it is not acceptable."""
        self._fields[field] = label
        field.validityChanged.connect(self._refresh)
        field.textChanged.connect(self._refresh)
        self._refresh()

    def bind(self, button: QPushButton, *fields: NumberField) -> None:
        for field in fields:
            if field not in self._fields:
                self.watch(field, field.objectName())
        self._bound.append((button, fields, button.toolTip()))
        self._refresh()

    def set_enabled(self, enabled: bool) -> None:
        """The motion lock: with it off no bound button is enabled, whatever the fields say."""
        self._enabled = enabled
        self._refresh()

    def refusal(self, *fields: NumberField) -> str | None:
        """Why an action reading ``fields`` must not go, or None; said in the note too."""
        problems = [f"{self._label(f)}: {f.problem()}" for f in fields]
        wrong = [p for f, p in zip(fields, problems, strict=True) if not f.is_acceptable()]
        if not wrong:
            return None
        reason = QCoreApplication.translate("NumberField", "Not sent — {0}").format(
            "; ".join(wrong)
        )
        self.note.setText(reason)
        self.note.show()
        return reason

    def _refresh(self, *_args: object) -> None:
        wrong = [
            f"{self._label(field)}: {field.problem()}"
            for field in self._fields
            if not field.is_acceptable()
        ]
        self.note.setText("; ".join(wrong))
        self.note.setVisible(bool(wrong))
        for button, fields, tip in self._bound:
            bad = [f.problem() or "" for f in fields if not f.is_acceptable()]
            button.setEnabled(self._enabled and not bad)
            disabled = (
                QCoreApplication.translate("NumberField", "Disabled: {0}").format(bad[0])
                if bad
                else ""
            )
            self._written[button] = f"{tip}\n{disabled}" if bad else tip
            button.setToolTip(self._written[button])
