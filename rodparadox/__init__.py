"""sears-paradox: Minkowski diagrams of a rigid rod struck by particles (J. Franklin, "The 'Sears paradox'")."""

__version__ = "0.1.0"
