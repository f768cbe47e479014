"""The cyclic collector frees cycles on the GUI thread only (app.main_thread_gc)."""

from __future__ import annotations

import gc
import threading
from collections.abc import Iterator
from typing import ClassVar

import pytest
from pytestqt.qtbot import QtBot

from app.main_thread_gc import MainThreadCollector, collect_due


class Cycle:
    """A cycle that says, when freed, which thread freed it."""

    freed_in: ClassVar[list[str]] = []

    def __init__(self) -> None:
        self.me = self

    def __del__(self) -> None:
        Cycle.freed_in.append(threading.current_thread().name)


@pytest.fixture
def low_thresholds() -> Iterator[None]:
    old = gc.get_threshold()
    gc.set_threshold(10, 10, 10)
    Cycle.freed_in = []
    yield
    gc.set_threshold(*old)


def _drop_a_cycle_and_allocate_elsewhere() -> None:
    Cycle()  # unreachable at once, only a collection frees it

    def allocate() -> None:
        _ = [[] for _ in range(10_000)]  # fills generation 0 many times over

    worker = threading.Thread(target=allocate, name="transport")
    worker.start()
    worker.join()


def test_a_cycle_is_freed_on_the_gui_thread_not_where_memory_was_asked(
    qtbot: QtBot, low_thresholds: None
) -> None:
    collector = MainThreadCollector(interval_ms=10)
    collector.start()
    try:
        _drop_a_cycle_and_allocate_elsewhere()
        assert Cycle.freed_in == []  # the transport thread's allocations collected nothing
        qtbot.waitUntil(lambda: Cycle.freed_in != [], timeout=5000)
    finally:
        collector.stop()
    assert Cycle.freed_in == [threading.main_thread().name]


def test_nothing_is_collected_before_a_threshold_is_passed(low_thresholds: None) -> None:
    gc.collect()
    assert collect_due() is None
