"""Whether a signal has any receiver: asked once per batch, so that a batch of a thousand
lines a second does not emit per line what nobody hears.

A streaming job tells every line written and every reply read as a frame
(``frameSent``/``frameReceived``, for the frame log) and every line sent
(``lineSent``); with nothing connected, each emit still cost about as much as
the line's whole bookkeeping on the window's thread.  An emit with no receiver
does nothing, so skipping it changes nothing; a receiver connected later is
heard from the next batch on (the check is made per batch, on the emitting
thread).
"""

from __future__ import annotations

from PySide6.QtCore import QMetaMethod, QObject

_methods: dict[tuple[type, str], QMetaMethod] = {}


def listened(owner: object, signal: str) -> bool:
    """Whether ``owner``'s signal named ``signal`` has a receiver now (True for what is
    no QObject, which cannot tell: a stand-in is emitted to as before)."""
    if not isinstance(owner, QObject):
        return True
    key = (type(owner), signal)
    method = _methods.get(key)
    if method is None:
        method = _methods[key] = QMetaMethod.fromSignal(getattr(owner, signal))
    return owner.isSignalConnected(method)
