"""The gamepad on a timer, fed to the jog state machine as one more held "button".

The pad is one source in :class:`~app.jog_state.JogState`, beside the keys and the
on-screen buttons, so it has their motion gate (a locked jog refuses it and says why,
a job owning the machine refuses it in the session) and their dead-man: each look that
finds the pad still held is the sign the session's dead-man waits for, and a pad that
stops being looked at (a stalled station) ends its jog after ``JOG_DEADMAN_S``.

A pad unplugged mid-jog is the key release that never comes: the next look finds it
gone and lets go at once.  Whatever let go of the pad's jog besides the pad (focus lost,
the lock, Stop, the dead-man, a refusal) holds until the pad is let go too — the stick
back in its dead zone or the enable button released — as a key must be pressed anew.

Each look is a few microseconds of SDL (no I/O wait), so it runs on the GUI thread.
"""

from __future__ import annotations

import enum
from collections.abc import Callable

from PySide6.QtCore import QCoreApplication, QObject, QTimer, Signal

from app.gamepad.background import BackgroundImport
from app.gamepad.mapping import IDLE, PadIntent, PadReading, intent
from app.gamepad.source import PadDevice, PadSource, PadUnavailable
from app.jog_state import JogState
from app.station import Station

# How often the pad is looked at: 25 times a second (a release is seen within 40 ms).
POLL_MS = 40
# The pad's key in the jog state machine's held sources.
SOURCE = "gamepad"


class PadState(enum.Enum):
    OFF = "off"
    # On, and its library is being imported (off the GUI thread).
    LOADING = "loading"
    # The gamepad support cannot load (:attr:`GamepadJog.unavailable` says why).
    UNAVAILABLE = "unavailable"
    # On, and waiting for the device chosen (or any) to be plugged in.
    SEARCHING = "searching"
    CONNECTED = "connected"


def _load_sdl() -> PadSource:
    from app.gamepad.sdl import SdlPadSource  # SDL only once the operator wants it

    return SdlPadSource()


def _import_sdl() -> None:
    from app.gamepad.sdl import import_sdl

    import_sdl()


