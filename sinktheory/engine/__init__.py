"""The compiled ensemble engine: generated per system, vectorised across runs."""
