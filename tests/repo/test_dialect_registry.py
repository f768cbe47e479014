"""Each dialect is registered once per layer, and nothing else asks a profile its dialect.

A sixth machine is added by registering it (``docs/architecture.md``, "Adding
a machine"); a ``profile.dialect == "…"`` test somewhere in a panel would be
one more place to find and edit, and the one forgotten shows the new machine
another's controls.  So the source tree is scanned for such tests, and the
tables that are keyed by dialect are held to the same list of names.
"""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

from app.jobs.estimate import ESTIMATORS
from app.jobs.run.drivers import DRIVERS
from app.machines.registry import DIALECTS
from app.profiles import DIALECTS as PROFILE_DIALECTS
from app.profiles import load_profile
from app.station import Station
from protocol.clock import ManualClock
from widgets.dialects import WINDOW_DIALECTS

ROOT = Path(__file__).resolve().parents[2]
SCANNED = ("app", "widgets", "protocol", "stepdeck")
#: The registries themselves, and the profile loader, which checks the name a file gives
#: against the list.
ALLOWED = {
    "app/machines/registry.py",
    "widgets/dialects.py",
    "app/profiles.py",
}
COMPARISONS = (ast.Eq, ast.NotEq, ast.In, ast.NotIn, ast.Is, ast.IsNot)


def _names_dialect(node: ast.expr) -> bool:
    return (isinstance(node, ast.Attribute) and node.attr == "dialect") or (
        isinstance(node, ast.Name) and node.id == "dialect"
    )


def dialect_tests(source: str, where: str) -> list[str]:
    """Each comparison (or ``match``) on a ``dialect`` in ``source``, as ``where:line``."""
    found: list[tuple[int, str]] = []
    for node in ast.walk(ast.parse(source)):
        if isinstance(node, ast.Compare):
            operands = [node.left, *node.comparators]
            if any(isinstance(op, COMPARISONS) for op in node.ops) and any(
                _names_dialect(operand) for operand in operands
            ):
                found.append((node.lineno, ast.unparse(node)))
        elif isinstance(node, ast.Match) and _names_dialect(node.subject):
            found.append((node.lineno, f"match {ast.unparse(node.subject)}"))
    return [f"{where}:{line}: {text}" for line, text in sorted(found)]


def test_the_scan_finds_each_way_of_asking_the_dialect() -> None:
    """The scan would see the tests the registries replaced (else the next test proves nothing)."""
    source = (
        'if profile.dialect == "drill": pass\n'
        'ok = station.profile.dialect != "usb3"\n'
        'homes = dialect in ("gcode", "drill")\n'
        "match profile.dialect:\n    case 'stage': pass\n"
        "entry = DIALECTS[profile.dialect]\n"  # a look-up in a table is what is wanted
        "same = profile.name == other.name\n"
    )
    assert [line.split(":")[1] for line in dialect_tests(source, "x.py")] == ["1", "2", "3", "4"]


def test_no_code_outside_the_registries_asks_a_profile_its_dialect() -> None:
    offenders = []
    for package in SCANNED:
        for path in sorted((ROOT / package).rglob("*.py")):
            where = path.relative_to(ROOT).as_posix()
            if where not in ALLOWED:
                offenders += dialect_tests(path.read_text(encoding="utf-8"), where)
    assert not offenders, "dialect tested outside the registries:\n" + "\n".join(offenders)


def test_every_table_keyed_by_dialect_has_every_dialect_and_no_other() -> None:
    names = set(DIALECTS)
    assert names == set(PROFILE_DIALECTS)
    assert set(DRIVERS) == names
    assert set(ESTIMATORS) == names
    assert set(WINDOW_DIALECTS) == names
    for name, entry in DIALECTS.items():
        assert entry.name == name and WINDOW_DIALECTS[name].name == name


@pytest.mark.parametrize(
    "profile", ["xy-stage", "usb3", "pcb-drill", "string-art", "corexy-plotter", "grbl-plotter"]
)
def test_the_station_finds_its_session_and_emulator_by_the_registry(
    qapp: object, profile: str
) -> None:
    """``session_as`` answers by class; the short names answer only for the station's dialect."""
    station = Station(load_profile(profile), ManualClock(), realtime=False)
    try:
        station.connect_emulator()
        own = station.profile.dialect
        session_type = DIALECTS[own].session_type
        assert isinstance(station.session, session_type)
        assert station.session_as(session_type) is station.session
        assert getattr(station, f"{own}_session") is station.session
        assert getattr(station, f"{own}_emulator") is station.emulator
        for other in set(DIALECTS) - {own}:
            assert station.session_as(DIALECTS[other].session_type) is None
            assert getattr(station, f"{other}_session") is None
            assert getattr(station, f"{other}_emulator") is None
        with pytest.raises(AttributeError):
            _ = station.lathe_session  # no such dialect: an error, not None
    finally:
        station.shutdown()
