"""The harness: scenes, engines, cell-by-cell diff against the published tables, report."""
