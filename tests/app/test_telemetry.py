"""Telemetry recorder: rotation slope, zero, unwrap, CSV, window, pause, throttle, buffers."""

from __future__ import annotations

import csv
from collections.abc import Iterator
from pathlib import Path

import numpy as np
import pytest
from pytestqt.qtbot import QtBot

from app.telemetry import (
    MAX_WINDOW_S,
    MIN_WINDOW_S,
    PeakEnvelope,
    SampleBuffer,
    TelemetryRecorder,
)
from app.velocity_estimate import VelocityEstimator
from protocol.stage.codec import Subscriber
from tests.helpers.harness import StationHarness

RATE_DPS = 10.0


@pytest.fixture
def recorder(harness: StationHarness) -> Iterator[TelemetryRecorder]:
    """A recorder with no throttle and no scroll beat: one ``updated`` per change."""
    recorder = TelemetryRecorder(harness.station, throttle_ms=0, scroll_ms=0)
    yield recorder
    recorder.deleteLater()


@pytest.fixture
def rotating(harness: StationHarness, recorder: TelemetryRecorder) -> TelemetryRecorder:
    """Connected, rotation plotted, the emulated platform turning at 10 °/s."""
    recorder.set_variable(Subscriber.ROTATION)
    harness.connect()
    harness.emulator.rotation_rate_dps = RATE_DPS
    return recorder


def slope(t: np.ndarray, y: np.ndarray) -> float:
    """Least-squares slope."""
    return float(np.polyfit(t, y, 1)[0])


def test_rotation_samples_follow_the_rate(
    harness: StationHarness, rotating: TelemetryRecorder
) -> None:
    harness.run(3.0)
    t, y = rotating.data("rotation")
    assert len(t) >= 10  # half the frames carry the plotted variable at the 100 ms period
    assert slope(t, y) == pytest.approx(RATE_DPS, abs=0.2)
    assert np.all(np.diff(t) > 0)


def test_variable_is_asked_of_the_session_and_again_after_a_new_session(
    harness: StationHarness, recorder: TelemetryRecorder
) -> None:
    recorder.set_variable(Subscriber.YAW_RATE)
    harness.connect()
    assert harness.session.subscribers.plotted == Subscriber.YAW_RATE
    harness.station.connect_emulator()  # a new session: the station announces it
    assert harness.session.subscribers.plotted == Subscriber.YAW_RATE
    recorder.set_variable(None)
    assert harness.session.subscribers.plotted is None
    assert recorder.series_names()[-1] == "Y velocity"


def test_zero_restarts_the_angle_and_keeps_the_slope(
    harness: StationHarness, rotating: TelemetryRecorder
) -> None:
    harness.run(3.0)
    assert rotating.latest("rotation") == pytest.approx(25.0, abs=6.0)
    rotating.zero()
    assert rotating.latest("rotation") == 0.0
    zeroed_at = rotating.now()
    harness.run(2.0)
    t, y = rotating.data("rotation")
    after = t > zeroed_at
    # The first sample after Zero reads what turned since: at most a couple of frames' worth.
    assert 0.0 < y[after][0] <= RATE_DPS * 0.3
    assert slope(t[after], y[after]) == pytest.approx(RATE_DPS, abs=0.2)
    # Zero moved the whole curve, so it stays one straight line.
    assert slope(t, y) == pytest.approx(RATE_DPS, abs=0.2)
    assert y[~after][-1] <= 0.0


def test_zero_before_any_reading_applies_to_the_first(
    harness: StationHarness, recorder: TelemetryRecorder
) -> None:
    recorder.zero()
    recorder.set_variable(Subscriber.ROTATION)
    harness.connect()
    harness.emulator.yaw_deg = 77.0
    harness.run(2.0)
    _, y = recorder.data("rotation")
    assert y[0] == 0.0 and np.all(y == 0.0)  # the platform stands: everything reads 0


def test_wrap_across_180_is_unwrapped(harness: StationHarness, rotating: TelemetryRecorder) -> None:
    harness.emulator.yaw_deg = 170.0
    harness.run(3.0)  # 170° → 200°, which the IMU reports as -160°
    assert harness.station.model.telemetry["rotation"] < 0
    t, y = rotating.data("rotation")
    assert np.all(np.diff(y) > 0) and np.all(np.diff(y) < 5.0)
    assert y[-1] > 180.0
    assert slope(t, y) == pytest.approx(RATE_DPS, abs=0.2)

    harness.emulator.rotation_rate_dps = -RATE_DPS  # and back the other way
    harness.run(4.0)
    _, y = rotating.data("rotation")
    assert np.all(np.abs(np.diff(y)) < 5.0)
    assert y[-1] < 180.0


