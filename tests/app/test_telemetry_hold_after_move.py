"""The curves of a machine at rest reach the present: G-code and usb3 reports hold values.

A CoreXY jog of 61 mm seemed to stop drawing early (issue 32): the recorder
took samples only when the model changed, and held values only on the stage's
echoes, so once the move ended its curves stopped where the last report
changed something, the velocity left at the last estimate instead of 0.
"""

from __future__ import annotations

import pytest

from app.profiles import load_profile
from app.telemetry import TelemetryRecorder
from tests.helpers.harness import StationHarness


@pytest.mark.parametrize(
    ("profile", "distance"), [("corexy-plotter", 61.0), ("grbl-plotter", 61.0)]
)
def test_after_a_move_the_curves_hold_the_end_up_to_the_last_report(
    qapp: object, profile: str, distance: float
) -> None:
    harness = StationHarness(load_profile(profile))
    try:
        recorder = TelemetryRecorder(harness.station, scroll_ms=0, throttle_ms=0)
        harness.connect()
        harness.run(1.0)
        session = harness.station.session
        assert session is not None and session.move_relative(0, distance)
        axis = harness.station.model.axes[0]
        harness.run_until(lambda: abs(axis.position - distance) < 0.05 and not axis.moving)
        harness.run(2.0)
        t, y = recorder.recorded(f"{axis.name} position")
        _, v = recorder.recorded(f"{axis.name} velocity")
        assert y[-1] == pytest.approx(axis.position, abs=1e-6)
        assert y[-1] == pytest.approx(distance, abs=0.05)
        assert v[-1] == pytest.approx(0.0, abs=1e-6), v[-6:]
        # Held up to a report of the last second, not left where the move ended.
        assert t[-1] >= recorder.now() - 1.0, (t[-6:], recorder.now())
    finally:
        harness.close()
