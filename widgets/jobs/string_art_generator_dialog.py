"""String art from a photo: choose the picture and the board, generate, look, export or load.

The photo is read and the sequence generated on worker threads
(:mod:`app.string_art_generator` has no Qt): the dialog only sends the
settings and shows what comes back.  Progress arrives in chunks of a few
milliseconds, at most every ``PROGRESS_MS``, with the thread picture so far,
so the picture grows beside the photo while the window stays responsive.
Cancel stops the worker between two chunks and throws its work away.

Both pictures are the board at the same scale: the photo as cropped to the
nail circle (after contrast), and the thread as the real thread of the given
width would look on a board of the given size (the generator's own model).
Export writes ``param.txt`` + ``poradi.txt`` + a PNG, all or nothing; Load as
job writes the pair (to the exported folder, else a new folder in the
station's data folder) and opens it through the jobs dock, so the job is
checked, drilled and wound like any other.
"""

from __future__ import annotations

import html
import time
from collections.abc import Callable
from pathlib import Path

import numpy as np
from PySide6.QtCore import QCoreApplication, QStandardPaths, Qt, Signal
from PySide6.QtGui import QCloseEvent, QImage, QPixmap, QResizeEvent
from PySide6.QtWidgets import (
    QCheckBox,
    QComboBox,
    QDialog,
    QDoubleSpinBox,
    QFileDialog,
    QFormLayout,
    QGridLayout,
    QHBoxLayout,
    QLabel,
    QLayout,
    QProgressBar,
    QPushButton,
    QSpinBox,
    QVBoxLayout,
    QWidget,
)

from app.jobs.formats.string_art.geometry import NAIL_INSET_MM
from app.jobs.formats.string_art.program import WindingSettings
from app.jobs.formats.string_art.reader import StringArtJob, StringArtParams
from app.string_art_generator.board import BoardRaster
from app.string_art_generator.greedy import Settings, default_skip
from app.string_art_generator.output import job_of, write_job
from app.string_art_generator.render import to_grey
from app.string_art_generator.target import (
    Adjust,
    ImageError,
    load_image,
    target_darkness,
    working_copy,
)
from widgets.jobs.string_art_worker import PREVIEW_PX, Cancelled, Finished, Generation, Worker
from widgets.number_field import localized

DEFAULT_BOARD = StringArtParams(0, 200, 14.5)
IMAGE_FILTER = "Images (*.png *.jpg *.jpeg *.bmp *.gif *.tif *.tiff *.webp);;All files (*)"

#: Asks for a photo to open / a folder to export into; None when the operator cancels.
PathAsker = Callable[[QWidget], Path | None]


def ask_image(parent: QWidget) -> Path | None:
    path, _ = QFileDialog.getOpenFileName(
        parent,
        QCoreApplication.translate("StringArtGeneratorDialog", "Photo for string art"),
        "",
        IMAGE_FILTER,
    )
    return Path(path) if path else None


def ask_folder(parent: QWidget) -> Path | None:
    path = QFileDialog.getExistingDirectory(
        parent,
        QCoreApplication.translate(
            "StringArtGeneratorDialog", "Folder for param.txt and poradi.txt"
        ),
    )
    return Path(path) if path else None


def generated_folder(stem: str) -> Path:
    """A new folder for a generated job in the station's data folder."""
    base = QStandardPaths.writableLocation(QStandardPaths.StandardLocation.AppDataLocation)
    stamp = time.strftime("%Y%m%d-%H%M%S")
    folder = Path(base) / "string-art" / f"{stem}-{stamp}"
    suffix = 1
    while folder.exists():
        suffix += 1
        folder = folder.with_name(f"{stem}-{stamp}-{suffix}")
    return folder


def grey_pixmap(grey: np.ndarray, size: int) -> QPixmap:
    """An 8-bit grey array as a ``size``-pixel square pixmap."""
    data = np.ascontiguousarray(grey, dtype=np.uint8)
    rows, columns = data.shape
    image = QImage(data.data, columns, rows, columns, QImage.Format.Format_Grayscale8).copy()
    return QPixmap.fromImage(image).scaled(
        size,
        size,
        Qt.AspectRatioMode.KeepAspectRatio,
        Qt.TransformationMode.SmoothTransformation,
    )


