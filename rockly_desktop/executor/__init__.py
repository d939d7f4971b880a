"""Running generated programs: a pure runner over a run control, and one Qt adapter."""
