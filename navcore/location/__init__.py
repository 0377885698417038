"""Location: frequency-of-arrival emitter location and satellite multilateration."""
