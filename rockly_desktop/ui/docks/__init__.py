"""The window's docks (code, console, variables, state panels, plot, plan, topic monitor, simulator,
tablet) and how they are laid out."""
