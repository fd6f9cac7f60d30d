"""Code generation: Python, C++ and Java bindings, skeletons and conformance programs."""

from .engine import LANGUAGES, Output, WriteReport, render, write_tree

__all__ = ["LANGUAGES", "Output", "WriteReport", "render", "write_tree"]
