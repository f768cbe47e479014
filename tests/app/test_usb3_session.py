"""The usb3 session against the emulated unit, on a manual clock (docs/protocols.md §2).

The station, its session and the emulated unit run exactly as in the app,
joined by the loopback transport; time moves only through the harness, so
every figure below is exact.  Hand-worked numbers, from the unit's defaults:
M6 thread is 1.0 mm a revolution, so 6400 counts (1/32 steps) a millimetre; at
1/8 step a pulse is 4 counts; the top pulse rate is 300/s, so the top speed at
1/8 step is 300 * 4 / 6400 = 0.1875 mm/s, and braking from it to the slowest
speed (9.375 pulses/s) at 600 pulses/s² takes 0.484375 s and 75 pulses.
"""

from __future__ import annotations

from collections.abc import Iterator
from itertools import pairwise

import pytest
from pytestqt.qtbot import QtBot

from app.machine import LinkState
from app.machines.usb3.session import JOG_LEAD_S, STILL_AFTER_S
from app.profiles import load_profile
from protocol.emulator.usb3_firmware import Usb3Config, Usb3Firmware
from protocol.transport.loopback import Direction, LoopbackTransport
from protocol.usb3.codec import AxisId, StepSize, Thread, count_to_mm
from tests.helpers.harness import StationHarness

X, Y, Z = 0, 1, 2
#: Braking from the top pulse rate to the slowest, in seconds (see the module docstring).
BRAKING_S = (300 - 9.375) / 600
CYCLE_S = 0.005


@pytest.fixture
def usb3(qtbot: QtBot) -> Iterator[StationHarness]:
    """A station on the usb3 profile with the emulated unit on a test clock, not connected."""
    harness = StationHarness(load_profile("usb3"))
    yield harness
    harness.close()


@pytest.fixture
def unit(usb3: StationHarness) -> StationHarness:
    """Connected, with the unit's settings read."""
    usb3.connect()
    usb3.run(0.05)
    assert usb3.written[0] == b"G;"
    return usb3


def statuses(harness: StationHarness, axis: int) -> list[str]:
    """The axis's status text now and after every change of it from now on."""
    model = harness.station.model
    seen = [model.axes[axis].status_text]

    def record(index: int) -> None:
        if index == axis and seen[-1] != model.axes[axis].status_text:
            seen.append(model.axes[axis].status_text)

    model.axisChanged.connect(record)
    return seen


def messages(harness: StationHarness) -> list[str]:
    said: list[str] = []
    harness.station.model.message.connect(said.append)
    return said


def sent_since(harness: StationHarness, mark: int) -> bytes:
    return b"".join(harness.written[mark:])


def wait_idle(harness: StationHarness, axis: int, timeout: float = 30.0) -> None:
    """Until the unit has stopped the axis and the session shows it idle."""
    model = harness.station.model
    harness.step()  # the unit takes commands at its next control cycle
    harness.run_until(
        lambda: (
            not harness.usb3_emulator.moving(AxisId(axis))
            and model.axes[axis].status_text == "idle"
        ),
        timeout=timeout,
    )


# --- connecting ----------------------------------------------------------------------


def test_connecting_asks_for_the_settings_and_the_session_follows_the_reply(
    usb3: StationHarness,
) -> None:
    # A unit whose power-on settings are not the session's defaults, so following shows.
    firmware = Usb3Firmware(
        usb3.clock,
        Usb3Config(
            step_sizes=(StepSize.HALF, StepSize.QUARTER, StepSize.THIRTY_SECOND),
            threads=(Thread.M3, Thread.M8, Thread.M10),
        ),
    )
    usb3.station.connect_transport(LoopbackTransport(firmware, usb3.clock, realtime=False))
    session = usb3.usb3_session
    changed: list[None] = []
    session.settingsChanged.connect(lambda: changed.append(None))
    assert usb3.written == [b"G;"]
    assert session.step_sizes == [StepSize.EIGHTH] * 3  # nothing heard yet

    usb3.run(0.05)

    assert changed
    assert session.step_sizes == [StepSize.HALF, StepSize.QUARTER, StepSize.THIRTY_SECOND]
    assert session.threads == [Thread.M3, Thread.M8, Thread.M10]
    # 1 mm on M3 (0.5 mm pitch) is 12800 counts, a whole number of half steps (16 counts).
    assert session.reachable(X, 1.0) == 1.0
    assert session.speed_mm_s(Z) == pytest.approx(300 * 1 * 1.5 / 6400)
    # Following the unit sends it nothing back; its first answer only has every axis asked
    # where it stands, by moves of nothing.
    assert b"".join(usb3.written) == (b"G;D+++;X000000000000000;Y000000000000000;Z000000000000000;")


