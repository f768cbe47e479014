"""What every ``stepdeck`` subcommand does with a wrong command line: exit status 1, one line.

argparse's own error path prints and exits from deep inside parsing; the
subcommands want the message back, to print it their way and return the code.
"""

from __future__ import annotations

import argparse
from typing import NoReturn


class UsageError(Exception):
    """The command line itself is wrong: exit status 1."""


class UsageParser(argparse.ArgumentParser):
    """An argument parser that raises :class:`UsageError` instead of exiting."""

    def error(self, message: str) -> NoReturn:
        raise UsageError(message)
