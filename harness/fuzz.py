"""Placeholder: the fuzz run over every public entry point (issue 11, in progress)."""
