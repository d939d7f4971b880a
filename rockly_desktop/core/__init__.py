"""Pure-Python heart of Rockly: program files, errors, paths. Standard library only."""
