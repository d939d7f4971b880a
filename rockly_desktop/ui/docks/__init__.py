"""The window's docks (code, console, variables, state panels, plot, plan, topic monitor, simulator,
tablet), their table (registry: a new dock is one entry there) and how they are laid out."""
