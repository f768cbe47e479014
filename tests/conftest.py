"""Test configuration shared by every test.

Qt runs offscreen; a test that leaves a thread running or a transport open
fails, because in the station either one is a link or a motor left behind.
"""

from __future__ import annotations

import gc
import os
import threading
from collections.abc import Iterator
from pathlib import Path

os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")

import pytest
from PySide6.QtCore import QStandardPaths

from app.main_thread_gc import collect_due
from protocol.transport.base import open_transports
from tests.helpers import busy_core
from tests.helpers.harness import StationHarness

# Checkpoints and other app data go to Qt's test locations, never the operator's.
QStandardPaths.setTestModeEnabled(True)

ROOT = Path(__file__).resolve().parent.parent
DATA = ROOT / "tests" / "data"
THIRD_PARTY = ROOT / "tests" / "third_party"


@pytest.fixture(scope="session", autouse=True)
def loaded_machine() -> Iterator[int]:
    """``STEPDECK_BUSY_CORE=1`` (or N): the whole session runs with that many cores kept busy
    by another process (:mod:`tests.helpers.busy_core`), so a test that only passes on an
    idle machine shows itself.  The fixture's value is the count (0: none)."""
    cores = busy_core.cores_wanted()
    if not cores:
        yield 0
        return
    with busy_core.busy_cores(cores):
        yield cores


def pytest_report_header(config: pytest.Config) -> str | None:
    cores = busy_core.cores_wanted()
    return f"STEPDECK_BUSY_CORE: {cores} core(s) kept busy by another process" if cores else None


def pytest_collection_modifyitems(items: list[pytest.Item]) -> None:
    for item in items:
        if {"qapp", "qtbot"} & set(getattr(item, "fixturenames", ())):
            item.add_marker(pytest.mark.gui)


@pytest.fixture(scope="session")
def i18n_cache(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """Where the tests compile the translations (once per session)."""
    return tmp_path_factory.mktemp("qm")


@pytest.fixture(autouse=True)
def english(request: pytest.FixtureRequest, i18n_cache: Path) -> None:
    """Widget tests read English as the operator sees it: with its plural forms installed."""
    if not {"qapp", "qtbot"} & set(request.fixturenames):
        return
    from app import i18n

    request.getfixturevalue("qapp")
    if i18n.current() != "en":
        i18n.install("en", i18n_cache)


@pytest.fixture(scope="session", autouse=True)
def collect_on_the_main_thread() -> Iterator[None]:
    """As the station does (app.main_thread_gc): no automatic collection, which could free a
    dropped station's Qt objects from a transport or asyncio thread of a later test."""
    gc.disable()
    yield
    gc.enable()


@pytest.fixture(autouse=True)
def collected_after_each_test() -> Iterator[None]:
    yield
    # Here, on the main thread, with no other test's thread running; by the collector's own
    # thresholds, as the station does (a full collection after every test cost minutes).
    collect_due()
    gc.disable()  # a test that stopped a MainThreadCollector switched it back on


@pytest.fixture(autouse=True)
def no_leftover_threads_or_transports() -> Iterator[None]:
    before = set(threading.enumerate())
    yield
    leaked_transports = open_transports()
    for transport in leaked_transports:
        transport.close()
    deadline = threading.Event()
    for _ in range(50):  # threads may still be finishing their last iteration
        extra = [t for t in threading.enumerate() if t not in before]
        if not extra:
            break
        deadline.wait(0.02)
    assert not leaked_transports, f"test left transports open: {leaked_transports}"
    assert not extra, f"test left threads running: {[t.name for t in extra]}"


@pytest.fixture
def harness(qapp: object) -> Iterator[StationHarness]:
    """A station with the emulator on a test clock, not yet connected; closed afterwards."""
    h = StationHarness()
    yield h
    h.close()


@pytest.fixture
def data_dir() -> Path:
    """Real job files and samples (``tests/data``; origin and licence in its SOURCES.md)."""
    return DATA