# --- moving by millimetres -----------------------------------------------------------


def test_x_by_12_5_mm_at_m6_and_an_eighth_step_sends_the_exact_count_and_ends_reachable(
    unit: StationHarness,
) -> None:
    session, model = unit.usb3_session, unit.station.model
    mark = len(unit.written)
    session.set_thread(X, Thread.M6)
    session.set_step_size(X, StepSize.EIGHTH)
    assert sent_since(unit, mark) == b"T444;G;M333;G;"
    seen = statuses(unit, X)

    mark = len(unit.written)
    assert session.move_relative(X, 12.5)
    # 12.5 mm * 6400 counts/mm = 80000 counts = 20000 eighth-step pulses, all three
    # directions +, the count in 15 digits.
    assert sent_since(unit, mark) == b"D+++;X000000000080000;"

    unit.run(1.0)
    assert model.axes[X].status_text == "moving" and model.axes[X].moving
    assert 0 < model.axes[X].position < 12.5
    # 20000 pulses at no more than 300 a second take more than 66 s.
    wait_idle(unit, X, timeout=80.0)

    assert model.axes[X].position == session.reachable(X, 12.5) == 12.5
    assert unit.usb3_emulator.positions == (80000, 0, 0)
    assert seen == ["idle", "moving", "idle"]  # standing (asked at connect), moving, standing
    assert not model.axes[X].moving and model.axes[X].velocity == 0.0
    assert (model.axes[Y].position, model.axes[Z].position) == (0.0, 0.0)


def test_a_distance_between_steps_moves_and_shows_the_reachable_one(
    unit: StationHarness,
) -> None:
    session, model = unit.usb3_session, unit.station.model
    session.set_thread(Y, Thread.M4)  # 0.7 mm pitch: 9142.857… counts a mm
    reachable = session.reachable(Y, 1.25)
    # 11428.57 counts is 2857.14 eighth-step pulses: 2857 pulses = 11428 counts.
    assert reachable == count_to_mm(11428, Thread.M4) == pytest.approx(1.2499375)
    assert reachable != 1.25

    mark = len(unit.written)
    assert session.move_relative(Y, 1.25)
    assert sent_since(unit, mark) == b"D+++;Y000000000011428;"
    wait_idle(unit, Y)

    assert model.axes[Y].position == reachable
    assert unit.usb3_emulator.positions == (0, 11428, 0)
    # Back past the zero it is counted from would leave the travel: refused.
    assert not session.move_relative(Y, -1.5)


def test_a_move_of_less_than_one_step_is_refused_with_a_message(unit: StationHarness) -> None:
    said = messages(unit)
    mark = len(unit.written)
    assert not unit.usb3_session.move_relative(Z, 0.0001)  # a pulse is 0.000625 mm
    assert unit.written[mark:] == []
    assert said == ["Z: 0.0001 mm is less than one step"]


# --- the unit's own menu -------------------------------------------------------------


def test_a_menu_change_on_the_unit_reaches_the_session_and_rescales_positions(
    unit: StationHarness,
) -> None:
    session, model = unit.usb3_session, unit.station.model
    assert session.move_relative(X, 1.0)
    wait_idle(unit, X)
    assert model.axes[X].position == 1.0
    changed: list[None] = []
    session.settingsChanged.connect(lambda: changed.append(None))
    mark = len(unit.written)

    unit.usb3_emulator.menu_set(
        step_sizes=(StepSize.THIRTY_SECOND, StepSize.EIGHTH, StepSize.EIGHTH),
        threads=(Thread.M5, Thread.M6, Thread.M6),
    )
    unit.run(0.05)

    assert changed
    assert session.step_sizes[X] is StepSize.THIRTY_SECOND
    assert session.threads[X] is Thread.M5
    # The axis stands on the same 6400 counts, which on a 0.8 mm thread are 0.8 mm.
    assert model.axes[X].position == pytest.approx(0.8)
    # 1/32 steps at 300 pulses/s on 0.8 mm: 300 * 0.8 / 6400 mm/s.
    assert session.speed_mm_s(X) == pytest.approx(0.0375)
    assert session.reachable(X, 0.00013) == pytest.approx(0.000125)  # one pulse of 1 count
    assert unit.written[mark:] == []


