"""Drill hole order figures for ``tools/benchmark.py``: speed at 50 000 holes, quality on boards.

The quality peer is Google OR-Tools' routing solver with guided local
search, 3 s per tool, on the same open path from the same start (the
``bench`` extra installs it; it is never a runtime dependency).  Without it
the row says so and prints only StepDeck's own lengths.
"""

from __future__ import annotations

import os
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
ORTOOLS_SECONDS = 3


def _load() -> str:
    one, five, _ = os.getloadavg()
    return f"[load {one:.2f}/{five:.2f}]"


def _ortools_path(
    points: np.ndarray, start: tuple[float, float], seconds: int
) -> tuple[float, int] | None:
    """OR-Tools' open path from ``start`` through ``points`` (guided local search): its length
    and its last hole (where the next tool starts), or None without OR-Tools."""
    try:
        from ortools.constraint_solver import pywrapcp, routing_enums_pb2
    except ImportError:
        return None
    nodes = np.vstack([np.asarray(start, dtype=np.float64), points])
    scale = 1000.0  # integer micrometres: the solver works in integers
    n = len(nodes)
    manager = pywrapcp.RoutingIndexManager(n, 1, 0)
    routing = pywrapcp.RoutingModel(manager)
    xs, ys = nodes[:, 0], nodes[:, 1]

    def cost(i: int, j: int) -> int:
        a, b = manager.IndexToNode(i), manager.IndexToNode(j)
        if b == 0:
            return 0  # the drill does not return: an open path is a tour with a free last edge
        return round(scale * float(np.hypot(xs[a] - xs[b], ys[a] - ys[b])))

    callback = routing.RegisterTransitCallback(cost)
    routing.SetArcCostEvaluatorOfAllVehicles(callback)
    params = pywrapcp.DefaultRoutingSearchParameters()
    params.first_solution_strategy = routing_enums_pb2.FirstSolutionStrategy.PATH_CHEAPEST_ARC
    params.local_search_metaheuristic = (
        routing_enums_pb2.LocalSearchMetaheuristic.GUIDED_LOCAL_SEARCH
    )
    params.time_limit.seconds = seconds
    solution = routing.SolveWithParameters(params)
    if solution is None:
        return None
    order = []
    index = solution.Value(routing.NextVar(routing.Start(0)))
    while not routing.IsEnd(index):
        order.append(manager.IndexToNode(index) - 1)
        index = solution.Value(routing.NextVar(index))
    path = np.vstack([nodes[0], points[order]])
    return float(np.hypot(*np.diff(path, axis=0).T).sum()), order[-1]


def bench_drill_order_quality() -> list[str]:
    """Per real board: StepDeck's travel against OR-Tools (GLS, 3 s a tool), each planning its own.

    OR-Tools orders tool after tool, each from where its own previous tool
    ended; StepDeck plans the board as its users get it (``plan_drilling``).
    """
    from app.jobs.formats.excellon.reader import plan_drilling, read_drill_file

    data = ROOT / "tests" / "data"
    boards = [data / "samples" / "pcb-driver" / "driver"]
    boards += sorted((data / "realdata" / "excellon").iterdir())
    lines = []
    for path in boards:
        plan = plan_drilling(read_drill_file(path))
        ours = sum(tool.travel_mm for tool in plan.tools)
        peer = 0.0
        here = (0.0, 0.0)
        for tool in plan.tools:
            # the same holes in file order: OR-Tools starts from its own previous end
            points = np.asarray([(h.x_mm, h.y_mm) for h in tool.holes], dtype=np.float64)
            solved = _ortools_path(points, here, ORTOOLS_SECONDS)
            if solved is None:
                peer = float("nan")
                break
            length, last = solved
            peer += length
            here = (float(points[last, 0]), float(points[last, 1]))
        if np.isnan(peer):
            verdict = "OR-Tools not installed (pip install -e '.[bench]')"
        else:
            verdict = f"OR-Tools {peer:,.1f} mm, ratio {ours / peer:.3f}x (goal <= 1.00x)"
        lines.append(
            f"drill order {path.name}: {sum(len(t.holes) for t in plan.tools)} holes, "
            f"{len(plan.tools)} tools, StepDeck {ours:,.1f} mm; {verdict} {_load()}"
        )
    return lines


def bench_drill_order_50k() -> list[str]:
    """5 tools x 10 000 random holes on 300 x 300 mm, each tour starting where the last ended."""
    started = time.perf_counter()
    from app.jobs.formats.excellon.hole_order import order_holes

    order_holes(np.random.default_rng(0).uniform(0, 10, size=(50, 2)))
    first_use = time.perf_counter() - started  # import and first call: nothing to compile
    rng = np.random.default_rng(1)
    tools = [rng.uniform(0, 300, size=(10_000, 2)) for _ in range(5)]
    samples = []
    cpu = []
    for _ in range(3):
        here = (0.0, 0.0)
        travel = 0.0
        started, cpu_started = time.perf_counter(), time.process_time()
        for points in tools:
            result = order_holes(points, start=here)
            travel += result.length
            here = (float(points[result.order[-1], 0]), float(points[result.order[-1], 1]))
        samples.append(time.perf_counter() - started)
        cpu.append(time.process_time() - cpu_started)
    # 0.7124 * sqrt(n * area): the expected optimal tour through n random points (Beardwood et al.)
    optimal = 5 * 0.7124 * (10_000 * 300 * 300) ** 0.5
    return [
        f"drill order 50,000 holes (5 tools x 10,000 on 300x300 mm): {min(samples):.2f} s "
        f"best of 3 (goal <= 0.5 s), processor time {min(cpu):.2f} s, travel {travel:,.0f} mm "
        f"({travel / optimal:.3f}x the expected optimum); import + first use {first_use:.2f} s "
        f"{_load()}"
    ]
