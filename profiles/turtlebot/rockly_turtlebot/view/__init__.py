"""The painters behind ``TurtleBotSimView`` (rockly_turtlebot/sim_view.py), one small module each:

model (reading a snapshot without trusting it), palette, texts, layout (pixels for a size),
room (floor, walls and boxes, cached), scan (the laser's rays), robot (the TurtleBot and its
trail), panel (radar, speed, battery), shapes (shared painting helpers).
"""
