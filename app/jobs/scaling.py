"""A job's coordinates stretched per axis: the drill's teaching constants (FIDELITY S2-42).

When the teacher sets another Excellon step or another number of microsteps
a millimetre, the file's holes land elsewhere on the machine: a job read with
such constants is this program with every MOVE target multiplied, so that
the preview, the travel check and the estimate all see where the machine will
really go.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Mapping
from types import MappingProxyType

from app.jobs.program import OpKind, Program


def scaled(program: Program, factors: Mapping[str, float], note: str) -> Program:
    """``program`` with each MOVE target on an axis of ``factors`` multiplied by its factor."""
    if all(factor == 1.0 for factor in factors.values()):
        return program
    ops = [
        dataclasses.replace(
            op,
            target=MappingProxyType(
                {name: value * factors.get(name, 1.0) for name, value in op.target.items()}
            ),
        )
        if op.kind is OpKind.MOVE and op.target
        else op
        for op in program.operations
    ]
    return Program(
        program.name,
        tuple(ops),
        program.source,
        notes=(*program.notes, note),
        start_relative=program.start_relative,
    )
