"""Make the manual's screenshots: ``python -m tools.screenshots [name ...]``.

Each shot is the operator window at 1280x800 over the built-in emulator on a
manual clock (so a shot is the same every time), driven the way an operator
would, then grabbed by Qt (no X server needed: ``QT_QPA_PLATFORM=offscreen``
works).  The PNGs go to ``resources/screenshots/``.
"""

from __future__ import annotations

import sys
import tempfile
import time
from collections.abc import Callable
from pathlib import Path

from PySide6.QtCore import QSize, Qt
from PySide6.QtWidgets import QApplication, QWidget

from app import i18n
from app.profiles import load_profile
from tests.helpers.harness import StationHarness
from widgets.main_window import MainWindow

OUT = Path(__file__).resolve().parent.parent / "resources" / "screenshots"
#: The real job files and samples kept with the tests (tests/data).
DATA = Path(__file__).resolve().parent.parent / "tests" / "data"
SCREEN = QSize(1280, 800)
SQUARE = "# square\n5, 5\n40, 5\n40, 40\n5, 40\n5, 5\n20, 20\n5, 5\n5, 5\n"


def _window(profile: str, work: Path) -> tuple[StationHarness, MainWindow]:
    harness = StationHarness(load_profile(profile))
    window = MainWindow(harness.station, checkpoint_dir=work / "checkpoints")
    window.show()
    window.resize(SCREEN)
    harness.connect()
    harness.run(2.0)
    return harness, window


def _page(window: MainWindow, title: str) -> None:
    for index in range(window.stack.count()):
        button = window.menu_panel.button(index)
        if button.text().replace("&", "") == title:
            button.click()
            return
    raise LookupError(title)


def _settle(window: QWidget) -> None:
    """The window at its size (a dialog at its own), and the views that redraw on a
    real-time timer (the frame log) given the time to."""
    if isinstance(window, MainWindow):
        window.resize(SCREEN)
        window.job_runner.progress.emit_eta()  # on the test clock no timer ticks the job's times
    until = time.monotonic() + 0.5
    while time.monotonic() < until:
        QApplication.processEvents()
        time.sleep(0.01)


def _hold_key(harness: StationHarness, window: MainWindow, key: Qt.Key, seconds: float) -> None:
    window.jog.key_press(key)
    t = 0.0
    while t < seconds:
        harness.run(0.1)
        window.jog.key_repeat(key)  # the auto-repeat a held key sends
        t += 0.1
    window.jog.key_release(key)


def main_window(work: Path, language: str | None = None) -> tuple[StationHarness, MainWindow]:
    harness, window = _window("xy-stage", work)
    if language is not None:
        window.set_language(language)
    job = work / "square.csv"
    job.write_text(SQUARE, encoding="utf-8")
    window.telemetry_dock.show()
    window.jobs_dock.show()
    window.jobs_dock.open_path(job)
    window.jobs_dock.run_button.click()
    harness.run(2.6)
    return harness, window


def dynamics(work: Path) -> tuple[StationHarness, MainWindow]:
    harness, window = _window("xy-stage", work)
    window.jobs_dock.show()  # the page beside it: the axes stacked, scrolled up and down
    _page(window, "Dynamics")
    return harness, window


def link(work: Path) -> tuple[StationHarness, MainWindow]:
    harness, window = _window("xy-stage", work)
    _page(window, "Link")
    return harness, window


def telemetry(work: Path) -> tuple[StationHarness, MainWindow]:
    harness, window = _window("xy-stage", work)
    window.telemetry_dock.show()
    _hold_key(harness, window, Qt.Key.Key_Right, 2.0)
    _hold_key(harness, window, Qt.Key.Key_Up, 1.5)
    harness.run(1.0)
    return harness, window


def developer(work: Path) -> tuple[StationHarness, MainWindow]:
    harness, window = _window("xy-stage", work)
    window.developer_pane.show()
    window.developer_pane.raise_()
    _hold_key(harness, window, Qt.Key.Key_Right, 0.6)
    harness.run(0.5)
    return harness, window


def usb3(work: Path) -> tuple[StationHarness, MainWindow]:
    harness, window = _window("usb3", work)
    _page(window, "Axes")
    window.usb3_panel.distances[0].setValue(2.5)
    window.usb3_panel.send_buttons[0].click()
    harness.run(3.0)
    return harness, window


def string_art(work: Path) -> tuple[StationHarness, MainWindow]:
    """The winder on the cardioid board of the samples in tests/data."""
    harness, window = _window("string-art", work)
    window.jobs_dock.show()
    window.jobs_dock.open_path(DATA / "samples" / "string-art-cardioid" / "poradi.txt")
    window.jobs_dock.run_button.click()
    harness.run(5.0)
    return harness, window


def _wait(condition: Callable[[], bool], seconds: float) -> None:
    """Process events until ``condition`` holds (a worker thread's result), wall-clock."""
    until = time.monotonic() + seconds
    while not condition():
        if time.monotonic() > until:
            raise TimeoutError("the shot's state was not reached")
        QApplication.processEvents()
        time.sleep(0.01)


def string_art_from_photo(work: Path) -> tuple[StationHarness, QWidget]:
    """The winder's From photo dialog after Generate, on the test portrait."""
    import numpy as np
    from PIL import Image

    from tests.helpers.string_art_images import face

    harness, window = _window("string-art", work)
    window.jobs_dock.show()
    photo = work / "face_in.png"
    Image.fromarray(np.round(face(300) * 255).astype(np.uint8)).save(photo)
    window.jobs_dock.photo_button.click()
    dialog = window.jobs_dock.string_art.dialog
    assert dialog is not None
    dialog.open_image(photo)
    _wait(dialog.generate_button.isEnabled, 30.0)
    dialog.generate_button.click()
    _wait(lambda: dialog.finished_result is not None, 120.0)
    return harness, dialog


