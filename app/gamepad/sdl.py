"""SDL2's joysticks and game controllers as a :class:`PadSource` (pysdl2, ctypes).

Only the joystick subsystem is started: no window, no video, no audio, no signal
handlers (Ctrl+C stays Python's).  SDL's event queue is not used: each look calls
``SDL_JoystickUpdate``, which reads the devices and notices hot-plugging in microseconds,
so the poller can run on the GUI thread.  A device SDL knows as a game controller (the
common pads, and SDL's virtual one in the tests) is read through its standard layout;
any other joystick through its raw axes 0 and 1 and its button 0 (the trigger), with no
Z: a joystick's third axis is as often a throttle that rests off centre.
"""

from __future__ import annotations

import warnings
from typing import Any

from app.gamepad.mapping import PadReading
from app.gamepad.source import PadDevice, PadUnavailable

#: SDL's axis reading at full deflection.
AXIS_FULL = 32767.0
#: pip's names of what ``stepdeck[gamepad]`` installs (said when it is missing).
EXTRA_HINT = "pip install 'stepdeck[gamepad]'"


def import_sdl() -> Any:
    """Import pysdl2: slow (ctypes bindings of SDL's whole API), so run off the GUI thread
    first.  pysdl2 warns that it found pysdl2-dll's library, which is just what is wanted
    (a filter, not ``catch_warnings``: that is not safe on a thread)."""
    warnings.filterwarnings(
        "ignore", message="Using SDL2 binaries from pysdl2-dll", category=UserWarning
    )
    import sdl2

    return sdl2


def load_sdl() -> Any:
    """pysdl2 (untyped: ctypes bindings), with its joystick subsystem started;
    :class:`PadUnavailable` says why not.

    The import is quick once :func:`import_sdl` has run (off the GUI thread).
    """
    try:
        sdl2 = import_sdl()
    except ImportError as exc:
        raise PadUnavailable(f"pysdl2 is not installed ({EXTRA_HINT})") from exc
    except (RuntimeError, OSError) as exc:  # pysdl2 found no usable SDL2 library
        raise PadUnavailable(f"the SDL2 library does not load: {exc}") from exc
    sdl2.SDL_SetHint(sdl2.SDL_HINT_NO_SIGNAL_HANDLERS, b"1")
    sdl2.SDL_SetHint(sdl2.SDL_HINT_JOYSTICK_ALLOW_BACKGROUND_EVENTS, b"1")
    if sdl2.SDL_InitSubSystem(sdl2.SDL_INIT_JOYSTICK | sdl2.SDL_INIT_GAMECONTROLLER) != 0:
        error = sdl2.SDL_GetError().decode(errors="replace")
        raise PadUnavailable(f"SDL's joystick support does not start: {error}")
    # No events queued for nobody to read: the state is read directly.
    sdl2.SDL_JoystickEventState(sdl2.SDL_IGNORE)
    sdl2.SDL_GameControllerEventState(sdl2.SDL_IGNORE)
    return sdl2


class SdlPadSource:
    """The game controllers SDL sees (a :class:`~app.gamepad.source.PadSource`)."""

    def __init__(self, sdl: Any = None) -> None:
        self.sdl: Any = sdl if sdl is not None else load_sdl()
        self._controller: Any = None  # SDL_GameController* (standard layout)
        self._joystick: Any = None  # SDL_Joystick* (raw: a plain joystick)

    def devices(self) -> list[PadDevice]:
        sdl = self.sdl
        sdl.SDL_JoystickUpdate()
        found = []
        for index in range(max(0, sdl.SDL_NumJoysticks())):
            raw = sdl.SDL_JoystickNameForIndex(index)
            name = raw.decode(errors="replace") if raw else f"Joystick {index + 1}"
            found.append(PadDevice(index, name))
        return found

    def open(self, device: PadDevice) -> bool:
        self.close()
        sdl = self.sdl
        if sdl.SDL_IsGameController(device.index):
            controller = sdl.SDL_GameControllerOpen(device.index)
            if controller:
                self._controller = controller
                return True
        joystick = sdl.SDL_JoystickOpen(device.index)
        if joystick:
            self._joystick = joystick
            return True
        return False

    def read(self) -> PadReading | None:
        sdl = self.sdl
        sdl.SDL_JoystickUpdate()
        if self._controller is not None:
            return self._read_controller()
        if self._joystick is not None:
            return self._read_joystick()
        return None

    def _read_controller(self) -> PadReading | None:
        sdl, pad = self.sdl, self._controller
        if not sdl.SDL_GameControllerGetAttached(pad):
            return None

        def axis(which: int) -> float:
            return float(sdl.SDL_GameControllerGetAxis(pad, which)) / AXIS_FULL

        def button(which: int) -> bool:
            return bool(sdl.SDL_GameControllerGetButton(pad, which))

        return PadReading(
            x=axis(sdl.SDL_CONTROLLER_AXIS_LEFTX),
            y=-axis(sdl.SDL_CONTROLLER_AXIS_LEFTY),
            z=-axis(sdl.SDL_CONTROLLER_AXIS_RIGHTY),
            enable=button(sdl.SDL_CONTROLLER_BUTTON_LEFTSHOULDER)
            or button(sdl.SDL_CONTROLLER_BUTTON_RIGHTSHOULDER),
        )

    def _read_joystick(self) -> PadReading | None:
        sdl, stick = self.sdl, self._joystick
        if not sdl.SDL_JoystickGetAttached(stick):
            return None
        axes = sdl.SDL_JoystickNumAxes(stick)
        buttons = sdl.SDL_JoystickNumButtons(stick)
        if axes < 2 or buttons < 1:
            return PadReading()  # nothing this mapping can read: it never jogs
        return PadReading(
            x=float(sdl.SDL_JoystickGetAxis(stick, 0)) / AXIS_FULL,
            y=-float(sdl.SDL_JoystickGetAxis(stick, 1)) / AXIS_FULL,
            enable=bool(sdl.SDL_JoystickGetButton(stick, 0)),
        )

    def close(self) -> None:
        sdl = self.sdl
        if self._controller is not None:
            sdl.SDL_GameControllerClose(self._controller)
        if self._joystick is not None:
            sdl.SDL_JoystickClose(self._joystick)
        self._controller = None
        self._joystick = None
