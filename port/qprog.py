"""Placeholder: the port of our QPROG stand-in (issue 11, in progress)."""
