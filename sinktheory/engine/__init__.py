"""The compiled ensemble engine: generated per system, vectorised across runs."""

#: Nothing here but the submodules (import them by name).
__all__: list[str] = []