def test_axes_are_sampled_at_every_echo_even_when_standing(
    harness: StationHarness, recorder: TelemetryRecorder
) -> None:
    harness.connect()
    harness.run(2.0)
    t, y = recorder.data("X position")
    period = harness.session.period_ms / 1000
    assert len(t) >= 1.5 / period
    assert np.all(y == 0.0)
    harness.session.set_jog([1, 0])
    harness.run(0.5)
    t, v = recorder.data("X velocity")
    first_moving = int(np.argmax(v > 0))
    # The last standing sample is at most one period before the first moving one, so the
    # line between them does not invent a slow ramp from long ago.
    assert v[first_moving - 1] == 0.0
    assert t[first_moving] - t[first_moving - 1] <= period + 1e-9


def test_csv_holds_exactly_the_shown_samples(
    harness: StationHarness, rotating: TelemetryRecorder, tmp_path: Path
) -> None:
    harness.session.move_absolute(0, 3.0)
    harness.run(14.0)  # longer than the 10 s window: the export must trim too
    path = tmp_path / "telemetry.csv"
    rows = rotating.export_csv(path)
    with path.open(newline="", encoding="utf-8") as handle:
        table = list(csv.reader(handle))
    header, body = table[0], table[1:]
    assert header == [
        "time (s)",
        "X position (mm)",
        "Y position (mm)",
        "X velocity (mm/s)",
        "Y velocity (mm/s)",
        "rotation (°)",
    ]
    assert len(body) == rows
    times = np.array([float(row[0]) for row in body])
    assert np.all(np.diff(times) > 0)
    assert times[0] >= rotating.view_start()
    for column, name in enumerate(rotating.series_names(), start=1):
        cells = [(float(row[0]), float(row[column])) for row in body if row[column] != ""]
        t, y = rotating.data(name)
        assert len(t) > 0, name
        np.testing.assert_array_equal([c[0] for c in cells], t, err_msg=name)
        np.testing.assert_array_equal([c[1] for c in cells], y, err_msg=name)
    x_positions = [float(row[1]) for row in body if row[1]]
    assert max(x_positions) == 3.0  # the move is in the file, to the micrometre


def test_window_length_trims_what_is_shown(
    harness: StationHarness, rotating: TelemetryRecorder
) -> None:
    harness.run(25.0)
    t, _ = rotating.data("X position")
    end = rotating.view_end()
    assert t[0] >= end - 10.0 and t[-1] <= end
    assert t[0] - (end - 10.0) < 0.2
    rotating.set_window_s(30.0)
    wider, _ = rotating.data("X position")
    assert len(wider) > 2 * len(t)
    assert wider[0] < 0.5  # the whole recording fits in 30 s
    rotating.set_window_s(1.0)
    assert rotating.window_s == MIN_WINDOW_S
    rotating.set_window_s(1e6)
    assert rotating.window_s == MAX_WINDOW_S


def test_pause_freezes_the_view_while_recording_goes_on(
    harness: StationHarness, rotating: TelemetryRecorder
) -> None:
    harness.run(2.0)
    rotating.set_paused(True)
    frozen_t, frozen_y = (a.copy() for a in rotating.data("rotation"))
    recorded_before = len(rotating.recorded("rotation")[0])
    harness.run(3.0)
    t, y = rotating.data("rotation")
    np.testing.assert_array_equal(t, frozen_t)
    np.testing.assert_array_equal(y, frozen_y)
    assert len(rotating.recorded("rotation")[0]) > recorded_before + 5
    rotating.set_paused(False)
    t, _ = rotating.data("rotation")
    assert t[-1] > frozen_t[-1] + 2.5


def test_clear_forgets_and_restarts_time(
    harness: StationHarness, rotating: TelemetryRecorder
) -> None:
    harness.run(2.0)
    rotating.clear()
    assert all(len(rotating.data(name)[0]) == 0 for name in rotating.series_names())
    assert rotating.now() == 0.0
    harness.run(1.0)
    t, _ = rotating.data("rotation")
    assert 0.0 < t[0] < 1.0


def test_unthrottled_emits_once_per_change(
    harness: StationHarness, recorder: TelemetryRecorder
) -> None:
    emits: list[int] = []
    recorder.updated.connect(lambda: emits.append(1))
    for i in range(1, 11):
        harness.station.model.update_axis(0, position=i * 0.1)
    assert len(emits) == 10


