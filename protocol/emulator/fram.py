"""The stage's FRAM: where the per-axis parameters of docs/protocols.md §1.4 live.

The emulator keeps the parameters as bytes, at fixed addresses and LSB first,
rather than in a dict, so that what a test (or the developer pane) inspects is
what the real board stores, and so that the two things the real firmware gets
wrong when it is careless can be reproduced: the shared IHOLD_IRUN register
(writing one current must keep the other) and a write whose read-back differs.

Memory map (one 64-byte block per axis, base ``0x40 * axis``)::

    base + 0x00  TYPE 4  acceleration      µm/s²   int32 LSB first
    base + 0x04  TYPE 3  slow speed        µm/s
    base + 0x08  TYPE 2  fast speed        µm/s
    base + 0x0C  TYPE 5  start speed       µm/s
    base + 0x10  TYPE 6  IHOLD_IRUN        TMC2130 register: IHOLD bits 0-4,
                 TYPE 7                    IRUN bits 8-12, IHOLDDELAY bits 16-19
    base + 0x14  (reserved: TYPE 7 shares the register above)
    base + 0x18  TYPE 8  microsteps per step
    base + 0x1C  TYPE 9  lead of the screw µm/rev
    base + 0x20  TYPE A  full steps per revolution
    base + 0x24  TYPE B  travel            µm
    base + 0x28  step count saved at shutdown  microsteps, int32  (FIDELITY S3-31)
    base + 0x2C  0x57E95AFE while that count is valid

TYPE C (encoder position) is measured, not stored, and has no address.
The saved step count is not a parameter either: the shutdown sequence
writes it when the board is set to, and power-on takes it (and marks it
used, so a later power cut without the sequence cannot bring back a stale
count).

The original names one address: "Začiatočná adresa … maximálnej akcelerácie
… 0x0000" (FIDELITY S3-14), so the acceleration starts the block; the rest
of its map is not given, and the other words keep their places (the fast
speed takes the word the acceleration left).
"""

from __future__ import annotations

from protocol.stage.codec import EchoType

AXIS_STRIDE = 0x40
WORD = 4
DEFAULT_SIZE = 0x2000  # an 8 KiB part (FM24CL64-class)

IHOLD_SHIFT = 0
IRUN_SHIFT = 8
IHOLDDELAY_SHIFT = 16
CURRENT_MASK = 0x1F
IHOLDDELAY_MASK = 0x0F
#: Power-on IHOLDDELAY: the TMC2130 datasheet's example value.  It is never
#: written over the wire; it is there so a test can see that current writes keep
#: every bit they do not own.
DEFAULT_IHOLDDELAY = 6

#: Where the shutdown sequence leaves the step count, and the mark that it is there.
STEP_COUNT_OFFSET = 0x28
STEP_COUNT_MARK_OFFSET = 0x2C
STEP_COUNT_MARK = 0x57E95AFE

_INT32_MIN = -(2**31)
_INT32_MAX = 2**31 - 1

_CURRENT_SHIFTS = {EchoType.IHOLD: IHOLD_SHIFT, EchoType.IRUN: IRUN_SHIFT}
_STORED = tuple(t for t in EchoType if EchoType.FAST_SPEED <= t <= EchoType.TRAVEL)
#: Word offsets within an axis block (see the map above); IHOLD shares IRUN's word.
_OFFSETS = {
    **{t: WORD * (t - EchoType.FAST_SPEED) for t in _STORED},
    EchoType.ACCELERATION: 0x00,
    EchoType.FAST_SPEED: 0x08,
}


