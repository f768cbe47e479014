"""How long a G-code board may stay silent: one number the session and its parts read.

Read as ``timing.SILENCE_S`` where used, not imported by value, so that a test
can shorten it in one place.
"""

#: No reply to status queries for this long: the link is lost (a job pauses) and the board is
#: asked on until it answers.  A board that answers a status query within milliseconds and
#: then goes silent for seconds has stopped listening, but a few seconds can be a host's or a
#: USB bridge's hiccup that loses nothing: a 2.5 s freeze of the board's replies mid-job must
#: not pause the job (the lamp is amber meanwhile, after
#: :data:`~app.machines.gcode.session.STALE_QUERIES`).
SILENCE_S = 4.0
