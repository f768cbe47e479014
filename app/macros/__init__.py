"""Macros: named G-code snippets kept per machine profile, each run as a small job.

A macro is text the operator wrote once ("Park", "Pen test", "Go to corner")
and runs with one button.  It is never sent as typed: it is read by the job
parser into a program (:mod:`app.macros.program`, the same pre-flight as a
G-code file, its travel checked from where the machine stands), refused with
``macro "Name":line: reason`` when anything in it is wrong, and run by a job
runner of its own (:mod:`app.macros.runner`), so every line goes through the
session's motion gate, a lost link pauses it and Stop ends it as it does a job.

Macros are stored with the machine's settings (:mod:`app.macros.store`) and
exported and imported as TOML (:mod:`app.macros.toml_file`).  They exist on the
machines sent G-code text (the registry's ``takes_gcode_text``); the others
speak in frames the station composes, and their way to run a list of moves
is a points file.
"""