class Fram:
    """Byte-addressed parameter memory with verified writes.

    ``verification_fault`` stands for a flaky part or bus: while it is set every
    write's read-back differs from what was written, so the write is undone and
    reported as rejected, the way the firmware must handle it.
    """

    def __init__(self, axes: int, size: int = DEFAULT_SIZE) -> None:
        if axes < 1 or AXIS_STRIDE * axes > size:
            raise ValueError(f"{axes} axes do not fit {size} bytes of FRAM")
        self.axes = axes
        self.memory = bytearray(size)
        self.verification_fault = False
        for axis in range(axes):
            register = DEFAULT_IHOLDDELAY << IHOLDDELAY_SHIFT
            self._store(self.address_of(axis, EchoType.IRUN), register)

    def address_of(self, axis: int, parameter: int) -> int:
        """Byte address of a parameter's word; IRUN and IHOLD share one."""
        if not 0 <= axis < self.axes:
            raise ValueError(f"no axis {axis}")
        if parameter not in _STORED:
            raise ValueError(f"parameter TYPE {parameter:X} is not stored in FRAM")
        if parameter == EchoType.IHOLD:
            parameter = EchoType.IRUN
        return AXIS_STRIDE * axis + _OFFSETS[EchoType(parameter)]

    def dump(self, address: int, length: int) -> bytes:
        """Raw bytes, as a logic analyser on the I²C bus would see them."""
        return bytes(self.memory[address : address + length])

    def read(self, axis: int, parameter: int) -> int:
        word = self._load(self.address_of(axis, parameter))
        shift = _CURRENT_SHIFTS.get(EchoType(parameter))
        if shift is None:
            return word
        return (word >> shift) & CURRENT_MASK

    def write(self, axis: int, parameter: int, value: int) -> bool:
        """Store ``value`` and verify it by reading it back.

        Returns False (with the old bytes restored) when the read-back differs;
        range checks against table 1.4 are the firmware's job, this only refuses
        values that cannot be represented at all.
        """
        address = self.address_of(axis, parameter)
        old = self._load(address)
        new = self._merge(old, EchoType(parameter), value)
        self._store(address, new)
        if self._read_back(address) == new:
            return True
        self._store(address, old)
        return False

    def save_step_count(self, axis: int, count: int) -> None:
        """The shutdown sequence's last words: the axis's step count, marked valid."""
        base = self._axis_base(axis)
        self._store(base + STEP_COUNT_OFFSET, self._merge(0, EchoType.POSITION, count))
        self._store(base + STEP_COUNT_MARK_OFFSET, STEP_COUNT_MARK)

    def take_step_count(self, axis: int) -> int | None:
        """The count saved at the last shutdown, or None; either way it is used up."""
        base = self._axis_base(axis)
        if self._load(base + STEP_COUNT_MARK_OFFSET) != STEP_COUNT_MARK:
            return None
        self._store(base + STEP_COUNT_MARK_OFFSET, 0)
        return self._load(base + STEP_COUNT_OFFSET)

    def _axis_base(self, axis: int) -> int:
        if not 0 <= axis < self.axes:
            raise ValueError(f"no axis {axis}")
        return AXIS_STRIDE * axis

    def ihold_irun(self, axis: int) -> int:
        """The whole IHOLD_IRUN register of an axis."""
        return self._load(self.address_of(axis, EchoType.IRUN))

    @staticmethod
    def _merge(old: int, parameter: EchoType, value: int) -> int:
        shift = _CURRENT_SHIFTS.get(parameter)
        if shift is None:
            if not _INT32_MIN <= value <= _INT32_MAX:
                raise ValueError(f"{value} does not fit a 32-bit word")
            return value
        if not 0 <= value <= CURRENT_MASK:
            raise ValueError(f"current {value} does not fit 5 bits")
        # Read-modify-write: the other current and IHOLDDELAY keep their bits.
        return (old & ~(CURRENT_MASK << shift)) | (value << shift)

    def _read_back(self, address: int) -> int:
        word = self._load(address)
        return word ^ 1 if self.verification_fault else word

    def _load(self, address: int) -> int:
        return int.from_bytes(self.memory[address : address + WORD], "little", signed=True)

    def _store(self, address: int, value: int) -> None:
        self.memory[address : address + WORD] = value.to_bytes(WORD, "little", signed=True)