def test_throttle_coalesces_a_burst_into_few_emits(harness: StationHarness, qtbot: QtBot) -> None:
    recorder = TelemetryRecorder(harness.station, throttle_ms=40, scroll_ms=0)
    model = harness.station.model
    seen: list[float | None] = []
    recorder.updated.connect(lambda: seen.append(recorder.latest("X position")))
    for i in range(1, 501):  # no event loop in between: the throttle timer cannot fire
        harness.clock.advance(0.001)
        model.update_axis(0, position=i * 0.01)
    assert len(seen) == 1  # the first change is shown at once
    qtbot.waitUntil(lambda: len(seen) == 2, timeout=2000)
    assert seen[-1] == pytest.approx(5.0)  # the trailing emit shows the last sample
    assert len(recorder.recorded("X position")[0]) == 500
    # Quiet again: the next change is shown at once, after the interval has passed.
    qtbot.waitUntil(lambda: not recorder._pacer.throttle.isActive(), timeout=2000)
    model.update_axis(0, position=9.0)
    assert len(seen) == 3 and seen[-1] == 9.0
    recorder.deleteLater()


def test_scroll_beat_moves_the_window_without_samples(
    harness: StationHarness, qtbot: QtBot
) -> None:
    recorder = TelemetryRecorder(harness.station, throttle_ms=0, scroll_ms=10)
    with qtbot.waitSignal(recorder.updated, timeout=2000):
        pass
    recorder.set_paused(True)
    emits: list[int] = []
    recorder.updated.connect(lambda: emits.append(1))
    with qtbot.waitSignal(recorder._pacer.scroll.timeout, timeout=2000):
        pass
    assert emits == []  # paused: nothing moves
    recorder.deleteLater()


def test_sample_buffer_drops_the_oldest_and_stays_contiguous() -> None:
    buffer = SampleBuffer(capacity=100, initial=8)
    for i in range(1000):
        buffer.append(float(i), float(-i))
    t, y = buffer.view()
    assert len(buffer) == 100
    np.testing.assert_array_equal(t, np.arange(900.0, 1000.0))
    np.testing.assert_array_equal(y, -t)
    with pytest.raises(ValueError):
        t[0] = 1.0  # views are read-only: the buffer is the recorder's
    buffer.extend(np.arange(1000.0, 1050.0), np.zeros(50))
    t, _ = buffer.view()
    np.testing.assert_array_equal(t, np.arange(950.0, 1050.0))
    buffer.extend(np.arange(2000.0, 2500.0), np.ones(500))
    t, y = buffer.view()
    np.testing.assert_array_equal(t, np.arange(2400.0, 2500.0))
    buffer.append(2499.0, 7.0)  # same time as the last sample: replaces it
    assert len(buffer) == 100 and buffer.last_y == 7.0


def _brute_envelope_bounds(y: np.ndarray) -> tuple[float, float]:
    return float(y.min()), float(y.max())


def test_peak_envelope_keeps_every_peak_and_reuses_its_blocks() -> None:
    rng = np.random.default_rng(7)
    buffer = SampleBuffer(capacity=50_000)
    cached = PeakEnvelope()

    def reduced(envelope: PeakEnvelope, first: int) -> tuple[np.ndarray, np.ndarray]:
        t, y = buffer.view()
        return envelope.reduce(
            t, y, first, len(t), 1000, base=buffer.first_index, epoch=buffer.epoch
        )

    t0 = 0.0
    for _ in range(12):  # grow past the capacity: blocks slide out at the front
        n = 7_777  # not a multiple of any block length
        buffer.extend(t0 + np.arange(n) / 1000, rng.normal(size=n).cumsum())
        t0 += n / 1000
        t, y = buffer.view()
        first = max(0, len(t) - 30_000)  # a 30 s window sliding along
        x, v = reduced(cached, first)
        if len(t) >= 30_000:  # same window length, same blocks: reuse must change nothing
            fresh_x, fresh_v = reduced(PeakEnvelope(), first)
            np.testing.assert_array_equal(x, fresh_x)
            np.testing.assert_array_equal(v, fresh_v)
        assert len(x) <= 2 * 1000 + 5
        assert np.all(np.diff(x) >= 0)
        assert (x[0], x[-1], v[-1]) == (t[first], t[-1], y[-1])
        assert (v.min(), v.max()) == _brute_envelope_bounds(y[first:])

    buffer.shift(1.0)  # values changed in place: the cache must not survive
    t, y = buffer.view()
    x, v = reduced(cached, 0)
    assert (v.min(), v.max()) == _brute_envelope_bounds(y)


