"""Telemetry dock: variable selection reaches the wire, curves, Zero, exports, Pause, window."""

from __future__ import annotations

import csv
from collections.abc import Iterator
from dataclasses import replace
from itertools import pairwise
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from PySide6.QtCore import QEvent, QObject, Qt
from PySide6.QtGui import QImage
from PySide6.QtWidgets import QApplication, QFileDialog, QWidget
from pytestqt.qtbot import QtBot

from app.profiles import load_profile
from app.station import Station
from app.telemetry import MAX_WINDOW_S, PeakEnvelope, TelemetryRecorder
from protocol.clock import ManualClock
from protocol.stage.codec import CommandFrame, Subscriber, decode
from tests.helpers.harness import STEP_S, StationHarness
from widgets.telemetry_dock import TelemetryDock, changed_spans

LEFT = Qt.MouseButton.LeftButton


@pytest.fixture
def dock(qtbot: QtBot, harness: StationHarness) -> Iterator[TelemetryDock]:
    recorder = TelemetryRecorder(harness.station, throttle_ms=0, scroll_ms=0)
    dock = TelemetryDock(recorder)
    qtbot.addWidget(dock)
    dock.resize(900, 520)
    dock.show()
    yield dock
    recorder.deleteLater()


def choose(dock: TelemetryDock, subscriber: int | None) -> None:
    dock.variable_combo.setCurrentIndex(dock.variable_combo.findData(subscriber))


def sent_subscribers(harness: StationHarness, since: int = 0) -> list[int]:
    out = []
    for raw in harness.written[since:]:
        _, frame = decode(raw)
        assert isinstance(frame, CommandFrame)
        out.append(frame.subscriber)
    return out


def curve_data(curve: object) -> tuple[np.ndarray, np.ndarray]:
    t, y = curve.getData()  # type: ignore[attr-defined]
    return (np.empty(0), np.empty(0)) if t is None else (t.copy(), y.copy())


def test_choosing_rotation_subscribes_on_the_wire(
    harness: StationHarness, dock: TelemetryDock
) -> None:
    harness.connect()
    harness.run(2.0)
    assert Subscriber.ROTATION not in sent_subscribers(harness)
    start = len(harness.written)
    choose(dock, Subscriber.ROTATION)
    assert dock.recorder.variable is not None
    assert dock.recorder.variable.subscriber == Subscriber.ROTATION
    harness.run(2.0)
    asked = sent_subscribers(harness, start)
    # Every frame the info panel does not need carries SS 05: about half at 100 ms.
    assert asked.count(Subscriber.ROTATION) >= len(asked) // 3
    choose(dock, None)
    start = len(harness.written)
    harness.run(2.0)
    assert Subscriber.ROTATION not in sent_subscribers(harness, start)


def test_curves_receive_the_recorded_data(harness: StationHarness, dock: TelemetryDock) -> None:
    choose(dock, Subscriber.ROTATION)
    harness.connect()
    harness.emulator.rotation_rate_dps = 10.0
    harness.session.move_absolute(0, 2.0)
    harness.run(3.0)
    # Frames come on the screen's timer, in real time; the test clock ran ahead of the last
    # one by up to a tick (how far depends on the machine): draw the frame of "now".
    dock.redraw()
    for name, curve in dock._curves.items():
        t, y = curve_data(curve)
        expected_t, expected_y = dock.recorder.data(name)
        np.testing.assert_array_equal(t, expected_t)
        np.testing.assert_array_equal(y, expected_y)
    _, x = curve_data(dock._curves["X position"])
    assert x[-1] == 2.0
    low, high = dock.position_plot.viewRange()[1]
    assert low <= 0.0 and high >= 2.0  # autoscale fits the shifted curves
    t, y = curve_data(dock.variable_curve)
    assert len(t) >= 10 and y[-1] > y[0]
    # The time axis counts back from now; the curves slide left as time goes by.
    assert dock.variable_plot.viewRange()[0] == pytest.approx([-10.0, 0.0])
    period = harness.session.period_ms / 1000
    assert dock.variable_curve.pos().x() == pytest.approx(-dock.recorder.view_end(), abs=period)
    # The curves move by whole pixels; the view's end is the first pixel boundary at or
    # after now, so the newest sample is never cut off at the right edge.
    pixel = 10.0 / (dock._max_points() / 2)
    shift = -dock.variable_curve.pos().x()
    assert 0.0 <= shift - dock.recorder.view_end() < pixel
    assert shift / pixel == pytest.approx(round(shift / pixel))
    newest = dock.variable_curve.pos().x() + t[-1]
    # Rotation rides every other frame; the clock may stand one test step past that frame.
    assert -2 * period - pixel - STEP_S <= newest <= 0.0
    assert dock.variable_curve.pos().x() == dock._curves["X position"].pos().x()
    assert "rotation (°)" in dock.title(dock.variable_plot)
    assert "X" in dock.title(dock.position_plot) and "Y" in dock.title(dock.velocity_plot)


