"""Bytes off the wire as one readable line, for the frame log and the composer."""

from __future__ import annotations


def escape_raw(raw: bytes) -> str:
    r"""The bytes as one printable line: ``\n``, ``\r``, ``\t`` and ``\xNN`` for the rest.

    A corrupted frame may hold any byte; the log must still be one line per frame.
    """
    out = []
    for byte in raw:
        if byte == 0x0A:
            out.append("\\n")
        elif byte == 0x0D:
            out.append("\\r")
        elif byte == 0x09:
            out.append("\\t")
        elif byte == 0x5C:
            out.append("\\\\")
        elif 0x20 <= byte < 0x7F:
            out.append(chr(byte))
        else:
            out.append(f"\\x{byte:02X}")
    return "".join(out)
