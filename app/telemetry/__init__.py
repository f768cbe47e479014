"""Telemetry: what the plots draw and what "Export CSV" writes.

:mod:`~app.telemetry.recorder` (the recorder, the views' side),
:mod:`~app.telemetry.sampling` (samples from the model and the session),
:mod:`~app.telemetry.series` (the variables, the buffers, the series) and
:mod:`~app.telemetry.pacing` (when the views hear of it).
"""

from app.telemetry.pacing import DEFAULT_SCROLL_MS, DEFAULT_THROTTLE_MS
from app.telemetry.recorder import TelemetryRecorder
from app.telemetry.series import (
    MAX_RATE_HZ,
    MAX_WINDOW_S,
    MIN_WINDOW_S,
    ROTATION_KEY,
    SERIES_CAPACITY,
    VARIABLES,
    VARIABLES_BY_ID,
    WINDOW_CHOICES_S,
    FloatArray,
    PeakEnvelope,
    SampleBuffer,
    Variable,
)

__all__ = [
    "DEFAULT_SCROLL_MS",
    "DEFAULT_THROTTLE_MS",
    "MAX_RATE_HZ",
    "MAX_WINDOW_S",
    "MIN_WINDOW_S",
    "ROTATION_KEY",
    "SERIES_CAPACITY",
    "VARIABLES",
    "VARIABLES_BY_ID",
    "WINDOW_CHOICES_S",
    "FloatArray",
    "PeakEnvelope",
    "SampleBuffer",
    "TelemetryRecorder",
    "Variable",
]
