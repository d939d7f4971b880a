"""HOBBIT, the care robot: Rockly's built-in robot profile."""
