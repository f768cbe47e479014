"""``python -m protocol.emulator``: the ``stepdeck-emulator`` command (see :mod:`.cli`)."""

from __future__ import annotations

import sys

from protocol.emulator.cli import main

if __name__ == "__main__":
    sys.exit(main())
