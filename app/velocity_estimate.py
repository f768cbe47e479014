"""An axis's velocity from its reported positions: a least-squares slope over a time window.

Positions arrive with the station's receive time, not the device's
measuring time: a link batches frames (two echoes 1 ms apart that were
measured 100 ms apart) and positions are quantised to a count or a
micrometre.  Differentiating consecutive samples divides a real step by a
jittered, sometimes tiny interval: a 10 mm/s move showed 210 mm/s spikes.
A straight line fitted to every sample of the last ``window_s`` seconds
spreads the timing error over the whole window instead, so the error in
the slope shrinks with the window's length (about jitter / window) while
a steady speed reads exactly.  The price is lag: a change of speed shows
fully after one window, half after half of it.
"""

from __future__ import annotations

from collections import deque

#: The time the slope is fitted over: 5 echoes at the stage's 100 ms period, 500 at 1 kHz.
DEFAULT_WINDOW_S = 0.5
#: Fewer samples than this, or a shorter span, give no slope yet (the first sample of a
#: move, or two in one batch).
MIN_SAMPLES = 3
MIN_SPAN_S = 0.05


class VelocityEstimator:
    """Least-squares slope of the samples in the last ``window_s`` seconds, in O(1) per sample.

    Running sums over times taken relative to a reference (the oldest held
    sample, moved forward now and then) keep the arithmetic well conditioned
    however long the recording runs.
    """

    def __init__(self, window_s: float = DEFAULT_WINDOW_S) -> None:
        if window_s <= 0:
            raise ValueError("window must be positive")
        self.window_s = window_s
        self._samples: deque[tuple[float, float]] = deque()
        self._t_ref = 0.0
        self._x_ref = 0.0
        self._n = 0
        self._st = self._sx = self._stt = self._stx = 0.0

    def reset(self) -> None:
        """Forget the samples (a gap: what happened meanwhile is unknown)."""
        self._samples.clear()
        self._n = 0
        self._st = self._sx = self._stt = self._stx = 0.0

    def update(self, t: float, x: float) -> float:
        """Add the position ``x`` at time ``t``; the velocity at ``t`` (0 until there is a slope).

        A sample at the time of the last one replaces it; one from before it
        (a clock that went back) or after a gap longer than the window starts over.
        """
        samples = self._samples
        if samples:
            last_t = samples[-1][0]
            if t == last_t:
                self._remove(*samples.pop())
            elif t < last_t or t - last_t > self.window_s:
                self.reset()
        if not samples:
            self._t_ref, self._x_ref = t, x
        samples.append((t, x))
        self._add(t, x)
        while samples and samples[0][0] < t - self.window_s:
            self._remove(*samples.popleft())
        if samples[0][0] - self._t_ref > self.window_s:
            self._rebase()
        return self.velocity()

    def velocity(self) -> float:
        """The current slope, 0.0 when too few samples or too short a span are held."""
        samples = self._samples
        if self._n < MIN_SAMPLES or samples[-1][0] - samples[0][0] < MIN_SPAN_S:
            return 0.0
        n = self._n
        denominator = n * self._stt - self._st * self._st
        if denominator <= 0.0:
            return 0.0
        return (n * self._stx - self._st * self._sx) / denominator

    def _add(self, t: float, x: float) -> None:
        dt, dx = t - self._t_ref, x - self._x_ref
        self._n += 1
        self._st += dt
        self._sx += dx
        self._stt += dt * dt
        self._stx += dt * dx

    def _remove(self, t: float, x: float) -> None:
        dt, dx = t - self._t_ref, x - self._x_ref
        self._n -= 1
        self._st -= dt
        self._sx -= dx
        self._stt -= dt * dt
        self._stx -= dt * dx

    def _rebase(self) -> None:
        """Move the reference to the oldest sample and recompute the sums from the samples."""
        held = list(self._samples)
        self.reset()
        self._t_ref, self._x_ref = held[0]
        for t, x in held:
            self._samples.append((t, x))
            self._add(t, x)
