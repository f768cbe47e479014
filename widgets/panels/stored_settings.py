"""Settings page: the device's stored settings (GRBL's ``$$``, the usb3 unit's EEPROM), edited.

One row per setting with its number, name, value, unit and what the
device last confirmed; the description and the allowed range are the
row's tooltip.  A value typed outside its range is framed red as it is
typed and Apply does not send it: the whole write is refused, with each
reason, before a byte goes out (:class:`~app.machines.settings_access.
SettingsAccess`, the object the scripting API uses too).  What is sent
is read back, and the state column says what the device keeps.

Snapshots save the values to a TOML file; loading one shows what differs
from the device and writes only that, once the operator confirms (and
confirms again for another machine's file).  Nothing is written while a
job runs or an axis moves.
"""

from __future__ import annotations

from pathlib import Path

from PySide6.QtCore import QCoreApplication, QEvent, QObject, QRect, Qt, QTimer
from PySide6.QtGui import QBrush, QColor
from PySide6.QtWidgets import (
    QComboBox,
    QFileDialog,
    QHBoxLayout,
    QHeaderView,
    QLabel,
    QMessageBox,
    QStyle,
    QTableWidget,
    QTableWidgetItem,
    QVBoxLayout,
    QWidget,
)

from app.machine import LinkState
from app.machines.settings_access import Outcome, SettingsAccess
from app.machines.stored_settings import Kind, StoredSetting
from app.scripting.errors import StepdeckError
from app.scripting.settings_snapshot import (
    SettingDifference,
    check_machine,
    diff,
    firmware_change,
    load_snapshot,
    save_snapshot,
)
from app.station import Station
from app.stored_access import settings_access
from widgets.number_field import localized
from widgets.retranslate import Texts

KEY, NAME, VALUE, UNIT, STATE = range(5)
# Room a cell's text leaves to its frame and the item's margins, in pixels.
NAME_PADDING = 10
_RED, _GREEN, _AMBER = "#d03030", "#2e9e44", "#b07000"


