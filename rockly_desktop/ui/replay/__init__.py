"""Replaying a recorded run: reading the recording in a thread, the timeline bar, the run shown again."""
