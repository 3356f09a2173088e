"""Placeholder (issue 27, in progress)."""
