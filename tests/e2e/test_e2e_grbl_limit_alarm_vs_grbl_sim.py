"""A soft limit's ALARM:2 on real GRBL 1.1h (grbl-sim) and on the emulated board: the same
silence until 0x18, the same words after it.

grbl-sim is driven into it as a board would be: ``$22=1`` (homing on, which ``$20`` needs),
``$20=1`` (soft limits), then ``G0 X10`` beyond its travel (GRBL's machine space is negative).
The emulated board stands for the limit with ``trigger_alarm(2)`` while a ``G4`` is being
taken (the line GRBL answers once the lock ends); from the alarm on, both get the same bytes.
"""

from __future__ import annotations

from protocol.emulator.gcode_firmware import grbl_plotter_config
from tests.e2e.test_e2e_grbl_resets_vs_grbl_sim import (
    UNLOCK,
    Sim,
    Step,
    grbl_sim_exe,
    sim,
)
from tests.protocol.test_gcode_firmware import Bench

__all__ = ["grbl_sim_exe", "sim"]  # the fixtures, shared with the resets' comparison

#: In the lock: a status report, an unlock, a move, a hold and a resume; none is answered.
LOCKED: list[Step] = [(b"?", 0), (b"$X\n", 0), (b"G0 X-1\n", 0), (b"?!~", 0)]
AFTER: list[Step] = [(b"\x18", 3), (b"?", 1), (b"$X\n", 2), (b"?", 1)]


def _shown(line: str) -> str:
    """A reply as compared: a status report by its state alone (the positions differ)."""
    return line.split("|", 1)[0] + ">" if line.startswith("<") else line


def _on_sim(sim: Sim, steps: list[Step]) -> list[str]:
    for data, answers in steps:
        want = len(sim.lines) + answers
        sim.send(data)
        sim.read_until(lambda lines, want=want: len(lines) >= want)
    return [_shown(line) for line in sim.lines]


def _emulated_after_a_limit() -> list[str]:
    bench = Bench(grbl_plotter_config())
    raw = bytearray()
    bench.fw.set_output(raw.extend)
    bench.fw.receive(b"G4 P10\n")
    bench.run(0.1)
    bench.fw.trigger_alarm(2)
    lines: list[str] = []
    for data, answers in LOCKED + AFTER:
        want = len(lines) + answers
        bench.fw.receive(data)
        for _ in range(100):  # a locked step: one emulated second of silence
            *whole, rest = bytes(raw).split(b"\n")
            raw[:] = rest
            lines += [t for t in (w.decode("ascii", "replace").strip() for w in whole) if t]
            if answers and len(lines) >= want:
                break
            bench.run(0.01)
    return [_shown(line) for line in lines]


def test_a_soft_limit_locks_grbl_until_a_reset_as_the_emulated_board_does(sim: Sim) -> None:
    real = _on_sim(sim, [(b"$22=1\n", 1), (b"$20=1\n", 1), (b"G0 X10\n", 2)])
    # The lock's silence, waited for as long as grbl-sim needs to answer a status report.
    for data, _ in LOCKED:
        sim.send(data)
    try:
        sim.read_until(lambda lines: len(lines) > 4, timeout=2.0)
    except AssertionError:
        pass
    assert real == ["ok", "ok", "ALARM:2", "[MSG:Reset to continue]"]
    assert sim.lines[4:] == [], "GRBL answered in its critical-event lock"
    real = _on_sim(sim, AFTER)
    assert real[4:] == [
        "ok",  # the line that hit the limit, answered once the lock ends
        "Grbl 1.1h ['$' for help]",
        UNLOCK,
        "<Alarm>",
        "[MSG:Caution: Unlocked]",
        "ok",
        "<Idle>",
    ]
    assert _emulated_after_a_limit() == real[2:]
