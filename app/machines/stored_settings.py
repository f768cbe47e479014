"""Values a device keeps across power cycles (GRBL's ``$N``, the usb3 unit's EEPROM), described.

One row per value: its name, unit, description, kind and the range the
station lets through.  The same row judges a value typed in the Settings
page, given to ``Machine.write_settings`` or read from a snapshot, and
makes the text that goes on the wire, so a value outside its range has no
path to the device: :meth:`StoredSetting.check` refuses it with the
reason, and :meth:`StoredSetting.wire_text` is only ever called on a value
it passed.

Labels and descriptions are English here and said in the operator's
language through ``QCoreApplication.translate`` with the table's own
context (each table marks its texts for lupdate).
"""

from __future__ import annotations

import enum
import math
import re
from dataclasses import dataclass

from PySide6.QtCore import QT_TRANSLATE_NOOP, QCoreApplication, QLocale

from app.local_numbers import local_number

#: The unit words of the stored settings, for lupdate (symbols like mm pass unchanged; the
#: window's :mod:`widgets.units` says the others in the same context).
UNIT_WORDS = (
    QT_TRANSLATE_NOOP("Unit", "step/mm"),
    QT_TRANSLATE_NOOP("Unit", "RPM"),
)

_DECIMAL_POINT = re.compile(r"(?<=\d)\.(?=\d)")


class Kind(enum.Enum):
    """How a value is typed and judged."""

    #: A whole number.
    INTEGER = "integer"
    #: A number with at most ``decimals`` decimals.
    DECIMAL = "decimal"
    #: 0 (off) or 1 (on).
    SWITCH = "switch"
    #: A whole number whose bits each mean one thing (``bits`` names them, lowest first).
    MASK = "mask"
    #: One of ``choices`` (a number that stands for a label).
    CHOICE = "choice"


@dataclass(frozen=True)
class StoredSetting:
    """One stored value: what it is called, what it means, what the station lets through."""

    #: How snapshots and scripts name it: ``"$110"``, ``"X.thread"``.
    key: str
    label: str
    unit: str
    description: str
    kind: Kind
    low: float
    high: float
    decimals: int = 0
    #: Bit names of a MASK, lowest bit first.
    bits: tuple[str, ...] = ()
    #: A CHOICE's (value, label) pairs.
    choices: tuple[tuple[int, str], ...] = ()
    #: Why the range is narrower than the device's own (said with a refusal), or "".
    narrowed: str = ""
    #: The translation context of the label, description and ``narrowed``.
    context: str = "StoredSetting"
    #: The device keeps the value as a 32-bit float (GRBL): read back, it may differ in
    #: its last digits from the one written, and still be the same.
    single_precision: bool = False
    #: The axis a per-axis row is of: its label's ``{0}``.
    axis: str = ""

    def shown_label(self) -> str:
        text = QCoreApplication.translate(self.context, self.label)
        return text.format(self.axis) if self.axis else text

    def shown_description(self) -> str:
        return QCoreApplication.translate(self.context, self.description)

    def shown_unit(self) -> str:
        return QCoreApplication.translate("Unit", self.unit) if self.unit else ""

    def check(self, value: object) -> str | None:
        """Why ``value`` must not be written, in the operator's language; None: it may."""
        name = f"{self.key} ({self.shown_label()})"
        if isinstance(value, bool) or not isinstance(value, int | float):
            return QCoreApplication.translate("StoredSetting", "{0}: {1!r} is not a number").format(
                name, value
            )
        if not math.isfinite(value):
            return QCoreApplication.translate("StoredSetting", "{0}: {1} is not a number").format(
                name, value
            )
        whole = self.kind is not Kind.DECIMAL
        if whole and value != int(value):
            return QCoreApplication.translate(
                "StoredSetting", "{0}: must be a whole number, not {1}"
            ).format(name, local_number(value))
        if not self.low <= value <= self.high:
            text = QCoreApplication.translate(
                "StoredSetting", "{0}: must be within {1}…{2} {3}"
            ).format(name, local_number(self.low), local_number(self.high), self.shown_unit())
            text = text.rstrip()
            if self.narrowed:
                text += f" ({QCoreApplication.translate(self.context, self.narrowed)})"
            return text
        if self.kind is Kind.DECIMAL and abs(round(value, self.decimals) - value) > 1e-9 * max(
            1.0, abs(value)
        ):
            return QCoreApplication.translate(
                "StoredSetting", "{0}: at most {1} decimals are kept, not {2}"
            ).format(name, self.decimals, local_number(value))
        if self.kind is Kind.CHOICE and int(value) not in {v for v, _ in self.choices}:
            return QCoreApplication.translate(
                "StoredSetting", "{0}: {1} is none of the choices"
            ).format(name, local_number(value))
        return None

    def wire_text(self, value: float) -> str:
        """The number as the device is sent it: never an exponent, no trailing zeros.

        Only for a value :meth:`check` passed.
        """
        if self.kind is not Kind.DECIMAL:
            return str(int(value))
        text = f"{value:.{self.decimals}f}"
        return text.rstrip("0").rstrip(".") if "." in text else text

    def same(self, wanted: float, held: float) -> bool:
        """Whether the device holds ``wanted`` when it reads back ``held``.

        A 32-bit float keeps about seven digits: GRBL reads ``$110=12345.678``
        into the nearest one and prints it back from that, so beyond a few
        thousand the last printed decimal may differ from the one written.
        """
        tolerance = 0.5 * 10.0**-self.decimals
        if self.single_precision:
            tolerance += abs(wanted) * 2.0**-20
        return abs(wanted - held) <= tolerance + 1e-12

    def shown_value(self, value: float) -> str:
        """The value as the operator reads it: a choice's label, a mask's bits, a number."""
        if self.kind is Kind.CHOICE:
            for number, label in self.choices:
                if number == int(value):
                    text = QCoreApplication.translate(self.context, label)
                    # "M8 (1.25 mm)": the pitch with the language's decimal separator.
                    return _DECIMAL_POINT.sub(QLocale().decimalPoint(), text)
        if self.kind is Kind.DECIMAL:
            return local_number(value)
        return str(int(value))