# --- zero ----------------------------------------------------------------------------


def test_zero_all_sets_every_position_to_0_without_a_false_motion(unit: StationHarness) -> None:
    session, model = unit.usb3_session, unit.station.model
    for axis, mm in ((X, 0.5), (Y, 0.25), (Z, 0.125)):
        assert session.move_relative(axis, mm)
    for axis in (X, Y, Z):
        wait_idle(unit, axis)
    assert [a.position for a in model.axes] == [0.5, 0.25, 0.125]
    seen = [statuses(unit, axis) for axis in (X, Y, Z)]

    mark = len(unit.written)
    session.zero_all()
    assert sent_since(unit, mark) == b"C;"
    unit.run(0.5)

    assert [a.position for a in model.axes] == [0.0, 0.0, 0.0]
    assert unit.usb3_emulator.positions == (0, 0, 0)
    assert all(a.status_text == "idle" and not a.moving for a in model.axes)
    assert seen == [["idle"]] * 3  # the new zero is not shown as a motion

    # Counting goes on from the new zero.
    assert session.move_relative(X, 0.5)
    wait_idle(unit, X)
    assert model.axes[X].position == 0.5


def test_zero_all_during_a_move_keeps_the_axis_moving_from_its_new_zero(
    unit: StationHarness,
) -> None:
    session, x = unit.usb3_session, unit.station.model.axes[X]
    assert session.move_relative(X, 0.5)
    unit.run(1.0)
    assert x.status_text == "moving" and x.position > 0
    seen = statuses(unit, X)
    velocities: list[float] = []
    unit.station.model.axisChanged.connect(lambda _i: velocities.append(x.velocity))

    session.zero_all()
    unit.run(0.5)
    assert x.status_text == "moving" and 0 < x.position < 0.5
    wait_idle(unit, X)

    assert seen == ["moving", "idle"]  # no idle flicker at the zero, no jump reported
    assert min(velocities) >= 0.0
    assert x.position == count_to_mm(unit.usb3_emulator.positions[X], Thread.M6)
    assert 0 < x.position < 0.5


# --- jogging -------------------------------------------------------------------------


def test_a_held_jog_moves_x_continuously_and_the_release_stops_it_at_once(
    unit: StationHarness,
) -> None:
    session, model = unit.usb3_session, unit.station.model
    x = model.axes[X]
    speed = session.speed_mm_s(X)
    assert speed == pytest.approx(0.1875)

    session.set_jog([1, 0, 0])
    track: list[float] = []
    for _ in range(20):  # held for 2 s, looked at every 100 ms
        unit.hold(0.1)
        track.append(x.position)
    assert unit.usb3_emulator.moving(AxisId.X)
    assert x.status_text == "moving"
    # After the first report the position rises at every look.
    rising = track[2:]
    assert all(b > a for a, b in pairwise(rising))
    # Past the 0.48 s ramp it runs at the top speed.
    assert x.velocity == pytest.approx(speed, rel=0.01)
    assert track[-1] - track[-11] == pytest.approx(speed * 1.0, rel=0.01)

    mark = len(unit.written)
    released_at = unit.clock.now()
    count_at_release = unit.usb3_emulator.positions[X]
    session.set_jog([0, 0, 0])
    assert sent_since(unit, mark) == b"S;"

    unit.run_until(lambda: not unit.usb3_emulator.moving(AxisId.X), timeout=2.0)
    stopped_after = unit.clock.now() - released_at
    # The unit brakes along its ramp (it cannot stop faster) instead of running out
    # the lead the jog kept ahead of the key.
    assert stopped_after <= BRAKING_S + 2 * CYCLE_S
    overrun = count_to_mm(unit.usb3_emulator.positions[X] - count_at_release, Thread.M6)
    assert 0 < overrun < speed * JOG_LEAD_S
    unit.run_until(lambda: x.status_text == "idle", timeout=STILL_AFTER_S + 0.2)
    stopped = x.position
    assert stopped == count_to_mm(unit.usb3_emulator.positions[X], Thread.M6)

    unit.run(1.0)
    assert x.position == stopped
    # Nothing more moved the unit after the release (G; asks a quiet unit it is still there).
    assert sent_since(unit, mark).replace(b"G;", b"") == b"S;"


