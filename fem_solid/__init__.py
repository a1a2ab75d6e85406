"""twoball.fem_solid -- finite elements of the elastic solid (placeholder)."""