def _button(text: str, name: str, tip: str) -> QPushButton:
    """A push button that never answers Enter (the dialog's fields take it)."""
    button = QPushButton(text)
    button.setObjectName(name)
    button.setToolTip(tip)
    button.setAutoDefault(False)
    return button


def _picture(name: str, tip: str) -> QLabel:
    """A square the size of the worker's previews, white as the board."""
    view = QLabel()
    view.setObjectName(name)
    view.setToolTip(tip)
    view.setFixedSize(PREVIEW_PX, PREVIEW_PX)
    view.setAlignment(Qt.AlignmentFlag.AlignCenter)
    view.setStyleSheet("background: white; border: 1px solid #bbb;")
    return view


def _spin(name: str, low: int, high: int, value: int, tip: str) -> QSpinBox:
    spin = QSpinBox()
    spin.setObjectName(name)
    spin.setRange(low, high)
    spin.setValue(value)
    spin.setToolTip(tip)
    spin.setKeyboardTracking(False)  # a value counts once typed, not digit by digit
    return spin


def _real(
    name: str, low: float, high: float, value: float, step: float, decimals: int
) -> QDoubleSpinBox:
    spin = QDoubleSpinBox()
    spin.setObjectName(name)
    spin.setRange(low, high)
    spin.setDecimals(decimals)
    spin.setSingleStep(step)
    spin.setValue(value)
    spin.setKeyboardTracking(False)
    return spin


class GrowingLabel(QLabel):
    """A word-wrapped label that asks its layout for the height its text needs.

    A wrapped label's height depends on its width, which a dialog's minimum size
    does not take in: the status growing to two lines after Generate took its
    line from the fixed-size pictures, and the caption was drawn over both.
    """

    def setText(self, text: str) -> None:
        super().setText(text)
        self._ask_height()

    def resizeEvent(self, event: QResizeEvent) -> None:
        super().resizeEvent(event)
        self._ask_height()

    def _ask_height(self) -> None:
        if self.width() > 0:
            need = self.heightForWidth(self.width())
            if need > 0 and need != self.minimumHeight():
                self.setMinimumHeight(need)


