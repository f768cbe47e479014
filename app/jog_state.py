"""The operator's jog input as a state machine: what is held, merged into one jog vector.

The stage is level-triggered, so what matters is the set of things the
operator is holding *right now*.  Keys and on-screen buttons are tracked here
together, so releasing a button cannot cancel a key that is still held (and
the other way round), and every change reaches the session at once instead
of waiting for the next periodic frame.  ``release_all`` is the one way out
for every "the operator let go without us seeing it" case (focus lost,
window deactivated, motion locked).

No widget here: keys are whatever integers the caller maps to an axis and a
direction, and whether the mouse still holds a button is told to
:meth:`JogState.poll_buttons`.  ``widgets/jog_input.py`` feeds it Qt's key
and mouse events.
"""

from __future__ import annotations

from collections.abc import Hashable, Mapping, Sequence

from PySide6.QtCore import QCoreApplication, QObject, Signal

from app.station import Station


class JogState(QObject):
    """Tracks what is held and keeps ``session.set_jog`` in step with it.

    ``keys`` maps each jog key to its (axis index, direction); a key for an
    axis the machine lacks is no jog key.
    """

    #: The jog vector (one -1/0/+1 per axis) after every change.
    vectorChanged = Signal(tuple)
    #: The jog the held arrow keys alone ask for (one -1/0/+1 per axis), after every change:
    #: the on-screen button for that direction shows itself pressed.
    keysChanged = Signal(tuple)
    shiftChanged = Signal(bool)
    #: Stop (Esc, a Stop button) was asked, before the session is told: a job under way
    #: must end with it, or it would set the machine going again on its own.
    stopRequested = Signal()

    def __init__(
        self,
        station: Station,
        keys: Mapping[int, tuple[int, int]],
        parent: QObject | None = None,
    ) -> None:
        super().__init__(parent)
        self._station = station
        self._jog_keys = dict(keys)
        self._axes = len(station.model.axes)
        #: Whether this machine jogs at all: if not, no key is a jog key.
        self.jogs = station.dialect.jogs
        self._keys: set[int] = set()
        self._buttons: dict[Hashable, tuple[int, ...]] = {}
        self._shift = False
        self._enabled = True
        #: Why input is refused while disabled (said when a key or button is pressed anyway).
        self._refusal: str | None = None
        self._key_vector: tuple[int, ...] = (0,) * self._axes
        self._sent: tuple[int, ...] = (0,) * self._axes
        #: What a tap of an arrow key moves; 0: the key jogs while held (see ``set_key_step``).
        self.key_step = 0.0
        self._stepped: set[int] = set()  # keys down in step mode: their release is ours too
        # A new session starts with no jog; forget what the old one was told.
        station.sessionChanged.connect(self._forget)
        station.sessionChanged.connect(self._follow_session)
        self._follow_session()

    # --- queries -------------------------------------------------------------

    @property
    def vector(self) -> tuple[int, ...]:
        """The jog vector as last handed to the session."""
        return self._sent

    @property
    def enabled(self) -> bool:
        return self._enabled

    def is_jog_key(self, key: int) -> bool:
        """Whether ``key`` jogs an axis this machine has."""
        return self.jogs and key in self._jog_keys and self._jog_keys[key][0] < self._axes

    def is_held(self, key: int) -> bool:
        return key in self._keys or key in self._stepped

    # --- input ---------------------------------------------------------------

    def set_key_step(self, step: float) -> None:
        """Arrow keys jog while held (0) or move ``step`` per tap (UGS's and CNCjs's choice)."""
        self.key_step = max(0.0, float(step))

    def key_press(self, key: int) -> bool:
        """A jog key went down; returns whether the key is a jog key at all."""
        if not self.is_jog_key(key):
            return False
        if not self._enabled:
            self._say_refused()
            return True
        if self.key_step > 0:
            session = self._station.session
            if self._enabled and session is not None and key not in self._stepped:
                self._stepped.add(key)
                axis, direction = self._jog_keys[key]
                session.step_jog(axis, direction, self.key_step)
                self._set_sent(self._sent)  # the key's button shows it down
            return True
        if self._enabled and key not in self._keys:
            self._keys.add(key)
            self._push()
        return True

    def key_repeat(self, key: int) -> bool:
        """An auto-repeat of a held key: the sign the station's dead-man waits for."""
        if key in self._stepped:
            return True  # a step per tap, never per repeat
        if key not in self._keys:
            return False
        session = self._station.session
        if session is not None:
            session.keep_jogging()
        return True

    def key_release(self, key: int) -> bool:
        """A key came up; returns whether it was a held jog key."""
        if key in self._stepped:
            self._stepped.discard(key)
            self._set_sent(self._sent)
            return True
        if key not in self._keys:
            return False
        self._keys.discard(key)
        self._push()
        return True

    def button_press(self, source: Hashable, directions: Sequence[int]) -> bool:
        """An on-screen jog button went down with its own direction per axis; whether taken."""
        if not self._enabled:
            self._say_refused()
            return False
        padded = (*directions, *(0,) * self._axes)[: self._axes]
        self._buttons[source] = tuple(padded)
        self._push()
        return True

    def button_release(self, source: Hashable) -> None:
        if self._buttons.pop(source, None) is not None:
            self._push()

    def holds(self, source: Hashable) -> bool:
        """Whether ``source`` (a button, the gamepad) is held as far as the jog knows: a
        source let go by the station (Stop, the lock, the dead-man) must be let go too."""
        return source in self._buttons

    def keep_held(self, source: Hashable) -> None:
        """A source that reports its state (the gamepad) says it is still held: the sign
        the session's dead-man waits for."""
        session = self._station.session
        if source in self._buttons and session is not None:
            session.keep_jogging()

    def set_shift(self, held: bool) -> None:
        """Shift held jogs at the other speed; the session switches at once."""
        if held == self._shift:
            return
        self._shift = held
        session = self._station.session
        if session is not None:
            session.set_shift(held)
        self.shiftChanged.emit(held)

    # --- letting go ----------------------------------------------------------

    def release_all(self) -> None:
        """Forget everything held and stop every jog (the runaway-jog guard)."""
        self._keys.clear()
        self._stepped.clear()
        self._buttons.clear()
        self.set_shift(False)
        session = self._station.session
        if session is not None:
            # Always told, even if we think nothing is held: the session ignores a no-op.
            session.set_jog((0,) * self._axes)
        self._set_sent((0,) * self._axes)

    def stop_all(self) -> None:
        """The Stop button and Esc: forget held input and STOP every axis, moves included."""
        self.stopRequested.emit()
        self._keys.clear()
        self._buttons.clear()
        self._set_sent((0,) * self._axes)
        session = self._station.session
        if session is not None:
            session.stop_all()

    def set_enabled(self, enabled: bool, reason: str | None = None) -> None:
        """Motion or jog lock: while disabled nothing new is held and what was held is let go.

        ``reason`` is said in the status bar when a jog key is pressed anyway, so a locked
        key is never silently dead.
        """
        self._enabled = enabled
        self._refusal = None if enabled else reason
        if not enabled:
            self.release_all()

    def _say_refused(self) -> None:
        if self._refusal:
            # Translated in JogInput's context, where the widget has always said it.
            said = QCoreApplication.translate("JogInput", "Jog refused: {0}")
            self._station.model.message.emit(said.format(self._refusal))

    # --- internals -----------------------------------------------------------

    def _compute(self) -> tuple[int, ...]:
        totals = [0] * self._axes
        for key in self._keys:
            axis, direction = self._jog_keys[key]
            totals[axis] += direction
        for directions in self._buttons.values():
            for axis, direction in enumerate(directions):
                totals[axis] += direction
        return tuple(max(-1, min(1, t)) for t in totals)

    def _push(self) -> None:
        wanted = self._compute()
        if wanted != self._sent:
            session = self._station.session
            if session is not None:
                session.set_jog(wanted)
        self._set_sent(wanted)  # the held keys may have changed even if the jog did not

    def _set_sent(self, vector: tuple[int, ...]) -> None:
        if vector != self._sent:
            self._sent = vector
            self.vectorChanged.emit(vector)
        keys = self._keys_vector()
        if keys != self._key_vector:
            self._key_vector = keys
            self.keysChanged.emit(keys)

    def _keys_vector(self) -> tuple[int, ...]:
        """The jog the held keys ask for (step-mode taps included while down)."""
        totals = [0] * self._axes
        for key in self._keys | self._stepped:
            axis, direction = self._jog_keys[key]
            totals[axis] += direction
        return tuple(max(-1, min(1, t)) for t in totals)

    def poll_buttons(self, mouse_held: bool) -> bool:
        """A held button sends no repeats: the mouse's state, looked at now and then, is the
        dead-man's sign.  While a button is held and ``mouse_held``, the jog goes on;
        whether any button is still held (False: stop looking)."""
        if not self._buttons:
            return False
        session = self._station.session
        if mouse_held and session is not None:
            session.keep_jogging()
        return True

    def _follow_session(self) -> None:
        session = self._station.session
        if session is not None:
            session.jogEnded.connect(self._jog_ended)

    def _jog_ended(self, _reason: str) -> None:
        """The session ended the jog (dead-man): what we thought held is let go."""
        self._keys.clear()
        self._buttons.clear()
        self._set_sent((0,) * self._axes)

    def _forget(self) -> None:
        self._keys.clear()
        self._buttons.clear()
        self._shift = False
        self._set_sent((0,) * self._axes)