def test_envelope_of_a_short_window_is_the_data(
    harness: StationHarness, rotating: TelemetryRecorder
) -> None:
    harness.run(2.0)
    t, y = rotating.envelope("rotation", 1000)
    expected_t, expected_y = rotating.data("rotation")
    np.testing.assert_array_equal(t, expected_t)
    np.testing.assert_array_equal(y, expected_y)


def test_envelope_of_a_long_window_is_small(recorder: TelemetryRecorder) -> None:
    t = np.arange(600_000) / 1000 - 600.0  # ten minutes at 1 kHz, up to now
    y = np.sin(t)
    recorder.extend("X position", t, y)
    recorder.set_window_s(MAX_WINDOW_S)
    x, v = recorder.envelope("X position", 2000)
    assert len(x) <= 2 * 2000 + 5
    assert v.max() == y.max() and v.min() == y.min()
    recorder.set_paused(True)  # the frozen view is reduced the same way
    _, v_paused = recorder.envelope("X position", 2000)
    np.testing.assert_array_equal(v_paused, v)


# --- velocity from positions -----------------------------------------------------------------

TRUE_SPEED = 10.0  # mm/s


def jittered_trace(
    seconds: float = 6.0, period: float = 0.1, quantum: float = 0.001, seed: int = 3
) -> tuple[np.ndarray, np.ndarray]:
    """A 10 mm/s axis as the station sees it: receive times, quantised positions.

    Each echo is measured on the device's beat but received 0-40 ms late, and
    every fifth one is held back until the next arrives 1 ms before it (a BLE
    connection event carrying two notifications): the naive derivative of
    consecutive samples then divides a 100 ms step by 1 ms.
    """
    rng = np.random.default_rng(seed)
    measured = np.arange(1, int(seconds / period) + 1) * period
    received = measured + rng.uniform(0.0, 0.04, len(measured))
    for k in range(4, len(received) - 1, 5):
        received[k] = received[k + 1] - 0.001
    received = np.maximum.accumulate(received)
    positions = np.round(TRUE_SPEED * measured / quantum) * quantum
    return received, positions


def test_velocity_estimate_of_a_jittered_trace_has_no_spikes() -> None:
    t, x = jittered_trace()
    naive = np.diff(x) / np.diff(t)
    assert naive.max() > 5 * TRUE_SPEED  # the trace does provoke the spikes seen in the field
    estimator = VelocityEstimator()
    v = np.array([estimator.update(ti, xi) for ti, xi in zip(t, x, strict=True)])
    assert v.max() <= 1.5 * TRUE_SPEED
    assert v.min() >= 0.0
    steady = v[t > t[0] + 2 * estimator.window_s]
    assert np.median(steady) == pytest.approx(TRUE_SPEED, rel=0.05)


def test_velocity_estimate_of_a_quantised_fast_stream_and_a_stop() -> None:
    # 1 kHz, positions in 0.01 mm steps (a coarse encoder), 0-0.5 ms receive jitter.
    rng = np.random.default_rng(7)
    t = np.arange(1, 3001) / 1000 + rng.uniform(0, 0.0005, 3000)
    x = np.round(np.minimum(TRUE_SPEED * np.arange(1, 3001) / 1000, 20.0) / 0.01) * 0.01
    estimator = VelocityEstimator()
    v = np.array([estimator.update(ti, xi) for ti, xi in zip(t, x, strict=True)])
    assert np.abs(v).max() <= 1.5 * TRUE_SPEED
    assert v[1000:1900] == pytest.approx(TRUE_SPEED, rel=0.05)  # moving, after one window
    assert np.all(v[-400:] == pytest.approx(0.0, abs=1e-9))  # stopped at 2 s, window over


def test_velocity_estimate_starts_over_after_a_gap_or_a_clock_going_back() -> None:
    estimator = VelocityEstimator(window_s=0.5)
    for k in range(10):
        estimator.update(k * 0.1, k * 1.0)
    assert estimator.velocity() == pytest.approx(10.0)
    assert estimator.update(5.0, 100.0) == 0.0  # after a gap: one sample, no slope
    assert estimator.update(4.0, 0.0) == 0.0  # the clock went back: starts over
    estimator.update(4.1, 0.0)
    estimator.update(4.1, 0.5)  # same time: replaces the last
    assert estimator.update(4.2, 1.0) == pytest.approx(5.0)


