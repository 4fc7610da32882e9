"""CREATIVE-py: learn to use tools from one demonstration and create new ones.

Re-implements Wicaksono & Sammut, "A cognitive robot equipped with autonomous tool
innovation expertise", IJECE 2020. Importing this package starts nothing: no Prolog
engine, no physics client.
"""

__version__ = "0.1.0"
