"""The window's pages, built from the dialect's entry (:mod:`widgets.dialects`).

Manual comes first on every machine, then the dialect's own pages in its
entry's order, then Dynamics where the device has stored parameters, then
Settings where it keeps settings the station edits (GRBL's ``$$``, the usb3
unit's EEPROM), then Link.  The page titles keep the ``MainWindow`` translation context they had
when the window built them itself.

A dialect's own pages (drill, usb3 axes, G-code with its overrides and work
zero, stored settings) are imported by the builder that makes them: a machine
without them does not import them before its window's first paint.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, TypeAlias

from PySide6.QtCore import QCoreApplication, Qt
from PySide6.QtWidgets import QFrame, QPushButton, QScrollArea, QWidget

from app.settings import StationSettings
from app.station import Station
from app.stored_access import specs_for
from protocol.drill.timing import DrillTiming
from widgets.dialects import Page, WindowDialect
from widgets.jog_input import JogInput
from widgets.panels.absolute import AbsolutePanel
from widgets.panels.dynamics import DynamicsPanel
from widgets.panels.manual import ManualPanel
from widgets.panels.relative import RelativePanel
from widgets.retranslate import Maker

if TYPE_CHECKING:
    from widgets.panels.drill import DrillPanel
    from widgets.panels.gcode import GcodePanel
    from widgets.panels.stored_settings import StoredSettingsPanel
    from widgets.panels.usb3 import Usb3Panel

#: A page with motion controls: the motion lock turns it off.
MotionPanel: TypeAlias = (
    "ManualPanel | AbsolutePanel | RelativePanel | Usb3Panel | DrillPanel | GcodePanel"
)

#: Adds a page button: its title, the page, its tooltip (both made again on a language switch).
AddPage = Callable[[Maker, QWidget, Maker], None]


@dataclass
class Pages:
    """The pages built for one machine; the dialect's own are None where it has none."""

    manual: ManualPanel
    #: Every page with motion controls, for the motion lock.
    motion_panels: list[MotionPanel] = field(default_factory=list)
    drill: DrillPanel | None = None
    usb3: Usb3Panel | None = None
    absolute: AbsolutePanel | None = None
    relative: RelativePanel | None = None
    gcode: GcodePanel | None = None
    dynamics: DynamicsPanel | None = None
    #: GRBL's $$ or the usb3 unit's EEPROM values (:mod:`widgets.panels.stored_settings`).
    settings: StoredSettingsPanel | None = None
    #: The Dynamics page: the panel in a scroll area that only scrolls up and down.
    dynamics_page: QScrollArea | None = None

    def home_buttons(self, home_page: Page | None) -> list[QPushButton]:
        """The page buttons that home this machine, as the machine means "home"."""
        if home_page is Page.GCODE and self.gcode is not None:
            return [self.gcode.home_button]  # $H homes every axis at once
        if home_page is Page.DRILL and self.drill is not None:
            return [self.drill.command_buttons["N"]]
        return list(self.manual.home_buttons)


class DrillTimingMemory:
    """The drill's timing constants kept between runs (FIDELITY S2-06), when settings are."""

    def __init__(self, station: Station, settings: StationSettings, remembers: bool) -> None:
        self._station = station
        self._settings = settings
        self._remembers = remembers

    def restore(self, panel: DrillPanel) -> None:
        """The constants the operator set last time, applied and shown."""
        base = self._station.profile.drill_timing
        timing = self._settings.drill_timing(base) if self._remembers else base
        if timing != base:
            self._station.set_drill_timing(timing)
            panel.timing_box.show_timing(timing)

    def remember(self, timing: DrillTiming | None) -> None:
        if not self._remembers:
            return
        self._settings.set_drill_timing(timing)
        self._settings.sync()


def build_pages(
    station: Station,
    jog: JogInput,
    dialect: WindowDialect,
    add_page: AddPage,
    drill_timing: DrillTimingMemory,
) -> Pages:
    """Manual, the dialect's own pages and Dynamics, each added with ``add_page``.

    (Link is the window's: it needs the launcher's settings and profile choice.)
    """
    pages = Pages(ManualPanel(station, jog))
    add_page(
        lambda: QCoreApplication.translate("MainWindow", "&Manual"),
        pages.manual,
        lambda: QCoreApplication.translate("MainWindow", "Hold-to-jog buttons, Home (Alt+M)"),
    )
    pages.motion_panels.append(pages.manual)
    for page in dialect.pages:
        _BUILDERS[page](station, pages, add_page, drill_timing)
    if station.profile.capabilities.parameters:
        _add_dynamics(station, pages, add_page)
    _add_settings(station, pages, add_page)
    return pages


