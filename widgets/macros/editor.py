"""The macro editor: add, change, delete and order one profile's macros; import and export TOML.

It edits a copy: nothing is kept, and no button changes, until OK, and OK
keeps the list only when every macro in it is valid (a name, unique, text
a person can read); otherwise it says what is wrong and stays open.
Whether the G-code runs on the machine is judged when it is run, from where
the machine then stands.
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path

from PySide6.QtWidgets import (
    QDialog,
    QDialogButtonBox,
    QFileDialog,
    QFormLayout,
    QGridLayout,
    QHBoxLayout,
    QLabel,
    QLineEdit,
    QListWidget,
    QPlainTextEdit,
    QVBoxLayout,
    QWidget,
)

from app.macros.store import MAX_MACROS, Macro, MacroError, checked_list
from app.macros.toml_file import export_macros, import_macros, merged
from widgets.retranslate import Texts


class MacroEditor(QDialog):
    """Edits a copy of ``macros``; :attr:`macros` holds the list once accepted."""

    def __init__(self, macros: Sequence[Macro], profile: str, parent: QWidget | None = None):
        super().__init__(parent)
        self.setObjectName("macro_editor")
        self.profile = profile
        self.macros: list[Macro] = list(macros)
        t = self.texts = Texts(self)
        t.set(self.setWindowTitle, lambda: self.tr("Macros — {0}").format(profile))
        self.list = QListWidget()
        self.list.setObjectName("macro_list")
        self.name_field = QLineEdit()
        self.name_field.setObjectName("macro_name")
        self.code_field = QPlainTextEdit()
        self.code_field.setObjectName("macro_code")
        self.code_field.setPlaceholderText("G90\nG0 X0 Y0")
        form = QFormLayout()
        name_label = t.label(lambda: self.tr("&Name"))
        name_label.setBuddy(self.name_field)
        code_label = t.label(lambda: self.tr("&G-code"))
        code_label.setBuddy(self.code_field)
        form.addRow(name_label, self.name_field)
        form.addRow(code_label, self.code_field)
        self.add_button = t.button(lambda: self.tr("&Add"))
        self.delete_button = t.button(lambda: self.tr("&Delete"))
        self.up_button = t.button(lambda: self.tr("&Up"))
        self.down_button = t.button(lambda: self.tr("Do&wn"))
        self.import_button = t.button(lambda: self.tr("&Import…"))
        self.export_button = t.button(lambda: self.tr("&Export…"))
        side = QGridLayout()
        for n, button in enumerate(
            (
                self.add_button,
                self.delete_button,
                self.up_button,
                self.down_button,
                self.import_button,
                self.export_button,
            )
        ):
            side.addWidget(button, n // 2, n % 2)
        left = QVBoxLayout()
        left.addWidget(self.list, 1)
        left.addLayout(side)
        right = QVBoxLayout()
        right.addLayout(form)
        top = QHBoxLayout()
        top.addLayout(left, 1)
        top.addLayout(right, 2)
        self.error_label = QLabel()
        self.error_label.setObjectName("macro_error")
        self.error_label.setWordWrap(True)
        self.error_label.setStyleSheet("color: #b00020;")
        self.buttons = QDialogButtonBox(
            QDialogButtonBox.StandardButton.Ok | QDialogButtonBox.StandardButton.Cancel
        )
        layout = QVBoxLayout(self)
        layout.addLayout(top, 1)
        layout.addWidget(self.error_label)
        layout.addWidget(self.buttons)
        self.resize(640, 420)
        self.buttons.accepted.connect(self.accept)
        self.buttons.rejected.connect(self.reject)
        self.add_button.clicked.connect(self.add)
        self.delete_button.clicked.connect(self.delete)
        self.up_button.clicked.connect(lambda: self.move_by(-1))
        self.down_button.clicked.connect(lambda: self.move_by(1))
        self.import_button.clicked.connect(self.ask_import)
        self.export_button.clicked.connect(self.ask_export)
        self.list.currentRowChanged.connect(self._show_current)
        self.name_field.textEdited.connect(self._edited)
        self.code_field.textChanged.connect(self._edited)
        self._showing = False
        self._refill(0)

    # --- the list ------------------------------------------------------------------

    def _refill(self, row: int) -> None:
        self._showing = True
        self.list.clear()
        self.list.addItems([macro.name or self.tr("(no name)") for macro in self.macros])
        self._showing = False
        row = min(row, len(self.macros) - 1)
        self.list.setCurrentRow(row)
        self._show_current(row)

    def _show_current(self, row: int) -> None:
        if self._showing:
            return
        has = 0 <= row < len(self.macros)
        self._showing = True
        self.name_field.setText(self.macros[row].name if has else "")
        self.code_field.setPlainText(self.macros[row].code if has else "")
        self._showing = False
        for widget in (self.name_field, self.code_field, self.delete_button):
            widget.setEnabled(has)
        self.up_button.setEnabled(has and row > 0)
        self.down_button.setEnabled(has and row < len(self.macros) - 1)
        self.add_button.setEnabled(len(self.macros) < MAX_MACROS)

    def _edited(self, *_: object) -> None:
        row = self.list.currentRow()
        if self._showing or not 0 <= row < len(self.macros):
            return
        name = self.name_field.text()
        self.macros[row] = Macro(name, self.code_field.toPlainText())
        item = self.list.item(row)
        if item is not None:
            item.setText(name or self.tr("(no name)"))

    def add(self) -> None:
        taken = {m.name.casefold() for m in self.macros}
        number = len(self.macros) + 1
        while self.tr("Macro {0}").format(number).casefold() in taken:
            number += 1
        self.macros.append(Macro(self.tr("Macro {0}").format(number), ""))
        self._refill(len(self.macros) - 1)
        self.name_field.setFocus()
        self.name_field.selectAll()

    def delete(self) -> None:
        row = self.list.currentRow()
        if 0 <= row < len(self.macros):
            del self.macros[row]
            self._refill(row)

    def move_by(self, step: int) -> None:
        row = self.list.currentRow()
        other = row + step
        if 0 <= row < len(self.macros) and 0 <= other < len(self.macros):
            self.macros[row], self.macros[other] = self.macros[other], self.macros[row]
            self._refill(other)

    # --- files ---------------------------------------------------------------------

    def ask_import(self) -> None:
        path, _ = QFileDialog.getOpenFileName(
            self, self.tr("Import macros"), "", self.tr("Macro files (*.toml)")
        )
        if path:
            self.import_from(Path(path))

    def import_from(self, path: Path) -> bool:
        """Macros of ``path`` added (one of the same name replaced); a bad file changes nothing."""
        try:
            imported, _ = import_macros(path)
            self.macros = merged(self.macros, imported)
        except MacroError as exc:
            self.error_label.setText(str(exc))
            return False
        self.error_label.setText(self.tr("{0} macro(s) imported").format(len(imported)))
        self._refill(0)
        return True

    def ask_export(self) -> None:
        path, _ = QFileDialog.getSaveFileName(
            self, self.tr("Export macros"), f"{self.profile}-macros.toml", "*.toml"
        )
        if path:
            self.export_to(Path(path))

    def export_to(self, path: Path) -> bool:
        try:
            export_macros(path, self.macros, self.profile)
        except (MacroError, OSError) as exc:
            self.error_label.setText(str(exc))
            return False
        self.error_label.setText(self.tr("Exported to {0}").format(path.name))
        return True

    # --- OK ------------------------------------------------------------------------

    def accept(self) -> None:
        """Kept only when every macro is valid; otherwise the first problem is shown."""
        for row, macro in enumerate(self.macros):
            try:
                checked_list([macro])
            except MacroError as exc:
                self.list.setCurrentRow(row)
                self.error_label.setText(f"{macro.name or row + 1}: {exc}")
                return
        try:
            self.macros = checked_list(self.macros)
        except MacroError as exc:
            self.error_label.setText(str(exc))
            return
        super().accept()
