"""A ``D`` that turns an axis round is sent twice: one lost on the way runs the move backwards.

The unit takes relative moves in the direction the last ``D`` set, and the
wire has no checksum.  A ``D`` mangled on the way (a flipped bit makes
``D+-+;`` into ``L+-+;``; lost bytes glue it to its neighbour) is answered
``?;`` and changes nothing, so the move after it runs in the direction the
``D`` before it set: backwards, when the lost one turned that axis round.
The station hears the ``?;`` but not which message it refused, and the
reports show the wrong way only once the axis is past the tolerance of its
path; the braking then carries it farther (the relay's seeds 98 and 180:
0.03 mm the wrong way, stopped).

Sent twice, one copy mangled still leaves the other to set the register
(a ``D`` repeated is harmless: it sets the same signs again).  Only a ``D``
that changes the sign of an axis that moves right after it is doubled; the
others change nothing that a loss could turn round, and the wire stays as
it was for every other command.
"""

from __future__ import annotations

from collections.abc import Sequence

from protocol.usb3.codec import Message, Move, SetDirection


def with_reversals_twice(messages: Sequence[Message], signs: Sequence[int]) -> list[Message]:
    """``messages`` with each ``D`` that reverses an axis moved after it written twice.

    ``signs`` is the direction register as the station last set it.
    """
    out: list[Message] = []
    register = list(signs)
    for index, message in enumerate(messages):
        out.append(message)
        if not isinstance(message, SetDirection):
            continue
        moved = _moved_before_next_direction(messages[index + 1 :])
        if any(message.signs[axis] != register[axis] for axis in moved):
            out.append(message)
        register = list(message.signs)
    return out


def _moved_before_next_direction(following: Sequence[Message]) -> set[int]:
    """The axes a move of more than nothing goes to before the next ``D``."""
    moved: set[int] = set()
    for message in following:
        if isinstance(message, SetDirection):
            break
        if isinstance(message, Move) and message.count:
            moved.add(int(message.axis))
    return moved
