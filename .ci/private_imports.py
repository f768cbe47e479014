"""Refuse imports of private names (``_name``) from another module of the project.

A module's underscored names are its own business; a module that needs one
from elsewhere shows that the name belongs in a public interface.  ruff's
PLC2701 exempts first-party imports, which are exactly the ones that matter
here, so this small check does it.  Usage: ``python .ci/private_imports.py``.
"""

from __future__ import annotations

import ast
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
PACKAGES = ("app", "widgets", "protocol", "tests", "tools")


def private_imports(path: Path) -> list[str]:
    tree = ast.parse(path.read_text(encoding="utf-8"), filename=str(path))
    found = []
    for node in ast.walk(tree):
        if isinstance(node, ast.ImportFrom) and node.module and node.level == 0:
            if node.module.split(".")[0] not in PACKAGES:
                continue
            for alias in node.names:
                if alias.name.startswith("_") and not alias.name.startswith("__"):
                    where = f"{path.relative_to(ROOT)}:{node.lineno}"
                    found.append(f"{where}: imports private {alias.name} from {node.module}")
    return found


def main() -> int:
    problems = [
        problem
        for package in PACKAGES
        for path in sorted((ROOT / package).rglob("*.py"))
        for problem in private_imports(path)
    ]
    for problem in problems:
        print(problem)
    print(f"private imports across modules: {len(problems)}")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
