"""The backend-neutral robot interface a profile's commands are written against, and its backends."""
