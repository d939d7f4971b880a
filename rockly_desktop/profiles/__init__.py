"""Robot profiles: manifest schema, discovery and the registry (profile code is imported lazily)."""