def test_a_jog_on_z_moves_z_both_ways(unit: StationHarness) -> None:
    session, model = unit.usb3_session, unit.station.model
    z = model.axes[Z]

    mark = len(unit.written)
    session.set_jog([0, 0, 1])  # PageUp
    assert unit.written[mark] == b"D+++;"
    assert unit.written[mark + 1].startswith(b"Z")
    unit.run(1.0)
    assert z.position > 0 and z.status_text == "moving"
    assert (model.axes[X].position, model.axes[Y].position) == (0.0, 0.0)
    session.set_jog([0, 0, 0])
    wait_idle(unit, Z, timeout=2.0)
    top = z.position

    mark = len(unit.written)
    session.set_jog([0, 0, -1])  # PageDown
    assert unit.written[mark] == b"D++-;"
    unit.run(1.0)
    assert z.position < top
    session.set_jog([0, 0, 0])
    wait_idle(unit, Z, timeout=2.0)
    assert unit.usb3_emulator.positions[:2] == (0, 0)  # X and Y never moved


# --- garbage -------------------------------------------------------------------------


@pytest.mark.parametrize(
    "garbage",
    [
        pytest.param(b"garbage;", id="unknown-message"),
        pytest.param(b"X12a4;", id="bad-count"),
        pytest.param(b"M9;", id="bad-settings"),
        pytest.param(b"\xff\x00\x80;", id="binary"),
        pytest.param(b"Q" * 40, id="too-long-without-terminator"),
    ],
)
def test_garbage_from_the_unit_is_counted_and_said_never_raised(
    unit: StationHarness, garbage: bytes
) -> None:
    session, model = unit.usb3_session, unit.station.model
    said = messages(unit)
    injected: list[bytes] = []

    def inject(direction: Direction, data: bytes) -> bytes:
        # Once, onto the first report of the move (the move goes on reporting after it).
        if direction is Direction.TO_HOST and not injected and data.startswith(b"X"):
            injected.append(data)
            return data + garbage
        return data

    unit.loopback.set_manipulator(inject)
    assert session.move_relative(X, 0.25)
    wait_idle(unit, X)

    assert injected
    assert session.rejected == 1
    assert session.decoder.rejected == 1 and session.not_understood == 0
    assert sum("Garbage from the unit dropped" in m for m in said) == 1
    # The reports around it still arrive: the move ends where the unit says it is.
    assert model.axes[X].position == 0.25
    assert model.axes[X].status_text == "idle"


def test_a_question_mark_from_the_unit_is_counted_before_the_frame_is_announced(
    unit: StationHarness,
) -> None:
    session = unit.usb3_session
    said = messages(unit)
    counts_seen: list[int] = []
    session.frameReceived.connect(lambda *_: counts_seen.append(session.rejected))
    assert unit.station.link is not None

    unit.station.link.write(b"hello;")  # nothing the unit can parse: it answers ?;
    unit.run(0.05)

    assert session.not_understood == 1 and session.rejected == 1
    assert counts_seen == [1]  # a listener (the status bar) already sees it counted
    assert said == ["The unit did not understand a command (?;)"]
    # The link and the unit carry on.
    assert session.move_relative(X, 0.125)
    wait_idle(unit, X)
    assert unit.station.model.axes[X].position == 0.125
    assert session.rejected == 1


