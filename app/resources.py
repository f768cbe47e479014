"""Where the files StepDeck ships are: machine profiles, translations, icons.

They are package data of ``stepdeck_resources`` (the repository's ``resources/``
folder, mapped to that name by setup.py), found through ``importlib.resources``
rather than beside this source file: an installed wheel keeps them in
site-packages, far from ``app/``, and only an editable checkout has them at
the repository's root.
"""

from __future__ import annotations

from importlib.resources import files
from pathlib import Path

PACKAGE = "stepdeck_resources"


def _folder() -> Path:
    """The resources as a folder on disk (Qt, TOML and lrelease all read real files)."""
    try:
        root = files(PACKAGE)
    except ModuleNotFoundError:
        # A checkout run without installing (PYTHONPATH=.), or an editable install made
        # before resources/ was mapped to the package: the folder is beside app/.
        checkout = Path(__file__).resolve().parent.parent / "resources"
        if (checkout / "__init__.py").is_file():
            return checkout
        raise
    if not isinstance(root, Path):
        # pip and pipx always install unpacked; a zip import would need extracting first.
        raise RuntimeError(f"StepDeck's resources must be installed as files, not in {root}")
    return root


RESOURCES = _folder()
MACHINES_DIR = RESOURCES / "machines"
I18N_DIR = RESOURCES / "i18n"
ICON = RESOURCES / "icons" / "stepdeck.svg"
DESKTOP_ENTRY = RESOURCES / "stepdeck.desktop"
MIME_TYPES = RESOURCES / "stepdeck-mime.xml"
