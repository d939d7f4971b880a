"""Replaying a recorded run: reading the recording, the timeline bar, the runs kept."""
