"""The window's half of each dialect: its pages, where its Home is, its stop caption, its
developer boxes.

:mod:`app.machines.registry` lists the dialects and what each can do (its
jogs, whether one command homes every axis, whether it is sent G-code text);
this table says what the window shows for
each, so :class:`~widgets.main_window.MainWindow`, the developer pane and the
jobs dock build from an entry instead of asking a profile which dialect it
speaks.  It holds names, not panels: the panels read the app's half, and a
table that imported them would go round in a circle with them.  The pages are
built from these names in :mod:`widgets.window.pages`.
"""

from __future__ import annotations

import enum
from collections.abc import Mapping
from dataclasses import dataclass

from app.profiles import MachineProfile


class Page(enum.Enum):
    """A dialect's own page, shown between Manual and Dynamics (in the entry's order)."""

    #: The drill's command buttons, X/Y in microsteps and its terminal (no Absolute/Relative:
    #: the plotter takes absolute microsteps only).
    DRILL = "drill"
    #: The usb3 unit's moves by mm, step sizes and threads.
    USB3_AXES = "usb3_axes"
    ABSOLUTE = "absolute"
    RELATIVE = "relative"
    #: The G-code console, pen, hold/resume/reset.
    GCODE = "gcode"


class DropCaption(enum.Enum):
    """What Stop promises on a machine without a stop command: what the dropped queue leaves.

    (A machine with one says STOP whatever its dialect: ``capabilities.stop_command``.)
    """

    #: The move it is running finishes.
    MOVE = "move"
    #: The procedure it is running (a home, a drilled hole) finishes.
    PROCEDURE = "procedure"


class DeveloperBox(enum.Enum):
    """A box of the developer pane that only means something on some dialects."""

    #: Echoes composed by hand and fed to the model.
    ECHO_COMPOSER = "echo_composer"
    #: The emulated stage's environment (charger, USB, end switches…).
    STAGE_EMULATOR = "stage_emulator"
    #: The usb3 unit's joystick.
    JOYSTICK = "joystick"
    #: Replies injected as if the G-code board had sent them.
    GCODE_REPLIES = "gcode_replies"
    #: The emulated G-code board's own buttons.
    GCODE_BOARD = "gcode_board"


@dataclass(frozen=True)
class WindowDialect:
    """What the window shows for one dialect."""

    name: str
    #: Its own pages, after Manual (Dynamics and Link follow on every machine).
    pages: tuple[Page, ...]
    #: The page whose buttons the Machine menu's Home entries press; None: the Manual
    #: page's Home buttons.
    home_page: Page | None
    #: The developer pane's dialect boxes shown (the others are built, hidden).
    developer_boxes: frozenset[DeveloperBox]
    #: Stop's caption where the machine has no stop command.
    drop_caption: DropCaption = DropCaption.MOVE


_ENTRIES = (
    WindowDialect(
        "stage",
        (Page.ABSOLUTE, Page.RELATIVE),
        None,
        frozenset({DeveloperBox.ECHO_COMPOSER, DeveloperBox.STAGE_EMULATOR}),
    ),
    WindowDialect("usb3", (Page.USB3_AXES,), None, frozenset({DeveloperBox.JOYSTICK})),
    WindowDialect(
        "drill", (Page.DRILL,), Page.DRILL, frozenset(), drop_caption=DropCaption.PROCEDURE
    ),
    WindowDialect(
        "gcode",
        (Page.ABSOLUTE, Page.RELATIVE, Page.GCODE),
        Page.GCODE,  # $H homes every axis at once
        frozenset({DeveloperBox.GCODE_REPLIES, DeveloperBox.GCODE_BOARD}),
    ),
)

#: Dialect name (a profile's ``dialect``) → what the window shows for it.
WINDOW_DIALECTS: Mapping[str, WindowDialect] = {entry.name: entry for entry in _ENTRIES}


def window_dialect(profile: MachineProfile) -> WindowDialect:
    """Every dialect the registry knows has an entry here (a test holds the two together)."""
    return WINDOW_DIALECTS[profile.dialect]
