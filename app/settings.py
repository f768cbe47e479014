"""Settings that survive a restart (QSettings), behind names rather than string keys.

Tests pass their own QSettings file so they never touch the operator's.
"""

from __future__ import annotations

from PySide6.QtCore import QSettings

from app.profiles import DEFAULT_PROFILE

ORGANISATION = "StepDeck"
APPLICATION = "StepDeck"


def default_settings() -> QSettings:
    return QSettings(ORGANISATION, APPLICATION)


class StationSettings:
    def __init__(self, store: QSettings) -> None:
        self.store = store

    def _text(self, key: str, default: str) -> str:
        value = self.store.value(key, default)
        return str(value) if value is not None else default

    @property
    def profile(self) -> str:
        return self._text("station/profile", DEFAULT_PROFILE)

    @profile.setter
    def profile(self, name: str) -> None:
        self.store.setValue("station/profile", name)

    @property
    def period_ms(self) -> int | None:
        value = self.store.value("station/period_ms")
        try:
            return int(str(value)) if value is not None else None
        except ValueError:
            return None

    @period_ms.setter
    def period_ms(self, value: int) -> None:
        self.store.setValue("station/period_ms", int(value))

    @property
    def transport(self) -> str:
        return self._text("link/transport", "emulator")

    @transport.setter
    def transport(self, value: str) -> None:
        self.store.setValue("link/transport", value)

    @property
    def device(self) -> str:
        """Last serial port or BLE address used."""
        return self._text("link/device", "")

    @device.setter
    def device(self, value: str) -> None:
        self.store.setValue("link/device", value)

    def sync(self) -> None:
        self.store.sync()