def _add_drill(station: Station, pages: Pages, add: AddPage, timing: DrillTimingMemory) -> None:
    from widgets.panels.drill import DrillPanel

    # The plotter takes absolute microsteps only: its own page, no Absolute/Relative.
    panel = pages.drill = DrillPanel(station)
    timing.restore(panel)
    panel.timing_box.applied.connect(timing.remember)
    add(
        lambda: QCoreApplication.translate("MainWindow", "D&rill"),
        panel,
        lambda: QCoreApplication.translate("MainWindow", "Command buttons, X/Y, terminal (Alt+R)"),
    )
    pages.motion_panels.append(panel)


def _add_usb3(station: Station, pages: Pages, add: AddPage, _timing: DrillTimingMemory) -> None:
    from widgets.panels.usb3 import Usb3Panel

    panel = pages.usb3 = Usb3Panel(station)
    add(
        lambda: QCoreApplication.translate("MainWindow", "A&xes"),
        panel,
        lambda: QCoreApplication.translate("MainWindow", "Move by mm, step size, thread (Alt+X)"),
    )
    pages.motion_panels.append(panel)


def _add_absolute(station: Station, pages: Pages, add: AddPage, _timing: DrillTimingMemory) -> None:
    panel = pages.absolute = AbsolutePanel(station)
    add(
        lambda: QCoreApplication.translate("MainWindow", "&Absolute"),
        panel,
        lambda: QCoreApplication.translate("MainWindow", "Move to a target (Alt+A)"),
    )
    pages.motion_panels.append(panel)


def _add_relative(station: Station, pages: Pages, add: AddPage, _timing: DrillTimingMemory) -> None:
    panel = pages.relative = RelativePanel(station)
    add(
        lambda: QCoreApplication.translate("MainWindow", "&Relative"),
        panel,
        lambda: QCoreApplication.translate("MainWindow", "Move by an increment (Alt+R)"),
    )
    pages.motion_panels.append(panel)


def _add_gcode(station: Station, pages: Pages, add: AddPage, _timing: DrillTimingMemory) -> None:
    from widgets.panels.gcode import GcodePanel

    panel = pages.gcode = GcodePanel(station)
    add(
        lambda: QCoreApplication.translate("MainWindow", "&G-code"),
        panel,
        lambda: QCoreApplication.translate("MainWindow", "Console, pen, hold/resume/reset (Alt+G)"),
    )
    pages.motion_panels.append(panel)


_BUILDERS: dict[Page, Callable[[Station, Pages, AddPage, DrillTimingMemory], None]] = {
    Page.DRILL: _add_drill,
    Page.USB3_AXES: _add_usb3,
    Page.ABSOLUTE: _add_absolute,
    Page.RELATIVE: _add_relative,
    Page.GCODE: _add_gcode,
}


def _add_dynamics(station: Station, pages: Pages, add: AddPage) -> None:
    panel = pages.dynamics = DynamicsPanel(station)
    # The page reflows to its width (axes stacked when narrow) and scrolls only
    # up and down: never sideways, where the second axis's column was cut off.
    page = pages.dynamics_page = QScrollArea()
    page.setObjectName("dynamics_page")
    page.setWidget(panel)
    page.setWidgetResizable(True)
    page.setFrameShape(QFrame.Shape.NoFrame)
    page.setHorizontalScrollBarPolicy(Qt.ScrollBarPolicy.ScrollBarAlwaysOff)
    bar = page.verticalScrollBar().sizeHint().width()
    page.setMinimumWidth(panel.minimumSizeHint().width() + bar)
    add(
        lambda: QCoreApplication.translate("MainWindow", "&Dynamics"),
        page,
        lambda: QCoreApplication.translate("MainWindow", "Device parameters (Alt+D)"),
    )


def _add_settings(station: Station, pages: Pages, add: AddPage) -> None:
    """The device's stored settings, where it keeps some the station edits."""
    specs = specs_for(station.dialect.session_type, station.profile)
    if specs is None:
        return
    from widgets.panels.stored_settings import StoredSettingsPanel

    panel = pages.settings = StoredSettingsPanel(station, specs)
    add(
        lambda: QCoreApplication.translate("MainWindow", "Se&ttings"),
        panel,
        lambda: QCoreApplication.translate(
            "MainWindow", "Stored settings: read, edit, snapshots (Alt+T)"
        ),
    )