def czech(work: Path) -> tuple[StationHarness, MainWindow]:
    """The main window with its docks, switched to Czech in the running window."""
    return main_window(work, "cs")


def dark(work: Path) -> tuple[StationHarness, MainWindow]:
    """The GRBL plotter in dark colours, a job waiting for the operator to go on."""
    harness, window = _window("grbl-plotter", work)
    window.set_theme("dark")
    job = work / "square-with-a-pause.gcode"
    job.write_text(
        "G21 G90\nG0 X10 Y10\nM3 S1000\nG1 X60 F3000\nG1 Y60\nM0 (check the pen)\n"
        "G1 X10\nG1 Y10\nM5\nG0 X0 Y0\n",
        encoding="utf-8",
    )
    window.jobs_dock.show()
    window.telemetry_dock.show()
    window.jobs_dock.open_path(job)
    window.jobs_dock.run_button.click()
    harness.run(8.0)
    return harness, window


def drill(work: Path) -> tuple[StationHarness, MainWindow]:
    """The drill on the sample board in tests/data, the first bit asked for."""
    harness, window = _window("pcb-drill", work)
    _page(window, "Drill")
    window.jobs_dock.show()
    window.jobs_dock.open_path(DATA / "samples" / "pcb-driver" / "driver.dri")
    window.jobs_dock.run_button.click()
    harness.run(12.0)
    return harness, window


def jobs(work: Path) -> tuple[StationHarness, MainWindow]:
    """A point-list job running on the stage, the jobs dock beside the Manual page."""
    harness, window = _window("xy-stage", work)
    job = work / "square.csv"
    job.write_text(SQUARE, encoding="utf-8")
    window.jobs_dock.show()
    window.jobs_dock.open_path(job)
    window.jobs_dock.run_button.click()
    harness.run(4.0)
    return harness, window


def plotter(work: Path) -> tuple[StationHarness, MainWindow]:
    """The CoreXY plotter drawing the Unicorn file of tests/data/realdata."""
    harness, window = _window("corexy-plotter", work)
    _page(window, "G-code")
    window.jobs_dock.show()
    window.jobs_dock.skip_check.setChecked(True)  # M300/M18 left out, listed
    window.jobs_dock.open_path(DATA / "realdata" / "gcode" / "CNC-Drawinger_unicorn_BUNNY.gcode")
    window.jobs_dock.run_button.click()
    harness.run(5.0)
    window.jobs_dock.continue_button.click()  # the file's M01 "Was registration test successful?"
    harness.run(40.0)
    return harness, window


def gcode_machine(work: Path) -> tuple[StationHarness, MainWindow]:
    """The GRBL plotter's G-code page mid-job: work zero, overrides (feed at 90 %), and the
    macros under the page (refused while the job runs)."""
    from app.macros.store import checked_macro

    harness, window = _window("grbl-plotter", work)
    _page(window, "G-code")
    job = work / "square.gcode"
    job.write_text(
        "G21 G90\nG0 X10 Y10\nM3 S1000\nG1 X60 F3000\nG1 Y60\nG1 X10\nG1 Y10\n"
        "G1 X60 Y60\nM5\nG0 X0 Y0\n",
        encoding="utf-8",
    )
    window.jobs_dock.show()
    assert window.macros is not None
    window.macros.dock.set_macros(
        [
            checked_macro("Park", "G90\nM5\nG0 X0 Y0"),
            checked_macro("Pen test", "M3 S1000\nG4 P0.5\nM5"),
            checked_macro("Centre", "G90\nG0 X150 Y100"),
        ]
    )
    window.macros.action.trigger()  # Ctrl+M: under the page
    window.jobs_dock.open_path(job)
    window.jobs_dock.run_button.click()
    harness.run(1.0)
    gcode = window.pages.gcode
    assert gcode is not None
    gcode.overrides.feed_minus_10.click()  # F5: the job slows to 90 %
    harness.run(2.0)
    return harness, window


def settings(work: Path) -> tuple[StationHarness, MainWindow]:
    """The GRBL plotter's stored settings read ($$), beside the jobs dock."""
    harness, window = _window("grbl-plotter", work)
    window.jobs_dock.show()
    _page(window, "Settings")
    panel = window.pages.settings
    assert panel is not None
    panel.read_button.click()
    harness.run(2.0)
    return harness, window


SHOTS: dict[str, Callable[[Path], tuple[StationHarness, QWidget]]] = {
    "main-window": main_window,
    "dynamics": dynamics,
    "link": link,
    "telemetry": telemetry,
    "developer": developer,
    "usb3": usb3,
    "string-art": string_art,
    "czech": czech,
    "dark": dark,
    "drill": drill,
    "jobs": jobs,
    "plotter": plotter,
    "string-art-from-photo": string_art_from_photo,
    "gcode-machine": gcode_machine,
    "settings": settings,
}


def main(names: list[str]) -> None:
    app = QApplication.instance() or QApplication(sys.argv)
    assert isinstance(app, QApplication)
    i18n.install("en")  # as the station starts: English with its plural forms
    for name in names or list(SHOTS):
        i18n.install("en")  # a shot in another language leaves it installed
        with tempfile.TemporaryDirectory() as temp:
            harness, window = SHOTS[name](Path(temp))
            try:
                _settle(window)
                window.grab().save(str(OUT / f"{name}.png"))
                print(f"{name}.png: {window.width()}x{window.height()}")
            finally:
                window.close()
                harness.close()


if __name__ == "__main__":
    main(sys.argv[1:])