class StringArtGeneratorDialog(QDialog):
    """Photo, board, budget, thread, skip → Generate (Cancel) → Export… / Load as job."""

    #: The thread picture was redrawn with this many threads (while generating).
    threadsShown = Signal(int)

    def __init__(
        self,
        open_job: Callable[[Path], bool],
        parent: QWidget | None = None,
        *,
        board: StringArtParams | None = None,
        reach_mm: float | None = None,
        choose_image: PathAsker | None = None,
        choose_folder: PathAsker | None = None,
    ) -> None:
        super().__init__(parent)
        self.setObjectName("string_art_generator")
        self.setWindowTitle(self.tr("String art from a photo"))
        self._open_job = open_job
        #: How far from the centre the winder's needle goes (its X travel), if known.
        self._reach_mm = reach_mm
        self._choose_image = choose_image
        self._choose_folder = choose_folder
        self._image_path: Path | None = None
        self._reading_path = Path()
        self._lightness: np.ndarray | None = None
        self._reading: Worker | None = None
        self._generation: Generation | None = None
        self.finished_result: Finished | None = None
        self._exported_to: Path | None = None

        layout = QVBoxLayout(self)
        layout.setSizeConstraint(QLayout.SizeConstraint.SetMinimumSize)
        top = QHBoxLayout()
        self.image_button = _button(
            self.tr("Photo…"), "sa_image", self.tr("Choose a PNG or JPEG photo")
        )
        self.image_button.clicked.connect(self.ask_image)
        self.image_label = QLabel(self.tr("no photo chosen"))
        self.image_label.setObjectName("sa_image_name")
        top.addWidget(self.image_button)
        top.addWidget(self.image_label, 1)
        layout.addLayout(top)

        layout.addLayout(self._build_pictures())

        form_row = QHBoxLayout()
        form_row.addLayout(self._build_board_form(board or DEFAULT_BOARD))
        form_row.addLayout(self._build_photo_form())
        layout.addLayout(form_row)

        self.progress = QProgressBar()
        self.progress.setObjectName("sa_progress")
        self.progress.setRange(0, 1)
        self.progress.setValue(0)
        self.status = GrowingLabel(self.tr("Choose a photo"))
        self.status.setObjectName("sa_status")
        self.status.setWordWrap(True)
        self.status.setTextInteractionFlags(Qt.TextInteractionFlag.TextSelectableByMouse)
        layout.addWidget(self.progress)
        layout.addWidget(self.status)

        layout.addLayout(self._build_buttons())
        self._board_changed()
        self._update_buttons()

    # --- building ------------------------------------------------------------

    def _build_pictures(self) -> QGridLayout:
        """The photo as cropped to the board beside the thread as generated."""
        pictures = QGridLayout()
        self.photo_view = _picture("sa_photo", self.tr("The photo cropped to the board"))
        self.thread_view = _picture("sa_thread", self.tr("The thread, as wound at the real width"))
        self.scale_label = QLabel()
        self.scale_label.setObjectName("sa_scale")
        pictures.addWidget(QLabel(self.tr("Photo on the board")), 0, 0)
        pictures.addWidget(QLabel(self.tr("Thread")), 0, 1)
        pictures.addWidget(self.photo_view, 1, 0)
        pictures.addWidget(self.thread_view, 1, 1)
        pictures.addWidget(self.scale_label, 2, 0, 1, 2)
        return pictures

    def _build_buttons(self) -> QHBoxLayout:
        buttons = QHBoxLayout()
        self.generate_button = _button(
            self.tr("Generate"), "sa_generate", self.tr("Make the nail sequence")
        )
        self.cancel_button = _button(
            self.tr("Cancel"), "sa_cancel", self.tr("Stop; nothing is kept")
        )
        self.export_button = _button(
            self.tr("Export…"),
            "sa_export",
            self.tr("Write param.txt, poradi.txt and a PNG into a folder"),
        )
        self.load_button = _button(
            self.tr("Load as job"),
            "sa_load",
            self.tr("Open the sequence in the jobs dock to drill and wind it"),
        )
        self.close_button = _button(
            self.tr("Close"), "sa_close", self.tr("Close (a generation is cancelled)")
        )
        self.generate_button.clicked.connect(self.start)
        self.cancel_button.clicked.connect(self.cancel)
        self.export_button.clicked.connect(self.ask_export)
        self.load_button.clicked.connect(self.load_as_job)
        self.close_button.clicked.connect(self.close)
        for button in (
            self.generate_button,
            self.cancel_button,
            self.export_button,
            self.load_button,
        ):
            buttons.addWidget(button)
        buttons.addStretch(1)
        buttons.addWidget(self.close_button)
        return buttons

    def _build_board_form(self, board: StringArtParams) -> QFormLayout:
        form = QFormLayout()
        self.shape = QComboBox()
        self.shape.setObjectName("sa_shape")
        self.shape.addItem(self.tr("circle"), 0)
        for sides in range(3, 13):
            self.shape.addItem(self.tr("{0}-gon").format(sides), sides)
        index = self.shape.findData(board.tvar)
        self.shape.setCurrentIndex(max(0, index))
        self.nails = _spin("sa_nails", 3, 2000, board.nails, "pocet_hrebiku")
        self.radius = _real("sa_radius", 1.6, 100.0, board.radius_cm, 0.5, 2)
        self.radius.setSuffix(" cm")
        self.radius.setToolTip(
            self.tr("Board radius (polomer_matrice); the nails sit 1.5 cm inside")
        )
        self.lines = _spin("sa_lines", 1, 100_000, Settings.lines, self.tr("The line budget"))
        self.thread_width = _real("sa_thread_mm", 0.01, 5.0, Settings.thread_mm, 0.01, 2)
        self.thread_width.setSuffix(" mm")
        self.thread_width.setToolTip(
            self.tr("The real thread's width: it sets how dark each thread looks")
        )
        self.skip = _spin(
            "sa_skip",
            1,
            1000,
            default_skip(board.nails),
            self.tr("Least nails between a thread's two ends (never to a neighbouring nail)"),
        )
        self.resolution = _spin(
            "sa_resolution", 32, 600, Settings.resolution, self.tr("Pixels across the nail circle")
        )
        form.addRow(self.tr("Shape"), self.shape)
        form.addRow(self.tr("Nails"), self.nails)
        form.addRow(self.tr("Board radius"), self.radius)
        form.addRow(self.tr("Line budget"), self.lines)
        form.addRow(self.tr("Thread width"), self.thread_width)
        form.addRow(self.tr("Minimum skip"), self.skip)
        form.addRow(self.tr("Raster"), self.resolution)
        self.shape.currentIndexChanged.connect(self._board_changed)
        self.nails.valueChanged.connect(self._nails_changed)
        for spin in (self.radius, self.thread_width):
            spin.valueChanged.connect(self._board_changed)
        self.resolution.valueChanged.connect(self._board_changed)
        return form

    def _build_photo_form(self) -> QFormLayout:
        form = QFormLayout()
        self.zoom = _real("sa_zoom", 1.0, 10.0, 1.0, 0.1, 2)
        self.zoom.setToolTip(self.tr("Crop: 1 fits the photo's shorter side to the board"))
        self.centre_x = _real("sa_centre_x", 0.0, 1.0, 0.5, 0.02, 2)
        self.centre_y = _real("sa_centre_y", 0.0, 1.0, 0.5, 0.02, 2)
        self.contrast = _real("sa_contrast", 0.1, 5.0, 1.0, 0.1, 2)
        self.brightness = _real("sa_brightness", -1.0, 1.0, 0.0, 0.05, 2)
        self.invert = QCheckBox(self.tr("Invert (light thread, dark board)"))
        self.invert.setObjectName("sa_invert")
        form.addRow(self.tr("Zoom"), self.zoom)
        form.addRow(self.tr("Centre across"), self.centre_x)
        form.addRow(self.tr("Centre down"), self.centre_y)
        form.addRow(self.tr("Contrast"), self.contrast)
        form.addRow(self.tr("Brightness"), self.brightness)
        form.addRow(self.invert)
        for spin in (self.zoom, self.centre_x, self.centre_y, self.contrast, self.brightness):
            spin.valueChanged.connect(self._show_photo)
        self.invert.toggled.connect(self._show_photo)
        return form

    # --- values --------------------------------------------------------------

    def params(self) -> StringArtParams:
        return StringArtParams(
            int(self.shape.currentData()), self.nails.value(), round(self.radius.value(), 2)
        )

    def settings(self) -> Settings:
        return Settings(
            lines=self.lines.value(),
            thread_mm=round(self.thread_width.value(), 3),
            min_skip=self.skip.value(),
            resolution=self.resolution.value(),
        )

    def adjust(self) -> Adjust:
        return Adjust(
            centre_x=self.centre_x.value(),
            centre_y=self.centre_y.value(),
            zoom=self.zoom.value(),
            contrast=self.contrast.value(),
            brightness=self.brightness.value(),
            invert=self.invert.isChecked(),
        )

    @property
    def running(self) -> bool:
        return self._generation is not None

    # --- the photo -----------------------------------------------------------

    def ask_image(self) -> None:
        path = (self._choose_image or ask_image)(self)
        if path is not None:
            self.open_image(path)

    def open_image(self, path: Path) -> None:
        """Read ``path`` on a worker (a large JPEG takes a while to decode)."""
        if self._reading is not None:
            return
        self.image_label.setText(self.tr("reading <b>{0}</b>…").format(html.escape(path.name)))
        self._reading_path = path
        self._reading = Worker(lambda _w: working_copy(load_image(path)), "photo-reader", self)
        self._reading.done.connect(self._image_read)
        self._update_buttons()
        self._reading.start()

    def _image_read(self, result: object) -> None:
        path = self._reading_path
        reading, self._reading = self._reading, None
        if reading is not None:
            reading.join()
        if isinstance(result, np.ndarray):
            self._image_path = path
            self._lightness = result
            self.image_label.setText(f"<b>{path.name}</b>")
            self.status.setText(self.tr("Set the board and the crop, then Generate"))
            self._show_photo()
        else:
            reason = str(result) if isinstance(result, ImageError) else f"{path.name}: {result}"
            self.image_label.setText(self.tr("no photo chosen") if self._lightness is None else "")
            self.status.setText(self.tr("Not opened: {0}").format(reason))
            if self._image_path is not None:
                self.image_label.setText(f"<b>{self._image_path.name}</b>")
        self._update_buttons()

    def _target(self, size: int) -> np.ndarray | None:
        if self._lightness is None:
            return None
        return target_darkness(self._lightness, self.adjust(), size)

    def _show_photo(self, *_args: object) -> None:
        target = self._target(PREVIEW_PX)
        if target is None:
            return
        mask = BoardRaster(self.params(), PREVIEW_PX).mask
        self.photo_view.setPixmap(grey_pixmap(to_grey(np.where(mask, target, 0.0)), PREVIEW_PX))

    def _nails_changed(self, nails: int) -> None:
        self.skip.setMaximum(max(1, nails // 2 - 1))
        self.skip.setValue(default_skip(nails))
        params = self.params()
        fitted = self.settings().fitted_resolution(params)
        if fitted < self.resolution.value():
            # Many nails: a coarser raster rather than a refusal (a raster the operator
            # types afterwards is taken as typed, and refused if it cannot be built).
            self.resolution.setValue(fitted)  # its change comes back to _board_changed
            return
        self._board_changed()

    def _board_changed(self, *_args: object) -> None:
        params = self.params()
        self.skip.setMaximum(max(1, params.nails // 2 - 1))
        problem = params.check() or self.settings().check(params)
        if problem is None:
            raster = BoardRaster(params, self.resolution.value())
            across_mm = 2 * raster.nail_radius_mm
            width = self.thread_width.value()
            self.scale_label.setText(
                self.tr(
                    "Both pictures: the nail circle, {0} cm across, drawn {1} px wide "
                    "(1 px = {2} mm).\nThread {3} mm = 1/{4} of it; chosen on a raster "
                    "of {5} mm pixels."
                ).format(
                    localized(f"{across_mm / 10:.1f}"),
                    PREVIEW_PX,
                    localized(f"{across_mm / PREVIEW_PX:.2f}"),
                    localized(f"{width:g}"),
                    f"{across_mm / width:.0f}",
                    localized(f"{raster.pixel_mm:.2f}"),
                )
                + self._reach_warning(raster.nail_radius_mm)
            )
        else:
            self.scale_label.setText(self.tr("Cannot generate: {0}").format(problem))
        self._show_photo()
        self._update_buttons()

    def _reach_warning(self, nail_radius_mm: float) -> str:
        """A line when the winder's needle cannot get round the outermost nails of this board
        (the SD-card files are still good for a larger machine; the dock refuses the job)."""
        reach = self._reach_mm
        needle_out = WindingSettings().needle_out_mm
        # The winding starts out 2 cm beyond the board's edge (the firmware's
        # ``polomer_matrice_cm + 2.0``, FIDELITY S0-19): the farthest the needle goes.
        if reach is None or nail_radius_mm + NAIL_INSET_MM + needle_out <= reach:
            return ""
        largest_cm = (reach - needle_out) / 10
        return "\n" + self.tr(
            "This winder's needle reaches {0} mm from the centre: boards up to "
            "{1} cm radius fit it (export the files for a larger one)."
        ).format(localized(f"{reach:g}"), localized(f"{largest_cm:.1f}"))

    # --- generating ----------------------------------------------------------

    def start(self) -> bool:
        """Generate with the settings shown; False (and says why) when it cannot begin."""
        if self.running or self._lightness is None:
            return False
        params, settings = self.params(), self.settings()
        problem = params.check() or settings.check(params)
        if problem is not None:
            self.status.setText(self.tr("Cannot generate: {0}").format(problem))
            return False
        target = self._target(settings.resolution)
        assert target is not None
        self.finished_result = None
        self._exported_to = None
        self.thread_view.clear()
        self.progress.setRange(0, params.nails)
        self.progress.setValue(0)
        self.status.setText(self.tr("Preparing the lines between the nails…"))
        self._generation = Generation(params, target, settings, self)
        self._generation.progressed.connect(self._progressed)
        self._generation.done.connect(self._generated)
        self._generation.start()
        self._update_buttons()
        return True

    def cancel(self) -> None:
        if self._generation is not None:
            self._generation.cancel()
            self.status.setText(self.tr("Cancelling…"))

    def _progressed(self, phase: str, done: int, total: int, darkness: object) -> None:
        if self._generation is None or self._generation.stop.is_set():
            return
        self.progress.setRange(0, max(1, total))
        self.progress.setValue(min(done, total))
        if phase == "lines":
            self.status.setText(
                self.tr("Preparing the lines between the nails: {0} of {1}").format(done, total)
            )
            return
        self.status.setText(self.tr("Winding: {0} threads of at most {1}").format(done, total))
        if isinstance(darkness, np.ndarray):
            self.thread_view.setPixmap(grey_pixmap(to_grey(darkness), PREVIEW_PX))
            self.threadsShown.emit(done)

    def _generated(self, outcome: object) -> None:
        generation, self._generation = self._generation, None
        if generation is not None:
            generation.join()
        if isinstance(outcome, Finished):
            self.finished_result = outcome
            result = outcome.result
            # Done is full, also when it stopped before the budget (the status says so).
            self.progress.setRange(0, max(1, result.lines))
            self.progress.setValue(result.lines)
            self.thread_view.setPixmap(grey_pixmap(outcome.preview, PREVIEW_PX))
            ended = (
                self.tr("stopped before the budget: no further thread brings it closer")
                if result.stopped_early
                else self.tr("the whole budget")
            )
            self.status.setText(
                self.tr("%n thread(s) ({0}), {1} m of thread; {2}; {3} s", "", result.lines).format(
                    ended,
                    localized(f"{job_of(result).thread_length_mm() / 1000:.1f}"),
                    localized(str(outcome.quality)),
                    localized(f"{result.seconds:.1f}"),
                )
            )
        elif isinstance(outcome, Cancelled):
            self.thread_view.clear()
            self.progress.setValue(0)
            self.status.setText(self.tr("Cancelled: nothing kept"))
        else:
            self.status.setText(self.tr("Generation failed: {0}").format(outcome))
        self._update_buttons()

    # --- results -------------------------------------------------------------

    def job(self) -> StringArtJob | None:
        return job_of(self.finished_result.result) if self.finished_result else None

    def ask_export(self) -> None:
        folder = (self._choose_folder or ask_folder)(self)
        if folder is not None:
            self.export(folder)

    def export(self, folder: Path) -> bool:
        finished = self.finished_result
        if finished is None:
            return False
        try:
            paths = write_job(job_of(finished.result), folder, finished.png)
        except OSError as exc:
            self.status.setText(self.tr("Nothing written to {0}: {1}").format(folder, exc))
            return False
        self._exported_to = folder
        self.status.setText(
            self.tr("Wrote {0} in {1}").format(", ".join(p.name for p in paths), folder)
        )
        return True

    def load_as_job(self) -> bool:
        """Open the sequence as a job in the dock; the dialog closes when it loaded."""
        finished = self.finished_result
        if finished is None:
            return False
        folder = self._exported_to
        if folder is None:
            stem = self._image_path.stem if self._image_path else "string-art"
            folder = generated_folder(stem)
            try:
                write_job(job_of(finished.result), folder, finished.png)
            except OSError as exc:
                self.status.setText(
                    self.tr("Not loaded: nothing written to {0}: {1}").format(folder, exc)
                )
                return False
        if not self._open_job(folder / "poradi.txt"):
            self.status.setText(self.tr("Not loaded: see the jobs dock's messages"))
            return False
        self.accept()
        return True

    def _update_buttons(self) -> None:
        running = self.running
        params = self.params()
        ready = params.check() is None and self.settings().check(params) is None
        self.generate_button.setEnabled(
            not running and self._lightness is not None and self._reading is None and ready
        )
        self.cancel_button.setEnabled(running)
        done = self.finished_result is not None and not running
        self.export_button.setEnabled(done)
        self.load_button.setEnabled(done)
        self.image_button.setEnabled(not running and self._reading is None)
        board = (self.shape, self.nails, self.radius, self.lines, self.thread_width, self.skip)
        for widget in (*board, self.resolution):
            widget.setEnabled(not running)

    # --- closing -------------------------------------------------------------

    def stop_workers(self) -> None:
        """Cancel and wait for the threads (each stops within one chunk)."""
        for worker in (self._generation, self._reading):
            if worker is not None:
                worker.cancel()
                worker.join()
        self._generation = None
        self._reading = None

    def done(self, code: int) -> None:
        self.stop_workers()
        super().done(code)

    def closeEvent(self, event: QCloseEvent) -> None:
        self.stop_workers()
        super().closeEvent(event)
