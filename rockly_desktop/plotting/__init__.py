"""The Plot panel's data, without Qt: bounded sample buffers per curve filled from the state
store, and the tidy CSV of what a plot shows. numpy (which the drawing needs anyway) keeps a
5-minute 1 kHz curve in fixed memory, so this is not in ``core``, which is standard library only."""
