"""StepDeck's shipped files: machine profiles, translations, the icon, the desktop entry.

The repository keeps them in ``resources/``; the build maps that folder to the
package ``stepdeck_resources`` (setup.py), so an editable checkout and an
installed wheel both find them with ``importlib.resources`` (see app/resources.py).
"""