class StoredSettingsPanel(QWidget):
    """The table of one device's stored settings, with Read, Apply and snapshots."""

    def __init__(
        self, station: Station, specs: tuple[StoredSetting, ...], parent: QWidget | None = None
    ) -> None:
        super().__init__(parent)
        self._station = station
        self.specs = specs
        self.access: SettingsAccess | None = None
        #: Keys the operator changed since the device last said what it holds.
        self.edited: set[str] = set()
        #: Keys the last write read back as written (their state says so until the next read).
        self.read_back: set[str] = set()
        self._filling = False
        #: The open "write these differences?" question, while it is asked.
        self.confirm_box: QMessageBox | None = None
        t = self.texts = Texts(self)

        self.table = QTableWidget(len(specs), 5)
        self.table.setObjectName("stored_settings")
        self.table.verticalHeader().hide()
        header = self.table.horizontalHeader()
        header.setSectionResizeMode(NAME, QHeaderView.ResizeMode.Stretch)
        # The names wrap: a row as tall as its name needs at the width the page gives.
        # (A stretched column's width follows the table's, without sectionResized.)
        self.table.installEventFilter(self)
        self.combos: dict[str, QComboBox] = {}
        for row, spec in enumerate(specs):
            self._build_row(row, spec)
        self.table.itemChanged.connect(self._item_changed)

        self.read_button = t.button(
            lambda: self.tr("Read"), lambda: self.tr("Read every setting from the device")
        )
        self.read_button.clicked.connect(self.read)
        self.apply_button = t.button(
            lambda: self.tr("Apply"),
            lambda: self.tr("Write the edited values, then read them back from the device"),
        )
        self.apply_button.clicked.connect(self.apply)
        self.save_button = t.button(
            lambda: self.tr("Save snapshot…"),
            lambda: self.tr("Save every setting to a TOML file"),
        )
        self.save_button.clicked.connect(self._ask_save)
        self.load_button = t.button(
            lambda: self.tr("Load snapshot…"),
            lambda: self.tr("Show what a snapshot changes, then write only that"),
        )
        self.load_button.clicked.connect(self._ask_load)
        self.summary = QLabel()
        self.summary.setObjectName("settings_summary")
        self.summary.setWordWrap(True)
        buttons = QHBoxLayout()
        for button in (self.read_button, self.apply_button, self.save_button, self.load_button):
            buttons.addWidget(button)
        buttons.addStretch(1)
        layout = QVBoxLayout(self)
        layout.addWidget(self.table, 1)
        layout.addLayout(buttons)
        layout.addWidget(self.summary)
        t.set(
            self.table.setHorizontalHeaderLabels,
            lambda: [self.tr("Setting"), self.tr("Name"), self.tr("Value"), "", self.tr("State")],  # type: ignore[arg-type,return-value]
        )
        t.also(self._retranslate_rows)
        self._retranslate_rows()
        station.sessionChanged.connect(self._bind)
        station.model.linkStateChanged.connect(self._update_enabled)
        station.model.lockChanged.connect(self._update_enabled)
        self._bind()

    # --- rows -------------------------------------------------------------------------

    def _build_row(self, row: int, spec: StoredSetting) -> None:
        for column in (KEY, NAME, UNIT, STATE):
            item = QTableWidgetItem()
            item.setFlags(item.flags() & ~Qt.ItemFlag.ItemIsEditable)
            self.table.setItem(row, column, item)
        self._cell(row, KEY).setText(spec.key)
        value = QTableWidgetItem()
        self.table.setItem(row, VALUE, value)
        if spec.kind is Kind.CHOICE:
            value.setFlags(value.flags() & ~Qt.ItemFlag.ItemIsEditable)
            combo = QComboBox()
            combo.setObjectName(f"choice_{spec.key}")
            for number, _label in spec.choices:
                combo.addItem(spec.shown_value(number), number)
            combo.setCurrentIndex(-1)
            combo.activated.connect(lambda _index, key=spec.key: self._mark_edited(key))
            self.combos[spec.key] = combo
            self.table.setCellWidget(row, VALUE, combo)

    def _retranslate_rows(self) -> None:
        # A new tooltip on a value cell is an itemChanged too: not an operator's edit.
        self._filling, filling = True, self._filling
        try:
            self._retranslate_cells()
        finally:
            self._filling = filling
        self.table.resizeColumnToContents(KEY)
        self.table.resizeColumnToContents(UNIT)
        self._size_columns()

    def _size_columns(self) -> None:
        """The value and state columns as wide as what they show, the rest to the names.

        At their default 100 px each, in Czech or Slovak the names were cut to
        "Inverze …" on a page beside the jobs dock; a long name now wraps onto a
        second line of its row instead.
        """
        metrics = self.table.fontMetrics()
        pad = 4 * self.table.style().pixelMetric(QStyle.PixelMetric.PM_FocusFrameHMargin) + 12
        widest_value = max(
            [metrics.horizontalAdvance("-00000.000")]
            + [combo.sizeHint().width() - pad for combo in self.combos.values()]
        )
        self.table.setColumnWidth(VALUE, widest_value + pad)
        states = [self.tr("✗ not allowed"), self.tr("✓ read back"), self.tr("• edited")]
        states += [self.tr("✗ refused"), self.tr("State")]
        self.table.setColumnWidth(STATE, max(metrics.horizontalAdvance(s) for s in states) + pad)
        self._fit_rows()

    def eventFilter(self, watched: QObject, event: QEvent) -> bool:
        if watched is self.table and event.type() == QEvent.Type.Resize:
            QTimer.singleShot(0, self, self._fit_rows)  # once the header has stretched
        return super().eventFilter(watched, event)

    def _fit_rows(self) -> None:
        """Each row as tall as its name wrapped at the name column's width (the item
        delegate measures one line whatever the width)."""
        metrics = self.table.fontMetrics()
        width = self.table.columnWidth(NAME) - NAME_PADDING
        line = self.table.verticalHeader().defaultSectionSize()
        for row in range(self.table.rowCount()):
            text = self._cell(row, NAME).text()
            needed = metrics.boundingRect(
                QRect(0, 0, max(width, 1), 10_000), Qt.TextFlag.TextWordWrap, text
            ).height()
            self.table.setRowHeight(row, max(line, needed + NAME_PADDING))

    def _retranslate_cells(self) -> None:
        for row, spec in enumerate(self.specs):
            self._cell(row, NAME).setText(spec.shown_label())
            self._cell(row, UNIT).setText(spec.shown_unit())
            tip = self._tip(spec)
            for column in (KEY, NAME, VALUE):
                self._cell(row, column).setToolTip(tip)
            combo = self.combos.get(spec.key)
            if combo is not None:
                for index, (number, _label) in enumerate(spec.choices):
                    combo.setItemText(index, spec.shown_value(number))
                combo.setToolTip(tip)

    def _tip(self, spec: StoredSetting) -> str:
        if spec.kind is Kind.CHOICE:
            allowed = ", ".join(spec.shown_value(n) for n, _ in spec.choices)
        elif spec.kind is Kind.SWITCH and spec.high == 1:
            allowed = self.tr("0 (off) or 1 (on)")
        else:
            low, high = localized(f"{spec.low:g}"), localized(f"{spec.high:g}")
            allowed = f"{low}…{high} {spec.shown_unit()}".rstrip()
        text = spec.shown_description() + "\n" + self.tr("Allowed: {0}").format(allowed)
        if spec.bits:
            bits = ", ".join(
                f"{1 << i} = {QCoreApplication.translate(spec.context, bit)}"
                for i, bit in enumerate(spec.bits)
            )
            text += "\n" + self.tr("Bits: {0}").format(bits)
        return text

    def _cell(self, row: int, column: int) -> QTableWidgetItem:
        item = self.table.item(row, column)
        assert item is not None  # every cell got its item in _build_row
        return item

    def row_of(self, key: str) -> int:
        return next(row for row, spec in enumerate(self.specs) if spec.key == key)

    # --- the device ---------------------------------------------------------------------

    def _bind(self) -> None:
        """The session changed (a connect): follow its settings."""
        access = settings_access(self._station.session)
        if access is self.access:
            return
        if self.access is not None:
            self.access.changed.disconnect(self._show_values)
            self.access.finished.disconnect(self._finished)
        self.access = access
        if access is not None:
            access.changed.connect(self._show_values)
            access.finished.connect(self._finished)
            self._show_values()
        self._update_enabled()

    def _show_values(self) -> None:
        """What the device holds, in every row the operator has not changed."""
        if self.access is None:
            return
        self._filling = True
        try:
            for row, spec in enumerate(self.specs):
                value = self.access.values.get(spec.key)
                if value is None or spec.key in self.edited:
                    continue
                combo = self.combos.get(spec.key)
                if combo is not None:
                    combo.setCurrentIndex(combo.findData(int(value)))
                else:
                    self._cell(row, VALUE).setText(localized(spec.wire_text(value)))
                self._judge(row, spec)
        finally:
            self._filling = False

    # --- operator actions -----------------------------------------------------------------

    def read(self) -> None:
        if self.access is None:
            return
        refusal = self.access.read()
        if refusal is not None:
            self.summary.setText(self.tr("Not read: {0}").format(refusal))
            return
        self.edited.clear()
        self.summary.setText(self.tr("Reading from the device…"))
        self._update_enabled()

    def changes(self) -> dict[str, object]:
        """The edited values, as typed (a text that is no number stays text: refused)."""
        out: dict[str, object] = {}
        for key in self.edited:
            combo = self.combos.get(key)
            if combo is not None:
                out[key] = float(combo.currentData())
            else:
                text = self._cell(self.row_of(key), VALUE).text().strip()
                out[key] = _number(text)
        return out

    def apply(self) -> bool:
        """Write every edited value, checked whole first; True when the write went out."""
        if self.access is None:
            return False
        changes = self.changes()
        if not changes:
            self.summary.setText(self.tr("Nothing changed"))
            return False
        refusal = self.access.write(changes)
        if refusal is not None:
            self.summary.setText(self.tr("Not written: {0}").format(refusal))
            return False
        self.summary.setText(self.tr("Writing, then reading back…"))
        self._update_enabled()
        return True

    def _finished(self, outcome: Outcome) -> None:
        if outcome.kind == "write":
            self.read_back = set(outcome.values)
        else:
            self.read_back.clear()
        if outcome.ok:
            text = (
                self.tr("Every setting read")
                if outcome.kind == "read"
                else self.tr("Written and read back: {0}").format(", ".join(outcome.values))
            )
        else:
            text = self.tr("Not written: {0}").format("; ".join(outcome.refusals))
            if outcome.kind == "read":
                text = self.tr("Not read: {0}").format("; ".join(outcome.refusals))
        self.summary.setText(text)
        self.edited -= set(outcome.values)
        self._show_values()
        for refusal in outcome.refusals:  # "$20=1: refused, error 10, …"
            key = refusal.split(":", 1)[0].split("=", 1)[0]
            if key in self.edited:
                self._set_state(self.row_of(key), self.tr("✗ refused"), _RED, refusal)
        self._update_enabled()

    # --- snapshots ------------------------------------------------------------------------

    def _ask_save(self) -> None:
        path, _ = QFileDialog.getSaveFileName(
            self, self.tr("Save settings snapshot"), "", self.tr("Settings snapshots (*.toml)")
        )
        if path:
            self.save_snapshot(Path(path))

    def _ask_load(self) -> None:
        path, _ = QFileDialog.getOpenFileName(
            self, self.tr("Load settings snapshot"), "", self.tr("Settings snapshots (*.toml)")
        )
        if path:
            self.load_snapshot(Path(path))

    def save_snapshot(self, path: Path) -> bool:
        if self.access is None:
            return False
        try:
            save_snapshot(path, self._station.profile, self.access)
        except (StepdeckError, OSError) as exc:
            self.summary.setText(self.tr("Not saved: {0} — press Read").format(exc))
            return False
        self.summary.setText(self.tr("Snapshot saved to {0}").format(path.name))
        return True

    def load_snapshot(self, path: Path) -> list[SettingDifference]:
        """Show what ``path`` changes and ask before writing it; the differences."""
        if self.access is None:
            return []
        try:
            snapshot = load_snapshot(path, self.access)
            other = False
            try:
                check_machine(snapshot, self._station.profile, other_machine=False)
            except StepdeckError:
                other = True
            differences = diff(snapshot, self.access)
        except StepdeckError as exc:
            self.summary.setText(self.tr("Not loaded: {0}").format(exc))
            return []
        if not differences:
            self.summary.setText(self.tr("{0}: the device holds every value").format(path.name))
            return []
        firmware = firmware_change(snapshot, self.access)
        self._confirm(path, differences, other, snapshot.title or snapshot.profile, firmware)
        return differences

    def _confirm(
        self,
        path: Path,
        differences: list[SettingDifference],
        other: bool,
        of: str,
        firmware: tuple[str, str] | None = None,
    ) -> None:
        """``firmware``: the snapshot's version and the device's, when they differ."""
        box = QMessageBox(self)
        box.setObjectName("settings_confirm")
        box.setWindowTitle(self.tr("Load settings snapshot"))
        text = self.tr("Values of {0} that differ from the device:").format(path.name)
        text += "\n\n" + "\n".join(str(d) for d in differences)
        if firmware is not None:  # a warning, not a refusal: the operator knows the boards
            box.setIcon(QMessageBox.Icon.Warning)
            text += "\n\n" + self.tr(
                "This snapshot was saved on firmware {0}; the device runs {1}. A setting may "
                "mean something else there: check each value before writing."
            ).format(*firmware)
        if other:
            box.setIcon(QMessageBox.Icon.Warning)
            text = (
                self.tr("This snapshot is of another machine ({0}), not {1}.").format(
                    of, self._station.profile.shown_title
                )
                + "\n\n"
                + text
            )
        box.setText(text)
        write = box.addButton(
            self.tr("Write anyway") if other else self.tr("Write"),
            QMessageBox.ButtonRole.AcceptRole,
        )
        box.addButton(QMessageBox.StandardButton.Cancel)

        def answered() -> None:
            if box.clickedButton() is write and self.access is not None:
                refusal = self.access.write({d.key: d.wanted for d in differences})
                self.summary.setText(
                    self.tr("Not written: {0}").format(refusal)
                    if refusal is not None
                    else self.tr("Writing the snapshot's values, then reading back…")
                )
            else:
                self.summary.setText(self.tr("Snapshot not loaded"))
            self.confirm_box = None
            box.deleteLater()
            self._update_enabled()

        box.finished.connect(lambda _result: answered())
        self.confirm_box = box
        box.open()  # never blocks: the answer arrives as a click

    # --- edits and states -------------------------------------------------------------------

    def _item_changed(self, item: QTableWidgetItem) -> None:
        if self._filling or item.column() != VALUE:
            return
        self._mark_edited(self.specs[item.row()].key)

    def _mark_edited(self, key: str) -> None:
        if self._filling:
            return
        self.edited.add(key)
        self.read_back.discard(key)
        row = self.row_of(key)
        if self._judge(row, self.specs[row]) is None:
            self._set_state(row, self.tr("• edited"), _AMBER)

    def _judge(self, row: int, spec: StoredSetting) -> str | None:
        """Frame a value that would be refused red, with the reason; the reason."""
        item = self._cell(row, VALUE)
        problem = None
        if spec.kind is not Kind.CHOICE and spec.key in self.edited:
            problem = spec.check(_number(item.text().strip()))
        self._filling, filling = True, self._filling
        try:
            item.setBackground(QBrush(QColor(_RED).lighter(170)) if problem else QBrush())
        finally:
            self._filling = filling
        if problem is not None:
            self._set_state(row, self.tr("✗ not allowed"), _RED, problem)
        elif spec.key not in self.edited:
            done = spec.key in self.read_back
            self._set_state(row, self.tr("✓ read back") if done else "", _GREEN)
        return problem

    def _set_state(self, row: int, text: str, colour: str, tip: str = "") -> None:
        item = self._cell(row, STATE)
        self._filling, filling = True, self._filling
        try:
            item.setText(text)
            item.setForeground(QBrush(QColor(colour)))
            item.setToolTip(tip)
        finally:
            self._filling = filling

    def _update_enabled(self, _state: object = None) -> None:
        """Buttons live while connected and idle; a moment the device may not be written
        (a job, a motion) is said when pressed, with the reason."""
        access = self.access
        live = (
            access is not None
            and access.busy is None
            and self._station.model.link_state in (LinkState.CONNECTED, LinkState.STALE)
        )
        self.read_button.setEnabled(live)
        self.apply_button.setEnabled(live)
        self.load_button.setEnabled(live)
        self.save_button.setEnabled(live and access is not None and bool(access.values))


def _number(text: str) -> object:
    """A typed number (a decimal comma too), or the text itself when it is none."""
    try:
        return float(text.replace(",", "."))
    except ValueError:
        return text
