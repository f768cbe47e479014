"""The station: one machine profile, its model, its link and the dialect session.

Widgets get a Station and talk to ``station.session`` for intents and to
``station.model`` for state; they never see a transport.  The built-in
emulator is created here, behind the loopback transport, so the rest of the
app is the same whether the device is real or emulated.
"""

from __future__ import annotations

from PySide6.QtCore import QObject, Signal

from app.link import Link
from app.machine import LinkState, MachineModel
from app.profiles import MachineProfile
from app.stage_session import StageSession
from protocol.clock import Clock, MonotonicClock
from protocol.emulator.stage_firmware import StageConfig, StageFirmware
from protocol.transport.base import Transport
from protocol.transport.loopback import LoopbackTransport


def stage_config_for(profile: MachineProfile) -> StageConfig:
    """The emulated stage built to the profile's axis count."""
    return StageConfig(axes=len(profile.axes))


class Station(QObject):
    sessionChanged = Signal()

    def __init__(
        self,
        profile: MachineProfile,
        clock: Clock | None = None,
        *,
        realtime: bool = True,
        parent: QObject | None = None,
    ) -> None:
        super().__init__(parent)
        if profile.dialect != "stage":
            raise ValueError(f"the {profile.dialect!r} dialect is not supported yet")
        self.profile = profile
        self.clock: Clock = clock or MonotonicClock()
        self.realtime = realtime
        self.model = MachineModel(profile, self)
        self.link: Link | None = None
        self.session: StageSession | None = None
        self.emulator: StageFirmware | None = None
        self.period_ms = profile.period_ms

    @property
    def loopback(self) -> LoopbackTransport | None:
        transport = self.link.transport if self.link else None
        return transport if isinstance(transport, LoopbackTransport) else None

    def connect_emulator(self) -> None:
        """Connect to a fresh in-process emulated device on this station's clock."""
        self.emulator = StageFirmware(self.clock, stage_config_for(self.profile))
        self.connect_transport(LoopbackTransport(self.emulator, self.clock, realtime=self.realtime))

    def connect_transport(self, transport: Transport) -> None:
        self.close_link()
        self.link = Link(transport, self)
        self.session = StageSession(
            self.model, self.link, self.clock, period_ms=self.period_ms, autotick=self.realtime
        )
        self.session.setParent(self)
        self.sessionChanged.emit()
        self.model.set_link_state(LinkState.CONNECTING, transport.describe())
        self.link.open()

    def close_link(self) -> None:
        if self.session is not None:
            self.session.shutdown()
        if self.link is not None:
            self.link.close()
            self.link.deleteLater()
        if self.session is not None:
            self.session.deleteLater()
        self.link = None
        self.session = None
        self.model.set_link_state(LinkState.DISCONNECTED)

    def set_period_ms(self, period_ms: int) -> None:
        self.period_ms = period_ms
        if self.session is not None:
            self.session.set_period_ms(period_ms)

    def shutdown(self) -> None:
        """Stop motion and close the link; called when the window closes."""
        if self.session is not None and self.link is not None and self.link.is_open:
            self.session.stop_all()
        self.close_link()