def test_after_connecting_every_axis_shows_where_it_stands_not_unknown(
    usb3: StationHarness,
) -> None:
    """The unit speaks of positions only when an axis stops: the session asks at connect."""
    # A unit switched on earlier and moved by its joystick: its axes are not at 0.
    firmware = Usb3Firmware(usb3.clock, Usb3Config())
    firmware.receive(b"D+-+;X000000000006400;Y000000000003200;")
    for _ in range(100):  # its reports go nowhere: no station listens yet
        usb3.clock.advance(0.5)
        firmware.run_until(usb3.clock.now())
    assert firmware.positions == (6400, -3200, 0)
    usb3.station.connect_transport(LoopbackTransport(firmware, usb3.clock, realtime=False))
    model = usb3.station.model
    assert [a.status_text for a in model.axes] == ["unknown"] * 3  # nothing heard yet
    usb3.run(0.1)
    assert [a.status_text for a in model.axes] == ["idle"] * 3
    assert not any(a.moving for a in model.axes)
    assert model.axes[X].position == pytest.approx(1.0)  # 6400 counts at M6
    assert model.axes[Y].position == pytest.approx(-0.5)
    assert model.axes[Z].position == 0.0
    assert firmware.positions == (6400, -3200, 0)  # asking moved nothing
    usb3.run(1.0)
    assert firmware.positions == (6400, -3200, 0)
    assert [a.status_text for a in model.axes] == ["idle"] * 3


# --- end switches ----------------------------------------------------------------------


def test_s4_18_an_axis_stopped_at_an_end_switch_is_named_with_its_end(
    usb3: StationHarness,
) -> None:
    """FIDELITY S4-18: the unit stops the motor whose switch is pressed and only reports its
    position; the station says which axis stopped at which end, and only then."""
    ends = ((1e6, 640.0), (1e6, 1e6), (1e6, 1e6))  # X's high switch 0.1 mm on
    firmware = Usb3Firmware(usb3.clock, Usb3Config(end_switches=ends))
    usb3.station.connect_transport(LoopbackTransport(firmware, usb3.clock, realtime=False))
    usb3.station.emulator = firmware  # as connect_emulator() does, with these switches
    usb3.run(0.05)
    session, model = usb3.usb3_session, usb3.station.model
    said = messages(usb3)
    hits: list[tuple[int, str, float]] = []
    session.endSwitchHit.connect(lambda axis, which, mm: hits.append((axis, which, mm)))

    assert session.move_relative(Y, 0.2)  # a move that ends where it was sent: no switch
    wait_idle(usb3, Y)
    usb3.run(1.0)
    assert hits == [] and not any("end switch" in m for m in said)

    assert session.move_relative(X, 0.5)
    wait_idle(usb3, X)
    usb3.run(1.0)
    assert firmware.positions[X] == 640
    assert hits == [(X, "high", 0.1)]
    assert "X stopped at its high end switch at 0.100 mm, 0.400 mm short of its target" in said
    assert model.axes[X].position == 0.1

    # On the way down, a switch closes under Y (a lever, or where the mechanics put it).
    assert session.move_relative(Y, -0.15)
    usb3.run(0.5)
    firmware.press_end_switch(AxisId.Y, "low")
    wait_idle(usb3, Y)
    usb3.run(1.0)
    assert hits[1][:2] == (Y, "low")
    assert 0.1 < model.axes[Y].position < 0.2
    assert any(m.startswith("Y stopped at its low end switch at ") for m in said)

    # Stopped on purpose (S;) short of the target is no switch.
    hits.clear()
    assert session.move_relative(X, -0.05)
    usb3.run(0.3)
    session.stop_all()
    wait_idle(usb3, X)
    usb3.run(1.0)
    assert hits == []


def test_a_link_gone_quiet_mid_move_is_a_lost_link_not_an_end_switch(unit: StationHarness) -> None:
    """Replies lost after the axis reported on its way: its silence short of the target looks
    like a switch, but nothing else is heard either. The session asks a harmless ``G;`` and,
    unanswered, declares the link lost; it never names a switch the axis did not reach."""
    session, model = unit.usb3_session, unit.station.model
    said = messages(unit)
    hits: list[tuple[int, str, float]] = []
    session.endSwitchHit.connect(lambda axis, which, mm: hits.append((axis, which, mm)))
    assert session.move_relative(X, 2.0)
    unit.run(0.3)
    assert 0 < model.axes[X].position < 2.0  # heard on its way
    mark = len(unit.written)
    unit.loopback.set_manipulator(lambda d, data: b"" if d is Direction.TO_HOST else data)
    unit.run(1.0)
    assert hits == [] and not any("end switch" in m for m in said)
    assert b"G;" in sent_since(unit, mark)  # asked at once, not a second later
    unit.run_until(lambda: model.link_state is LinkState.LOST, timeout=10)
    assert hits == [] and not any("end switch" in m for m in said)
