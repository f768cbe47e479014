"""GRBL 1.1h's ``$$`` and ``$N=value``, emulated as its ``system.c`` and ``settings.c`` do them.

What a host sees of a setting is decided here, to the byte: the order in
which a bad line is judged (not idle ``error:8`` first, then a number GRBL
cannot read ``error:2``, a malformed line or a setting it does not have
``error:3``, a negative value ``error:4``, ``$0`` under 3 µs ``error:6``,
soft limits without homing ``error:10``), the one byte the whole-number
settings are kept in (``$1=256`` keeps 0, as a C cast to ``uint8_t`` does),
switches kept as 0 or 1, and the 32-bit floats behind the decimal ones,
read with GRBL's own ``read_float`` (8 significant digits at most, no
exponent) and printed with its ``printFloat`` (three decimals; ``$30`` and
``$31`` none).  GRBL 1.1h is compiled for three axes: ``$100…$132`` list
X, Y and Z whatever the machine has.
"""

from __future__ import annotations

import struct

OK = 0
BAD_NUMBER_FORMAT = 2
INVALID_STATEMENT = 3
NEGATIVE_VALUE = 4
STEP_PULSE_MIN = 6
NOT_IDLE = 8
SOFT_LIMIT_ERROR = 10

#: N_AXIS of GRBL 1.1h on a 328p.
GRBL_AXES = 3
#: Settings kept as one byte (``int_value`` in settings.c).
_BYTES = frozenset({0, 1, 2, 3, 10, 23, 26})
#: Settings kept as a flag bit: listed 0 or 1.
_FLAGS = frozenset({4, 5, 6, 13, 20, 21, 22, 32})
#: Decimal settings printed with no decimals (N_DECIMAL_RPMVALUE).
_RPM = frozenset({30, 31})
_DECIMAL = frozenset({11, 12, 24, 25, 27}) | _RPM
#: GRBL's MAX_INT_DIGITS: digits read_float keeps.
_MAX_INT_DIGITS = 8


def f32(value: float) -> float:
    """``value`` as a C ``float`` holds it."""
    result: float = struct.unpack("<f", struct.pack("<f", value))[0]
    return result


def read_float(text: str) -> tuple[float, str] | None:
    """GRBL's ``read_float``: the number at the start of ``text`` and what follows it.

    None when no digit was read (GRBL's ``error:2``).
    """
    i = 0
    negative = False
    if text[:1] in ("-", "+"):
        negative = text[0] == "-"
        i = 1
    intval, exponent, digits, decimal = 0, 0, 0, False
    while i < len(text):
        c = text[i]
        if c.isdigit() and c.isascii():
            digits += 1
            if digits <= _MAX_INT_DIGITS:
                if decimal:
                    exponent -= 1
                intval = intval * 10 + int(c)
            elif not decimal:
                exponent += 1
        elif c == "." and not decimal:
            decimal = True
        else:
            break
        i += 1
    if not digits:
        return None
    value = f32(float(intval))
    if value != 0:
        while exponent <= -2:
            value = f32(value * f32(0.01))
            exponent += 2
        if exponent < 0:
            value = f32(value * f32(0.1))
        while exponent > 0:
            value = f32(value * 10.0)
            exponent -= 1
    return (-value if negative else value), text[i:]


def print_float(value: float, decimals: int) -> str:
    """GRBL's ``printFloat``: rounded in float arithmetic, then the digits of a uint32."""
    sign = ""
    if value < 0:
        sign, value = "-", -value
    n = f32(value)
    places = decimals
    while places >= 2:
        n = f32(n * 100)
        places -= 2
    if places:
        n = f32(n * 10)
    n = f32(n + 0.5)
    digits = str(int(n) & 0xFFFFFFFF) if int(n) > 0 else ""
    digits = digits.rjust(decimals, "0")
    if len(digits) == decimals:
        digits = "0" + digits
    if decimals:
        digits = digits[:-decimals] + "." + digits[-decimals:]
    return sign + digits


def setting_lines(table: dict[int, float]) -> list[str]:
    """``$$``: every setting as GRBL 1.1h lists it, in its order."""
    lines = []
    for key in sorted(table):
        value = table[key]
        if key >= 100 or key in _DECIMAL:
            lines.append(f"${key}={print_float(value, 0 if key in _RPM else 3)}")
        else:
            lines.append(f"${key}={int(value)}")
    return lines


def store(table: dict[int, float], line: str, *, idle: bool) -> int:
    """``$N=value`` (the line as GRBL holds it: no spaces, upper case); GRBL's status code.

    ``table`` is changed only when the answer is 0 (``ok``).
    """
    if not idle:
        return NOT_IDLE
    parameter = read_float(line[1:])
    if parameter is None:
        return BAD_NUMBER_FORMAT
    number, rest = parameter
    if rest[:1] != "=":
        return INVALID_STATEMENT
    read = read_float(rest[1:])
    if read is None:
        return BAD_NUMBER_FORMAT
    value, rest = read
    if rest or number > 255:
        return INVALID_STATEMENT
    return _store_global(table, int(number), value)


def _store_global(table: dict[int, float], key: int, value: float) -> int:
    """``settings_store_global_setting``."""
    if value < 0:
        return NEGATIVE_VALUE
    if key >= 100:
        group, axis = divmod(key - 100, 10)
        if group > 3 or axis >= GRBL_AXES:
            return INVALID_STATEMENT
        table[key] = value
        return OK
    if key not in table:
        return INVALID_STATEMENT
    whole = int(value) & 0xFF  # uint8_t int_value = trunc(value)
    if key == 0 and whole < 3:
        return STEP_PULSE_MIN
    if key in _BYTES:
        table[key] = float(whole)
    elif key in _FLAGS:
        if key == 20 and whole and not table.get(22):
            return SOFT_LIMIT_ERROR
        table[key] = 1.0 if whole else 0.0
        if key == 22 and not whole:
            table[20] = 0.0  # homing off forces soft limits off
    else:
        table[key] = value
    return OK
