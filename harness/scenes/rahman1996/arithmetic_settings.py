"""What ``linkrepro arithmetic`` (``commands.py``) and the study it runs (``arithmetic.py``)
share: the study's title, its files and its committed record.  A module of their own: the
command line reads them for ``linkrepro --help``, and ``arithmetic.py`` imports numpy, pandas
and the builds."""
from pathlib import Path

TITLE = "Rahman (1996): which digits survive a change of arithmetic"
OUTPUTS = ("arithmetic.csv", "arithmetic_cells.csv", "arithmetic.md")
#: which arithmetics reach each published cell's printed digit, as ``--record`` last wrote it
RECORD = Path(__file__).with_name("arithmetic_reached.csv")
