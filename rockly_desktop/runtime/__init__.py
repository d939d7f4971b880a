"""Running a program without the window."""
