"""Words the model keeps in English (the scripts read them) as the operator reads them.

The link state's and an axis status's values are the protocol's and the
scripts' words; only their display is translated, here, so every view says
the same thing in the same language.
"""

from __future__ import annotations

from PySide6.QtCore import QT_TRANSLATE_NOOP, QCoreApplication

from app.machine import LinkState

_STATES = {
    LinkState.DISCONNECTED: QT_TRANSLATE_NOOP("LinkState", "disconnected"),
    LinkState.CONNECTING: QT_TRANSLATE_NOOP("LinkState", "connecting"),
    LinkState.CONNECTED: QT_TRANSLATE_NOOP("LinkState", "connected"),
    LinkState.STALE: QT_TRANSLATE_NOOP("LinkState", "stale"),
    LinkState.LOST: QT_TRANSLATE_NOOP("LinkState", "lost"),
}

#: Every axis status a session reports (the stage's, the drill's, usb3's and GRBL's).
AXIS_STATUSES = (
    QT_TRANSLATE_NOOP("AxisStatus", "unknown"),
    QT_TRANSLATE_NOOP("AxisStatus", "idle"),
    QT_TRANSLATE_NOOP("AxisStatus", "moving"),
    QT_TRANSLATE_NOOP("AxisStatus", "parking"),
    QT_TRANSLATE_NOOP("AxisStatus", "parked"),
    QT_TRANSLATE_NOOP("AxisStatus", "accelerating"),
    QT_TRANSLATE_NOOP("AxisStatus", "constant speed"),
    QT_TRANSLATE_NOOP("AxisStatus", "decelerating"),
    QT_TRANSLATE_NOOP("AxisStatus", "target reached"),
    QT_TRANSLATE_NOOP("AxisStatus", "stopped"),
    QT_TRANSLATE_NOOP("AxisStatus", "homing"),
    QT_TRANSLATE_NOOP("AxisStatus", "end switch hit"),
    QT_TRANSLATE_NOOP("AxisStatus", "blocked: battery low"),
    QT_TRANSLATE_NOOP("AxisStatus", "blocked: charger connected"),
    QT_TRANSLATE_NOOP("AxisStatus", "blocked: USB connected"),
    QT_TRANSLATE_NOOP("AxisStatus", "sleeping"),
    QT_TRANSLATE_NOOP("AxisStatus", "driver fault"),
    QT_TRANSLATE_NOOP("AxisStatus", "parameter rejected"),
    QT_TRANSLATE_NOOP("AxisStatus", "unknown command"),
    QT_TRANSLATE_NOOP("AxisStatus", "run"),
    QT_TRANSLATE_NOOP("AxisStatus", "hold"),
    QT_TRANSLATE_NOOP("AxisStatus", "jog"),
    QT_TRANSLATE_NOOP("AxisStatus", "alarm"),
    QT_TRANSLATE_NOOP("AxisStatus", "door"),
    QT_TRANSLATE_NOOP("AxisStatus", "check"),
    QT_TRANSLATE_NOOP("AxisStatus", "home"),
    QT_TRANSLATE_NOOP("AxisStatus", "sleep"),
)


def link_state_text(state: LinkState) -> str:
    """``state`` as the operator reads it: "connected", "připojeno", "pripojené"…"""
    return QCoreApplication.translate("LinkState", str(_STATES.get(state, state.value)))


#: Link details the transports give in English (protocol/ has no Qt to translate them).
LINK_DETAILS = (QT_TRANSLATE_NOOP("LinkDetail", "built-in emulator"),)


def link_detail_text(detail: str) -> str:
    """The link's detail as the operator reads it; one not listed stays as given."""
    return QCoreApplication.translate("LinkDetail", detail) if detail else detail


def axis_status_text(status: str) -> str:
    """An axis status as the operator reads it; one not listed stays as reported."""
    return QCoreApplication.translate("AxisStatus", status)
