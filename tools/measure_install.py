"""What a new user waits for and installs: ``python tools/measure_install.py`` prints the figures.

From a fresh clone of this repository's committed HEAD (or ``--rev``), in a temporary folder:

* **install and launch**: the README's install-and-launch command (the part
  after the system packages: ``python3 -m venv .venv && .venv/bin/pip install
  …``), timed from the clone to the first paint of the main window.  The last
  step, ``.venv/bin/stepdeck``, runs through a small wrapper that starts the
  same ``app.__main__.main`` and quits once the window has painted (offscreen
  unless ``--display``); the settings go to a temporary folder;
* **runtime venv size**: ``du`` of that venv, which holds the runtime
  dependencies only (no test or bench extras), PySide6 included, and its
  largest packages;
* **first drill file**: the first Excellon file opened in a fresh process of
  that venv, parsed and its holes ordered as the jobs dock does it: the time
  the operator waits (from the loaders imported, as in the running window,
  so the drill reader, gerbonara and fast-tsp are imported in it), and from
  process start (Qt and numpy imported too).

Not part of the test run.  pip's cache is used as it is (say ``--cold`` to
install without it: then the download is timed too).
"""

from __future__ import annotations

import argparse
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
BOARD = "tests/data/realdata/excellon/tracespace_eagle_arduino-uno.drd"

#: Runs ``stepdeck`` (app.__main__.main) and quits at the main window's first paint; prints
#: the wall-clock time of that paint (time.time()).
FIRST_PAINT = """
import sys, time
from PySide6.QtCore import QEvent, QObject, QTimer
from PySide6.QtWidgets import QApplication, QMainWindow

app = QApplication(sys.argv[:1])

class FirstPaint(QObject):
    def eventFilter(self, watched, event):
        if event.type() == QEvent.Type.Paint and isinstance(watched, QMainWindow):
            print(f"painted {time.time():.6f}", flush=True)
            app.removeEventFilter(self)
            QTimer.singleShot(0, app.quit)
        return False

watcher = FirstPaint()
app.installEventFilter(watcher)
from app.__main__ import main
sys.exit(main(sys.argv[1:]))
"""

#: The first drill file in a fresh process, as the jobs dock reads it (parse + hole order).
FIRST_DRILL = """
import sys, time
started = time.perf_counter()
from pathlib import Path
from app.jobs.loaders import load_job
ready = time.perf_counter()
program = load_job(Path(sys.argv[1]), ["X", "Y"])
done = time.perf_counter()
print(f"loaded {done - started:.6f} {done - ready:.6f} {len(program)}", flush=True)
"""


def readme_install_command(rev: str) -> str:
    """The README's launch command from ``python3 -m venv`` on (the apt step is the system's)."""
    text = subprocess.run(
        ["git", "-C", str(ROOT), "show", f"{rev}:README.md"],
        capture_output=True,
        text=True,
        check=True,
    ).stdout
    block = re.search(r"<!-- launch-command -->\s*```sh\n(.*?)\n```", text, re.S)
    if block is None:
        raise SystemExit("README has no launch-command block")
    command = block[1].strip()
    at = command.index("python3 -m venv")
    return command[at:]


def du_mb(path: Path) -> float:
    out = subprocess.run(["du", "-sk", str(path)], capture_output=True, text=True, check=True)
    return int(out.stdout.split()[0]) / 1024


def largest(site: Path, count: int = 8) -> list[tuple[float, str]]:
    sizes = [(du_mb(p), p.name) for p in site.iterdir() if not p.name.endswith(".dist-info")]
    return sorted(sizes, reverse=True)[:count]


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0] if __doc__ else None)
    parser.add_argument("--cold", action="store_true", help="install without pip's cache")
    parser.add_argument("--display", action="store_true", help="use the real display")
    parser.add_argument("--keep", action="store_true", help="keep the temporary folder")
    parser.add_argument("--rev", default="HEAD", help="measure this commit (default: HEAD)")
    args = parser.parse_args(argv)

    folder = Path(tempfile.mkdtemp(prefix="stepdeck-measure-"))
    env = dict(os.environ, XDG_CONFIG_HOME=str(folder / "config"))
    env.pop("VIRTUAL_ENV", None)
    if not args.display:
        env["QT_QPA_PLATFORM"] = "offscreen"
    if args.cold:
        env["PIP_NO_CACHE_DIR"] = "1"
    clone = folder / "stepdeck"
    install = readme_install_command(args.rev)
    wrapper = folder / "first_paint.py"
    wrapper.write_text(FIRST_PAINT)
    launch = re.sub(r"\.venv/bin/stepdeck\s*$", f".venv/bin/python {wrapper}", install)
    if launch == install:
        raise SystemExit(f"the README command does not end in .venv/bin/stepdeck: {install}")
    load = os.getloadavg()
    try:
        started = time.time()
        subprocess.run(["git", "clone", "-q", str(ROOT), str(clone)], check=True, env=env)
        if args.rev != "HEAD":
            subprocess.run(["git", "-C", str(clone), "checkout", "-q", args.rev], check=True)
        cloned = time.time()
        shell = subprocess.run(
            ["bash", "-c", launch], cwd=clone, env=env, capture_output=True, text=True
        )
        if shell.returncode != 0:
            print(shell.stdout, shell.stderr, sep="\n", file=sys.stderr)
            raise SystemExit(f"the install-and-launch command failed ({shell.returncode})")
        painted = float(re.findall(r"painted ([0-9.]+)", shell.stdout)[-1])

        venv = clone / ".venv"
        site = next((venv / "lib").glob("python3*/site-packages"))
        size = du_mb(venv)
        biggest = largest(site)

        python = str(venv / "bin" / "python")
        board = str(clone / BOARD)
        runs = []
        for _ in range(3):  # the first is the fresh install's very first load
            before = time.perf_counter()
            out = subprocess.run(
                [python, "-c", FIRST_DRILL, board],
                cwd=folder,
                env=env,
                capture_output=True,
                text=True,
                check=True,
            ).stdout
            fields = out.split()
            runs.append((time.perf_counter() - before, float(fields[1]), float(fields[2])))
        operations = int(fields[3])
    finally:
        if args.keep:
            print(f"kept {folder}")
        else:
            shutil.rmtree(folder, ignore_errors=True)

    print(
        f"measured {args.rev} on {time.strftime('%Y-%m-%d %H:%M')} "
        f"[load {load[0]:.2f}/{load[1]:.2f}]"
    )
    print(f"install-and-launch command: {install}")
    cache = "without pip's cache" if args.cold else "pip's cache as it was"
    print(
        f"fresh clone to first window: {painted - started:.1f} s "
        f"(clone {cloned - started:.1f} s, then venv + pip install + launch to first paint; "
        f"{cache})"
    )
    print(f"runtime venv (du, PySide6 included): {size:.0f} MB")
    print("  largest: " + ", ".join(f"{name} {mb:.0f} MB" for mb, name in biggest))
    first, inside, opened = runs[0]
    print(
        f"first drill file ({Path(BOARD).name}, {operations} operations) in a fresh process: "
        f"{opened:.2f} s to read and order it once the loaders are imported (as in the "
        f"window); {first:.2f} s from process start, {inside:.2f} s from the first import; "
        f"the next two processes: {min(r[2] for r in runs[1:]):.2f} / "
        f"{min(r[0] for r in runs[1:]):.2f} / {min(r[1] for r in runs[1:]):.2f} s"
    )
    return 0


if __name__ == "__main__":
    sys.exit(main())
