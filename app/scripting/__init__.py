"""The station driven from a Python script instead of a window (re-exported as ``stepdeck``).

Everything here calls the same session intents the panels call, so every
motion passes the same motion gate and soft limits; nothing here writes a
byte to a link itself.
"""