def test_zero_button_resets_the_cross(
    qtbot: QtBot, harness: StationHarness, dock: TelemetryDock
) -> None:
    assert dock.cross.angle is None and not dock.zero_button.isEnabled()
    assert dock.angle_label.text() == ""  # no rotation plotted: no lone dash under the cross
    choose(dock, Subscriber.ROTATION)
    assert dock.angle_label.text() == "—"  # plotted, no value yet
    harness.connect()
    harness.emulator.rotation_rate_dps = 10.0
    harness.run(3.0)
    assert dock.cross.angle is not None and dock.cross.angle > 15.0
    qtbot.mouseClick(dock.zero_button, LEFT)
    assert dock.cross.angle == 0.0
    assert dock.angle_label.text() == "+0.00°"
    harness.run(1.0)
    assert 5.0 < dock.cross.angle < 15.0
    choose(dock, Subscriber.BATTERY_VOLTAGE)
    assert dock.cross.angle is None and not dock.zero_button.isEnabled()
    assert dock.angle_label.text() == ""


def test_export_buttons_write_files(
    qtbot: QtBot,
    harness: StationHarness,
    dock: TelemetryDock,
    tmp_path: Path,
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    choose(dock, Subscriber.BATTERY_VOLTAGE)
    harness.connect()
    harness.run(3.0)
    target = tmp_path / "out.csv"
    monkeypatch.setattr(QFileDialog, "getSaveFileName", lambda *_a, **_k: (str(target), ""))
    qtbot.mouseClick(dock.csv_button, LEFT)
    with target.open(newline="", encoding="utf-8") as handle:
        rows = list(csv.reader(handle))
    assert rows[0][0] == "time (s)" and rows[0][-1] == "battery voltage (V)"
    voltages = [float(row[-1]) for row in rows[1:] if row[-1]]
    assert voltages and all(v == pytest.approx(4.02, abs=0.01) for v in voltages)
    assert len(rows) - 1 == len(np.unique(dock.recorder.data("X position")[0]))

    image = tmp_path / "out.png"
    monkeypatch.setattr(QFileDialog, "getSaveFileName", lambda *_a, **_k: (str(image), ""))
    qtbot.mouseClick(dock.png_button, LEFT)
    loaded = QImage(str(image))
    assert not loaded.isNull() and loaded.width() > 300

    monkeypatch.setattr(QFileDialog, "getSaveFileName", lambda *_a, **_k: ("", ""))
    target.unlink()
    qtbot.mouseClick(dock.csv_button, LEFT)  # cancelled: nothing written
    assert not target.exists()


def test_pause_freezes_curves_while_recording_goes_on(
    qtbot: QtBot, harness: StationHarness, dock: TelemetryDock
) -> None:
    choose(dock, Subscriber.ROTATION)
    harness.connect()
    harness.emulator.rotation_rate_dps = 10.0
    harness.run(2.0)
    qtbot.mouseClick(dock.pause_button, LEFT)
    assert dock.recorder.paused and dock.paused_label.isVisibleTo(dock)
    frozen = curve_data(dock.variable_curve)
    frozen_shift = dock.variable_curve.pos().x()
    frozen_angle = dock.cross.angle
    recorded = len(dock.recorder.recorded("rotation")[0])
    harness.run(3.0)
    now = curve_data(dock.variable_curve)
    np.testing.assert_array_equal(now[0], frozen[0])
    np.testing.assert_array_equal(now[1], frozen[1])
    assert dock.variable_curve.pos().x() == frozen_shift  # the curves stand still
    assert dock.cross.angle == frozen_angle
    assert len(dock.recorder.recorded("rotation")[0]) > recorded + 5  # still recording
    qtbot.mouseClick(dock.pause_button, LEFT)
    assert not dock.recorder.paused and not dock.paused_label.isVisibleTo(dock)
    t, _ = curve_data(dock.variable_curve)
    assert t[-1] > frozen[0][-1] + 2.5  # what came in meanwhile is shown at once


def test_window_selector_sets_the_time_span(harness: StationHarness, dock: TelemetryDock) -> None:
    harness.connect()
    harness.run(1.0)
    dock.window_combo.setCurrentIndex(dock.window_combo.findText("1 min"))
    assert dock.recorder.window_s == 60.0
    assert dock.variable_plot.viewRange()[0] == pytest.approx([-60.0, 0.0])
    assert dock.position_plot.viewRange()[0] == pytest.approx([-60.0, 0.0])  # linked


def test_autoscale_toggles_the_vertical_fit(qtbot: QtBot, dock: TelemetryDock) -> None:
    view = dock.position_plot.getViewBox()
    assert dock.autoscale_button.isChecked() and view.autoRangeEnabled()[1]
    qtbot.mouseClick(dock.autoscale_button, LEFT)
    assert not view.autoRangeEnabled()[1]
    qtbot.mouseClick(dock.autoscale_button, LEFT)
    assert view.autoRangeEnabled()[1]


def test_a_machine_without_subscribers_offers_no_variable(qtbot: QtBot) -> None:
    profile = load_profile("xy-stage")
    bare = replace(profile, capabilities=replace(profile.capabilities, subscribers=False))
    harness = StationHarness(bare)
    recorder = TelemetryRecorder(harness.station, throttle_ms=0, scroll_ms=0)
    dock = TelemetryDock(recorder)
    qtbot.addWidget(dock)
    assert not dock.variable_combo.isEnabled()
    assert dock.variable_combo.currentData() is None
    harness.close()
    recorder.deleteLater()


def test_captions_sit_beside_the_data_and_apart(dock: TelemetryDock) -> None:
    """Titles and keys neither cover the curves nor print over each other."""
    choose(dock, Subscriber.BATTERY_VOLTAGE)
    dock.redraw()
    rects = [caption.sceneBoundingRect() for caption in dock.captions]
    for plot, rect in zip(dock.plots, rects, strict=True):
        assert not rect.intersects(plot.getViewBox().sceneBoundingRect())
    for upper, lower in pairwise(rects):
        assert upper.bottom() <= lower.top()
    assert "battery voltage (V)" in dock.title(dock.variable_plot)
    assert all(plot.getViewBox().height() >= 40 for plot in dock.plots)


def _segments(t: np.ndarray, y: np.ndarray) -> set[tuple[float, float, float, float]]:
    return {(a, b, c, d) for a, b, c, d in zip(t[:-1], y[:-1], t[1:], y[1:], strict=True)}


def _assert_spans_cover_the_changes(
    old: tuple[np.ndarray, np.ndarray], new: tuple[np.ndarray, np.ndarray]
) -> list[tuple[float, float]] | None:
    """Every segment (or lone point) in one polyline and not the other lies in a span."""
    spans = changed_spans(old[0], old[1], new[0], new[1])
    if spans is None:
        return None  # the whole curve is repainted
    before, after = _segments(*old), _segments(*new)
    changed = [(t0, t1) for t0, _, t1, _ in before ^ after]
    lone = [{(float(t[0]), float(y[0]))} if len(t) == 1 else set() for t, y in (old, new)]
    changed += [(t0, t0) for t0, _ in lone[0] ^ lone[1]]  # a curve of one point: a dot
    for t0, t1 in changed:
        assert any(start <= t0 and t1 <= stop for start, stop in spans), (t0, t1, spans)
    return spans


@settings(max_examples=60, deadline=None)
@given(
    seed=st.integers(0, 2**16),
    window=st.integers(500, 20_000),
    step=st.integers(0, 400),
    points=st.sampled_from([200, 1000, 2000]),
    pinned=st.booleans(),
)
def test_changed_spans_cover_every_change_of_a_scrolling_envelope(
    seed: int, window: int, step: int, points: int, pinned: bool
) -> None:
    """Two consecutive frames of a window sliding over samples, reduced as the dock draws them
    (``pinned``: from a left edge that stays put between the dock's whole-pixel shifts)."""
    rng = np.random.default_rng(seed)
    total = window + step + 1
    t = np.arange(total) / 1000
    y = rng.normal(size=total).cumsum()
    envelope = PeakEnvelope()
    old = envelope.reduce(t, y, 0, window, points)
    old = (old[0].copy(), old[1].copy())
    new = envelope.reduce(t, y, 0 if pinned else step, window + step, points)
    spans = _assert_spans_cover_the_changes(old, new)
    if step == 0:
        assert spans == []
    elif step < window // 20 and window > 4 * points:
        # A scrolling window changes at its ends only: the middle is left alone.
        assert spans is not None
        assert sum(stop - start for start, stop in spans) < (t[window] - t[0]) / 4
        if pinned:  # and with the left end pinned, at the right end alone
            assert len(spans) == 1 and spans[0][0] > t[window // 2]


@settings(max_examples=60, deadline=None)
@given(
    old=st.lists(st.tuples(st.integers(0, 30), st.integers(-3, 3)), max_size=30),
    new=st.lists(st.tuples(st.integers(0, 30), st.integers(-3, 3)), max_size=30),
)
def test_changed_spans_cover_any_change(
    old: list[tuple[int, int]], new: list[tuple[int, int]]
) -> None:
    """Whatever two curves are, nothing that differs is left out of the repaint."""

    def curve(points: list[tuple[int, int]]) -> tuple[np.ndarray, np.ndarray]:
        points = sorted(points)
        return (
            np.array([p[0] for p in points], dtype=float),
            np.array([p[1] for p in points], dtype=float),
        )

    _assert_spans_cover_the_changes(curve(old), curve(new))


def _window_pixels(widget: QWidget) -> QImage:
    """What the window shows now (its backing store), not a fresh rendering of it."""
    screen = widget.screen()
    return screen.grabWindow(widget.winId()).toImage()


def test_a_scrolling_frame_repaints_a_sliver_and_shows_the_full_picture(qtbot: QtBot) -> None:
    """Between whole-pixel shifts a frame repaints only the curves' ends, yet shows what a
    full repaint shows."""
    clock = ManualClock()
    station = Station(load_profile("xy-stage"), clock, realtime=False)
    recorder = TelemetryRecorder(station, throttle_ms=0, scroll_ms=0)
    dock = TelemetryDock(recorder)
    qtbot.addWidget(dock)
    dock.resize(1000, 600)
    dock.show()
    qtbot.waitExposed(dock)
    dock.window_combo.setCurrentIndex(dock.window_combo.findData(MAX_WINDOW_S))
    rate = 1000
    rng = np.random.default_rng(3)
    t = np.arange(int(MAX_WINDOW_S * rate)) / rate
    names = ("X position", "X velocity", "Y position", "Y velocity")
    walks = {name: rng.normal(size=len(t) + 400).cumsum() for name in names}
    for name in names:
        recorder.extend(name, t, walks[name][: len(t)])
    clock.advance(MAX_WINDOW_S)
    dock.redraw()
    QApplication.processEvents()

    regions: list[int] = []  # the area each paint covers, in pixels

    class Regions(QObject):
        def eventFilter(self, _watched: QObject, event: QEvent) -> bool:
            if event.type() == QEvent.Type.Paint:
                region = event.region()  # type: ignore[attr-defined]
                regions.append(sum(rect.width() * rect.height() for rect in region))
            return False

    watcher = Regions()
    viewport = dock.graphics.viewport()
    viewport.installEventFilter(watcher)
    fed = len(t)
    for _ in range(20):  # 20 frames of 16 samples, about one pixel of a 10-minute window
        clock.advance(0.016)
        new_t = np.arange(fed, fed + 16) / rate
        for name in names:
            recorder.extend(name, new_t, walks[name][fed : fed + 16])
        fed += 16
        QApplication.processEvents()
    viewport.removeEventFilter(watcher)
    shown = _window_pixels(dock)
    assert len(regions) >= 15
    slivers = [area for area in regions if area < viewport.width() * viewport.height() / 20]
    assert len(slivers) >= len(regions) - 3  # a shift or two repaint the lot
    viewport.repaint()
    assert _window_pixels(dock) == shown
    recorder.deleteLater()