def test_recorded_velocity_comes_from_filtered_positions(
    harness: StationHarness, recorder: TelemetryRecorder
) -> None:
    """The model's naive velocity is not what the plot shows."""
    t, x = jittered_trace()
    model = harness.station.model
    for ti, xi in zip(t, x, strict=True):
        harness.clock.advance(ti - recorder.now())
        naive = 999.0  # what a session dividing by a 1 ms interval would report
        model.update_axis(0, position=float(xi), velocity=naive)
    shown_t, v = recorder.data("X velocity")
    assert len(shown_t) == len(t)
    assert v.max() <= 1.5 * TRUE_SPEED
    assert np.median(v[shown_t > 2.0]) == pytest.approx(TRUE_SPEED, rel=0.05)


def test_scroll_beat_stays_silent_while_samples_keep_coming(
    harness: StationHarness, qtbot: QtBot
) -> None:
    """The beat only fills silences: every sample's frame restarts its interval."""
    recorder = TelemetryRecorder(harness.station, throttle_ms=0, scroll_ms=5000)
    emits: list[int] = []
    recorder.updated.connect(lambda: emits.append(1))
    model = harness.station.model
    for k in range(5):
        qtbot.wait(300)  # 1.5 s in all: an interval not restarted would have < 3.5 s left
        harness.clock.advance(0.3)
        model.update_axis(0, position=float(k + 1))
        # counted afresh from this frame (a coarse timer may round by 5 %)
        assert recorder._pacer.scroll.remainingTime() > 4000
    assert len(emits) == 5
    recorder.deleteLater()


def test_scroll_beat_fills_a_silence(harness: StationHarness, qtbot: QtBot) -> None:
    recorder = TelemetryRecorder(harness.station, throttle_ms=0, scroll_ms=20)
    with qtbot.waitSignal(recorder.updated, timeout=2000):
        pass  # nothing recorded, yet the window moves
    recorder.deleteLater()


def test_recorded_velocity_drops_to_zero_when_the_session_says_the_axis_stopped(
    harness: StationHarness, recorder: TelemetryRecorder
) -> None:
    """Machines without echoes report no more positions once standing: the stop ends the slope."""
    model = harness.station.model
    for k in range(1, 11):
        harness.clock.advance(0.1)
        model.update_axis(0, position=k * 1.0, moving=True, velocity=10.0)
    assert recorder.latest("X velocity") == pytest.approx(10.0)
    harness.clock.advance(0.05)
    model.update_axis(0, moving=True, velocity=3.0)  # no new position while moving: no news
    assert recorder.latest("X velocity") == pytest.approx(10.0)
    model.update_axis(0, moving=False, velocity=0.0)
    assert recorder.latest("X velocity") == 0.0
    assert recorder.latest("X position") == 10.0


def test_envelope_since_pins_the_left_end_while_samples_come_in(
    recorder: TelemetryRecorder,
) -> None:
    """A view whose left edge lies a little after the window's start draws from that edge:
    new samples then change the envelope's right end only, and the revision says so."""
    rate = 1000
    t = np.arange(600 * rate) / rate - 600.0  # ten minutes at 1 kHz, up to now
    y = np.cos(t / 3.0)
    recorder.extend("X position", t[:-500], y[:-500])
    recorder.set_window_s(MAX_WINDOW_S)
    since = -599.5  # the view's left edge: half a second after the window's start
    before_t, before_y = recorder.envelope("X position", 2000, since)
    before_t, before_y = before_t.copy(), before_y.copy()
    assert before_t[0] >= since
    first_t, _ = recorder.data("X position")
    assert first_t[0] < since  # the recorder's own window still starts earlier
    recorder.extend("X position", t[-500:], y[-500:])
    after_t, after_y = recorder.envelope("X position", 2000, since)
    assert after_t[0] == before_t[0] and after_y[0] == before_y[0]
    _, first, last = recorder.revision("X position", since)
    shown_t, shown_y = recorder.data("X position")
    assert last - first == np.count_nonzero(shown_t >= since)
    np.testing.assert_array_equal(after_t[-1:], shown_t[-1:])
    # Every peak from the edge on survives.
    inside = shown_t >= since
    assert (after_y.min(), after_y.max()) == (shown_y[inside].min(), shown_y[inside].max())
