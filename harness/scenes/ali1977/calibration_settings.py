"""What ``linkrepro ked-bound`` (``commands.py``) and the sample it runs (``calibration.py``)
share: the sample's defaults, its title and its files.  A module of their own: the command line
reads them for ``linkrepro --help``, and ``calibration.py`` imports every Ali engine."""

TITLE = "Ali (1977): the K.E.D. engines' error bound on random geometries and sections, Cases I-III"
#: the sample's defaults: 1250 draws of four runs each
SEED, DRAWS = 0, 1250
OUTPUTS = ("calibration.csv", "summary.csv", "calibration.md")
