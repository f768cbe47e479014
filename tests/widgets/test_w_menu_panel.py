"""Menu panel: one checked button per page, switching the stacked dynamic panel."""

from __future__ import annotations

from PySide6.QtCore import Qt
from PySide6.QtWidgets import QLabel, QStackedWidget
from pytestqt.qtbot import QtBot

from widgets.panels.menu import MenuPanel


def test_buttons_switch_the_stack(qtbot: QtBot) -> None:
    stack = QStackedWidget()
    menu = MenuPanel(stack)
    qtbot.addWidget(stack)
    qtbot.addWidget(menu)
    pages = [QLabel(name) for name in ("one", "two", "three")]
    buttons = [menu.add_page(label.text(), label) for label in pages]
    assert stack.currentWidget() is pages[0] and buttons[0].isChecked()

    with qtbot.waitSignal(menu.pageChanged) as blocker:
        qtbot.mouseClick(buttons[2], Qt.MouseButton.LeftButton)
    assert blocker.args == [2]
    assert stack.currentWidget() is pages[2]
    assert buttons[2].isChecked() and not buttons[0].isChecked()

    menu.set_page(1)
    assert stack.currentWidget() is pages[1] and buttons[1].isChecked()
    menu.set_page(7)  # out of range: ignored
    assert menu.current == 1
