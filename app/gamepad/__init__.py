"""Jogging with a gamepad or joystick: the pure mapping, SDL behind a small interface, and
the poller that feeds the same jog state machine as the arrow keys.

SDL (pysdl2 + pysdl2-dll) is the optional extra ``stepdeck[gamepad]``: without it the
station runs as before and the gamepad setting says it is unavailable.
"""
