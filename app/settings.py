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


class _MemoryStore:
    """Stands in for QSettings when a window is built without one (tests, benchmarks)."""

    def __init__(self) -> None:
        self._values: dict[str, object] = {}

    def value(self, key: str, default: object = None) -> object:
        return self._values.get(key, default)

    def setValue(self, key: str, value: object) -> None:
        self._values[key] = value

    def sync(self) -> None:
        pass


class StationSettings:
    def __init__(self, store: QSettings | None) -> None:
        self.store: QSettings | _MemoryStore = store if store is not None else _MemoryStore()

    def _text(self, key: str, default: str) -> str:
        value = self.store.value(key, default)
        return str(value) if value is not None else default

    def _int(self, key: str) -> int | None:
        value = self.store.value(key)
        try:
            return int(str(value)) if value is not None else None
        except ValueError:
            return None

    @property
    def profile(self) -> str:
        return self._text("station/profile", DEFAULT_PROFILE)

    @profile.setter
    def profile(self, name: str) -> None:
        self.store.setValue("station/profile", name)

    @property
    def period_ms(self) -> int | None:
        return self._int("station/period_ms")

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

    @property
    def baud(self) -> int | None:
        return self._int("link/baud")

    @baud.setter
    def baud(self, value: int) -> None:
        self.store.setValue("link/baud", int(value))

    def sync(self) -> None:
        self.store.sync()
