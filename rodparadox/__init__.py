"""sears-paradox: Minkowski diagrams of a rod struck by particles or pushed by forces, rigid or causal (J. Franklin, "The 'Sears paradox'")."""

__version__ = "0.1.0"