class GamepadJog(QObject):
    """Looks at the chosen pad and keeps the jog state machine in step with it."""

    # The state or the device changed (the window shows it).
    stateChanged = Signal()

    def __init__(
        self,
        station: Station,
        jog: JogState,
        *,
        source_factory: Callable[[], PadSource] | None = None,
        preload: Callable[[], None] | None = None,
        active: Callable[[], bool] = lambda: True,
        poll_ms: int | None = POLL_MS,
        parent: QObject | None = None,
    ) -> None:
        super().__init__(parent)
        self._station = station
        self._jog = jog
        # SDL unless a test hands in its own device; SDL's import runs off the GUI thread.
        self._factory = source_factory or _load_sdl
        if preload is None and source_factory is None:
            preload = _import_sdl
        self._preload = None if preload is None else BackgroundImport(preload, self)
        if self._preload is not None:
            self._preload.done.connect(self._preloaded)
        # Whether the operator wants the pad on (kept while its library loads).
        self._wanted_on = False
        # Whether the station's window is the one the operator uses now: a pad in another
        # program's hands (or a second StepDeck's) jogs nothing here.
        self._active = active
        self._source: PadSource | None = None
        self.state = PadState.OFF
        # Why the gamepad support is unavailable (None: it is not known to be).
        self.unavailable: str | None = None
        # The device chosen by name ("" : the first found).
        self.wanted = ""
        # The device read now (None: none).
        self.device: PadDevice | None = None
        self._held: tuple[int, ...] = IDLE.directions
        self._speed = 1.0
        # Let go by something else while the pad still asked for a jog: wait for its release.
        self._latched = False
        self.timer: QTimer | None = None
        if poll_ms is not None:
            self.timer = QTimer(self)
            self.timer.setInterval(poll_ms)
            self.timer.timeout.connect(self.poll)

    # --- the operator's choices -----------------------------------------------------

    @property
    def enabled(self) -> bool:
        """Whether the operator has the pad on (available or not)."""
        return self.state is not PadState.OFF

    def set_enabled(self, enabled: bool) -> None:
        """Turn the gamepad on (loading SDL the first time) or off (letting go of its jog)."""
        self._wanted_on = enabled
        if not enabled:
            self._let_go()
            if self._source is not None:
                self._source.close()
            self.device = None
            self._stop_timer()
            self._set_state(PadState.OFF)
            return
        if not self._ready():
            self._set_state(PadState.LOADING)
            return
        if not self._load():
            self._set_state(PadState.UNAVAILABLE)
            return
        self._set_state(PadState.CONNECTED if self.device else PadState.SEARCHING)
        if self.timer is not None:
            self.timer.start()
        self.poll()

    def set_device(self, name: str) -> None:
        """Read the device of this name from now on ("": the first found)."""
        if name == self.wanted:
            return
        self.wanted = name
        if self.device is not None and name and self.device.name != name:
            self._drop_device()
        if self.state is not PadState.OFF and self.state is not PadState.UNAVAILABLE:
            self.poll()

    def device_names(self) -> list[str]:
        """The names of the devices attached now (loading the library to see them)."""
        if not self._ready() or not self._load() or self._source is None:
            return []
        return [device.name for device in self._source.devices()]

    # --- each look -----------------------------------------------------------------

    def poll(self) -> None:
        """Look at the pad once: find it, notice it gone, or follow its sticks."""
        source = self._source
        if source is None or self.state not in (PadState.SEARCHING, PadState.CONNECTED):
            return
        if self.device is None and not self._find(source):
            return
        reading = source.read()
        if reading is None:
            self._gone()
            return
        if not self._active():
            reading = PadReading()  # as if let go
        self._follow(intent(reading, self._held))

    def _follow(self, wanted: PadIntent) -> None:
        jog = self._jog
        if any(self._held) and not jog.holds(SOURCE):
            # Let go by the station (Stop, the lock, focus, the dead-man, a new link).
            self._held = IDLE.directions
            self._set_speed(1.0)
            self._latched = True
        if self._latched:
            if wanted.jogs:
                return
            self._latched = False
        if not wanted.jogs:
            self._let_go()
            return
        self._set_speed(wanted.speed)
        if wanted.directions == self._held:
            jog.keep_held(SOURCE)
            return
        if jog.button_press(SOURCE, wanted.directions):
            self._held = wanted.directions
        else:  # refused (and said why): not again until the pad is let go
            self._held = IDLE.directions
            self._set_speed(1.0)
            self._latched = True

    def _let_go(self) -> None:
        if any(self._held):
            self._jog.button_release(SOURCE)
        self._held = IDLE.directions
        self._set_speed(1.0)

    def _set_speed(self, share: float) -> None:
        if share == self._speed:
            return
        self._speed = share
        session = self._station.session
        if session is not None:
            session.set_jog_speed(share)

    # --- devices ---------------------------------------------------------------------

    def _ready(self) -> bool:
        """Whether the library can be loaded now without a wait; if not, its import starts
        (:meth:`_preloaded` follows)."""
        preload = self._preload
        if self._source is not None or preload is None or preload.finished:
            return True
        preload.start()
        return False

    def _preloaded(self) -> None:
        """The library's import ended: go on where the operator was."""
        if self._wanted_on:
            self.set_enabled(True)
        else:
            self.stateChanged.emit()  # the devices can be listed now

    def _load(self) -> bool:
        """Load the library (once it works); whether it is there (else ``unavailable`` says
        why)."""
        if self._source is not None:
            return True
        try:
            self._source = self._factory()
        except PadUnavailable as exc:
            self.unavailable = str(exc)
            return False
        self.unavailable = None
        return True

    def _find(self, source: PadSource) -> bool:
        for device in source.devices():
            if (not self.wanted or device.name == self.wanted) and source.open(device):
                self.device = device
                self._latched = True  # a stick already pushed when found does not jog
                self._set_state(PadState.CONNECTED)
                return True
        return False

    def _gone(self) -> None:
        """The pad was unplugged: its jog stops now, and it is looked for again."""
        device = self.device
        jogged = any(self._held)
        self._drop_device()
        if jogged and device is not None:
            said = QCoreApplication.translate("Gamepad", "Gamepad {0} unplugged: jog stopped")
            self._station.model.message.emit(said.format(device.name))

    def _drop_device(self) -> None:
        self._let_go()
        self._latched = False
        if self._source is not None:
            self._source.close()
        self.device = None
        self._set_state(PadState.SEARCHING)

    def _stop_timer(self) -> None:
        if self.timer is not None:
            self.timer.stop()

    def _set_state(self, state: PadState) -> None:
        self.state = state
        self.stateChanged.emit()

    def shutdown(self) -> None:
        """The window closes: let go and close the device."""
        self.set_enabled(False)
